// LutSampler's path for the catalogue's common form (kiln/lut.h: axis 0 root4-layer, axis 1
// sqrt; detail::floatCellsLayerSqrt, detail::floatTaps2) against the float path computed axis
// by axis from its scalar parts (detail::floatLayerScale, floatCellAt, floatLerp): the same
// floats, bit for bit, one point and the batch call, on 2 and 3 axes and 1 to 3 channels.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "float_bits.h"
#include "kiln/lut.h"

using namespace kiln;

namespace {

using test::Bits;

/// The float path of view v at x, one axis and one channel after the other, from the scalar
/// parts of kiln/lut_float_path.h (what LutSampler's float path promises to compute).
void AxisByAxis(const LutView& v, const double* x, float* out) {
  detail::FloatAxis a[3];
  std::size_t stride = static_cast<std::size_t>(v.channels);
  const detail::FloatWarp warps[3] = {detail::FloatWarp::Root4Layer, detail::FloatWarp::Sqrt,
                                      detail::FloatWarp::Sqrt};
  for (int d = 0; d < 3; ++d) {
    a[d].stride = stride;
    a[d].last = static_cast<float>(v.size(d) - 1);
    a[d].snap = detail::kFloatNodeSnap * a[d].last;
    stride *= static_cast<std::size_t>(v.size(d));
    if (d >= v.dims) continue;
    a[d].lo = v.axis[d].lo;
    a[d].invRange = 1.0 / (v.axis[d].hi - v.axis[d].lo);
    a[d].warp = warps[d];
  }
  const float c = detail::floatLayerScale(v.axis[1].lo, v.axis[1].hi, x[1]);
  detail::FloatCell k[3];
  for (int d = 0; d < v.dims; ++d) k[d] = detail::floatCellAt(a[d], x[d], c);
  const float* p = v.data + (k[0].offset + k[1].offset + k[2].offset);
  for (int ch = 0; ch < v.channels; ++ch) {
    auto plane = [&](const float* q) {
      const float near = detail::floatLerp(q[ch], q[k[0].step + ch], k[0].f);
      const float far = detail::floatLerp(q[k[1].step + ch], q[k[1].step + k[0].step + ch], k[0].f);
      return detail::floatLerp(near, far, k[1].f);
    };
    float value = plane(p);
    if (v.dims == 3) value = detail::floatLerp(value, plane(p + k[2].step), k[2].f);
    out[ch] = value;
  }
}

/// Random points of v: inside the axes, on nodes, at and beyond the ends, NaN, r = 0 and
/// positive values below the least float (a layer scale of 1e-12, not a collapsed layer).
std::vector<double> Points(const LutView& v, int count, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xs;
  for (int k = 0; k < count; ++k)
    for (int d = 0; d < v.dims; ++d) {
      const Axis& a = v.axis[d];
      const double pick = u(rng), span = a.hi - a.lo;
      double x = a.lo + span * u(rng) * u(rng);  // dense near lo, where the layer is
      if (pick < 0.05)
        x = a.lo;
      else if (pick < 0.10)
        x = a.hi;
      else if (pick < 0.13)
        x = a.lo - 0.5 * span * u(rng);
      else if (pick < 0.16)
        x = a.hi + 0.5 * span * u(rng);
      else if (pick < 0.17)
        x = std::numeric_limits<double>::quiet_NaN();
      else if (pick < 0.18)
        x = pick < 0.175 ? std::numeric_limits<double>::denorm_min() : 1e-46;
      else if (pick < 0.19)
        x = -0.0;
      else if (pick < 0.35)
        x = a.node(static_cast<int>(u(rng) * a.size), 1e-12);
      xs.push_back(x);
    }
  return xs;
}

/// The ranges of a LayerSqrtView's axes: lo[d], hi[d].
struct Ranges {
  double lo[3], hi[3];
};

/// The catalogue's ranges: mu and roughness on [0, 1], eta on [1, 3].
constexpr Ranges kUnitRanges = {{0.0, 0.0, 1.0}, {1.0, 1.0, 3.0}};

/// A (mu: root4-layer, roughness: sqrt[, eta: sqrt]) view over `data`, random texels.
LutView LayerSqrtView(std::vector<float>& data, int dims, int channels, uint32_t seed,
                      const Ranges& range = kUnitRanges) {
  LutView v;
  v.dims = dims;
  v.channels = channels;
  const Warp warps[3] = {Warp::Root4Layer, Warp::Sqrt, Warp::Sqrt};
  const int sizes[3] = {24, 17, 6};
  const double* lo = range.lo;
  const double* hi = range.hi;
  for (int d = 0; d < dims; ++d) {
    v.axis[d].lo = lo[d];
    v.axis[d].hi = hi[d];
    v.axis[d].size = sizes[d];
    v.axis[d].warp = warps[d];
  }
  data.assign(v.valueCount(), 0.0f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  for (float& t : data) t = u(rng);
  v.data = data.data();
  return v;
}

/// The count of channel values where sampler's single and batch lookups at random points of
/// v (dims axes, channels channels) differ from AxisByAxis in any bit.
int DifferingBits(const LutView& v, uint32_t seed) {
  const int dims = v.dims, channels = v.channels;
  const LutSampler sampler(v);
  REQUIRE(sampler.floatPath());
  const std::vector<double> xs = Points(v, 4000, seed);
  const std::size_t count = xs.size() / static_cast<std::size_t>(dims);
  std::vector<float> batch(count * static_cast<std::size_t>(channels));
  sampler.sample(xs.data(), count, batch.data());
  std::vector<float> expected(channels), one(channels);
  int bad = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double* x = &xs[k * static_cast<std::size_t>(dims)];
    AxisByAxis(v, x, expected.data());
    sampler.sample(x, one.data());
    for (int c = 0; c < channels; ++c) {
      const float b = batch[k * static_cast<std::size_t>(channels) + c];
      const bool same = Bits(one[c]) == Bits(expected[c]) && Bits(b) == Bits(expected[c]);
      if (!same && bad < 3)
        UNSCOPED_INFO("dims " << dims << " channels " << channels << " x " << x[0] << ", " << x[1]
                              << ": expected " << expected[c] << ", one " << one[c] << ", batch "
                              << b);
      bad += !same;
    }
  }
  return bad;
}

}  // namespace

