// The root4-layer-angle warp of kiln/lut.h (issue #15): root4-layer composed with the angle
// warp, u = (2 / pi) asin(y), so that a mu axis is dense at both ends: the grazing layer of
// width ~r^2 at mu = 0 as root4-layer grades it, and mu = 1 graded in the angle theta = acos(mu),
// where a function of (1 - mu)^(3/2) (E_T of rough glass at roughness 1) is smooth in t.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "kiln/lut.h"

using namespace kiln;

TEST_CASE("root4-layer-angle: the name round-trips, only on axis 0 of a 2+ axis view",
          "[runtime][angle-layer]") {
  Warp w = Warp::Linear;
  REQUIRE(warpFromName("root4-layer-angle", w));
  CHECK(w == Warp::Root4LayerAngle);
  CHECK(std::string(warpName(Warp::Root4LayerAngle)) == "root4-layer-angle");
  CHECK(isLayerWarp(Warp::Root4LayerAngle));
  const float data[9 * 3] = {};
  LutView v;
  v.data = data;
  v.channels = 1;
  v.dims = 1;
  v.axis[0] = Axis{0.0, 1.0, 9, Warp::Root4LayerAngle};
  CHECK(!v.valid());
  v.dims = 2;
  v.axis[1] = Axis{0.0, 1.0, 3, Warp::Sqrt};
  CHECK(v.valid());
}

TEST_CASE("root4-layer-angle: t = root4-layer of (2 / pi) asin(y), inverted to the last bits",
          "[runtime][angle-layer]") {
  const Axis a{0.0, 1.0, 48, Warp::Root4LayerAngle}, plain{0.0, 1.0, 48, Warp::Root4Layer};
  for (double c : {1e-12, 1e-4, 0.01, 0.25, 1.0}) {
    for (double y : {1e-9, 1e-4, 0.1, 0.5, 0.9, 0.999, 1 - 1e-9}) {
      INFO("c " << c << " y " << y);
      const double u = std::asin(y) * (2 / kPi);
      CHECK(a.warped(y, c) == Approx(Axis::layerWarp(u, c)).epsilon(1e-14));
      CHECK(a.unwarped(a.warped(y, c), c) == Approx(y).epsilon(1e-13));
    }
    for (int i = 0; i < a.size; ++i) {
      INFO("c " << c << " node " << i);
      CHECK(a.texel(a.node(i, c), c) == i);  // a lookup at a node reads that node
      if (i > 0) CHECK(a.node(i, c) > a.node(i - 1, c));
    }
    CHECK(a.node(0, c) == 0.0);
    CHECK(a.node(47, c) == 1.0);
  }
  // At mu -> 1 the last cell is graded in the angle: at r = 1 (c = 1) it spans ~0.09 rad in
  // theta, ~0.004 in mu, where root4-layer's last cell is ~0.055 wide in mu.
  const double last = 1 - a.node(46, 1.0), lastPlain = 1 - plain.node(46, 1.0);
  CHECK(last < 0.01);
  CHECK(lastPlain > 0.04);
  CHECK(std::acos(a.node(46, 1.0)) < 0.1);
}

TEST_CASE("root4-layer-angle at c = 0: collapses as root4-layer, smooth nodes from t = 1/2",
          "[runtime][angle-layer]") {
  const Axis a{0.0, 1.0, 49, Warp::Root4LayerAngle};
  CHECK(a.collapsedStart() == 0.5);
  CHECK(a.warped(0.0, 0.0) == 0.5);
  CHECK(a.unwarped(0.5, 0.0) == 0.0);
  CHECK(a.unwarped(0.25, 0.0) == 0.0);
  for (double y : {1e-6, 0.3, 0.99}) {
    const double u = std::asin(y) * (2 / kPi);
    CHECK(a.warped(y, 0.0) == Approx(0.5 * (std::sqrt(std::sqrt(u)) + 1)).epsilon(1e-14));
    CHECK(a.unwarped(a.warped(y, 0.0), 0.0) == Approx(y).epsilon(1e-13));
  }
  CHECK(a.holdsLayerLimit(0.25));
  CHECK(!a.holdsLayerLimit(0.75));
}

TEST_CASE("root4-layer-angle: (1 - mu)^(3/2) at mu -> 1 interpolates where root4-layer cannot",
          "[runtime][angle-layer]") {
  // One row of 48 nodes at c = 1; the worst linear lookup error of f = (1 - mu)^(3/2) over
  // the last quarter of mu, probed on a fine grid: 4.0e-4 against 1.8e-3 (the largest error
  // moves from the last cell into the bulk, where f'' is finite).
  auto worst = [](Warp warp) {
    const Axis a{0.0, 1.0, 48, warp};
    auto f = [](double mu) { return std::pow(1 - mu, 1.5); };
    double e = 0;
    for (int k = 0; k <= 4000; ++k) {
      const double mu = 0.75 + 0.25 * k / 4000.0, s = a.texel(mu, 1.0);
      const int i = std::min(static_cast<int>(std::floor(s)), a.size - 2);
      const double w = s - i;
      const double v = (1 - w) * f(a.node(i, 1.0)) + w * f(a.node(i + 1, 1.0));
      e = std::max(e, std::fabs(v - f(mu)));
    }
    return e;
  };
  const double angle = worst(Warp::Root4LayerAngle), plain = worst(Warp::Root4Layer);
  INFO("root4-layer-angle " << angle << ", root4-layer " << plain);
  CHECK(angle < plain / 4);
}

TEST_CASE("root4-layer-angle: the sampler returns the stored value at every node",
          "[runtime][angle-layer]") {
  // A 2D table (mu 17 root4-layer-angle x roughness 5 sqrt) holding a distinct value per node:
  // a lookup at a node's (mu, roughness), mu placed at that row's layer scale c = r^2, reads
  // exactly that node, and the GPU coordinate puts it on its texel centre.
  const int n0 = 17, n1 = 5;
  float data[n0 * n1];
  for (int k = 0; k < n0 * n1; ++k) data[k] = 0.25f + 0.01f * static_cast<float>(k);
  LutView v;
  v.data = data;
  v.channels = 1;
  v.dims = 2;
  v.axis[0] = Axis{0.0, 1.0, n0, Warp::Root4LayerAngle};
  v.axis[1] = Axis{0.0, 1.0, n1, Warp::Sqrt};
  REQUIRE(v.valid());
  for (int j = 1; j < n1; ++j) {  // r > 0: every node of the row holds a smooth value
    const double r = v.axis[1].node(j), c = layerScale(0.0, 1.0, r);
    for (int i = 0; i < n0; ++i) {
      INFO("node " << i << ", " << j);
      const double x[2] = {v.axis[0].node(i, c), r};
      float out = -1;
      v.sample(x, &out);
      CHECK(out == data[j * n0 + i]);
      CHECK(v.axis[0].gpuCoord(x[0], c) == Approx((0.5 + i) / n0).epsilon(1e-12));
    }
  }
}
