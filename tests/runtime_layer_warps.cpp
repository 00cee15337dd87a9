// The layer warps of kiln/lut.h at their collapse points: root4-layer at roughness 0 (c = 0,
// the smooth limit) and layer-eta (c = sqrt(|eta^2 - 1|), 0 at eta = 1). Round trips, the
// collapsed mapping, and that files written with the old root4-layer name still load.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "kiln/exr_loader.h"
#include "kiln/lut.h"
#include "test_util.h"

using namespace kiln;

TEST_CASE("layer scales: 0 exactly at the collapse point, floored at 1e-12 past it",
          "[runtime][layer]") {
  CHECK(layerScale(0.0, 1.0, 0.0) == 0.0);
  CHECK(layerScale(0.0, 1.0, -1.0) == 0.0);  // clamped to lo = 0
  CHECK(layerScale(0.0, 1.0, 1e-300) == 1e-12);
  CHECK(layerScale(0.0, 1.0, 0.5) == 0.25);
  CHECK(layerScale(0.1, 1.0, 0.0) == Approx(0.01));  // an axis that starts past 0 never collapses
  CHECK(etaLayerScale(1.0, 3.0, 1.0) == 0.0);
  CHECK(etaLayerScale(1.0, 3.0, 0.5) == 0.0);  // clamped to lo = 1
  CHECK(etaLayerScale(1.0, 3.0, 2.0) == Approx(std::sqrt(3.0)));
  CHECK(etaLayerScale(0.5, 3.0, 0.6) == Approx(0.8));  // eta < 1: the critical cosine
  CHECK(etaLayerScale(1.0, 3.0, std::nextafter(1.0, 2.0)) == Approx(std::sqrt(2 * 0x1p-52)));
}

TEST_CASE("root4-layer at c = 0: every y maps to (y^(1/4) + 1) / 2, smooth nodes from t_s on",
          "[runtime][layer]") {
  for (int n : {2, 3, 4, 9, 128, 129}) {
    const Axis a{0.0, 1.0, n, Warp::Root4Layer};
    const double ts = static_cast<double>((n - 1) / 2) / (n - 1);  // floor((n - 1) / 2) / (n - 1)
    INFO("N = " << n);
    CHECK(a.collapsedStart() == ts);
    CHECK(ts <= 0.5);
    CHECK(ts > 0.5 - 1.0 / (n - 1));  // the last node at or below 1/2
    CHECK(a.warped(0.0, 0.0) == 0.5);
    CHECK(a.texel(0.0, 0.0) >= (n - 1) / 2);  // a lookup at mu = 0, r = 0 reads nodes >= t_s
    CHECK(a.warped(1.0, 0.0) == 1.0);
    CHECK(a.unwarped(0.0, 0.0) == 0.0);
    CHECK(a.unwarped(0.5, 0.0) == 0.0);
    CHECK(a.unwarped(0.25, 0.0) == 0.0);  // every t <= 1/2: the collapsed layer sits at lo
    CHECK(a.warped(1e-40, 0.0) > 0.5);    // every mu > 0 lies in the outer half
    for (double y : {1e-12, 1e-6, 0.01, 0.3, 0.999}) {
      const double t = a.warped(y, 0.0);
      CHECK(t == 0.5 * (std::sqrt(std::sqrt(y)) + 1));
      CHECK(a.unwarped(t, 0.0) == Approx(y).epsilon(1e-12));
      // the limit c -> 0+ of the layered warp, for y > 0
      CHECK(t == Approx(a.warped(y, 1e-300)).margin(1e-15));
    }
  }
  // r > 0 still maps mu = 0 to t = 0, and the round trip holds at the floor.
  const Axis a{0.0, 1.0, 128, Warp::Root4Layer};
  CHECK(a.warped(0.0, 1e-12) == 0.0);
  for (double y : {1e-15, 1e-12, 1e-9, 0.5})
    CHECK(a.unwarped(a.warped(y, 1e-12), 1e-12) == Approx(y).epsilon(1e-12));
}

TEST_CASE("layer-eta: t = y (1 + c) / (y + c), inverted exactly, c = 0 sends y > 0 to t = 1",
          "[runtime][layer]") {
  const Axis a{0.0, 1.0, 128, Warp::LayerEta};
  CHECK(a.collapsedStart() == 1.0);
  for (double c : {2.1e-8, 1e-4, 0.0158, 0.5, 1.0, 2.83}) {
    CHECK(a.warped(0.0, c) == 0.0);
    CHECK(a.warped(1.0, c) == 1.0);
    // half of the nodes lie in mu < c / (1 + 2 c) ~ c
    CHECK(a.warped(c / (1 + 2 * c), c) == Approx(0.5).epsilon(1e-12));
    // x round-trips to the last bits inside the layer (y up to 100 c); past it 1 - t ~ c / y
    // holds y only to ~1e-16 y / c (there F ~ c^4 / 16 and the nodes are sparse on purpose),
    // and t round-trips everywhere.
    for (double y : {1e-300, 1e-12, 1e-6, 0.01, 0.3, 0.999}) {
      const double eps = y <= 100 * c ? 1e-12 : std::max(1e-12, 1e-15 * y / c);
      CHECK(a.unwarped(a.warped(y, c), c) == Approx(y).epsilon(eps));
    }
    for (int i = 0; i <= 64; ++i) {
      const double t = i / 64.0;
      CHECK(a.warped(a.unwarped(t, c), c) == Approx(t).margin(1e-15));
    }
    for (int i = 0; i < 128; ++i) CHECK(a.texel(a.node(i, c), c) == i);
  }
  CHECK(a.warped(0.0, 0.0) == 0.0);
  CHECK(a.warped(1e-300, 0.0) == 1.0);
  CHECK(a.warped(0.5, 0.0) == 1.0);
  CHECK(a.unwarped(0.999, 0.0) == 0.0);
  CHECK(a.unwarped(1.0, 0.0) == 1.0);
  Warp parsed = Warp::Linear;
  REQUIRE(warpFromName("layer-eta", parsed));
  CHECK(parsed == Warp::LayerEta);
  CHECK(std::string(warpName(Warp::LayerEta)) == "layer-eta");
}

TEST_CASE("layer warps only on axis 0 of a view of 2+ axes, a layer-eta view reads axis 1",
          "[runtime][layer]") {
  const float data[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  LutView v;
  v.data = data;
  v.channels = 1;
  v.dims = 2;
  v.axis[0] = Axis{0.0, 1.0, 4, Warp::LayerEta};
  v.axis[1] = Axis{1.0, 3.0, 2, Warp::Sqrt};
  CHECK(v.valid());
  const double x[2] = {0.0, 2.0};
  CHECK(v.layerScaleAt(x) == Approx(std::sqrt(3.0)));
  v.axis[1].warp = Warp::LayerEta;
  CHECK_FALSE(v.valid());
  v.dims = 1;
  v.axis[1].warp = Warp::Sqrt;
  CHECK_FALSE(v.valid());
}

TEST_CASE("Files written with the root4-layer warp before the collapse point still load",
          "[runtime][layer]") {
  // luts/ggx-dfg.exr keeps the warp's name; only the row r = 0 changed meaning.
  Table t = loadTable(std::string(KILN_SOURCE_DIR) + "/luts/ggx-dfg.exr");
  REQUIRE(t.axes.size() == 2);
  CHECK(t.axes[0].axis.warp == Warp::Root4Layer);
  CHECK(t.view().valid());
}