TEST_CASE("The root4-layer and sqrt path computes the axis-by-axis float path bit for bit",
          "[runtime][sampler][float]") {
  for (int dims = 2; dims <= 3; ++dims)
    for (int channels = 1; channels <= 3; ++channels) {
      std::vector<float> data;
      const LutView v = LayerSqrtView(data, dims, channels, 7u * dims + channels);
      CHECK(DifferingBits(v, 100u + dims * 10u + channels) == 0);
    }
}

TEST_CASE("The root4-layer and sqrt path off [0, 1] axes computes the axis-by-axis float path",
          "[runtime][sampler][float]") {
  // Axes that are not [0, 1] take the normalization and the layer scale's own clamp: a mu
  // range off 0, a roughness range holding 0 inside (r = 0 within the axis) or above it.
  const Ranges ranges[3] = {{{0.125, -0.5, 1.0}, {0.875, 1.0, 3.0}},
                            {{0.0, 0.05, 1.0}, {1.0, 0.8, 3.0}},
                            {{0.0, 0.0, 1.0}, {1.0, 2.0, 3.0}}};
  for (int k = 0; k < 3; ++k)
    for (int dims = 2; dims <= 3; ++dims) {
      std::vector<float> data;
      const LutView v = LayerSqrtView(data, dims, 2, 31u * k + dims, ranges[k]);
      CHECK(DifferingBits(v, 200u + 10u * k + dims) == 0);
    }
}
