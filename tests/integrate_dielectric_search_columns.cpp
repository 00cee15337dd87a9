// The glass averages' lookup-error search by columns (integrate/dielectric_albedo_avg.h,
// PrepareDielectricAverageColumn; QuantityInfo::prepareSearch): the search hands the points of a
// batch to the kind first, which integrates the points of one roughness as one column of
// entering etas. Each point must then read exactly the bits and the evaluation count it gets
// alone (the search's budget is counted in evaluations, and its report must not depend on the
// batching), on both sides: E_avg of the entering side at eta, the exit side's E_avg_T at 1 / eta.
// The exit side's E_avg_R takes one kernel per roughness (integrate/dielectric_kernel.h), which
// the search's points of one roughness share through its memo of rows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/models/roughness.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"

using namespace kiln;

namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("a prepared column gives each average point the bits and evaluations it gets alone",
          "[dielectric][glass-rule]") {
  // Roughnesses no table's grid or search uses (the memo is the process's), entering etas over
  // [1.1, 3] at cell centres of no table, 5 of them (an odd lane count).
  const double etas[] = {1.1037, 1.377, 1.9013, 2.4441, 2.999};
  for (double alpha : {0.0123457, 0.4321, 0.987654}) {
    std::array<double, 2> alone[5];
    double exitT[5];
    long long evAlone[5], evExitAlone[5];
    for (int e = 0; e < 5; ++e) {
      evAlone[e] = evExitAlone[e] = 0;
      alone[e] =
          FixedRuleDielectricAlbedoAverage(alpha, etas[e], kDielectricAverageNodes, &evAlone[e]);
      exitT[e] = FixedRuleDielectricExitAverageT(alpha, 1 / etas[e], kDielectricAverageNodes,
                                                 &evExitAlone[e]);
    }
    PrepareDielectricAverageColumn(alpha, etas, 5);
    for (int e = 0; e < 5; ++e) {
      long long ev = 0, evExit = 0;
      const std::array<double, 2> got = FixedRuleDielectricAlbedoAverage(alpha, etas[e], &ev);
      const double gotExit =
          FixedRuleDielectricExitAverageT(alpha, 1 / etas[e], kDielectricAverageNodes, &evExit);
      CHECK(SameBits(got[0], alone[e][0]));
      CHECK(SameBits(got[1], alone[e][1]));
      CHECK(SameBits(gotExit, exitT[e]));
      CHECK(ev == evAlone[e]);
      CHECK(evExit == evExitAlone[e]);
    }
  }
}

TEST_CASE("the column-sharing kinds of the glass averages prepare their search points",
          "[dielectric][glass-rule]") {
  // The entering pair and the exit side's E_avg_T (by reciprocity from the entering columns)
  // batch; the exit side's E_avg_R walks each point's own panels (mu_c moves with eta').
  CHECK(Describe(Quantity::DielectricAlbedoRAvg).prepareSearch != nullptr);
  CHECK(Describe(Quantity::DielectricAlbedoTAvg).prepareSearch != nullptr);
  CHECK(Describe(Quantity::DielectricAlbedoTExitAvg).prepareSearch != nullptr);
}

TEST_CASE("the exit E_avg_R table's search reads the bake's rule, one kernel per roughness",
          "[dielectric][glass-rule]") {
  // A point of the kernel route costs one kernel row alone, and the search's points of one
  // roughness share it: no cheaper search form.
  const QuantityInfo& q = Describe(Quantity::DielectricAlbedoRExitAvg);
  CHECK(q.searchRule == nullptr);
  const TableSpec spec = q.makeSpec("ggx-dielectric", q.defaultAxes("ggx-dielectric"));
  const double x[2] = {0.4321, 0.6543};  // roughness, eta'
  IntegrationStats bakeStats, searchStats;
  const std::vector<double> bake = EvaluateSpec(spec, x, bakeStats);
  const std::vector<double> search = SearchReference(spec, x, searchStats);
  REQUIRE(search.size() == 1);
  CHECK(SameBits(search[0], bake[0]));
  CHECK(searchStats.evals == bakeStats.evals);
}
