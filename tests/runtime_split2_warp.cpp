// The root4-layer-split2 warp of kiln/lut.h: a mu axis split at two points of axis 2's eta
// (eta < 1, the view inside the denser medium), the critical cosine mu_c = sqrt(1 - eta^2)
// (the kink of total internal reflection) and mu_e = eta (theta_o + theta_c = pi / 2, where a
// rough dielectric's transmission has a one-sided point at high roughness). Both must be grid
// lines in every eta layer, the map invertible, monotone and continuous in eta where the two
// cross (eta = 1 / sqrt 2, the middle pieces of zero width), and a function with a structure
// at mu = eta must interpolate where root4-layer-split (one split, at mu_c) cannot.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kiln/lut.h"
#include "kiln/table.h"

using namespace kiln;

namespace {
double Critical(double eta) { return std::sqrt((1 - eta) * (1 + eta)); }
const double kCross = std::sqrt(0.5);  // where mu_c = mu_e
// Node indices of the lines T1 = 8/16 and T3 = 13/16 on 97 nodes (96 intervals).
constexpr int kLineA = 48, kLineB = 78;

std::vector<double> Etas() {
  return {1.0 / 3, 0.4,           0.5,  0.6, 0.7, kCross - 1e-6,
          kCross,  kCross + 1e-6, 0.72, 0.8, 0.9, 1 / 1.1};
}
}  // namespace

TEST_CASE(
    "root4-layer-split2: the name round-trips, valid with (N - 1) % 32 == 0 on axis 0 of "
    "a 3-axis view",
    "[runtime][split2]") {
  Warp w = Warp::Linear;
  REQUIRE(warpFromName("root4-layer-split2", w));
  CHECK(w == Warp::Root4LayerSplit2);
  CHECK(std::string(warpName(Warp::Root4LayerSplit2)) == "root4-layer-split2");
  CHECK(isLayerWarp(Warp::Root4LayerSplit2));
  CHECK(isRoughnessLayerWarp(Warp::Root4LayerSplit2));
  CHECK(readsAxis2(Warp::Root4LayerSplit2, false));
  CHECK(Axis{0.0, 1.0, 97, Warp::Root4LayerSplit2}.valid());
  CHECK(Axis{0.0, 1.0, 33, Warp::Root4LayerSplit2}.valid());
  CHECK(!Axis{0.0, 1.0, 49, Warp::Root4LayerSplit2}.valid());
  CHECK(!Axis{0.0, 1.0, 17, Warp::Root4LayerSplit2}.valid());
  CHECK(!Axis{0.0, 1.0, 97, Warp::Root4LayerSplit2, 0.5}.valid());  // no constant split
  CHECK(!axisProblem(Axis{0.0, 1.0, 49, Warp::Root4LayerSplit2}).empty());
  std::vector<float> data(97 * 2 * 3, 0.0f);
  LutView v;
  v.data = data.data();
  v.channels = 1;
  v.dims = 3;
  v.axis[0] = Axis{0.0, 1.0, 97, Warp::Root4LayerSplit2};
  v.axis[1] = Axis{0.0, 1.0, 2, Warp::Sqrt};
  v.axis[2] = Axis{1.0 / 3, 1 / 1.1, 3, Warp::Linear};
  CHECK(v.valid());
  const double x[3] = {0.5, 0.5, 0.9};
  CHECK(v.splitAt(x) == 0.9);  // the split parameter is axis 2's eta
  v.dims = 2;
  CHECK(!v.valid());
}

TEST_CASE(
    "root4-layer-split2: min(mu_c, eta) and max(mu_c, eta) are grid lines in every eta "
    "layer",
    "[runtime][split2]") {
  const Axis a{0.0, 1.0, 97, Warp::Root4LayerSplit2};
  for (double eta : Etas()) {
    const double lo = std::min(Critical(eta), eta), hi = std::max(Critical(eta), eta);
    for (double c : {0.0, 1e-12, 1e-4, 0.01, 0.25, 1.0}) {
      INFO("eta " << eta << " c " << c);
      CHECK(a.node(kLineA, c, eta) == lo);
      CHECK(a.node(kLineB, c, eta) == hi);
      CHECK(a.node(0, c, eta) == 0.0);
      CHECK(a.node(96, c, eta) == 1.0);
      if (c > 0 && hi > lo) {
        CHECK(a.texel(lo, c, eta) == kLineA);
        CHECK(a.texel(hi, c, eta) == kLineB);
      }
    }
  }
}

