// The root4-layer-split warp of kiln/lut.h: a mu axis split at the critical cosine
// mu_c = sqrt(1 - eta^2) of axis 2 (eta < 1), where a dielectric's albedo seen from the denser
// side has the kink of total internal reflection. The kink must be the grid line t = 1/2 in
// every eta layer, the map must be invertible and continuous, and a lookup of a function with
// a kink at mu_c(eta) must interpolate it where a warp without the split cannot.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "kiln/lut.h"
#include "kiln/table.h"

using namespace kiln;

namespace {
double Critical(double eta) { return std::sqrt((1 - eta) * (1 + eta)); }
}  // namespace

TEST_CASE("root4-layer-split: the critical cosine is t = 1/2 in every eta layer",
          "[runtime][split]") {
  const Axis a{0.0, 1.0, 49, Warp::Root4LayerSplit};
  REQUIRE(a.valid());
  for (double eta : {1.0 / 3, 0.5, 0.8, 1 / 1.1}) {
    const double s = criticalSplit(0, 1, 1.0 / 3, 1 / 1.1, eta);
    CHECK(s == Approx(Critical(eta)).epsilon(1e-15));
    for (double c : {0.0, 1e-12, 1e-4, 0.01, 0.25, 1.0}) {
      INFO("eta " << eta << " c " << c);
      CHECK(a.node(24, c, s) == s);  // node 24 of 48 intervals is t = 1/2
      if (c > 0) CHECK(a.texel(s, c, s) == 24.0);
      CHECK(a.node(0, c, s) == 0.0);
      CHECK(a.node(48, c, s) == 1.0);
    }
  }
}

TEST_CASE("root4-layer-split: round trip, monotone, continuous at the piece boundaries",
          "[runtime][split]") {
  const Axis a{0.0, 1.0, 49, Warp::Root4LayerSplit};
  for (double s : {0.42, 0.7, 0.94}) {
    for (double c : {1e-12, 1e-5, 4e-3, 0.1, 1.0}) {
      INFO("split " << s << " c " << c);
      double before = -1;
      for (int k = 0; k <= 4000; ++k) {
        const double t = k / 4000.0;
        const double x = a.unwarped(t, c, s);
        CHECK(x >= before);  // monotone
        before = x;
        // x = unwarped(t) round-trips to x to rounding; to t too, except where the layer at
        // the split is narrower than the doubles near s resolve (c = 1e-12 next to s ~ 0.5)
        CHECK(a.unwarped(a.warped(x, c, s), c, s) == Approx(x).margin(2e-15));
        if (c >= 1e-5) CHECK(a.warped(x, c, s) == Approx(t).margin(1e-9));
      }
      // continuity of t(x) across the piece boundaries m = s / 2 and s (the root4 term has an
      // infinite slope there: a step of one ulp moves t by ~ulp^(1/4))
      for (double b : {0.5 * s, s}) {
        const double lo = a.warped(std::nextafter(b, 0.0), c, s);
        const double hi = a.warped(std::nextafter(b, 1.0), c, s);
        CHECK(std::fabs(hi - lo) < 1e-3);
      }
      CHECK(a.warped(0.5 * s, c, s) == Approx(0.25).margin(1e-15));
      CHECK(a.warped(s, c, s) == Approx(0.5).margin(1e-15));
    }
  }
}

TEST_CASE("root4-layer-split: nodes crowd the split over a width ~c on both sides",
          "[runtime][split]") {
  const Axis a{0.0, 1.0, 49, Warp::Root4LayerSplit};
  const double s = 0.9, c = 1e-3;
  int below = 0, above = 0;
  for (int i = 0; i < 49; ++i) {
    const double x = a.node(i, c, s);
    if (x < s && x > s - 10 * c) ++below;
    if (x > s && x < s + 10 * c) ++above;
  }
  CHECK(below >= 3);
  CHECK(above >= 6);
}

