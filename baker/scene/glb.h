// The glb container (glTF 2.0 binary): a 12-byte header (magic "glTF", version 2, total length,
// little-endian uint32 each), then chunks of {uint32 length, uint32 type, data padded to 4 bytes};
// the first chunk is the JSON ("JSON" = 0x4E4F534A), an optional second one the buffer
// ("BIN\0" = 0x004E4942).
#pragma once
#include <string>

namespace kiln {

/// True when `bytes` start with the glb magic "glTF".
bool IsGlb(const std::string& bytes);

/// The text of the JSON chunk of the glb container `bytes`. Throws SceneError at "byte N (...)"
/// for a bad header (magic, version other than 2, length) or a first chunk that is not JSON.
std::string GlbJsonChunk(const std::string& bytes, const std::string& file);

/// A glb container holding `json` (space-padded) and, when not empty, `bin` (zero-padded).
std::string MakeGlb(const std::string& json, const std::string& bin = "");

}  // namespace kiln
