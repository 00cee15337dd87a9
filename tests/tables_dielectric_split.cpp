// The exit-side glass tables (ggx-dielectric-albedo-r-exit, -t-exit) place mu by the
// root4-layer-split warp: the kink of total internal reflection at mu_c = sqrt(1 - eta^2) is
// a node of every eta layer (t = 1/2), so no cell straddles it.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE("the exit tables' mu node 24 is the critical cosine in every (roughness, eta) row",
          "[dielectric][split]") {
  for (const char* name : {"ggx-dielectric-albedo-r-exit", "ggx-dielectric-albedo-t-exit"}) {
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes[0].warp == Warp::Root4LayerSplit);
    REQUIRE(spec.axes[0].size == 49);
    const size_t n0 = 49, n1 = spec.axes[1].size, n2 = spec.axes[2].size;
    for (size_t k = 0; k < n2; ++k)
      for (size_t j = 1; j < n1; ++j) {  // the r = 0 row: node 24 holds the layer's limit
        double x[3];
        NodeCoordinates(spec, (k * n1 + j) * n0 + 24, x);
        INFO(name << " roughness " << x[1] << " eta " << x[2]);
        CHECK(x[0] == Approx(std::sqrt(1 - x[2] * x[2])).epsilon(1e-15));
      }
  }
}
