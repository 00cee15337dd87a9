// The search's cell ranking (bake/lookup_error.h, CellErrorEstimates) runs in parallel and the
// search orders only the cells its budget can reach: the same estimates for any thread count,
// and the same report for any thread count on a table of more cells than the budget probes.
#include <catch2/catch.hpp>

#include <tbb/task_arena.h>

#include <cstring>
#include <vector>

#include "baker/bake/lookup_error.h"
#include "test_bake_cache.h"

using namespace kiln;

TEST_CASE("The cells' error estimates are the same for any thread count",
          "[lookup][search][cell-order]") {
  BakeOptions texelsOnly;
  texelsOnly.measureLookupError = false;
  texelsOnly.threads = 2;
  // A 3D table (mu, roughness, eta) and a 2D one with two channels.
  for (const TableSpec& spec : {test::SmallSpec(Quantity::FresnelConductor, "none", 17),
                                test::SmallSpec(Quantity::Dfg, "ggx", 65)}) {
    INFO(spec.name);
    const Table& table = test::CachedBake(spec, texelsOnly);
    std::vector<double> one, four;
    tbb::task_arena(1).execute([&] { one = CellErrorEstimates(table.view()); });
    tbb::task_arena(4).execute([&] { four = CellErrorEstimates(table.view()); });
    REQUIRE(one.size() == four.size());
    CHECK(std::memcmp(one.data(), four.data(), one.size() * sizeof(double)) == 0);
    // Every cell has an estimate, and the curved table shows some.
    double largest = 0;
    for (double e : one) largest = std::max(largest, e);
    CHECK(largest > 0);
  }
}

TEST_CASE("A search that reaches few of a table's cells reports the same for any thread count",
          "[lookup][search][cell-order]") {
  BakeOptions texelsOnly;
  texelsOnly.measureLookupError = false;
  texelsOnly.threads = 2;
  // 16^3 = 4096 cells (more than the centre sweep's 1024), 300 points: at most 20 cells probed.
  const TableSpec spec = test::SmallSpec(Quantity::FresnelConductor, "none", 17);
  const Table& table = test::CachedBake(spec, texelsOnly);
  LookupSearchOptions opt;
  opt.budget = 300;
  opt.threads = 1;
  const LookupErrorReport serial = MeasureLookupError(spec, table.view(), opt);
  CHECK(serial.cells > 0);
  CHECK(serial.cells <= (300 + 14) / 15);  // within the budget: ceil(300 / 15 probes)
  CHECK(serial.allCells == 4096);
  opt.threads = 3;
  const LookupErrorReport parallel = MeasureLookupError(spec, table.view(), opt);
  CHECK(parallel.cells == serial.cells);
  CHECK(parallel.points == serial.points);
  CHECK(parallel.max == serial.max);
  CHECK(parallel.where == serial.where);
}
