// Specification of the 16-bit PNG writer: --format png16 stores plain [0, 1] values (value =
// stored / 65535, what every PNG loader returns) and refuses a channel outside [0, 1];
// --format png16-scaled stores each channel unsigned normalised over its range, with the scale
// and offset in tEXt chunks. Both say their samples are linear (cICP, gAMA 1.0, no sRGB/iCCP).
// Read back by an independent little PNG reader (chunk CRCs; the image data inflated by zlib)
// within scale / 65535 of every texel.
#include <catch2/catch.hpp>
#include <zlib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "baker/io/texture_writers.h"
#include "io_texture_util.h"

using namespace kiln::test;

namespace {

std::uint32_t Be32(const std::string& s, std::size_t at) {
  return std::uint32_t(std::uint8_t(s.at(at))) << 24 |
         std::uint32_t(std::uint8_t(s[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(s[at + 2])) << 8 | std::uint32_t(std::uint8_t(s[at + 3]));
}

std::uint32_t Crc(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (char ch : bytes) {
    crc ^= std::uint8_t(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

struct Png {
  std::uint32_t width = 0, height = 0;
  int bitDepth = 0, colourType = 0;
  std::map<std::string, std::string> text;
  std::map<std::string, std::string> chunks;  ///< the last chunk of each type
  std::vector<std::string> order;             ///< chunk types in file order
  std::string raw;  ///< the inflated IDAT: per row a filter byte and the samples
};

Png Parse(const std::string& f) {
  REQUIRE(f.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  Png p;
  std::string idat;
  for (std::size_t at = 8; at < f.size();) {
    const std::uint32_t n = Be32(f, at);
    const std::string type = f.substr(at + 4, 4), data = f.substr(at + 8, n);
    REQUIRE(Be32(f, at + 8 + n) == Crc(type + data));
    p.chunks[type] = data;
    p.order.push_back(type);
    if (type == "IHDR") {
      p.width = Be32(data, 0);
      p.height = Be32(data, 4);
      p.bitDepth = std::uint8_t(data[8]);
      p.colourType = std::uint8_t(data[9]);
    } else if (type == "tEXt") {
      const std::size_t nul = data.find('\0');
      REQUIRE(nul != std::string::npos);
      p.text[data.substr(0, nul)] = data.substr(nul + 1);
    } else if (type == "IDAT") {
      idat += data;
    }
    at += 12 + n;
  }
  // Inflated by zlib itself (an independent decoder of the deflate stream and its Adler-32),
  // into the exact size IHDR gives (per row a filter byte and the samples) and one byte more: a
  // stream that inflates to more does not fit and fails, one to less fails the size check.
  REQUIRE(idat.size() >= 6);
  const std::map<int, std::size_t> samplesOfColourType = {{0, 1}, {2, 3}, {4, 2}, {6, 4}};
  REQUIRE(samplesOfColourType.count(p.colourType) == 1);
  REQUIRE(p.bitDepth == 16);
  const std::size_t rowBytes = 1 + std::size_t(p.width) * samplesOfColourType.at(p.colourType) * 2;
  const std::size_t expected = rowBytes * p.height;
  std::string raw(expected + 1, '\0');
  uLongf rawSize = uLongf(raw.size());
  REQUIRE(uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawSize,
                     reinterpret_cast<const Bytef*>(idat.data()), uLong(idat.size())) == Z_OK);
  REQUIRE(rawSize == expected);
  raw.resize(rawSize);
  p.raw = raw;
  return p;
}

/// The 16-bit sample s of pixel (x, y).
std::uint16_t Sample(const Png& p, int samples, std::size_t x, std::size_t y, int s) {
  const std::size_t rowBytes = 1 + std::size_t(p.width) * samples * 2;
  REQUIRE(p.raw[y * rowBytes] == 0);  // filter None
  const std::size_t at = y * rowBytes + 1 + (x * samples + s) * 2;
  return std::uint16_t(std::uint8_t(p.raw[at]) << 8 | std::uint8_t(p.raw[at + 1]));
}

std::vector<double> Numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

}  // namespace

TEST_CASE("a ggx-dfg PNG16 is 16-bit RGB of plain values: stored = round(value x 65535)",
          "[io][png16]") {
  const kiln::Table t = SmallGgxDfg();
  const Png p = Parse(kiln::EncodePng16(t));
  CHECK(p.bitDepth == 16);
  CHECK(p.colourType == 2);  // RGB: R = A, G = B, blue 0 (unused)
  CHECK(Numbers(p.text.at("kiln.scale")) == std::vector<double>{1, 1});
  CHECK(Numbers(p.text.at("kiln.offset")) == std::vector<double>{0, 0});
  const auto meta = nlohmann::json::parse(p.text.at("kiln.json"));
  CHECK(meta["png16"]["encoding"] == "unit");
  for (std::size_t y = 0; y < 8; ++y)
    for (std::size_t x = 0; x < 8; ++x) {
      for (int c = 0; c < 2; ++c) {
        INFO("x " << x << " y " << y << " c " << c);
        const double want = t.data[(y * 8 + x) * 2 + c];
        CHECK(Sample(p, 3, x, y, c) == std::lround(want * 65535));
      }
      CHECK(Sample(p, 3, x, y, 2) == 0);
    }
}

TEST_CASE("png16 refuses a channel outside [0, 1], naming the channel and its range",
          "[io][png16]") {
  const kiln::Table t = Small3D();  // channel E, 0 .. 123
  CHECK_THROWS_WITH(kiln::EncodePng16(t), Catch::Contains("channel 'E' spans [0, 123]") &&
                                              Catch::Contains("png16-scaled"));
  kiln::Table negative = SmallGgxDfg();
  negative.data[5] = -0.25f;
  CHECK_THROWS_WITH(kiln::EncodePng16(negative), Catch::Contains("channel 'B' spans [-0.25, "));
}

TEST_CASE("both PNG16s say their samples are linear: cICP, gAMA 1.0, no sRGB or iCCP",
          "[io][png16]") {
  for (bool scaled : {false, true}) {
    INFO("scaled " << scaled);
    const Png p = Parse(kiln::EncodePng16(SmallGgxDfg(), scaled));
    // cICP: colour primaries 1 (BT.709), transfer 8 (linear), matrix 0 (RGB), full range.
    CHECK(p.chunks.at("cICP") == std::string("\x01\x08\x00\x01", 4));
    CHECK(Be32(p.chunks.at("gAMA"), 0) == 100000);  // gamma 1.0
    CHECK(p.chunks.count("sRGB") == 0);
    CHECK(p.chunks.count("iCCP") == 0);
    const auto before = [&](const char* a, const char* b) {
      return std::find(p.order.begin(), p.order.end(), a) <
             std::find(p.order.begin(), p.order.end(), b);
    };
    CHECK(before("cICP", "IDAT"));
    CHECK(before("gAMA", "IDAT"));
  }
}

TEST_CASE("a ggx-dfg PNG16 scaled is 16-bit RGB with its scale in tEXt, within scale / 65535",
          "[io][png16]") {
  const kiln::Table t = SmallGgxDfg();
  const Png p = Parse(kiln::EncodePng16(t, /*scaled=*/true));
  CHECK(p.width == 8);
  CHECK(p.height == 8);
  CHECK(p.bitDepth == 16);
  CHECK(p.colourType == 2);  // RGB: R = A, G = B, blue 0
  const std::vector<double> scale = Numbers(p.text.at("kiln.scale"));
  const std::vector<double> offset = Numbers(p.text.at("kiln.offset"));
  REQUIRE(scale.size() == 2);
  REQUIRE(offset.size() == 2);
  CHECK(scale[0] > 0.5);  // A spans most of [0, 1]
  const auto meta = nlohmann::json::parse(p.text.at("kiln.json"));
  CHECK(meta["name"] == "ggx-dfg");
  CHECK(meta["png16"]["scale"][0].get<double>() == scale[0]);
  CHECK(p.text.at("kiln.decode").find("65535") != std::string::npos);
  REQUIRE(p.raw.size() == 8 * (1 + 8 * 3 * 2));
  int lowest = 65535, highest = 0;
  for (std::size_t y = 0; y < 8; ++y)
    for (std::size_t x = 0; x < 8; ++x)
      for (int c = 0; c < 2; ++c) {
        const int stored = Sample(p, 3, x, y, c);
        const double value = stored / 65535.0 * scale[c] + offset[c];
        const double want = t.data[(y * 8 + x) * 2 + c];
        INFO("x " << x << " y " << y << " c " << c);
        REQUIRE(std::fabs(value - want) <= scale[c] / 65535);
        if (c == 0) lowest = std::min(lowest, stored), highest = std::max(highest, stored);
        CHECK(Sample(p, 3, x, y, 2) == 0);
      }
  CHECK(lowest == 0);  // the range is used in full
  CHECK(highest == 65535);
}

TEST_CASE("a one-channel PNG16 scaled is grey, a constant channel stores 0", "[io][png16]") {
  kiln::Table t = Small3D();
  const Png p = Parse(kiln::EncodePng16(t, true));
  CHECK(p.colourType == 0);
  CHECK(p.width == 4);
  CHECK(p.height == 6);  // 3 rows x 2 slices, stacked as in the EXR
  const double scale = Numbers(p.text.at("kiln.scale")).at(0);
  CHECK(scale == 123);  // 0 .. 123
  CHECK(Sample(p, 1, 3, 5, 0) == 65535);
  for (float& v : t.data) v = 0.25f;
  const Png c = Parse(kiln::EncodePng16(t, true));
  CHECK(Numbers(c.text.at("kiln.scale")).at(0) == 0);
  CHECK(Numbers(c.text.at("kiln.offset")).at(0) == 0.25);
  CHECK(Sample(c, 1, 2, 2, 0) == 0);
}