TEST_CASE("root4-layer-split2: monotone, round trip, finite where the breaks cross",
          "[runtime][split2]") {
  const Axis a{0.0, 1.0, 97, Warp::Root4LayerSplit2};
  for (double eta : Etas()) {
    for (double c : {1e-12, 1e-4, 0.01, 0.3, 1.0}) {
      INFO("eta " << eta << " c " << c);
      double before = -1, tBefore = -1;
      for (int k = 0; k <= 1920; ++k) {
        const double t = k / 1920.0, x = a.unwarped(t, c, eta);
        REQUIRE(std::isfinite(x));
        CHECK(x >= before);  // nodes never cross (equal in a zero-width piece)
        before = x;
        const double y = k / 1920.0, ty = a.warped(y, c, eta);
        REQUIRE(std::isfinite(ty));
        CHECK(ty >= tBefore);
        tBefore = ty;
        CHECK(a.unwarped(ty, c, eta) == Approx(y).margin(1e-12));
        if (std::fabs(eta - kCross) > 1e-3) CHECK(a.warped(x, c, eta) == Approx(t).margin(1e-12));
      }
    }
  }
}

TEST_CASE("root4-layer-split2: nodes move continuously with eta across eta = 1 / sqrt 2",
          "[runtime][split2]") {
  // The breaks are min and max of mu_c and eta: each node follows them with a kink at the
  // crossing, not a jump: over a step d in eta a node moves by O(d).
  const Axis a{0.0, 1.0, 97, Warp::Root4LayerSplit2};
  for (double c : {1e-4, 0.01, 0.3, 1.0}) {
    for (double d : {1e-3, 1e-6, 1e-9}) {
      double worst = 0;
      for (int i = 0; i < 97; ++i) {
        const double below = a.node(i, c, kCross - d), above = a.node(i, c, kCross + d);
        const double at = a.node(i, c, kCross);
        worst = std::max({worst, std::fabs(above - below), std::fabs(at - below)});
      }
      INFO("c " << c << " d " << d);
      CHECK(worst <= 6 * d);
    }
  }
  // At the crossing both middle pieces collapse onto one point.
  const double xs = a.node(kLineA, 0.3, kCross);
  for (int i = kLineA; i <= kLineB; ++i) CHECK(a.node(i, 0.3, kCross) == Approx(xs).margin(1e-15));
}

TEST_CASE("root4-layer-split2 at c = 0: the lookups read only the outer halves of the pieces",
          "[runtime][split2]") {
  const Axis a{0.0, 1.0, 97, Warp::Root4LayerSplit2};
  for (double eta : Etas()) {
    for (int k = 0; k <= 4000; ++k) {
      const double t = a.warped(k / 4000.0, 0.0, eta);
      INFO("eta " << eta << " mu " << k / 4000.0 << " t " << t);
      CHECK(!a.holdsLayerLimit(t));
      // and every such t falls in a cell whose two nodes hold smooth values
      const double s = t * 96, lo = std::floor(s);
      CHECK(!a.holdsLayerLimit(lo / 96));
      if (s > lo) CHECK(!a.holdsLayerLimit((lo + 1) / 96));
    }
  }
}

