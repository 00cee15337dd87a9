// Specification of kiln::Axis: node placement, warps, texel and GPU coordinates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "kiln/lut.h"

namespace {

using kiln::Axis;
using kiln::Warp;

const Warp kAllWarps[] = {Warp::Linear, Warp::Sqrt,  Warp::Square, Warp::Log,
                          Warp::Root4,  Warp::Angle, Warp::Arcsine};

/// Axes exercising every warp over a few ranges and sizes.
std::vector<Axis> sampleAxes() {
  std::vector<Axis> axes;
  for (Warp w : kAllWarps) {
    for (int n : {2, 3, 17, 64, 257}) {
      if (w == Warp::Log) {
        axes.push_back({0.01, 100.0, n, w});
        axes.push_back({1.0, 3.0, n, w});
      } else {
        axes.push_back({0.0, 1.0, n, w});
        axes.push_back({-2.5, 7.25, n, w});
        axes.push_back({1.0, 3.0, n, w});
      }
    }
  }
  return axes;
}

/// The inverse warp written out independently of the implementation.
double inverseWarp(const Axis& a, double t) {
  switch (a.warp) {
    case Warp::Linear:
      return a.lo + (a.hi - a.lo) * t;
    case Warp::Sqrt:
      return a.lo + (a.hi - a.lo) * t * t;
    case Warp::Square:
      return a.lo + (a.hi - a.lo) * std::sqrt(t);
    case Warp::Log:
      return a.lo * std::pow(a.hi / a.lo, t);
    case Warp::Root4:
      return a.lo + (a.hi - a.lo) * std::pow(t, 4.0);
    case Warp::Root4Layer:
    case Warp::LayerEta:
    case Warp::Root4LayerSplit:
    case Warp::Root4LayerAngle:
    case Warp::Root4LayerSplit2:
      break;  // read another axis: tested on their own (below, runtime_layer_warps.cpp)
    case Warp::Angle:
      return a.lo + (a.hi - a.lo) * std::sin(t * M_PI / 2);
    case Warp::Arcsine:
      return a.lo + (a.hi - a.lo) * std::pow(std::sin(t * M_PI / 2), 2.0);
  }
  return 0.0;
}

}  // namespace

TEST_CASE("warp names round-trip and unknown names are refused", "[runtime][axis]") {
  for (Warp w : kAllWarps) {
    Warp parsed = w == Warp::Linear ? Warp::Log : Warp::Linear;
    REQUIRE(kiln::warpFromName(kiln::warpName(w), parsed));
    CHECK(parsed == w);
  }
  CHECK(std::string(kiln::warpName(Warp::Linear)) == "linear");
  CHECK(std::string(kiln::warpName(Warp::Sqrt)) == "sqrt");
  CHECK(std::string(kiln::warpName(Warp::Square)) == "square");
  CHECK(std::string(kiln::warpName(Warp::Log)) == "log");

  Warp untouched = Warp::Square;
  for (const char* bad : {"Linear", "", "cubic", "sqrt ", "lo"}) {
    CHECK_FALSE(kiln::warpFromName(bad, untouched));
    CHECK(untouched == Warp::Square);
  }
  CHECK_FALSE(kiln::warpFromName(nullptr, untouched));
}

TEST_CASE("the first and last nodes are exactly lo and hi", "[runtime][axis]") {
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " [" << a.lo << ", " << a.hi << "] N=" << a.size);
    CHECK(a.node(0) == a.lo);
    CHECK(a.node(a.size - 1) == a.hi);
    CHECK(a.node(-3) == a.lo);          // clamped
    CHECK(a.node(a.size + 4) == a.hi);  // clamped
  }
}

TEST_CASE("nodes follow x_i = lo + (hi - lo) w^-1(i / (N - 1))", "[runtime][axis]") {
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " N=" << a.size);
    for (int i = 0; i < a.size; ++i) {
      const double expected = inverseWarp(a, double(i) / (a.size - 1));
      CHECK(a.node(i) == Approx(expected).epsilon(1e-13).margin(1e-13));
    }
    for (int i = 1; i < a.size; ++i) CHECK(a.node(i) > a.node(i - 1));
  }
}

TEST_CASE("each warp puts its nodes where it says", "[runtime][axis]") {
  const int n = 17;
  const Axis sqrtAxis{0.0, 1.0, n, Warp::Sqrt};
  const Axis squareAxis{0.0, 1.0, n, Warp::Square};
  const Axis logAxis{0.01, 100.0, n, Warp::Log};
  // sqrt: dense near lo; square: dense near hi.
  CHECK(sqrtAxis.node(1) - sqrtAxis.node(0) < 0.2 * (sqrtAxis.node(n - 1) - sqrtAxis.node(n - 2)));
  CHECK(squareAxis.node(n - 1) - squareAxis.node(n - 2) <
        0.2 * (squareAxis.node(1) - squareAxis.node(0)));
  // log: a constant ratio between neighbours (10^(4/16) here).
  for (int i = 1; i < n; ++i)
    CHECK(logAxis.node(i) / logAxis.node(i - 1) == Approx(std::pow(10.0, 0.25)).epsilon(1e-12));
}

