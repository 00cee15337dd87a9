// A climb with threads to spare evaluates the golden section's next point ahead on them
// (bake/lookup_error.cpp, ClimbCell): it must climb exactly as the serial climb does (the same
// points counted, the same worst point, the same report and the same recorded references) for
// any thread count.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "baker/bake/lookup_error.h"
#include "test_bake_cache.h"

using namespace kiln;

namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The search of `spec` with `budget` at 1 thread (no climb evaluates ahead), and at 2 and 4
/// (a chunk of fewer climbs than threads does): every field of the report to the bit.
void CheckSameForAnyThreads(const TableSpec& spec, long long budget) {
  BakeOptions texelsOnly;
  texelsOnly.measureLookupError = false;
  texelsOnly.threads = 2;
  const Table& table = test::CachedBake(spec, texelsOnly);
  LookupSearchOptions opt;
  opt.budget = budget;
  opt.alsoCubic = true;
  opt.threads = 1;
  SearchMemo serialMemo;
  opt.record = &serialMemo;
  const LookupErrorReport serial = MeasureLookupError(spec, table.view(), opt);
  REQUIRE(serial.climbed > 0);
  for (int threads : {2, 4}) {
    INFO(spec.name << " at " << threads << " threads");
    opt.threads = threads;
    SearchMemo memo;
    opt.record = &memo;
    const LookupErrorReport r = MeasureLookupError(spec, table.view(), opt);
    CHECK(r.points == serial.points);
    CHECK(r.climbed == serial.climbed);
    CHECK(r.cells == serial.cells);
    CHECK(SameBits(r.max, serial.max));
    CHECK(SameBits(r.rms, serial.rms));
    CHECK(SameBits(r.cubicMax, serial.cubicMax));
    CHECK(SameBits(r.maxOutsideCorner, serial.maxOutsideCorner));
    CHECK(SameBits(r.referenceError, serial.referenceError));
    CHECK(r.where == serial.where);
    CHECK(memo.size() == serialMemo.size());
  }
}

}  // namespace

TEST_CASE("A climb that evaluates ahead climbs as the serial climb does",
          "[lookup][search][speculative-climb]") {
  // A closed form, a fixed rule with a search form, and glass averages whose points are whole
  // mu integrals spread over the threads (their one climb runs alone once the budget is spent).
  CheckSameForAnyThreads(test::SmallSpec(Quantity::FresnelConductor, "none", 6), 3000);
  CheckSameForAnyThreads(test::SmallSpec(Quantity::Dfg, "beckmann", 9), 900);
  CheckSameForAnyThreads(test::SmallSpec(Quantity::DielectricAlbedoRAvg, "ggx-dielectric", 6), 120);
  // Its kernel-route exit side, whose points spread over the threads (QuantityInfo::parallelPoint):
  // its lone climb takes the threads, no point ahead.
  CheckSameForAnyThreads(test::SmallSpec(Quantity::DielectricAlbedoRExitAvg, "ggx-dielectric", 6),
                         120);
}
