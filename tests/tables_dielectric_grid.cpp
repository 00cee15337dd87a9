// The entering glass tables' shared grid (issue #15): albedo-r, albedo-t and the BTDF pair over
// the same (mu, roughness) pairs, mu root4-layer-angle (graded at both ends), 40 cheap eta nodes;
// their declared linear lookup bounds below 1e-3 were measured on this grid (README, glass;
// docs/models.md section 16). The exit pair: mu 97 root4-layer-split2 x roughness 50 arcsine x
// eta' 41 angle (its own bounds below 1e-3, measured on that grid).
#include <catch2/catch.hpp>

#include <cmath>

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

TEST_CASE(
    "the exit glass tables: mu 97 root4-layer-split2 x roughness 50 arcsine x eta' 41 "
    "angle, an eta' node by the crossing of mu_c and eta",
    "[dielectric]") {
  for (const char* name : {"ggx-dielectric-albedo-r-exit", "ggx-dielectric-albedo-t-exit"}) {
    INFO(name);
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes.size() == 3);
    CHECK(spec.axes[0].size == 97);
    CHECK(spec.axes[0].warp == Warp::Root4LayerSplit2);
    CHECK(spec.axes[1].size == 50);
    CHECK(spec.axes[1].warp == Warp::Arcsine);
    CHECK(spec.axes[2].size == 41);
    CHECK(spec.axes[2].warp == Warp::Angle);
    // Where mu_c = eta (eta' = 1 / sqrt 2) the warp's breaks swap: the node positions have a
    // kink in eta' there, harmless at a node. Node 18 of the angle axis is 1.5e-4 from it.
    const Axis eta = spec.axes[2].ToAxis();
    CHECK(std::fabs(eta.node(18) - std::sqrt(0.5)) < 2e-4);
  }
}