TEST_CASE("texel(node(i)) == i exactly for every warp", "[runtime][axis]") {
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " [" << a.lo << ", " << a.hi << "] N=" << a.size);
    for (int i = 0; i < a.size; ++i) CHECK(a.texel(a.node(i)) == double(i));
  }
}

TEST_CASE("texel applies the warp to y = (x - lo) / (hi - lo)", "[runtime][axis]") {
  const double lo = 0.5, hi = 4.5;
  const int n = 33;
  for (double x : {0.6, 1.0, 2.2, 3.999, 4.4}) {
    const double y = (x - lo) / (hi - lo);
    CHECK(Axis{lo, hi, n, Warp::Linear}.texel(x) == Approx(y * (n - 1)).epsilon(1e-14));
    CHECK(Axis{lo, hi, n, Warp::Sqrt}.texel(x) == Approx(std::sqrt(y) * (n - 1)).epsilon(1e-14));
    CHECK(Axis{lo, hi, n, Warp::Square}.texel(x) == Approx(y * y * (n - 1)).epsilon(1e-14));
    CHECK(Axis{lo, hi, n, Warp::Log}.texel(x) ==
          Approx(std::log(x / lo) / std::log(hi / lo) * (n - 1)).epsilon(1e-14));
  }
}

TEST_CASE("warps invert: texel(w^-1(t)) recovers t", "[runtime][axis]") {
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " N=" << a.size);
    for (int k = 0; k <= 1000; ++k) {
      const double t = k / 1000.0;
      const double x = inverseWarp(a, t);
      CHECK(a.texel(x) / (a.size - 1) == Approx(t).margin(1e-12));
      CHECK(a.warped(x) == Approx(t).margin(1e-12));
    }
  }
}

TEST_CASE("texel clamps to the edge and maps NaN to 0", "[runtime][axis]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " N=" << a.size);
    CHECK(a.texel(a.lo - 1.0) == 0.0);
    CHECK(a.texel(-inf) == 0.0);
    CHECK(a.texel(a.hi + 1.0) == double(a.size - 1));
    CHECK(a.texel(inf) == double(a.size - 1));
    CHECK(a.texel(nan) == 0.0);
    CHECK(a.gpuCoord(nan) == 0.5 / a.size);
  }
  // Below lo on a log axis (including x <= 0) also clamps.
  const Axis logAxis{0.1, 10.0, 9, Warp::Log};
  CHECK(logAxis.texel(0.0) == 0.0);
  CHECK(logAxis.texel(-5.0) == 0.0);
}

TEST_CASE("an axis of size 1 is a single node at lo", "[runtime][axis]") {
  const Axis a{2.0, 3.0, 1, Warp::Sqrt};
  CHECK(a.node(0) == 2.0);
  CHECK(a.node(7) == 2.0);
  CHECK(a.texel(2.7) == 0.0);
  CHECK(a.gpuCoord(2.7) == 0.5);
}

TEST_CASE("gpuCoord is (0.5 + t (N - 1)) / N", "[runtime][axis]") {
  for (const Axis& a : sampleAxes()) {
    INFO("warp " << kiln::warpName(a.warp) << " N=" << a.size);
    const double n = a.size;
    CHECK(a.gpuCoord(a.lo) == 0.5 / n);                               // centre of the first texel
    CHECK(a.gpuCoord(a.hi) == Approx(1.0 - 0.5 / n).epsilon(1e-15));  // centre of the last
    for (int i = 0; i < a.size; ++i)
      CHECK(a.gpuCoord(a.node(i)) == (i + 0.5) / n);  // node i sits on texel centre i
    for (int k = 1; k < 20; ++k) {
      const double x = a.lo + (a.hi - a.lo) * k / 20.0;
      CHECK(a.gpuCoord(x) == Approx((0.5 + a.warped(x) * (n - 1)) / n).epsilon(1e-15));
    }
  }
}

TEST_CASE("valid() states the conditions an axis must meet", "[runtime][axis]") {
  CHECK(Axis{0.0, 1.0, 1, Warp::Linear}.valid());
  CHECK(Axis{0.1, 1.0, 8, Warp::Log}.valid());
  CHECK_FALSE(Axis{0.0, 1.0, 0, Warp::Linear}.valid());
  CHECK_FALSE(Axis{1.0, 1.0, 4, Warp::Linear}.valid());
  CHECK_FALSE(Axis{2.0, 1.0, 4, Warp::Linear}.valid());
  CHECK_FALSE(Axis{0.0, 1.0, 4, Warp::Log}.valid());
  CHECK_FALSE(Axis{0.0, std::numeric_limits<double>::infinity(), 4, Warp::Linear}.valid());
}

