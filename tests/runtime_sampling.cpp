// Specification of kiln::LutView: layout, node exactness, linear and cubic filters.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "kiln/lut.h"

namespace {

using kiln::Axis;
using kiln::Filter;
using kiln::LutView;
using kiln::Warp;

/// An owning table for tests: data filled from value(i0, i1, i2, c).
struct TestLut {
  std::vector<float> data;
  LutView view;

  TestLut(const std::vector<Axis>& axes, int channels,
          const std::function<float(int, int, int, int)>& value) {
    view.channels = channels;
    view.dims = static_cast<int>(axes.size());
    for (std::size_t d = 0; d < axes.size(); ++d) view.axis[d] = axes[d];
    data.resize(view.valueCount());
    for (int i2 = 0; i2 < view.size(2); ++i2)
      for (int i1 = 0; i1 < view.size(1); ++i1)
        for (int i0 = 0; i0 < view.size(0); ++i0)
          for (int c = 0; c < channels; ++c)
            data[((std::size_t(i2) * view.size(1) + i1) * view.size(0) + i0) * channels + c] =
                value(i0, i1, i2, c);
    view.data = data.data();
  }
  TestLut(const TestLut&) = delete;
  TestLut& operator=(const TestLut&) = delete;
};

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Tables of 1, 2 and 3 axes mixing every warp and small sizes (1, 2, 3 included).
std::vector<std::vector<Axis>> axisSets() {
  return {
      {{0.0, 1.0, 9, Warp::Linear}},
      {{0.1, 10.0, 3, Warp::Log}},
      {{0.0, 1.0, 2, Warp::Sqrt}},
      {{0.0, 1.0, 7, Warp::Sqrt}, {-1.0, 2.0, 5, Warp::Square}},
      {{0.0, 1.0, 4, Warp::Linear}, {0.5, 3.0, 1, Warp::Linear}},
      {{1.0, 3.0, 3, Warp::Log}, {0.0, 1.0, 2, Warp::Linear}},
      {{0.0, 1.0, 5, Warp::Square}, {0.0, 1.0, 4, Warp::Sqrt}, {1.0, 2.5, 3, Warp::Log}},
      {{0.0, 1.0, 2, Warp::Linear}, {0.0, 1.0, 6, Warp::Linear}, {0.0, 1.0, 4, Warp::Linear}},
  };
}

const char* filterName(Filter f) { return f == Filter::Linear ? "linear" : "cubic"; }

}  // namespace

TEST_CASE("data is laid out as the stacked EXR image", "[runtime][sampling]") {
  // 3 x 2 x 2 nodes, 2 channels: image width 3, height 2 * 2, slice i2 at rows 2*i2..
  TestLut lut(
      {{0, 1, 3, Warp::Linear}, {0, 1, 2, Warp::Linear}, {0, 1, 2, Warp::Linear}}, 2,
      [](int i0, int i1, int i2, int c) { return float(1000 * c + 100 * i2 + 10 * i1 + i0); });
  const int width = 3, rows = 4, channels = 2;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < width; ++col) {
      const int i2 = row / 2, i1 = row % 2;
      for (int c = 0; c < channels; ++c) {
        const float pixel = lut.data[(std::size_t(row) * width + col) * channels + c];
        CHECK(pixel == float(1000 * c + 100 * i2 + 10 * i1 + col));
        CHECK(lut.view.at(col, i1, i2, c) == pixel);
      }
    }
  }
  CHECK(lut.view.valueCount() == 24);
  // at() clamps its indices to the grid.
  CHECK(lut.view.at(-1, 5, 9, 7) == lut.view.at(0, 1, 1, 1));
}

TEST_CASE("a lookup at a node returns the stored texel bit for bit", "[runtime][sampling]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> uniform(-3.0f, 3.0f);
  for (const auto& axes : axisSets()) {
    // Random values with awkward ones mixed in: zeros of both signs,
    // a denormal and a large magnitude next to them.
    const float special[] = {0.0f, -0.0f, 1e-40f, -7.5e6f, 1.0f / 3.0f};
    int counter = 0;
    TestLut lut(axes, 3, [&](int, int, int, int) {
      ++counter;
      return counter % 4 == 0 ? special[(counter / 4) % 5] : uniform(rng);
    });
    for (Filter filter : {Filter::Linear, Filter::Cubic}) {
      INFO("dims " << axes.size() << ", filter " << filterName(filter));
      for (int i2 = 0; i2 < lut.view.size(2); ++i2)
        for (int i1 = 0; i1 < lut.view.size(1); ++i1)
          for (int i0 = 0; i0 < lut.view.size(0); ++i0) {
            const int idx[3] = {i0, i1, i2};
            double x[3];
            for (int d = 0; d < lut.view.dims; ++d) x[d] = lut.view.axis[d].node(idx[d]);
            float out[3];
            lut.view.sample(x, out, filter);
            for (int c = 0; c < 3; ++c) {
              INFO("node (" << i0 << ", " << i1 << ", " << i2 << ") channel " << c);
              CHECK(sameBits(out[c], lut.view.at(i0, i1, i2, c)));
            }
          }
    }
  }
}

