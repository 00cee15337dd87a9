// lafortune's tables at roughness 1: the model there is Lambertian (n = 0, Lafortune's
// max(0, m.l)^0 = 1 on the whole hemisphere, E = 1), while r -> 1- tends to the half-space
// m.l > 0, E = (1 + mu) / 2. The tables hold the limit, continuous in r, say so in their method
// text, and `kiln verify` checks that node against the limit's closed form, not against the
// Lambertian point (docs/models.md "r = 1 is a point apart").
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "baker/integrate/fixed_rule_lobe.h"
#include "baker/quantities/unity_tables.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "cli_util.h"

namespace kiln {
namespace {

TableSpec OnRequestSpec(const std::string& name) {
  for (const TableSpec& s : OnRequestTables(CatalogueOptions{}))
    if (s.name == name) return s;
  FAIL("no on-request table " << name);
  return {};
}

}  // namespace

TEST_CASE("lafortune-albedo: every reference at roughness 1 is the half-space limit (1 + mu) / 2",
          "[lafortune][unity-rule]") {
  const TableSpec spec = OnRequestSpec("lafortune-albedo");
  for (double mu : {0.0, 1e-6, 0.1, 0.5, 0.9, 1.0}) {
    const double x[3] = {mu, 1.0, 0};
    IntegrationStats bake, reference;
    const double baked = EvaluateSpec(spec, x, bake)[0];
    const double adaptive = EvaluateSpec(spec, x, 1e-10, reference)[0];
    INFO("mu " << mu);
    CHECK(baked == (1 + mu) / 2);
    CHECK(adaptive == (1 + mu) / 2);
    // The rule's own n -> 0+ agrees: the node is continuous with r -> 1-.
    CHECK(std::abs(FixedRuleMirrorLobeAlbedo(mu, 0) - baked) < kMirrorLobeRuleBound);
  }
  // Below r = 1 the model itself is the reference (n > 0).
  const double inside[3] = {0.5, 0.99, 0};
  std::vector<double> limit;
  CHECK_FALSE(MirrorLobeLimitAt(spec, inside, limit));
  CHECK(spec.Method().find("roughness 1 (n = 0) holds the limit n -> 0+") != std::string::npos);
}

TEST_CASE("lafortune-albedo-avg: its roughness-1 node is the half-space limit's average 5 / 6",
          "[lafortune][unity-rule]") {
  const TableSpec spec = OnRequestSpec("lafortune-albedo-avg");
  const double x[3] = {1.0, 0, 0};
  IntegrationStats bake, reference;
  CHECK(EvaluateSpec(spec, x, bake)[0] == 5.0 / 6.0);
  CHECK(EvaluateSpec(spec, x, 1e-10, reference)[0] == 5.0 / 6.0);
}

TEST_CASE("kiln verify passes a baked lafortune-albedo and -avg, their roughness-1 nodes included",
          "[lafortune][cli]") {
  const std::string dir = test::TempDir("lafortune_limit");
  auto bake = test::RunKiln("bake --only lafortune-albedo,lafortune-albedo-avg --size 24 --out " +
                            dir + " -j 2");
  INFO(bake.out << bake.err);
  REQUIRE(bake.exitCode == 0);
  // Its bake-error check takes the corners, (mu 0, r 1) among them.
  auto verify = test::RunKiln("verify " + dir + "/lafortune-albedo.exr " + dir +
                              "/lafortune-albedo-avg.exr -j 2");
  INFO(verify.out << verify.err);
  CHECK(verify.exitCode == 0);
  CHECK(verify.out.find("2 tables, 0 over their bound") != std::string::npos);
}

}  // namespace kiln
