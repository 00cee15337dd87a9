// The entering glass tables' shared grid (issue #15): albedo-r, albedo-t and the BTDF pair over
// the same (mu, roughness) pairs, mu root4-layer-angle (graded at both ends), 40 cheap eta nodes;
// their declared linear lookup bounds below 1e-3 were measured on this grid (README, glass;
// docs/models.md section 16). The exit pair keeps root4-layer-split 49 x 40 x 24.
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE(
    "the entering glass tables share one grid: mu 80 root4-layer-angle x roughness 50 "
    "sqrt x eta 40 sqrt",
    "[dielectric]") {
  for (const char* name :
       {"ggx-dielectric-albedo-r", "ggx-dielectric-albedo-t", "ggx-dielectric-btdf-split-sum"}) {
    INFO(name);
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes.size() == 3);
    CHECK(spec.axes[0].name == "mu");
    CHECK(spec.axes[0].size == 80);
    CHECK(spec.axes[0].warp == Warp::Root4LayerAngle);
    CHECK(spec.axes[1].name == "roughness");
    CHECK(spec.axes[1].size == 50);
    CHECK(spec.axes[1].warp == Warp::Sqrt);
    CHECK(spec.axes[2].name == "eta");
    CHECK(spec.axes[2].size == 40);
    CHECK(spec.axes[2].warp == Warp::Sqrt);
    CHECK(spec.axes[2].lo == Approx(1.1));
    CHECK(spec.axes[2].hi == 3);
  }
}

TEST_CASE("the exit glass tables keep mu 49 root4-layer-split x roughness 40 x eta' 24",
          "[dielectric]") {
  for (const char* name : {"ggx-dielectric-albedo-r-exit", "ggx-dielectric-albedo-t-exit"}) {
    INFO(name);
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes.size() == 3);
    CHECK(spec.axes[0].size == 49);
    CHECK(spec.axes[0].warp == Warp::Root4LayerSplit);
    CHECK(spec.axes[1].size == 40);
    CHECK(spec.axes[2].size == 24);
    CHECK(spec.axes[2].warp == Warp::Linear);
  }
}