TEST_CASE("both filters reproduce linear functions exactly", "[runtime][sampling]") {
  // Linear warps: f is linear in x. Other warps: f is linear in texel space.
  const std::vector<std::vector<Axis>> cases = {
      {{-1.0, 3.0, 9, Warp::Linear}},
      {{0.0, 2.0, 5, Warp::Linear}, {1.0, 4.0, 7, Warp::Linear}},
      {{0.0, 1.0, 4, Warp::Linear}, {0.0, 1.0, 3, Warp::Linear}, {-2.0, 2.0, 6, Warp::Linear}},
      {{0.0, 1.0, 6, Warp::Sqrt}, {0.2, 5.0, 5, Warp::Log}, {0.0, 1.0, 4, Warp::Square}},
  };
  const double coef[4] = {0.25, 1.5, -0.75, 2.0};
  std::mt19937 rng(7);
  for (const auto& axes : cases) {
    const bool inX = axes[0].warp == Warp::Linear;
    auto coordinate = [&](int d, double x) { return inX ? x : axes[d].texel(x); };
    auto f = [&](const double* x) {
      double v = coef[0];
      for (std::size_t d = 0; d < axes.size(); ++d) v += coef[d + 1] * coordinate(int(d), x[d]);
      return v;
    };
    TestLut lut(axes, 1, [&](int i0, int i1, int i2, int) {
      const int idx[3] = {i0, i1, i2};
      double x[3];
      for (std::size_t d = 0; d < axes.size(); ++d) x[d] = axes[d].node(idx[d]);
      return float(f(x));
    });
    for (Filter filter : {Filter::Linear, Filter::Cubic}) {
      INFO("dims " << axes.size() << ", filter " << filterName(filter));
      for (int k = 0; k < 500; ++k) {
        double x[3];
        for (std::size_t d = 0; d < axes.size(); ++d)
          x[d] = std::uniform_real_distribution<double>(axes[d].lo, axes[d].hi)(rng);
        float out;
        lut.view.sample(x, &out, filter);
        // Float storage of the node values is the only error source.
        CHECK(out == Approx(f(x)).margin(4e-6));
      }
    }
  }
}

TEST_CASE("cubic reproduces quadratics in every cell, edge cells included, linear does not",
          "[runtime][sampling]") {
  const int n = 9;
  const Axis ax{0.0, 2.0, n, Warp::Linear};
  const Axis ay{-1.0, 1.0, 7, Warp::Linear};
  auto q = [](double x, double y) { return 0.75 * x * x - 0.5 * x * y - y * y + 0.25 * x + 1.0; };
  TestLut lut({ax, ay}, 1,
              [&](int i, int j, int, int) { return float(q(ax.node(i), ay.node(j))); });
  double worstLinear = 0.0;
  // Every cell, the edge cells (quadratic ghost nodes) included.
  for (int a = 0; a <= 40; ++a) {
    for (int b = 0; b <= 40; ++b) {
      const double x[2] = {ax.lo + (ax.hi - ax.lo) * a / 40.0, ay.lo + (ay.hi - ay.lo) * b / 40.0};
      float cubic, linear;
      lut.view.sample(x, &cubic, Filter::Cubic);
      lut.view.sample(x, &linear, Filter::Linear);
      CHECK(cubic == Approx(q(x[0], x[1])).margin(4e-6));
      worstLinear = std::max(worstLinear, std::fabs(linear - q(x[0], x[1])));
    }
  }
  CHECK(worstLinear > 1e-3);  // the quadratic is not trivially representable
}

