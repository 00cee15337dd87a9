#include "baker/scene/glb.h"

#include <cstdint>
#include <cstdio>

#include "baker/scene/scene_error.h"

namespace kiln {
namespace {

constexpr uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t U32(const std::string& b, size_t at) {
  return static_cast<uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

void PutU32(std::string& b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b += static_cast<char>((v >> (8 * i)) & 0xFF);
}

std::string Hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", v);
  return buf;
}

}  // namespace

bool IsGlb(const std::string& bytes) { return bytes.size() >= 4 && U32(bytes, 0) == kMagic; }

std::string GlbJsonChunk(const std::string& bytes, const std::string& file) {
  if (bytes.size() < 12)
    throw SceneError(file, "byte 0 (glb header)",
                     "file has " + std::to_string(bytes.size()) + " bytes, a glb header needs 12");
  if (!IsGlb(bytes))
    throw SceneError(
        file, "byte 0 (glb magic)",
        "not a glTF binary: magic " + Hex(U32(bytes, 0)) + ", expected 0x46546C67 ('glTF')");
  uint32_t version = U32(bytes, 4), length = U32(bytes, 8);
  if (version != 2)
    throw SceneError(
        file, "byte 4 (glb version)",
        "glb version " + std::to_string(version) + ", kiln reads glTF 2.0 (version 2)");
  if (length != bytes.size())
    throw SceneError(file, "byte 8 (glb length)",
                     "header says " + std::to_string(length) + " bytes, the file has " +
                         std::to_string(bytes.size()));
  if (bytes.size() < 20)
    throw SceneError(file, "byte 12 (first chunk)",
                     "no chunk after the header (a glb needs a JSON chunk)");
  uint32_t chunkLength = U32(bytes, 12), chunkType = U32(bytes, 16);
  if (chunkType != kChunkJson)
    throw SceneError(file, "byte 16 (first chunk type)",
                     "first chunk is " + Hex(chunkType) + ", expected JSON (0x4E4F534A)");
  if (chunkLength > bytes.size() - 20)
    throw SceneError(
        file, "byte 12 (JSON chunk length)",
        "chunk of " + std::to_string(chunkLength) + " bytes runs past the end of the file");
  return bytes.substr(20, chunkLength);
}

std::string MakeGlb(const std::string& json, const std::string& bin) {
  std::string jsonChunk = json;
  while (jsonChunk.size() % 4) jsonChunk += ' ';
  std::string binChunk = bin;
  while (binChunk.size() % 4) binChunk += '\0';
  size_t total = 12 + 8 + jsonChunk.size() + (bin.empty() ? 0 : 8 + binChunk.size());
  std::string out;
  PutU32(out, kMagic);
  PutU32(out, 2);
  PutU32(out, static_cast<uint32_t>(total));
  PutU32(out, static_cast<uint32_t>(jsonChunk.size()));
  PutU32(out, kChunkJson);
  out += jsonChunk;
  if (!bin.empty()) {
    PutU32(out, static_cast<uint32_t>(binChunk.size()));
    PutU32(out, kChunkBin);
    out += binChunk;
  }
  return out;
}

}  // namespace kiln
