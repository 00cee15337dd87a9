// Specification of the 8-bit PNGs `kiln bake --preset gltf-viewer` writes beside its float tables
// (docs/engines.md "gltf-viewer"): lut_ggx.png, lut_charlie.png and lut_sheen_E.png, each table
// channel in the PNG channel the glTF Sample Viewer's shaders read (lut_ggx .rg, lut_charlie .b,
// lut_sheen_E .r), values clamped to [0, 1] and rounded to 8 bits, rows in kiln's order.
#include <catch2/catch.hpp>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "baker/io/engine_png_writer.h"
#include "baker/io/texture_readers.h"
#include "cli_util.h"

namespace {

/// An 8-bit RGB PNG as read back: its size and its rows, top first, 3 bytes a pixel.
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

std::uint32_t BigEndian32(const std::string& bytes, size_t at) {
  return std::uint32_t(std::uint8_t(bytes[at])) << 24 |
         std::uint32_t(std::uint8_t(bytes[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(bytes[at + 2])) << 8 |
         std::uint32_t(std::uint8_t(bytes[at + 3]));
}

/// Decodes an 8-bit RGB, non-interlaced PNG whose rows use filter None (what EnginePng8 writes);
/// fails the test on anything else.
Rgb8Image DecodeRgb8(const std::string& bytes) {
  REQUIRE(bytes.size() > 8);
  REQUIRE(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  Rgb8Image img;
  std::string idat;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const std::uint32_t len = BigEndian32(bytes, at);
    const std::string type = bytes.substr(at + 4, 4);
    if (type == "IHDR") {
      img.width = int(BigEndian32(bytes, at + 8));
      img.height = int(BigEndian32(bytes, at + 12));
      REQUIRE(int(std::uint8_t(bytes[at + 16])) == 8);  // bit depth
      REQUIRE(int(std::uint8_t(bytes[at + 17])) == 2);  // colour type RGB
      REQUIRE(int(std::uint8_t(bytes[at + 20])) == 0);  // no interlace
    }
    if (type == "IDAT") idat += bytes.substr(at + 8, len);
    at += 12 + len;
  }
  const size_t stride = size_t(img.width) * 3 + 1;
  std::vector<std::uint8_t> raw(stride * size_t(img.height));
  uLongf rawSize = raw.size();
  REQUIRE(uncompress(raw.data(), &rawSize, reinterpret_cast<const Bytef*>(idat.data()),
                     idat.size()) == Z_OK);
  REQUIRE(rawSize == raw.size());
  for (int y = 0; y < img.height; ++y) {
    REQUIRE(raw[size_t(y) * stride] == 0);  // filter None
    img.rgb.insert(img.rgb.end(), raw.begin() + long(size_t(y) * stride + 1),
                   raw.begin() + long(size_t(y + 1) * stride));
  }
  return img;
}

/// The 8-bit level of a value: clamped to [0, 1], nearest of 256.
int Level(double v) { return int(std::lround(std::fmin(std::fmax(v, 0.0), 1.0) * 255)); }

/// Checks that `png` holds `table` with table channel k in PNG channel placement[k] and 0 in the
/// other PNG channels; returns how many table values were above 1 (stored as 255).
long CheckPlacement(const Rgb8Image& png, const kiln::Table& table,
                    const std::vector<int>& placement) {
  REQUIRE(png.width == table.size(0));
  REQUIRE(png.height == table.size(1));
  const size_t nc = table.channels.size();
  long above = 0;
  for (size_t texel = 0; texel < size_t(png.width) * size_t(png.height); ++texel) {
    std::vector<int> expected(3, 0);
    for (size_t k = 0; k < nc; ++k) {
      const double v = table.data[texel * nc + k];
      above += v > 1;
      expected[size_t(placement[k])] = Level(v);
    }
    for (int c = 0; c < 3; ++c) CHECK(int(png.rgb[texel * 3 + size_t(c)]) == expected[size_t(c)]);
  }
  return above;
}

}  // namespace

TEST_CASE("kiln bake --preset gltf-viewer writes lut_*.png with the channels the viewer reads",
          "[engine-presets][gltf-viewer]") {
  const std::string dir = kiln::test::TempDir("preset_gltf_viewer");
  const auto r = kiln::test::RunKiln("bake --preset gltf-viewer --size 8 -j 2 --out " + dir);
  REQUIRE(r.exitCode == 0);
  const auto table = [&](const char* name) {
    return kiln::DecodeKtx2(kiln::test::ReadFile(dir + "/" + name + ".ktx2"));
  };
  const auto png = [&](const char* name) {
    return DecodeRgb8(kiln::test::ReadFile(dir + "/" + name + ".png"));
  };
  // lut_ggx: R = scale, G = bias (texture(u_GGXLUT, vec2(NdotV, roughness)).rg), B = 0.
  const kiln::Table ggx = table("ggx-dfg-engine");
  CHECK(CheckPlacement(png("lut_ggx"), ggx, {0, 1}) == 0);
  // lut_charlie: the Charlie DFG in B (texture(u_CharlieLUT, ...).b); above 1 at grazing view,
  // where the 8-bit file holds 1, and the bake says so.
  const long charlieAbove = CheckPlacement(png("lut_charlie"), table("charlie-dfg-engine"), {2});
  CHECK(charlieAbove > 0);
  CHECK(r.err.find("note    lut_charlie.png: " + std::to_string(charlieAbove) +
                   " values above 1 stored as 1") != std::string::npos);
  // lut_sheen_E: the sheen albedo in R (texture(u_SheenELUT, ...).r).
  CheckPlacement(png("lut_sheen_E"), table("charlie-smith-albedo-engine"), {0});
  // Row order: the first PNG row is the smallest roughness (the smooth row reflects more at
  // normal incidence), as in the float file.
  const Rgb8Image g = png("lut_ggx");
  const size_t lastColumn = size_t(g.width - 1) * 3;
  CHECK(g.rgb[lastColumn] > g.rgb[size_t(g.height - 1) * size_t(g.width) * 3 + lastColumn]);
  std::filesystem::remove_all(dir);
}

TEST_CASE("EnginePng8 refuses placements that do not name one PNG channel per table channel",
          "[engine-presets][gltf-viewer]") {
  kiln::Table t;
  t.name = "t";
  t.channels = {"A", "B"};
  t.axes.resize(2);
  t.axes[0].axis.size = 2;
  t.axes[1].axis.size = 1;
  t.data = {0.25f, 1.5f, -1.0f, std::nanf("")};
  const Rgb8Image img = DecodeRgb8(kiln::EnginePng8(t, {2, 0}));
  // texel 0: A = 0.25 -> B = 64, B = 1.5 -> R = 255 (clamped); texel 1: -1 -> 0, NaN -> 0.
  CHECK(img.rgb == std::vector<std::uint8_t>{255, 0, 64, 0, 0, 0});
  CHECK_THROWS_AS(kiln::EnginePng8(t, {0}), std::invalid_argument);
  CHECK_THROWS_AS(kiln::EnginePng8(t, {1, 1}), std::invalid_argument);
  CHECK_THROWS_AS(kiln::EnginePng8(t, {0, 3}), std::invalid_argument);
}
