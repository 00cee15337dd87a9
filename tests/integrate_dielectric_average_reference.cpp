// The glass averages' nested reference as the texel check takes it (glass_average_reference.h):
// EvaluateSpec's integral, its tolerance split evenly between mu and E(mu) with E's share graded
// by the weight 2 mu, and one integration a point for the r and t kinds.
#include <catch2/catch.hpp>

#include <cmath>

#include "baker/tables/catalogue.h"
#include "glass_average_reference.h"

using namespace kiln;

namespace {

/// The tolerance the texel check holds the glass averages' nested reference to.
constexpr double kTol = 1e-8;

/// At (r, eta) of the r kind `rName` and the t kind `tName` (one side of the interface; a point
/// off the size-5 tables' nodes, whose references the texel check of the same process may have
/// put in the memo): the reference is EvaluateSpec's to within the two tolerances, costs fewer
/// evaluations, and the t kind after the r kind costs none. EvaluateSpec's t kind after its r
/// kind reads the same integration (DielectricAlbedoAverage remembers it) and is charged alike.
void CheckAgainstEvaluateSpec(const char* rName, const char* tName, double r, double eta) {
  CatalogueOptions copt;
  copt.size = 5;
  const TableSpec rSpec = CatalogueTable(rName, copt), tSpec = CatalogueTable(tName, copt);
  const double x[2] = {r, eta};
  long long evals = 0, tEvals = 0;
  const double rRef = test::GlassAverageReference(rSpec, x, kTol, &evals)[0];
  const double tRef = test::GlassAverageReference(tSpec, x, kTol, &tEvals)[0];
  IntegrationStats rSt, tSt;
  const double rExact = EvaluateSpec(rSpec, x, kTol, rSt)[0];
  const double tExact = EvaluateSpec(tSpec, x, kTol, tSt)[0];
  INFO(rName << " r " << r << " eta " << eta << ": " << evals << " evaluations, EvaluateSpec "
             << rSt.evals);
  CHECK(std::abs(rRef - rExact) <= kTol);
  CHECK(std::abs(tRef - tExact) <= kTol);
  CHECK(evals > 0);
  CHECK(evals < rSt.evals);
  CHECK(tEvals == 0);
  CHECK(tSt.evals == rSt.evals);
}

}  // namespace

TEST_CASE("A glass average's nested reference is EvaluateSpec's, one integration for r and t",
          "[dielectric][avg]") {
  SECTION("entering") {
    CheckAgainstEvaluateSpec("ggx-dielectric-albedo-r-avg", "ggx-dielectric-albedo-t-avg", 0.99,
                             2.95);
  }
  SECTION("exit") {
    CheckAgainstEvaluateSpec("ggx-dielectric-albedo-r-exit-avg", "ggx-dielectric-albedo-t-exit-avg",
                             0.99, 0.34);
  }
}

TEST_CASE("A glass average's nested reference at roughness 0 is the smooth interface's",
          "[dielectric][avg]") {
  CatalogueOptions copt;
  copt.size = 5;
  for (const char* name : {"ggx-dielectric-albedo-r-avg", "ggx-dielectric-albedo-t-exit-avg"}) {
    const TableSpec spec = CatalogueTable(name, copt);
    const double x[2] = {0, std::string(name).find("exit") == std::string::npos ? 1.5 : 1 / 1.5};
    IntegrationStats st;
    long long evals = 0;
    INFO(name);
    CHECK(test::GlassAverageReference(spec, x, kTol, &evals)[0] ==
          EvaluateSpec(spec, x, kTol, st)[0]);
    CHECK(evals == 0);
  }
}
