// The glass tables' layouts (issue #15): the grids, warps and stored forms the catalogue bakes,
// which their declared lookup bounds were measured on (README, glass).
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE(
    "the glass averages: roughness linear by eta, 24 x 16 entering, 32 x 24 exit (its search "
    "found 9.8e-4 on 24 x 16)",
    "[dielectric]") {
  struct Case {
    const char* name;
    int roughness, eta;
  };
  for (const Case& c :
       {Case{"ggx-dielectric-albedo-r-avg", 24, 16}, Case{"ggx-dielectric-albedo-t-avg", 24, 16},
        Case{"ggx-dielectric-albedo-r-exit-avg", 32, 24},
        Case{"ggx-dielectric-albedo-t-exit-avg", 32, 24}}) {
    INFO(c.name);
    TableSpec spec = CatalogueTable(c.name, CatalogueOptions{});
    REQUIRE(spec.axes.size() == 2);
    CHECK(spec.axes[0].name == "roughness");
    CHECK(spec.axes[0].size == c.roughness);
    CHECK(spec.axes[0].warp == Warp::Linear);
    CHECK(spec.axes[1].name == "eta");
    CHECK(spec.axes[1].size == c.eta);
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
