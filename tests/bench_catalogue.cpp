// kiln bench --catalogue: each table's stored texels against the adaptive reference, for the
// channels that are integrals (a fitted table's coefficients have no reference).
#include <catch2/catch.hpp>

#include "baker/bench/catalogue_report.h"

using namespace kiln;

TEST_CASE(
    "The catalogue bench compares a fitted table's integral channels only: ltc-ggx's norm and "
    "Fresnel are within its declared bake error, as a DFG table's channels are",
    "[bench][ltc]") {
  CatalogueBenchOptions opt;
  opt.threads = 2;
  opt.samples = 3;
  opt.only = {"ltc-ggx", "ggx-dfg"};
  std::vector<CatalogueBenchRow> rows = RunCatalogueBench(opt, nullptr);
  REQUIRE(rows.size() == 2);
  for (const CatalogueBenchRow& r : rows) {
    INFO(r.table << ": sampled " << r.sampledError << ", declared " << r.declared);
    CHECK(r.sampled == 3);
    CHECK(r.sampledError < 1e-6);
    CHECK(r.sampledError <= r.declared);
  }
  CHECK_THROWS_WITH(
      [] {
        CatalogueBenchOptions bad;
        bad.only = {"no-such-table"};
        RunCatalogueBench(bad, nullptr);
      }(),
      Catch::Contains("unknown table"));
}
