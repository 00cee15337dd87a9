// Specification of the KTX2 writer (issue #14, --format ktx2): a ggx-dfg parses with an
// independent little KTX 2.0 reader (identifier, header, level index, DFD, key/value data) and
// its texels round-trip: float32 exactly, half within 2^-11.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <string>

#include "baker/io/texture_writers.h"
#include "io_texture_util.h"

using namespace kiln::test;

namespace {

struct Ktx2 {
  std::uint32_t vkFormat = 0, typeSize = 0, width = 0, height = 0, depth = 0, layers = 0, faces = 0,
                levels = 0, supercompression = 0;
  std::uint32_t dfdOffset = 0, dfdLength = 0, kvdOffset = 0, kvdLength = 0;
  std::uint64_t levelOffset = 0, levelLength = 0, levelUncompressed = 0;
  std::map<std::string, std::string> kv;  ///< values without their trailing NUL
  std::vector<std::string> keyOrder;
};

Ktx2 Parse(const std::string& f) {
  static const unsigned char id[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                       0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  REQUIRE(f.size() > 104);
  REQUIRE(std::memcmp(f.data(), id, 12) == 0);
  Ktx2 k;
  k.vkFormat = Le32(f, 12);
  k.typeSize = Le32(f, 16);
  k.width = Le32(f, 20);
  k.height = Le32(f, 24);
  k.depth = Le32(f, 28);
  k.layers = Le32(f, 32);
  k.faces = Le32(f, 36);
  k.levels = Le32(f, 40);
  k.supercompression = Le32(f, 44);
  k.dfdOffset = Le32(f, 48);
  k.dfdLength = Le32(f, 52);
  k.kvdOffset = Le32(f, 56);
  k.kvdLength = Le32(f, 60);
  CHECK(Le64(f, 64) == 0);  // sgdByteOffset
  CHECK(Le64(f, 72) == 0);  // sgdByteLength
  k.levelOffset = Le64(f, 80);
  k.levelLength = Le64(f, 88);
  k.levelUncompressed = Le64(f, 96);
  for (std::size_t at = k.kvdOffset; at < std::size_t(k.kvdOffset) + k.kvdLength;) {
    const std::uint32_t n = Le32(f, at);
    const std::string kv = f.substr(at + 4, n);
    const std::size_t nul = kv.find('\0');
    REQUIRE(nul != std::string::npos);
    std::string value = kv.substr(nul + 1);
    if (!value.empty() && value.back() == '\0') value.pop_back();
    k.kv[kv.substr(0, nul)] = value;
    k.keyOrder.push_back(kv.substr(0, nul));
    at += 4 + (n + 3) / 4 * 4;
  }
  return k;
}

}  // namespace

TEST_CASE("a ggx-dfg KTX2 parses: RG32F 2D texture, DFD, key/value data, exact texels",
          "[io][ktx2]") {
  const kiln::Table t = SmallGgxDfg();
  const std::string f = kiln::EncodeKtx2(t, /*half=*/false);
  const Ktx2 k = Parse(f);
  CHECK(k.vkFormat == 103);  // VK_FORMAT_R32G32_SFLOAT
  CHECK(k.typeSize == 4);
  CHECK(k.width == 8);
  CHECK(k.height == 8);
  CHECK(k.depth == 0);
  CHECK(k.layers == 0);
  CHECK(k.faces == 1);
  CHECK(k.levels == 1);
  CHECK(k.supercompression == 0);

  // DFD: total size, then a basic block: RGBSDA, linear, 8-byte texels, two float samples.
  REQUIRE(k.dfdOffset == 104);
  CHECK(Le32(f, k.dfdOffset) == k.dfdLength);
  CHECK(k.dfdLength == 4 + 24 + 2 * 16);
  const std::size_t b = k.dfdOffset + 4;
  CHECK(Le32(f, b) == 0);                        // Khronos vendor, basic descriptor type
  CHECK((Le32(f, b + 4) & 0xFFFF) == 2);         // version
  CHECK((Le32(f, b + 4) >> 16) == 24 + 2 * 16);  // block size
  CHECK((Le32(f, b + 8) & 0xFF) == 1);           // colour model RGBSDA
  CHECK(((Le32(f, b + 8) >> 16) & 0xFF) == 1);   // transfer function linear
  CHECK((Le32(f, b + 16) & 0xFF) == 8);          // bytesPlane0
  for (std::uint32_t c = 0; c < 2; ++c) {
    const std::uint32_t w = Le32(f, b + 24 + 16 * c);
    CHECK((w & 0xFFFF) == 32 * c);          // bit offset
    CHECK(((w >> 16) & 0xFF) == 31);        // bit length - 1
    CHECK((w >> 24) == (c | 0x80 | 0x40));  // channel R/G, FLOAT | SIGNED
  }

  // Key/value data sorted by key, kiln's metadata as JSON.
  CHECK(k.kvdOffset == k.dfdOffset + k.dfdLength);
  CHECK(std::is_sorted(k.keyOrder.begin(), k.keyOrder.end()));
  CHECK(k.kv.at("KTXwriter") == t.generator);
  CHECK(k.kv.at("KTXorientation") == "rd");
  CHECK(k.kv.at("kiln.spec_hash") == t.specHash);
  const auto meta = nlohmann::json::parse(k.kv.at("kiln.json"));
  CHECK(meta["name"] == "ggx-dfg");
  CHECK(meta["channels"] == nlohmann::json({"A", "B"}));
  CHECK(meta["axes"][0]["warp"] == "root4-layer");

  // The level: 16-byte aligned, the whole rest of the file, every float exact.
  CHECK(k.levelOffset % 16 == 0);
  CHECK(k.levelOffset >= std::uint64_t(k.kvdOffset) + k.kvdLength);
  CHECK(k.levelLength == t.data.size() * 4);
  CHECK(k.levelUncompressed == k.levelLength);
  REQUIRE(k.levelOffset + k.levelLength == f.size());
  for (std::size_t i = 0; i < t.data.size(); ++i)
    REQUIRE(LeFloat(f, k.levelOffset + 4 * i) == t.data[i]);
}

TEST_CASE("a half KTX2 is RG16F within 2^-11, a 3D table is a 3D texture, --flip-y says ru",
          "[io][ktx2]") {
  const kiln::Table t = SmallGgxDfg();
  const std::string f = kiln::EncodeKtx2(t, /*half=*/true);
  const Ktx2 k = Parse(f);
  CHECK(k.vkFormat == 83);  // VK_FORMAT_R16G16_SFLOAT
  CHECK(k.typeSize == 2);
  CHECK(k.levelLength == t.data.size() * 2);
  const std::uint32_t g = Le32(f, k.dfdOffset + 4 + 24 + 16);  // sample 1: G
  CHECK((g & 0xFFFF) == 16);                                   // bit offset
  CHECK(((g >> 16) & 0xFF) == 15);                             // 16 bits
  CHECK((g >> 24) == (1 | 0x80 | 0x40));
  for (std::size_t i = 0; i < t.data.size(); ++i) {
    INFO("value " << i << " = " << t.data[i]);
    REQUIRE(WithinHalf(HalfToFloat(Le16(f, k.levelOffset + 2 * i)), t.data[i]));
  }

  const kiln::Table cube = Small3D();
  const Ktx2 c = Parse(kiln::EncodeKtx2(cube, false));
  CHECK(c.vkFormat == 100);  // VK_FORMAT_R32_SFLOAT
  CHECK(c.width == 4);
  CHECK(c.height == 3);
  CHECK(c.depth == 2);
  CHECK(c.kv.at("KTXorientation") == "rdi");

  kiln::Table flipped = cube;
  flipped.params = "flip_y=1";
  const std::string ff = kiln::EncodeKtx2(flipped, false);
  const Ktx2 fk = Parse(ff);
  CHECK(fk.kv.at("KTXorientation") == "rui");
  // Row 0 of slice 0 holds roughness node 2 (20, 21, ...); slice 1 starts at node 2 again.
  CHECK(LeFloat(ff, fk.levelOffset) == 20.0f);
  CHECK(LeFloat(ff, fk.levelOffset + 4 * 4) == 10.0f);
  CHECK(LeFloat(ff, fk.levelOffset + 4 * 12) == 120.0f);
}

TEST_CASE("KTX2 refuses more than 4 channels and halves out of range", "[io][ktx2]") {
  kiln::Table t = Small3D();
  t.data[5] = 1e6f;
  CHECK_NOTHROW(kiln::EncodeKtx2(t, false));
  CHECK_THROWS_WITH(kiln::EncodeKtx2(t, true), Catch::Contains("half precision"));
  t = Small3D();
  t.channels = {"a", "b", "c", "d", "e"};
  t.channelMeanings.clear();
  t.data.resize(t.data.size() * 5, 0.5f);
  CHECK_THROWS_WITH(kiln::EncodeKtx2(t, false), Catch::Contains("5 channels"));
}
