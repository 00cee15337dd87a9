// Specification of the DDS writer (issue #14, --format dds): DX10 header with the DXGI float
// formats, 3D tables as volume textures; texels round-trip (float32 exact, half within 2^-11).
#include <catch2/catch.hpp>

#include <string>

#include "baker/io/texture_writers.h"
#include "io_texture_util.h"

using namespace kiln::test;

namespace {

struct Dds {
  std::uint32_t flags = 0, height = 0, width = 0, pitch = 0, depth = 0, caps = 0, caps2 = 0;
  std::uint32_t dxgi = 0, dimension = 0, arraySize = 0;
};

constexpr std::size_t kDataAt = 4 + 124 + 20;

Dds Parse(const std::string& f) {
  REQUIRE(f.size() >= kDataAt);
  REQUIRE(f.substr(0, 4) == "DDS ");
  REQUIRE(Le32(f, 4) == 124);  // dwSize
  Dds d;
  d.flags = Le32(f, 8);
  d.height = Le32(f, 12);
  d.width = Le32(f, 16);
  d.pitch = Le32(f, 20);
  d.depth = Le32(f, 24);
  REQUIRE(Le32(f, 76) == 32);  // ddspf.dwSize
  CHECK(Le32(f, 80) == 0x4);   // DDPF_FOURCC
  CHECK(f.substr(84, 4) == "DX10");
  d.caps = Le32(f, 108);
  d.caps2 = Le32(f, 112);
  d.dxgi = Le32(f, 128);
  d.dimension = Le32(f, 132);
  CHECK(Le32(f, 136) == 0);  // miscFlag
  d.arraySize = Le32(f, 140);
  return d;
}

}  // namespace

TEST_CASE("a ggx-dfg DDS parses: DX10 R32G32_FLOAT 2D texture, exact texels", "[io][dds]") {
  const kiln::Table t = SmallGgxDfg();
  const std::string f = kiln::EncodeDds(t, false);
  const Dds d = Parse(f);
  CHECK(d.flags == (0x1u | 0x2u | 0x4u | 0x8u | 0x1000u));
  CHECK(d.width == 8);
  CHECK(d.height == 8);
  CHECK(d.pitch == 8 * 8);
  CHECK(d.depth == 0);
  CHECK(d.caps == 0x1000);  // DDSCAPS_TEXTURE
  CHECK(d.caps2 == 0);
  CHECK(d.dxgi == 16);      // DXGI_FORMAT_R32G32_FLOAT
  CHECK(d.dimension == 3);  // TEXTURE2D
  CHECK(d.arraySize == 1);
  REQUIRE(f.size() == kDataAt + t.data.size() * 4);
  for (std::size_t i = 0; i < t.data.size(); ++i) REQUIRE(LeFloat(f, kDataAt + 4 * i) == t.data[i]);
}

TEST_CASE("a half DDS is R16G16_FLOAT within 2^-11, a 3D table is a volume texture", "[io][dds]") {
  const kiln::Table t = SmallGgxDfg();
  const std::string f = kiln::EncodeDds(t, true);
  const Dds d = Parse(f);
  CHECK(d.dxgi == 34);  // DXGI_FORMAT_R16G16_FLOAT
  CHECK(d.pitch == 8 * 4);
  REQUIRE(f.size() == kDataAt + t.data.size() * 2);
  for (std::size_t i = 0; i < t.data.size(); ++i) {
    INFO("value " << i << " = " << t.data[i]);
    REQUIRE(WithinHalf(HalfToFloat(Le16(f, kDataAt + 2 * i)), t.data[i]));
  }

  const kiln::Table cube = Small3D();
  const std::string c = kiln::EncodeDds(cube, true);
  const Dds v = Parse(c);
  CHECK(v.dxgi == 54);                // DXGI_FORMAT_R16_FLOAT
  CHECK((v.flags & 0x800000u) != 0);  // DDSD_DEPTH
  CHECK(v.caps2 == 0x200000u);        // DDSCAPS2_VOLUME
  CHECK(v.dimension == 4);            // TEXTURE3D
  CHECK(v.width == 4);
  CHECK(v.height == 3);
  CHECK(v.depth == 2);
  REQUIRE(c.size() == kDataAt + cube.data.size() * 2);
  for (std::size_t i = 0; i < cube.data.size(); ++i)
    CHECK(HalfToFloat(Le16(c, kDataAt + 2 * i)) == cube.data[i]);  // small integers: exact
}

TEST_CASE("DDS refuses 3 half channels and more than 4 channels", "[io][dds]") {
  kiln::Table t = Small3D();
  t.channels = {"a", "b", "c"};
  t.channelMeanings.clear();
  t.data.resize(t.data.size() * 3, 0.25f);
  CHECK(Parse(kiln::EncodeDds(t, false)).dxgi == 6);  // DXGI_FORMAT_R32G32B32_FLOAT
  CHECK_THROWS_WITH(kiln::EncodeDds(t, true), Catch::Contains("R16G16B16"));
  t.channels = {"a", "b", "c", "d", "e"};
  t.data.resize(Small3D().data.size() * 5, 0.25f);
  CHECK_THROWS_WITH(kiln::EncodeDds(t, false), Catch::Contains("5 channels"));
}
