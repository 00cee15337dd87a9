// baker/io/texture_readers.h: kiln's own reader of the texture files `kiln bake --format` writes
// (texture_writers.h): KTX2, DDS and 16-bit PNG back into a kiln::Table, so that `kiln inspect`,
// `kiln sample` and the tests read every format kiln writes, not only EXR.
//
// The metadata (axes, channels, errors, spec hash) comes from the file's own kiln.json (KTX2
// key/value data, PNG tEXt chunk); a DDS file has nowhere to keep it, so its description is the
// entry of manifest.json beside it whose "file" names it. The texels come back in kiln order
// (rows un-flipped when the file was written with --flip-y), as float: exact for float32 files,
// the stored half for float16 ones, stored / 65535 * scale + offset for 16-bit PNG (within
// scale / 131070 of the baked value).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "kiln/table.h"

namespace kiln {

/// The file formats a kiln table may be stored in, told apart by their first bytes.
enum class TableFileKind { Exr, Ktx2, Dds, Png, Unknown };

/// The kind of a file from its first bytes (at least 12 for KTX2; fewer give Unknown).
TableFileKind SniffTableFile(const std::string& firstBytes);

/// A table from the JSON description kiln writes (manifest entry, kiln.json): name, model,
/// quantity, channels, channel_meanings, axes, params, method, tolerance, bake_error,
/// lookup_error, spec_hash, generator (the keys AppendTableDescription writes). No texels.
/// Throws std::invalid_argument naming the first missing or malformed key (an axis size must be
/// a JSON integer within int), or the first problem tableHeaderProblem (kiln/table_checks.h, the
/// EXR loader's header checks) finds. The format version is checked by the callers.
Table TableFromDescription(const nlohmann::ordered_json& description);

/// The table in the bytes of a KTX2 file kiln wrote (one level, R/RG/RGB/RGBA 16- or 32-bit
/// float, kiln.json present, nested at most kMaxJsonDepth deep, with the integer "format" 1).
/// Throws std::invalid_argument with a one-line reason for a file that is not one (truncated,
/// another vkFormat, sizes that disagree with kiln.json, ...); a level shorter than the texels
/// the header declares is refused before anything is allocated for them.
Table DecodeKtx2(const std::string& bytes);

/// The table in the bytes of a DDS file kiln wrote (DX10 header, R/RG/RGB/RGBA float formats),
/// described by `description` (its manifest.json entry). Throws std::invalid_argument as
/// DecodeKtx2.
Table DecodeDds(const std::string& bytes, const nlohmann::ordered_json& description);

/// The table in the bytes of a 16-bit PNG kiln wrote (grey, RGB or RGBA, 16 bits, kiln.json
/// tEXt chunk with the per-channel scale and offset). Any deflate stream and any of the five
/// row filters are read (zlib). Throws std::invalid_argument as DecodeKtx2.
Table DecodePng16(const std::string& bytes);

/// Loads any kiln table file: EXR (kiln/exr_loader.h), KTX2, DDS (with manifest.json beside it)
/// or 16-bit PNG, by its first bytes. A DDS file's manifest.json (its top-level "format" must be
/// 1) is parsed once per run (ReadJsonFileCached). Throws std::runtime_error "cannot read 'PATH':
/// REASON" (one line).
Table LoadAnyTable(const std::string& path);

}  // namespace kiln