TEST_CASE("cubic is more accurate than linear on a smooth function", "[runtime][sampling]") {
  // By a factor 5 overall and an order of magnitude in the interior cells (the
  // quadratic ghost nodes keep cubic third order in the edge cells too).
  const Axis ax{0.0, 1.0, 16, Warp::Linear};
  const Axis ay{0.1, 2.0, 12, Warp::Log};
  auto f = [](double x, double y) { return std::sin(3.0 * x) * std::exp(-0.5 * y) + x * y; };
  TestLut lut({ax, ay}, 1,
              [&](int i, int j, int, int) { return float(f(ax.node(i), ay.node(j))); });
  double worstLinear = 0.0, worstCubic = 0.0, interiorLinear = 0.0, interiorCubic = 0.0;
  for (int a = 0; a <= 200; ++a) {
    for (int b = 0; b <= 200; ++b) {
      const double x[2] = {a / 200.0, ay.lo * std::pow(ay.hi / ay.lo, b / 200.0)};
      float cubic, linear;
      lut.view.sample(x, &cubic, Filter::Cubic);
      lut.view.sample(x, &linear, Filter::Linear);
      const double errorLinear = std::fabs(linear - f(x[0], x[1]));
      const double errorCubic = std::fabs(cubic - f(x[0], x[1]));
      worstLinear = std::max(worstLinear, errorLinear);
      worstCubic = std::max(worstCubic, errorCubic);
      const double s0 = ax.texel(x[0]), s1 = ay.texel(x[1]);
      if (s0 >= 1.0 && s0 <= ax.size - 2.0 && s1 >= 1.0 && s1 <= ay.size - 2.0) {
        interiorLinear = std::max(interiorLinear, errorLinear);
        interiorCubic = std::max(interiorCubic, errorCubic);
      }
    }
  }
  INFO("max error linear " << worstLinear << ", cubic " << worstCubic << "; interior linear "
                           << interiorLinear << ", cubic " << interiorCubic);
  CHECK(worstCubic < 0.2 * worstLinear);
  CHECK(interiorCubic < 0.1 * interiorLinear);
}

TEST_CASE("cubic falls back to linear on an axis of size 2", "[runtime][sampling]") {
  TestLut lut({{0.0, 1.0, 2, Warp::Linear}, {0.0, 1.0, 2, Warp::Sqrt}}, 2,
              [](int i, int j, int, int c) { return float(0.3 * i - 1.7 * j + 0.9 * i * j + c); });
  for (int k = 0; k <= 30; ++k) {
    const double x[2] = {k / 30.0, (30 - k) / 31.0};
    float cubic[2], linear[2];
    lut.view.sample(x, cubic, Filter::Cubic);
    lut.view.sample(x, linear, Filter::Linear);
    CHECK(sameBits(cubic[0], linear[0]));
    CHECK(sameBits(cubic[1], linear[1]));
  }
}

TEST_CASE("lookups outside the axes clamp to the edge, NaN maps to lo", "[runtime][sampling]") {
  TestLut lut({{0.0, 1.0, 5, Warp::Sqrt}, {1.0, 2.0, 4, Warp::Linear}}, 1,
              [](int i, int j, int, int) { return float(i * i - 2 * j + 0.5 * i * j); });
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Filter filter : {Filter::Linear, Filter::Cubic}) {
    float out;
    const double below[2] = {-4.0, -1e30};
    lut.view.sample(below, &out, filter);
    CHECK(out == lut.view.at(0, 0, 0, 0));
    const double above[2] = {7.0, std::numeric_limits<double>::infinity()};
    lut.view.sample(above, &out, filter);
    CHECK(out == lut.view.at(4, 3, 0, 0));
    const double mixed[2] = {nan, 5.0};
    lut.view.sample(mixed, &out, filter);
    CHECK(out == lut.view.at(0, 3, 0, 0));
  }
}

TEST_CASE("an axis of size 1 contributes its single node", "[runtime][sampling]") {
  TestLut line({{0.0, 1.0, 6, Warp::Linear}}, 1, [](int i, int, int, int) { return float(i * i); });
  TestLut flat({{0.0, 1.0, 6, Warp::Linear}, {0.0, 1.0, 1, Warp::Linear}}, 1,
               [](int i, int, int, int) { return float(i * i); });
  for (Filter filter : {Filter::Linear, Filter::Cubic}) {
    for (int k = 0; k <= 25; ++k) {
      const double x[2] = {k / 25.0, 0.8};
      float a, b;
      line.view.sample(x, &a, filter);
      flat.view.sample(x, &b, filter);
      CHECK(sameBits(a, b));
    }
  }
}

TEST_CASE("an invalid view samples to zeros", "[runtime][sampling]") {
  TestLut lut({{0.0, 1.0, 4, Warp::Linear}}, 2, [](int, int, int, int) { return 5.0f; });
  const double x[3] = {0.5, 0.5, 0.5};
  float out[2] = {-1.0f, -1.0f};
  LutView broken = lut.view;
  broken.dims = 4;
  broken.sample(x, out);
  CHECK(out[0] == 0.0f);
  CHECK(out[1] == 0.0f);
  broken = lut.view;
  broken.data = nullptr;
  out[0] = out[1] = -1.0f;
  broken.sample(x, out);
  CHECK(out[0] == 0.0f);
  CHECK(broken.at(0, 0, 0, 0) == 0.0f);
  lut.view.sample(x, out);  // the original is fine
  CHECK(out[0] == 5.0f);
}
