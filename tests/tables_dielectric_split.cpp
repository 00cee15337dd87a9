// The exit-side glass tables (ggx-dielectric-albedo-r-exit, -t-exit) place mu by the
// root4-layer-split2 warp: the kink of total internal reflection at mu_c = sqrt(1 - eta^2) and
// E_T's one-sided point at mu = eta (theta_o + theta_c = pi / 2) are nodes of every eta layer
// (t = 8/16 the smaller, t = 13/16 the larger of the two), so no cell straddles either.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE(
    "the exit tables' mu nodes 48 and 78 are min and max of mu_c and eta in every "
    "(roughness, eta) row",
    "[dielectric][split]") {
  for (const char* name : {"ggx-dielectric-albedo-r-exit", "ggx-dielectric-albedo-t-exit"}) {
    TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    REQUIRE(spec.axes[0].warp == Warp::Root4LayerSplit2);
    REQUIRE(spec.axes[0].size == 97);
    const size_t n0 = 97, n1 = spec.axes[1].size, n2 = spec.axes[2].size;
    for (size_t k = 0; k < n2; ++k)
      for (size_t j = 0; j < n1; ++j) {
        double a[3], b[3];
        NodeCoordinates(spec, (k * n1 + j) * n0 + 48, a);
        NodeCoordinates(spec, (k * n1 + j) * n0 + 78, b);
        const double muc = std::sqrt(1 - a[2] * a[2]), eta = a[2];
        INFO(name << " roughness " << a[1] << " eta " << a[2]);
        CHECK(a[0] == Approx(std::min(muc, eta)).epsilon(1e-15));
        CHECK(b[0] == Approx(std::max(muc, eta)).epsilon(1e-15));
      }
  }
}
