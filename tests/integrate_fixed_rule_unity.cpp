// The fixed rule of unity-brdf1's albedo (integrate/fixed_rule_microfacet.h, FixedRuleNdf::
// UnityBRDF1) against the adaptive integrator (issue #16: bake error below 1e-6).
#include <catch2/catch.hpp>
#include <cmath>

#include "baker/bake/bake.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/tables/catalogue.h"

namespace kiln {

TEST_CASE("unity-brdf1: the fixed rule's albedo is the adaptive integrator's within 1e-6",
          "[unity-rule]") {
  FixedRuleModel m;
  REQUIRE(FixedRuleModelFor("unity-brdf1", &m));
  double worst = 0, wmu = 0, wr = 0;
  const double mus[] = {0,   1e-12, 1e-9, 1e-6, 1e-4, 1e-3, 3e-3, 0.01, 0.03,
                        0.1, 0.2,   0.35, 0.5,  0.7,  0.85, 0.95, 1};
  const double rs[] = {0, 0.02, 0.05, 0.1, 0.115, 0.13, 0.16, 0.2, 0.25, 0.3, 0.45, 0.6, 0.8, 1};
  for (double r : rs)
    for (double mu : mus) {
      ModelParams p;
      p.roughness = r;
      IntegrationOptions opt;
      opt.tol = 1e-10;
      IntegrationStats stats;
      // At mu = 0 the rule takes the limit mu -> 0+; the adaptive integrator's value at mu = 0
      // exactly lies 1.4e-6 off its own limit (r = 0.13: kiln integrate albedo --model
      // unity-brdf1 --roughness 0.13 --mu 0, then --mu 1e-12), so mu = 0 is compared with it.
      RhoParts e = DirectionalAlbedo(MakeModel("unity-brdf1", p), mu > 0 ? mu : 1e-12, opt, stats);
      std::array<double, 2> ab = FixedRuleMicrofacetDFG(m, mu, r * r);
      double err = std::abs(ab[0] + ab[1] - (e.lin + e.quad));
      if (err > worst) worst = err, wmu = mu, wr = r;
    }
  INFO("worst " << worst << " at mu " << wmu << " r " << wr);
  CHECK(worst < 6e-7);  // kFixedRuleBound, the bound its texels declare
}

}  // namespace kiln

namespace kiln {

TEST_CASE(
    "unity-brdf1's albedo tables: on request, from r = sqrt(0.002) where the model stops "
    "changing, the same bytes on 1 and 2 threads",
    "[unity-rule]") {
  bool inDefault = false, onRequest = false;
  for (const TableSpec& s : DefaultCatalogue())
    inDefault |= s.name == "unity-brdf1-albedo" || s.name == "unity-brdf1-albedo-avg";
  for (const TableSpec& s : OnRequestTables()) onRequest |= s.name == "unity-brdf1-albedo";
  CHECK_FALSE(inDefault);
  CHECK(onRequest);
  // Below r = sqrt(0.002) Unity's a = max(r^2, 0.002) is constant: the table's roughness axis
  // starts there and a lookup below clamps to the same model.
  TableSpec spec = CatalogueTable("unity-brdf1-albedo", CatalogueOptions{});
  REQUIRE(spec.axes[1].name == "roughness");
  const double r0 = spec.axes[1].lo;
  CHECK(r0 * r0 == Approx(0.002).epsilon(1e-15));
  for (double mu : {0.0, 0.3, 1.0}) {
    std::array<double, 2> at0 = FixedRuleMicrofacetDFG(FixedRuleModel{FixedRuleNdf::UnityBRDF1}, mu,
                                                       0.0),
                          atR0 = FixedRuleMicrofacetDFG(FixedRuleModel{FixedRuleNdf::UnityBRDF1},
                                                        mu, r0 * r0);
    CHECK(at0[0] + at0[1] == atR0[0] + atR0[1]);
  }
  // A smaller table of the same spec: -j 1 and -j 2 bake the same bytes and bound.
  CatalogueOptions small;
  small.size = 9;
  for (const char* name : {"unity-brdf1-albedo", "unity-brdf1-albedo-avg"}) {
    TableSpec s = CatalogueTable(name, small);
    BakeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    Table a = BakeTable(s, one), b = BakeTable(s, two);
    INFO(name);
    CHECK(a.data == b.data);
    CHECK(a.lookupError.max == b.lookupError.max);
  }
}

}  // namespace kiln
