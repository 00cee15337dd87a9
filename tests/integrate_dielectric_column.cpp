// The glass rule's eta columns (baker/integrate/dielectric_albedo.cpp, "Columns"): on the
// entering side one walk of the microfacet normals serves every eta of a table's eta axis. The
// column must give each eta exactly the bits the rule gives it alone (the lookup-error search and
// `kiln verify` evaluate single points), whatever the column's other etas, its length and the
// thread count; the walks' polynomial cos must stay within rounding of std::cos.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/dielectric_walk.h"
#include "baker/models/roughness.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

TEST_CASE("the walks' cos is std::cos within 4e-16 over [0, pi]", "[dielectric][glass-rule]") {
  double worst = 0;
  for (int i = 0; i <= 100000; ++i) {
    const double phi = Pi * i / 100000;
    worst = std::max(worst, std::abs(dielectric_walk::CosHalfTurn(phi) - std::cos(phi)));
  }
  CHECK(worst < 4e-16);
  CHECK(dielectric_walk::CosHalfTurn(0) == Approx(1).margin(4e-16));
  CHECK(dielectric_walk::CosHalfTurn(Pi) == Approx(-1).margin(4e-16));
}

TEST_CASE("an eta column gives every eta the bits of the rule at that eta alone",
          "[dielectric][glass-rule]") {
  // 23 etas (odd: the last lane pair padded), over the entering tables' [1.1, 3].
  std::vector<double> etas;
  for (int k = 0; k < 23; ++k) etas.push_back(1.1 + 1.9 * std::pow(k / 22.0, 2));
  for (double mu : {0.0, 1e-6, 0.2, 0.7, 1.0})
    for (double r : {1e-3, 0.3, 1.0}) {
      const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
      std::vector<std::array<double, 2>> col(etas.size());
      long long evals = 0;
      FixedRuleDielectricAlbedoColumn(mu, alpha, etas.data(), static_cast<int>(etas.size()),
                                      TunedDielectricRuleOptions(), col.data(), &evals);
      CHECK(evals > 0);
      for (size_t k = 0; k < etas.size(); k += 5) {
        INFO("mu " << mu << " r " << r << " eta " << etas[k]);
        long long one = 0;
        const std::array<double, 2> e =
            FixedRuleDielectricAlbedo(mu, alpha, etas[k], TunedDielectricRuleOptions(), &one);
        CHECK(std::memcmp(&e, &col[k], sizeof e) == 0);
        CHECK(one == evals);  // every eta of a column walks the same nodes
      }
    }
  // The averages' columns likewise.
  std::vector<std::array<double, 2>> avg(4);
  FixedRuleDielectricAlbedoAverageColumn(0.09, etas.data(), 4, avg.data(), nullptr);
  for (int k = 0; k < 4; ++k) {
    const std::array<double, 2> e = FixedRuleDielectricAlbedoAverage(0.09, etas[k]);
    CHECK(std::memcmp(&e, &avg[k], sizeof e) == 0);
  }
  // Off the entering side the column refuses (its panels hold for eta >= 1.1 only).
  const double below[] = {1.05};
  std::array<double, 2> out;
  CHECK_THROWS(FixedRuleDielectricAlbedoColumn(0.5, 0.1, below, 1, TunedDielectricRuleOptions(),
                                               &out, nullptr));
}

TEST_CASE("the entering tables baked by columns hold the rule's point values, for 1 and 2 threads",
          "[dielectric][glass-rule]") {
  for (const char* name : {"ggx-dielectric-albedo-r", "ggx-dielectric-albedo-t-avg"}) {
    CatalogueOptions copt;
    copt.size = 4;
    TableSpec spec = CatalogueTable(name, copt);
    BakeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.measureLookupError = two.measureLookupError = false;
    Table a = BakeTable(spec, one), b = BakeTable(spec, two);
    REQUIRE(a.data.size() == b.data.size());
    CHECK(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(a.data[0])) == 0);
    // Every texel as EvaluateSpec gives it at its node (what the search and verify evaluate).
    const size_t nc = spec.channels.size();
    for (size_t i = 0; i < spec.TexelCount(); ++i) {
      double x[3];
      NodeEvaluationPoint(spec, i, x);
      IntegrationStats st;
      const std::vector<double> v = EvaluateSpec(spec, x, st);
      for (size_t c = 0; c < nc; ++c) {
        INFO(name << " texel " << i);
        CHECK(a.data[i * nc + c] == static_cast<float>(v[c]));
      }
    }
  }
}

TEST_CASE(
    "an entering average asked for twice (the r-avg and t-avg searches' shared points) gives the "
    "bits and evaluations of the rule at the average's nodes both times",
    "[dielectric][glass-rule]") {
  for (double eta : {1.1, 1.5, 2.9}) {
    INFO("eta " << eta);
    long long direct = 0, first = 0, second = 0;
    const std::array<double, 2> e =
        FixedRuleDielectricAlbedoAverage(0.2, eta, kDielectricAverageNodes, &direct);
    const std::array<double, 2> a = FixedRuleDielectricAlbedoAverage(0.2, eta, &first);
    const std::array<double, 2> b = FixedRuleDielectricAlbedoAverage(0.2, eta, &second);
    CHECK(std::memcmp(&e, &a, sizeof e) == 0);
    CHECK(std::memcmp(&e, &b, sizeof e) == 0);
    CHECK(first == direct);
    CHECK(second == direct);
  }
}
