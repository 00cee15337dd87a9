// Hand-made KTX2, DDS and 16-bit PNG table files for the stress tests (stress_declared_sizes.cpp,
// stress_table_headers.cpp): a header declaring any size, a description (kiln.json or manifest
// entry) saying anything, and only the texel bytes the test gives, so that a file can claim more
// than it holds. Built from the format specifications (KTX 2.0, DDS DX10, PNG), not by kiln's
// writers.
#pragma once
#include <zlib.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace kiln::stress {

using nlohmann::ordered_json;

/// A kiln description of a 2D table of `width` x `height` nodes with `channels` channels (E0,
/// E1, ...), format 1, linear axes mu and roughness on [0, 1], png16 scale 1 and offset 0.
inline ordered_json HandDescription(std::uint64_t width, std::uint64_t height, int channels) {
  ordered_json j;
  j["format"] = 1;
  j["generator"] = "hand-made";
  j["name"] = "hand";
  j["model"] = "none";
  j["quantity"] = "albedo";
  j["channels"] = ordered_json::array();
  j["channel_meanings"] = ordered_json::array();
  ordered_json scale = ordered_json::array(), offset = ordered_json::array();
  for (int c = 0; c < channels; ++c) {
    j["channels"].push_back("E" + std::to_string(c));
    j["channel_meanings"].push_back("test");
    scale.push_back(1.0);
    offset.push_back(0.0);
  }
  j["axes"] = {
      {{"name", "mu"}, {"lo", 0.0}, {"hi", 1.0}, {"size", width}, {"warp", "linear"}},
      {{"name", "roughness"}, {"lo", 0.0}, {"hi", 1.0}, {"size", height}, {"warp", "linear"}}};
  j["params"] = "";
  j["method"] = "hand";
  j["tolerance"] = 0.0;
  j["bake_error"] = 0.0;
  j["spec_hash"] = "0";
  j["png16"] = {{"scale", scale}, {"offset", offset}};
  return j;
}

inline void PutLe32(std::string& s, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s += static_cast<char>((v >> (8 * k)) & 0xFF);
}
inline void PutLe64(std::string& s, std::uint64_t v) {
  PutLe32(s, static_cast<std::uint32_t>(v));
  PutLe32(s, static_cast<std::uint32_t>(v >> 32));
}
inline void PutBe32(std::string& s, std::uint32_t v) {
  for (int k = 3; k >= 0; --k) s += static_cast<char>((v >> (8 * k)) & 0xFF);
}

/// A KTX2 file: one level of 32-bit float texels (VK_FORMAT_R32..R32G32B32A32_SFLOAT), no DFD,
/// kiln.json as its only key/value entry, declaring `width` x `height` and a level of
/// `declaredLevelBytes` of which only `texels` follow.
inline std::string HandKtx2(const ordered_json& description, std::uint32_t width,
                            std::uint32_t height, int channels, const std::string& texels,
                            std::uint64_t declaredLevelBytes) {
  std::string kv = "kiln.json";
  kv += '\0';
  kv += description.dump();
  kv += '\0';
  std::string kvd;
  PutLe32(kvd, static_cast<std::uint32_t>(kv.size()));
  kvd += kv;
  while (kvd.size() % 16 != 0) kvd += '\0';
  const std::uint64_t kvdAt = 80 + 24, levelAt = kvdAt + kvd.size();
  std::string f("\xABKTX 20\xBB\r\n\x1A\n", 12);
  PutLe32(f, 100 + 3 * static_cast<std::uint32_t>(channels - 1));  // vkFormat
  PutLe32(f, 4);                                                   // typeSize
  PutLe32(f, width);
  PutLe32(f, height);
  PutLe32(f, 0);  // depth
  PutLe32(f, 0);  // layers
  PutLe32(f, 1);  // faces
  PutLe32(f, 1);  // levels
  PutLe32(f, 0);  // supercompression
  PutLe32(f, 0);  // dfd offset
  PutLe32(f, 0);  // dfd length
  PutLe32(f, static_cast<std::uint32_t>(kvdAt));
  PutLe32(f, static_cast<std::uint32_t>(kvd.size()));
  PutLe64(f, 0);  // sgd offset
  PutLe64(f, 0);  // sgd length
  PutLe64(f, levelAt);
  PutLe64(f, declaredLevelBytes);
  PutLe64(f, declaredLevelBytes);
  return f + kvd + texels;
}

/// A DDS file (DX10 header, R32_FLOAT..R32G32B32A32_FLOAT) declaring `width` x `height`, followed
/// by `texels` only; its description is a manifest entry (HandManifest).
inline std::string HandDds(std::uint32_t width, std::uint32_t height, int channels,
                           const std::string& texels) {
  static const std::uint32_t kDxgi[] = {41, 16, 6, 2};
  std::string f = "DDS ";
  PutLe32(f, 124);
  PutLe32(f, 0x1 | 0x2 | 0x4 | 0x1000);  // caps, height, width, pixel format
  PutLe32(f, height);
  PutLe32(f, width);
  while (f.size() < 84) f += '\0';
  f += "DX10";
  while (f.size() < 128) f += '\0';
  PutLe32(f, kDxgi[channels - 1]);
  PutLe32(f, 3);  // TEXTURE2D
  PutLe32(f, 0);
  PutLe32(f, 1);  // array size
  PutLe32(f, 0);
  return f + texels;
}

/// manifest.json describing `file` by `description` (its "format" moved to the top level, as
/// kiln writes it).
inline std::string HandManifest(ordered_json description, const std::string& file) {
  ordered_json m;
  m["generator"] = "hand-made";
  m["format"] = description["format"];
  description.erase("format");
  description["file"] = file;
  m["tables"] = ordered_json::array({description});
  return m.dump(2);
}

/// A PNG chunk: length, type, data, CRC.
inline std::string PngChunk(const std::string& type, const std::string& data) {
  std::string c;
  PutBe32(c, static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  c += body;
  PutBe32(c, static_cast<std::uint32_t>(
                 crc32(0L, reinterpret_cast<const Bytef*>(body.data()), body.size())));
  return c;
}

/// A 16-bit PNG (grey, RGB or RGBA: `samples`) declaring `width` x `height`, with kiln.json in a
/// tEXt chunk and `raw` (filter bytes and samples, as many rows as the test gives) deflated.
inline std::string HandPng16(const ordered_json& description, std::uint32_t width,
                             std::uint32_t height, int samples, const std::string& raw) {
  std::string ihdr;
  PutBe32(ihdr, width);
  PutBe32(ihdr, height);
  ihdr += static_cast<char>(16);
  ihdr += static_cast<char>(samples == 1 ? 0 : samples == 3 ? 2 : 6);
  ihdr += std::string(3, '\0');
  std::string text = "kiln.json";
  text += '\0';
  text += description.dump();
  uLongf packedSize = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packedSize, '\0');
  compress(reinterpret_cast<Bytef*>(packed.data()), &packedSize,
           reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()));
  packed.resize(packedSize);
  return std::string("\x89PNG\r\n\x1A\n", 8) + PngChunk("IHDR", ihdr) + PngChunk("tEXt", text) +
         PngChunk("IDAT", packed) + PngChunk("IEND", "");
}

}  // namespace kiln::stress
