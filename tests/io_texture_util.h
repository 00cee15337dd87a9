// Helpers of the texture-format tests (io_ktx2.cpp, io_dds.cpp, io_png16.cpp): a small baked
// ggx-dfg, little-endian readers and a half decoder of their own (independent of the writers').
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"

namespace kiln::test {

/// ggx-dfg baked at `size` x `size` nodes, without the lookup-error measurement.
inline Table SmallGgxDfg(int size = 8) {
  CatalogueOptions copt;
  copt.size = size;
  BakeOptions opt;
  opt.threads = 1;
  opt.measureLookupError = false;
  return BakeTable(CatalogueTable("ggx-dfg", copt), opt);
}

/// A 3D table (4 x 3 x 2 nodes) with one channel, values i0 + 10 i1 + 100 i2 (exact in half).
inline Table Small3D() {
  Table t;
  t.generator = "kiln test";
  t.name = "cube";
  t.model = "none";
  t.quantity = "albedo";
  t.channels = {"E"};
  t.channelMeanings = {"test"};
  t.axes = {{"mu", {0, 1, 4, Warp::Linear}},
            {"roughness", {0, 1, 3, Warp::Linear}},
            {"eta", {1, 3, 2, Warp::Linear}}};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) t.data.push_back(float(i + 10 * j + 100 * k));
  return t;
}

inline std::uint32_t Le32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | std::uint8_t(s.at(at + std::size_t(k)));
  return v;
}

inline std::uint64_t Le64(const std::string& s, std::size_t at) {
  return std::uint64_t(Le32(s, at)) | std::uint64_t(Le32(s, at + 4)) << 32;
}

inline std::uint16_t Le16(const std::string& s, std::size_t at) {
  return std::uint16_t(std::uint8_t(s.at(at)) | std::uint8_t(s.at(at + 1)) << 8);
}

inline float LeFloat(const std::string& s, std::size_t at) {
  std::uint32_t bits = Le32(s, at);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

/// IEEE 754 binary16 to float (normals, subnormals, zeros; no inf/NaN in kiln tables).
inline float HalfToFloat(std::uint16_t h) {
  const int sign = h >> 15, exponent = (h >> 10) & 0x1F, mantissa = h & 0x3FF;
  double v = exponent == 0 ? std::ldexp(mantissa, -24) : std::ldexp(1024 + mantissa, exponent - 25);
  return float(sign ? -v : v);
}

/// True when `got` is `want` rounded to half: within 2^-11 relative (2^-25 absolute near 0).
inline bool WithinHalf(float got, float want) {
  return std::fabs(double(got) - want) <= std::ldexp(std::fabs(double(want)), -11) + 0x1p-25;
}

}  // namespace kiln::test