TEST_CASE("root4-layer-split at c = 0: the lookups read only the outer halves of the pieces",
          "[runtime][split]") {
  const Axis a{0.0, 1.0, 49, Warp::Root4LayerSplit};
  const double s = 0.8;
  for (int k = 0; k <= 1000; ++k) {
    const double x = k / 1000.0;
    const double t = a.warped(x, 0.0, s);
    INFO("x " << x << " t " << t);
    CHECK(!a.holdsLayerLimit(t));
  }
  CHECK(a.holdsLayerLimit(0.0));
  CHECK(a.holdsLayerLimit(0.5));
  CHECK(!a.holdsLayerLimit(0.125));
  CHECK(!a.holdsLayerLimit(0.375));
  CHECK(!a.holdsLayerLimit(0.75));
  CHECK(a.unwarped(0.125, 0.0, s) == 0.0);
  CHECK(a.unwarped(0.375, 0.0, s) == Approx(s).epsilon(1e-15));
  CHECK(a.unwarped(0.75, 0.0, s) == Approx(s).epsilon(1e-15));
}

TEST_CASE("root4-layer-split: valid only with (N - 1) % 8 == 0 on axis 0 of a 3-axis table",
          "[runtime][split]") {
  CHECK(!Axis{0.0, 1.0, 48, Warp::Root4LayerSplit}.valid());
  CHECK(Axis{0.0, 1.0, 17, Warp::Root4LayerSplit}.valid());
  Warp w;
  REQUIRE(warpFromName("root4-layer-split", w));
  CHECK(w == Warp::Root4LayerSplit);
  std::vector<float> data(49 * 2 * 3, 0.0f);
  LutView v;
  v.data = data.data();
  v.channels = 1;
  v.dims = 3;
  v.axis[0] = Axis{0.0, 1.0, 49, Warp::Root4LayerSplit};
  v.axis[1] = Axis{0.0, 1.0, 2, Warp::Sqrt};
  v.axis[2] = Axis{1.0 / 3, 1 / 1.1, 3, Warp::Linear};
  CHECK(v.valid());
  v.dims = 2;
  CHECK(!v.valid());
}

// f = max(0, mu - mu_c(eta)): a kink that moves with eta. Tabulated on 49 x 2 x 9 nodes and
// looked up between the eta layers, the split warp keeps the kink on a grid line; root4-layer
// (no split) interpolates across it between layers whose kinks sit at different mu.
TEST_CASE("root4-layer-split: a kink that moves with eta interpolates", "[runtime][split]") {
  auto maxError = [](Warp warp, int n0) {
    const Axis a0{0.0, 1.0, n0, warp}, a1{0.0, 1.0, 2, Warp::Sqrt},
        a2{1.0 / 3, 1 / 1.1, 9, Warp::Linear};
    std::vector<float> data(static_cast<size_t>(n0) * 2 * 9);
    for (int k = 0; k < 9; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < n0; ++i) {
          const double eta = a2.node(k), r = a1.node(j);
          const double c = layerScale(0, 1, r);
          const double s = criticalSplit(0, 1, a2.lo, a2.hi, eta);
          const double mu = a0.node(i, c, s);
          data[(static_cast<size_t>(k) * 2 + j) * n0 + i] =
              static_cast<float>(std::max(0.0, mu - Critical(eta)));
        }
    LutView v;
    v.data = data.data();
    v.channels = 1;
    v.dims = 3;
    v.axis[0] = a0;
    v.axis[1] = a1;
    v.axis[2] = a2;
    double worst = 0;
    for (int k = 0; k <= 200; ++k)
      for (int i = 0; i <= 200; ++i) {
        const double x[3] = {i / 200.0, 0.5, a2.lo + (a2.hi - a2.lo) * k / 200.0};
        float got = 0;
        v.sample(x, &got);
        worst = std::max(worst, std::fabs(got - std::max(0.0, x[0] - Critical(x[2]))));
      }
    return worst;
  };
  const double split = maxError(Warp::Root4LayerSplit, 49);
  const double plain = maxError(Warp::Root4Layer, 49);
  INFO("split " << split << " plain " << plain);
  CHECK(split < 0.025);
  CHECK(plain > 4 * split);
}
