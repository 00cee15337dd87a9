// The glass averages' search points are kept by the process (integrate/dielectric_albedo_avg.h,
// PrepareDielectricAverageColumn): a point one search prepared is not integrated again when
// another search (t-avg after r-avg: both channels come from one walk) prepares it, and the
// search that reads it reports exactly what it reports when it integrates every point itself.
#include <catch2/catch.hpp>

#include <array>
#include <cstring>

#include "baker/bake/lookup_error.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/tables/quantity.h"
#include "test_bake_cache.h"

using namespace kiln;

namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("A prepared glass average point is integrated once per process",
          "[lookup][search][glass-memo]") {
  // A roughness and etas no table's grid or search uses (the memo is the process's).
  const double alpha = 0.3141593;
  const double etas[] = {1.2345, 1.8765, 2.6543};
  std::array<double, 2> alone[3];
  long long evAlone[3];
  for (int e = 0; e < 3; ++e) {
    evAlone[e] = 0;
    alone[e] =
        FixedRuleDielectricAlbedoAverage(alpha, etas[e], kDielectricAverageNodes, &evAlone[e]);
  }
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 2) == 2);
  // Again, and a column holding the two and a new eta: only the new one is integrated.
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 2) == 0);
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3) == 1);
  CHECK(PrepareDielectricAverageColumn(alpha, etas, 3) == 0);
  for (int e = 0; e < 3; ++e) {
    long long ev = 0;
    const std::array<double, 2> got = FixedRuleDielectricAlbedoAverage(alpha, etas[e], &ev);
    CHECK(SameBits(got[0], alone[e][0]));
    CHECK(SameBits(got[1], alone[e][1]));
    CHECK(ev == evAlone[e]);
  }
  CHECK_THROWS_AS(PrepareDielectricAverageColumn(alpha, etas, 0), std::invalid_argument);
}

TEST_CASE("A glass average's search reports the same after another search kept its points",
          "[lookup][search][glass-memo]") {
  // 7 x 7 nodes, a grid no other test searches: the t-avg search first integrates its points
  // itself, then runs again after the r-avg search of the same grid prepared theirs. A budget of
  // 120 (152 points searched): the same points in both searches, each one a column the memo
  // holds.
  const TableSpec r = test::SmallSpec(Quantity::DielectricAlbedoRAvg, "ggx-dielectric", 7);
  const TableSpec t = test::SmallSpec(Quantity::DielectricAlbedoTAvg, "ggx-dielectric", 7);
  BakeOptions texelsOnly;
  texelsOnly.measureLookupError = false;
  texelsOnly.threads = 2;
  const Table& tTable = test::CachedBake(t, texelsOnly);
  LookupSearchOptions opt;
  opt.budget = 120;
  opt.threads = 2;
  const LookupErrorReport first = MeasureLookupError(t, tTable.view(), opt);
  MeasureLookupError(r, test::CachedBake(r, texelsOnly).view(), opt);
  const LookupErrorReport again = MeasureLookupError(t, tTable.view(), opt);
  CHECK(again.points == first.points);
  CHECK(SameBits(again.max, first.max));
  CHECK(SameBits(again.rms, first.rms));
  CHECK(again.where == first.where);
}
