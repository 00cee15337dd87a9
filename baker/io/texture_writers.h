// baker/io/texture_writers.h: a kiln table as a GPU texture file engines load directly: KTX2,
// DDS (DX10) or a 16-bit PNG, next to the EXR of exr_writer.h (--format).
#pragma once

#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

class PendingFile;

/// The file formats `kiln bake --format` writes: Png16 stores plain [0, 1] values (stored /
/// 65535), Png16Scaled a scale and offset per channel (any range).
enum class OutputFormat { Exr, Ktx2, Dds, Png16, Png16Scaled };

/// Parses "exr", "ktx2", "dds", "png16" or "png16-scaled"; throws std::invalid_argument
/// ("unknown --format 'x' (exr, ktx2, dds, png16 or png16-scaled)") otherwise.
OutputFormat ParseOutputFormat(const std::string& text);

/// The --format name of `format` ("exr", "ktx2", "dds", "png16", "png16-scaled").
const char* FormatName(OutputFormat format);

/// The file extension of `format`, with its dot: ".exr", ".ktx2", ".dds", ".png" (both PNGs).
const char* FormatExtension(OutputFormat format);

/// The 16-bit PNG quantisation of one channel: value = stored / 65535 * scale + offset, with
/// offset = the channel's minimum and scale = its maximum - minimum (0 for a constant channel,
/// whose samples are then all 0). Rounding to the nearest step errs by at most scale / 131070.
struct Png16Channel {
  double scale = 0, offset = 0;
};

/// Each channel's range as a Png16Channel (offset = min, scale = max - min), in storage order:
/// the quantisation of png16-scaled.
std::vector<Png16Channel> Png16Scales(const Table& table);

/// The quantisation EncodePng16 uses: Png16Scales when `scaled`, else scale 1 and offset 0 for
/// every channel (plain values, value = stored / 65535).
std::vector<Png16Channel> Png16Quantisation(const Table& table, bool scaled);

/// Whether `format` is one of the 16-bit PNGs (Png16, Png16Scaled).
bool IsPng16(OutputFormat format);

/// True when `table`'s params carry flip_y=1 (its rows are written in reverse order within
/// each axis-2 slice: tables/engine_layout.h ApplyFlipY).
bool FlipsY(const Table& table);

/// The image rows of `table` in file order: row r of the file holds the table's image row
/// Rows[r] (kiln order: slice k = row / size1, node i1 = row % size1); with flipY the rows of
/// each axis-2 slice are reversed (the slices stay in order).
std::vector<int> FileRowOrder(const Table& table, bool flipY);

/// A KTX 2.0 file of `table` (Khronos KTX 2.0 specification): one mip level, no
/// supercompression, vkFormat R32_SFLOAT / R32G32_SFLOAT / R32G32B32_SFLOAT /
/// R32G32B32A32_SFLOAT (R16_SFLOAT ... R16G16B16A16_SFLOAT with `half`, round to nearest even)
/// for 1 to 4 channels in storage order as R, G, B, A; pixelWidth = size0, pixelHeight = size1
/// (a 1D table is a 2D N x 1 texture), pixelDepth = size2 for a 3D table (a 3D texture, slices
/// in axis-2 order) and 0 otherwise; layerCount 0, faceCount 1, levelCount 1. A basic Data
/// Format Descriptor (RGBSDA, linear transfer, one signed-float sample per channel). Key/value
/// data, sorted by key: KTXorientation ("rd", "rdi" for 3D; "ru"/"rui" with flipped rows),
/// KTXwriter (table.generator), kiln.json (the table's metadata as JSON: name, model,
/// quantity, channels and meanings, axes, params, errors, spec hash, flip_y) and
/// kiln.spec_hash. The level data starts on a 16-byte boundary. Rows are flipped when
/// FlipsY(table). Throws std::invalid_argument for more than 4 channels, or in half mode a
/// value beyond 65504.
std::string EncodeKtx2(const Table& table, bool half);

/// A DDS file of `table`: "DDS ", DDS_HEADER (flags CAPS | HEIGHT | WIDTH | PITCH |
/// PIXELFORMAT, plus DEPTH for a 3D table; pitch = size0 x texel bytes; caps TEXTURE, caps2
/// VOLUME for a 3D table; pixel format FOURCC "DX10"), DDS_HEADER_DXT10 (DXGI_FORMAT_R32_FLOAT
/// 41, R32G32_FLOAT 16, R32G32B32_FLOAT 6, R32G32B32A32_FLOAT 2; with `half` R16_FLOAT 54,
/// R16G16_FLOAT 34, R16G16B16A16_FLOAT 10; resource dimension TEXTURE2D (3), TEXTURE3D (4) for a
/// 3D table; array size 1), then the texels, rows as FileRowOrder. A 1D table is a 2D N x 1
/// texture. Throws std::invalid_argument for more than 4 channels, for 3 channels in half mode
/// (DXGI has no 3-channel half format) or in half mode a value beyond 65504.
std::string EncodeDds(const Table& table, bool half);

/// A 16-bit PNG of `table`'s image (size0 x size1*size2, slices stacked as in the EXR, rows as
/// FileRowOrder): grey for 1 channel, RGB for 2 (blue 0, unused) or 3, RGBA for 4, quantised
/// by Png16Quantisation: plain (`scaled` false: value = stored / 65535; a channel with a value
/// outside [0, 1] is refused with std::invalid_argument naming the channel and its range) or
/// with a scale and offset per channel (`scaled`). Chunks saying the samples are linear (cICP
/// BT.709 / linear transfer, gAMA 1.0; no sRGB, no iCCP: encodePngImage's `linear`), then tEXt
/// chunks: "kiln.scale" and "kiln.offset" (one %.17g number per channel, space-separated; 1 and
/// 0 when plain), "kiln.decode" (the formula) and "kiln.json" (as in EncodeKtx2, plus "png16":
/// scale, offset, encoding "unit" or "scaled"). Throws std::invalid_argument for more than 4
/// channels.
std::string EncodePng16(const Table& table, bool scaled = false);

/// Writes `table` in `format` (not Exr: exr_writer.h) into `file`'s temporary file, after
/// validateTable; the caller commits it (PendingFile::CommitAll). Throws std::runtime_error
/// "kiln: cannot write '<path>': <reason>" (one line).
void WriteTextureTable(PendingFile& file, const Table& table, OutputFormat format, bool half);

}  // namespace kiln
