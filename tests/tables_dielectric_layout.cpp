// The glass tables' layouts (issue #15): the grids, warps and stored forms the catalogue bakes,
// which their declared lookup bounds were measured on (README, glass).
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE("the glass averages: 24 roughness nodes, linear, by 16 eta nodes", "[dielectric]") {
  for (const char* name :
       {"ggx-dielectric-albedo-r-avg", "ggx-dielectric-albedo-t-avg",
        "ggx-dielectric-albedo-r-exit-avg", "ggx-dielectric-albedo-t-exit-avg"}) {
    INFO(name);
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes.size() == 2);
    CHECK(spec.axes[0].name == "roughness");
    CHECK(spec.axes[0].size == 24);
    CHECK(spec.axes[0].warp == Warp::Linear);
    CHECK(spec.axes[1].name == "eta");
    CHECK(spec.axes[1].size == 16);
  }
}

TEST_CASE(
    "the exit E tables store E minus dielectricExitClosedForm, the entering ones E minus "
    "dielectricAlbedoClosedForm",
    "[dielectric]") {
  struct Case {
    const char* name;
    const char* channel;
  };
  for (const Case& c : {Case{"ggx-dielectric-albedo-r", "E_R_residual"},
                        Case{"ggx-dielectric-albedo-t", "E_T_residual"},
                        Case{"ggx-dielectric-albedo-r-exit", "E_R_tir_residual"},
                        Case{"ggx-dielectric-albedo-t-exit", "E_T_tir_residual"}}) {
    INFO(c.name);
    TableSpec spec = CatalogueTable(c.name, CatalogueOptions{});
    REQUIRE(spec.channels.size() == 1);
    CHECK(spec.channels[0] == c.channel);
  }
}
