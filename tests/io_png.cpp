// Specification of the false-colour PNG preview: a valid PNG (checked by a little reader of its
// own, the image data inflated by zlib), one viridis panel per channel.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "baker/io/png_writer.h"

#include <zlib.h>

namespace fs = std::filesystem;

namespace {

std::uint32_t bigEndian32(const std::string& s, std::size_t at) {
  return std::uint32_t(std::uint8_t(s[at])) << 24 | std::uint32_t(std::uint8_t(s[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(s[at + 2])) << 8 | std::uint32_t(std::uint8_t(s[at + 3]));
}

/// Bitwise CRC-32 (no table), independent of the writer's.
std::uint32_t referenceCrc(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (char ch : bytes) {
    crc ^= std::uint8_t(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

struct DecodedPng {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

/// Decodes a PNG made of stored deflate blocks, checking signature, chunk
/// CRCs, the zlib header and Adler-32; fails the test on any defect.
DecodedPng decode(const std::string& png) {
  REQUIRE(png.size() > 8);
  REQUIRE(png.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  DecodedPng out;
  std::string zlib;
  std::vector<std::string> chunkTypes;
  for (std::size_t at = 8; at < png.size();) {
    REQUIRE(at + 12 <= png.size());
    const std::uint32_t length = bigEndian32(png, at);
    REQUIRE(at + 12 + length <= png.size());
    const std::string type = png.substr(at + 4, 4);
    const std::string data = png.substr(at + 8, length);
    CHECK(bigEndian32(png, at + 8 + length) == referenceCrc(type + data));
    chunkTypes.push_back(type);
    if (type == "IHDR") {
      REQUIRE(length == 13);
      out.width = int(bigEndian32(data, 0));
      out.height = int(bigEndian32(data, 4));
      CHECK(data.substr(8) == std::string("\x08\x02\x00\x00\x00", 5));  // 8-bit RGB
    }
    if (type == "IDAT") zlib += data;
    at += 12 + length;
  }
  CHECK(chunkTypes.front() == "IHDR");
  CHECK(chunkTypes.back() == "IEND");
  REQUIRE(zlib.size() >= 6);
  CHECK((std::uint8_t(zlib[0]) * 256 + std::uint8_t(zlib[1])) % 31 == 0);
  CHECK((std::uint8_t(zlib[0]) & 0x0F) == 8);  // deflate
  // Inflated by zlib itself (an independent decoder of the deflate stream and its Adler-32).
  std::vector<std::uint8_t> raw((std::size_t(out.width) * 3 + 1) * std::size_t(out.height));
  uLongf rawSize = uLongf(raw.size());
  REQUIRE(uncompress(raw.data(), &rawSize, reinterpret_cast<const Bytef*>(zlib.data()),
                     uLong(zlib.size())) == Z_OK);
  REQUIRE(rawSize == raw.size());
  const std::size_t row = std::size_t(out.width) * 3 + 1;
  REQUIRE(raw.size() == row * std::size_t(out.height));
  for (int y = 0; y < out.height; ++y) {
    CHECK(raw[std::size_t(y) * row] == 0);  // filter None
    out.rgb.insert(out.rgb.end(), raw.begin() + long(std::size_t(y) * row + 1),
                   raw.begin() + long(std::size_t(y + 1) * row));
  }
  return out;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("encodePngRgb8 writes a valid PNG holding exactly the pixels", "[io][png]") {
  // Wide enough for several stored blocks (> 65535 bytes of scanlines).
  const int width = 300, height = 90;
  std::vector<std::uint8_t> rgb(std::size_t(width) * height * 3);
  for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = std::uint8_t((k * 7 + k / 911) & 0xFF);
  const DecodedPng png = decode(kiln::encodePngRgb8(width, height, rgb));
  CHECK(png.width == width);
  CHECK(png.height == height);
  CHECK(png.rgb == rgb);
  CHECK_THROWS(kiln::encodePngRgb8(2, 2, rgb));
  CHECK_THROWS(kiln::encodePngRgb8(0, 0, {}));
}

TEST_CASE("viridis runs from dark purple through green to yellow", "[io][png]") {
  std::uint8_t lo[3], mid[3], hi[3], nan[3];
  kiln::viridis(0.0, lo);
  kiln::viridis(0.5, mid);
  kiln::viridis(1.0, hi);
  kiln::viridis(std::numeric_limits<double>::quiet_NaN(), nan);
  // matplotlib: viridis(0) = (68, 1, 84), viridis(0.5) = (33, 145, 140), viridis(1) = (253, 231,
  // 37)
  const int expected[3][3] = {{68, 1, 84}, {33, 145, 140}, {253, 231, 37}};
  const std::uint8_t* got[3] = {lo, mid, hi};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) CHECK(std::abs(int(got[i][k]) - expected[i][k]) <= 6);
  CHECK(std::vector<int>(nan, nan + 3) == std::vector<int>(lo, lo + 3));
}

TEST_CASE("the false-colour PNG has one normalized panel per channel", "[io][png]") {
  const fs::path dir = fs::temp_directory_path() / ("kiln-test-png-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  kiln::Table t;
  t.name = "ramp";
  t.channels = {"up", "down"};
  t.axes = {{"x", {0.0, 1.0, 8, kiln::Warp::Linear}}, {"y", {0.0, 1.0, 4, kiln::Warp::Linear}}};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i) {
      t.data.push_back(float(i));           // "up" grows to the right, range 0..7
      t.data.push_back(100.0f - 3.0f * j);  // "down" falls downwards, range 91..100
    }
  const std::string path = (dir / "ramp.png").string();
  kiln::writeFalseColourPng(path, t);
  CHECK_FALSE(fs::exists(path + ".tmp"));
  const DecodedPng png = decode(readBytes(path));
  const kiln::PreviewLayout l = kiln::FalseColourLayout(t);
  REQUIRE(png.width == l.width);
  REQUIRE(png.height == l.height);
  // 8 x 4 texels scale by 512 / 8 = 64 -> capped at 16: images 128 x 64, side by side.
  REQUIRE(l.imageWidth == 128);
  REQUIRE(l.imageHeight == 64);
  REQUIRE(l.imageLeft.size() == 2);
  CHECK(l.imageLeft[1] >= l.imageLeft[0] + 128);
  auto pixel = [&](int x, int y) {
    const std::uint8_t* p = &png.rgb[(std::size_t(y) * png.width + x) * 3];
    return std::vector<int>{p[0], p[1], p[2]};
  };
  auto colour = [](double v) {
    std::uint8_t c[3];
    kiln::viridis(v, c);
    return std::vector<int>{c[0], c[1], c[2]};
  };
  const int x0 = l.imageLeft[0], x1 = l.imageLeft[1], y0 = l.imageTop;
  CHECK(pixel(x0, y0) == colour(0.0));             // "up" minimum at the left
  CHECK(pixel(x0 + 127, y0 + 63) == colour(1.0));  // maximum at the right
  CHECK(pixel(x0 + 16 * 3 + 5, y0 + 40) == colour(3.0 / 7.0));
  CHECK(pixel(x0 + 130, y0 + 10) == std::vector<int>{40, 40, 40});  // background between
  CHECK(pixel(x1, y0) == colour(1.0));                              // "down" maximum at the top
  CHECK(pixel(x1 + 127, y0 + 63) == colour(0.0));                   // minimum at the bottom
  // The colour bar under each image runs from the minimum's colour to the maximum's.
  CHECK(pixel(x0, l.barTop) == colour(0.0));
  CHECK(pixel(x0 + 127, l.barTop + l.barHeight - 1) == colour(1.0));
  CHECK(pixel(x1 + 64, l.barTop) == colour(64.0 / 127.0));
  // Labels: light ink above the image (the title), below it (axis 0, the range under the bar)
  // and at its left (axis 1), nowhere inside the image.
  auto inkIn = [&](int xa, int xb, int ya, int yb) {
    int n = 0;
    for (int y = std::max(0, ya); y < std::min(png.height, yb); ++y)
      for (int x = std::max(0, xa); x < std::min(png.width, xb); ++x)
        n += pixel(x, y) == std::vector<int>{230, 230, 230};
    return n;
  };
  CHECK(inkIn(x0, x0 + 128, 0, y0) > 10);                              // "R = up"
  CHECK(inkIn(x0, x0 + 128, y0 + 64, l.barTop) > 20);                  // 0, 1, "x (linear, 8) ->"
  CHECK(inkIn(x0, x0 + 128, l.barTop + l.barHeight, png.height) > 5);  // 0 and 7
  CHECK(inkIn(0, x0, y0, y0 + 64) > 20);                               // 0, 1, "y (linear, 4)"
  CHECK(inkIn(x0, x0 + 128, y0, y0 + 64) == 0);
  fs::remove_all(dir);
}