TEST_CASE("root4-layer: the warp of y and of the layer scale c, inverted to the last bit",
          "[runtime][axis][layer]") {
  for (double c : {1e-12, 1e-8, 1e-4, 0.01, 0.3, 1.0})
    for (int n : {2, 3, 17, 128}) {
      const Axis a{0.0, 1.0, n, Warp::Root4Layer};
      INFO("c " << c << " N " << n);
      CHECK(a.node(0, c) == 0.0);
      CHECK(a.node(n - 1, c) == 1.0);
      for (int i = 0; i < n; ++i) {
        CHECK(a.texel(a.node(i, c), c) == double(i));
        if (i > 0) CHECK(a.node(i, c) > a.node(i - 1, c));
      }
      for (double y : {1e-15, 1e-9, 3e-5, 0.01, 0.2, 0.7, 0.999}) {
        const double t = 0.5 * (std::pow(y, 0.25) + y * (1 + c) / (y + c));
        CHECK(a.warped(y, c) == Approx(t).epsilon(1e-14));
        CHECK(a.unwarped(t, c) == Approx(y).epsilon(1e-12));
      }
    }
  // A quarter of the nodes inside the layer y < c, whatever its width.
  for (double c : {1e-10, 1e-6, 1e-3}) {
    const Axis a{0.0, 1.0, 129, Warp::Root4Layer};
    int inside = 0;
    for (int i = 0; i < a.size; ++i) inside += a.node(i, c) < c;
    INFO("c " << c << ": " << inside << " of 129 nodes below c");
    CHECK(inside >= 129 / 4);
  }
  Warp parsed = Warp::Linear;
  REQUIRE(kiln::warpFromName("root4-layer", parsed));
  CHECK(parsed == Warp::Root4Layer);
}

TEST_CASE("root4-layer: only on axis 0 of a view of 2+ axes, lookups at its nodes are exact",
          "[runtime][axis][layer]") {
  const Axis mu{0.0, 1.0, 9, Warp::Root4Layer}, r{0.0, 1.0, 5, Warp::Sqrt};
  std::vector<float> data(9 * 5);
  for (std::size_t k = 0; k < data.size(); ++k) data[k] = 0.1f * float(k) + 0.01f;
  kiln::LutView view;
  view.data = data.data();
  view.channels = 1;
  view.dims = 2;
  view.axis[0] = mu;
  view.axis[1] = r;
  REQUIRE(view.valid());
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i) {
      // At r = 0 the layer collapsed: its nodes below t_s = 1/2 hold the limit r -> 0+ and are
      // read by lookups at 0 < r < r_1 only (runtime_layer_warps.cpp).
      if (j == 0 && i < 4) continue;
      const double x[2] = {mu.node(i, kiln::layerScale(0.0, 1.0, r.node(j))), r.node(j)};
      float got = 0;
      view.sample(x, &got);
      CHECK(got == data[std::size_t(j) * 9 + std::size_t(i)]);
    }
  kiln::LutView swapped = view;
  swapped.axis[0] = r;
  swapped.axis[1] = mu;
  CHECK_FALSE(swapped.valid());
  kiln::LutView oneD = view;
  oneD.dims = 1;
  CHECK_FALSE(oneD.valid());
}

TEST_CASE(
    "root4-layer: the inverse converges at every node of the catalogue grid and at random "
    "points (the warp is steep inside the layer, where a plain Newton iteration cycles)",
    "[runtime][axis][layer]") {
  const Axis mu{0.0, 1.0, 128, Warp::Root4Layer};
  int misplaced = 0;
  for (int j = 0; j < 128; ++j) {  // the catalogue's roughness nodes (sqrt warp)
    const double r = (j / 127.0) * (j / 127.0), c = kiln::layerScale(0.0, 1.0, r);
    // (the collapsed row r = 0 places its nodes up to t = 1/2 at mu = 0 and the others by the
    // closed form: runtime_layer_warps.cpp)
    for (int i = c == 0.0 ? mu.size : 0; i < mu.size; ++i)
      misplaced += mu.texel(mu.node(i, c), c) != double(i);
  }
  CHECK(misplaced == 0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int k = 0; k < 200000; ++k) {
    const double c = k % 3 ? std::max(std::pow(10.0, -14 * u(rng)), 1e-12) : 1e-12 + u(rng);
    const double t = u(rng);
    worst = std::max(worst, std::fabs(mu.warped(mu.unwarped(t, c), c) - t));
  }
  INFO("worst |warped(unwarped(t)) - t| " << worst);
  CHECK(worst <= 1e-14);
}
