// kiln bench --catalogue: each table's stored texels against the adaptive reference, for the
// channels that are integrals (a fitted table's coefficients have no reference); the rows per
// table kind and the yardstick that say where a catalogue's time goes. The command line's run
// (its printed rows and its default folder) is tests/cli_bench_folders.cpp.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

#include "baker/bench/catalogue_report.h"
#include "cli_util.h"

using namespace kiln;

TEST_CASE(
    "The catalogue bench compares a fitted table's integral channels only: ltc-ggx's norm and "
    "Fresnel are within its declared bake error, as a DFG table's channels are",
    "[bench][ltc]") {
  CatalogueBenchOptions opt;
  opt.threads = 2;
  opt.samples = 3;
  opt.only = {"ltc-ggx", "ggx-dfg"};
  opt.yardstickRuns = 0;
  std::vector<CatalogueBenchRow> rows = RunCatalogueBench(opt, nullptr).rows;
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

TEST_CASE(
    "The catalogue bench sums texel and search seconds per table kind and states the total as a "
    "multiple of the yardstick timed in the same run",
    "[bench]") {
  CatalogueBenchOptions opt;
  opt.threads = 2;
  opt.reference = false;
  opt.yardstickRuns = 1;
  opt.only = {"ggx-dfg", "burley-albedo", "ggx-albedo", "lambert-albedo"};
  CatalogueBenchResult run = RunCatalogueBench(opt, nullptr);
  REQUIRE(run.rows.size() == 4);
  REQUIRE(run.yardstickRuns.size() == 1);
  CHECK(run.yardstickSeconds == run.yardstickRuns[0]);
  CHECK(run.yardstickSeconds > 0);
  // Kinds in order of their first table; each sums its own tables.
  REQUIRE(run.kinds.size() == 2);
  CHECK(run.kinds[0].kind == "dfg");
  CHECK(run.kinds[0].tables == 1);
  CHECK(run.kinds[1].kind == "albedo");
  CHECK(run.kinds[1].tables == 3);
  double seconds = 0, searchSeconds = 0;
  long long texels = 0, points = 0;
  for (const CatalogueBenchRow& r : run.rows) {
    INFO(r.table);
    CHECK(r.sampled == 0);  // no references asked for
    CHECK(r.searchSeconds >= 0);
    seconds += r.seconds;
    searchSeconds += r.searchSeconds;
    texels += r.texels;
    points += r.searchPoints;
  }
  CHECK(run.rows[0].searchPoints > 0);  // ggx-dfg searched its own lookup error
  CHECK(run.rows[0].searchSeconds > 0);
  CHECK(run.total.tables == 4);
  CHECK(run.total.texels == texels);
  CHECK(run.total.searchPoints == points);
  CHECK(run.total.seconds == Approx(seconds));
  CHECK(run.total.searchSeconds == Approx(searchSeconds));
  CHECK(run.total.Times(run.yardstickSeconds) ==
        Approx((seconds + searchSeconds) / run.yardstickSeconds));
  CHECK(run.kinds[0].TexelsPerSecond() == Approx(run.rows[0].texels / run.rows[0].seconds));
  CHECK(run.kinds[0].SearchesPerSecond() ==
        Approx(run.rows[0].searchPoints / run.rows[0].searchSeconds));

  // The CSV holds every row: tables, kinds, the total and the yardstick.
  std::istringstream csv(CatalogueCsv(run));
  std::string line;
  std::vector<std::string> firsts;
  while (std::getline(csv, line))
    firsts.push_back(line.substr(0, line.find(',', line.find(',') + 1)));
  CHECK(firsts == std::vector<std::string>{"row,name", "table,ggx-dfg", "table,burley-albedo",
                                           "table,ggx-albedo", "table,lambert-albedo", "kind,dfg",
                                           "kind,albedo", "total,total",
                                           std::string("yardstick,") + kCatalogueYardstick});
}

TEST_CASE("The catalogue bench without lookup-error searches times the texels alone", "[bench]") {
  CatalogueBenchOptions opt;
  opt.threads = 2;
  opt.reference = false;
  opt.lookupError = false;
  opt.yardstickRuns = 0;
  opt.only = {"ggx-dfg"};
  CatalogueBenchResult run = RunCatalogueBench(opt, nullptr);
  REQUIRE(run.rows.size() == 1);
  CHECK(run.rows[0].searchSeconds == 0);
  CHECK(run.rows[0].searchPoints == 0);
  CHECK(run.rows[0].seconds > 0);
  CHECK(run.yardstickSeconds == 0);
  CHECK(run.total.Times(run.yardstickSeconds) == 0);
}