TEST_CASE("root4-layer-split2: the sampler returns the stored value at every node",
          "[runtime][split2]") {
  const int n0 = 33, n1 = 3, n2 = 4;
  std::vector<float> data(static_cast<size_t>(n0 * n1 * n2));
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<float>(i) + 0.25f;
  LutView v;
  v.data = data.data();
  v.channels = 1;
  v.dims = 3;
  v.axis[0] = Axis{0.0, 1.0, n0, Warp::Root4LayerSplit2};
  v.axis[1] = Axis{0.0, 1.0, n1, Warp::Sqrt};
  v.axis[2] = Axis{1.0 / 3, 1 / 1.1, n2, Warp::Linear};
  REQUIRE(v.valid());
  for (int k = 0; k < n2; ++k)
    for (int j = 1; j < n1; ++j)  // the r = 0 row: its inner-half nodes hold the layer limit
      for (int i = 0; i < n0; ++i) {
        double x[3] = {0, v.axis[1].node(j), v.axis[2].node(k)};
        x[0] = v.axis[0].node(i, v.layerScaleAt(x), v.splitAt(x));
        float got = 0;
        v.sample(x, &got);
        INFO("node " << i << " " << j << " " << k);
        CHECK(got == data[static_cast<size_t>((k * n1 + j) * n0 + i)]);
      }
}

// f = (eta - mu)_+^(3/2): a one-sided point at mu = eta that moves with eta (a rough
// dielectric's transmission seen from inside has one, docs/models.md section 16). Tabulated on
// 97 x 2 x 33 nodes (an eta node at the crossing 1 / sqrt 2) and looked up at roughness 1 (a
// node): in every eta layer split2 holds the point on a grid line, graded on both sides;
// root4-layer-split (one split, at mu_c) interpolates across it.
TEST_CASE("root4-layer-split2: a point at mu = eta that moves with eta interpolates",
          "[runtime][split2]") {
  auto f = [](double mu, double eta) { return std::pow(std::max(0.0, eta - mu), 1.5); };
  struct Errors {
    double nearPoint = 0, anywhere = 0;
  };
  auto errors = [&](Warp warp) {
    const int n0 = 97, n2 = 33;
    const Axis a0{0.0, 1.0, n0, warp}, a1{0.0, 1.0, 2, Warp::Sqrt},
        a2{kCross - 0.2, kCross + 0.2, n2, Warp::Linear};
    std::vector<float> data(static_cast<size_t>(n0) * 2 * n2);
    LutView v;
    v.data = data.data();
    v.channels = 1;
    v.dims = 3;
    v.axis[0] = a0;
    v.axis[1] = a1;
    v.axis[2] = a2;
    for (int k = 0; k < n2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < n0; ++i) {
          double x[3] = {0, a1.node(j), a2.node(k)};
          x[0] = a0.node(i, v.layerScaleAt(x), v.splitAt(x));
          data[(static_cast<size_t>(k) * 2 + j) * n0 + i] = static_cast<float>(f(x[0], x[2]));
        }
    Errors e;
    for (int k = 0; k <= 2 * (n2 - 1); ++k)  // the eta nodes and the midpoints between them
      for (int i = 0; i <= 2000; ++i) {
        const double eta = k % 2 ? 0.5 * (a2.node(k / 2) + a2.node(k / 2 + 1)) : a2.node(k / 2);
        const double x[3] = {i / 2000.0, 1.0, eta};
        float got = 0;
        v.sample(x, &got);
        const double err = std::fabs(got - f(x[0], x[2]));
        e.anywhere = std::max(e.anywhere, err);
        if (k % 2 == 0 && std::fabs(x[0] - eta) < 0.03) e.nearPoint = std::max(e.nearPoint, err);
      }
    return e;
  };
  const Errors two = errors(Warp::Root4LayerSplit2), one = errors(Warp::Root4LayerSplit);
  INFO("near mu = eta at the eta nodes: root4-layer-split2 "
       << two.nearPoint << ", root4-layer-split " << one.nearPoint);
  INFO("anywhere: root4-layer-split2 " << two.anywhere << ", root4-layer-split " << one.anywhere);
  CHECK(two.nearPoint < 3e-4);
  CHECK(one.nearPoint > 4 * two.nearPoint);
  CHECK(two.anywhere < one.anywhere);
}
