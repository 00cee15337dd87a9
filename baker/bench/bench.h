// kiln bench: bake time against bake and lookup error for kiln's integrator and for the methods
// peers use (Monte Carlo over Hammersley points with importance sampling, and the same
// estimator over a fixed Gauss-Legendre product rule), on the same texels of the same tables.
//
// Every error is measured against a reference (kiln at tol 1e-10, in double; see reference.h),
// computed once per table and size. Wall times are the median of 5 runs below 0.25 s, of 3 below
// 1 s, else of one. Writes DIR/bench.csv (bench_csv.h) and DIR/bench.svg.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "baker/bench/bench_csv.h"

namespace kiln {

/// Full: the measured README run (under ten minutes on 2 cores). Quick: the CI smoke run (under
/// a minute). Tiny: a few seconds, every section with tiny tables (the tests).
enum class BenchScale { Tiny, Quick, Full };

struct BenchOptions {
  BenchScale scale = BenchScale::Full;
  std::string outDir = "bench";
  int threads = 0;  ///< bakes and references; 0: all cores
};

struct BenchResult {
  std::vector<BenchRow> rows;
  std::vector<std::string> summary;  ///< the conclusions, one line each
  double seconds = 0;                ///< wall time of the whole run
};

/// Runs the benchmark, printing one line per row (and the summary) to `log` when it is not null,
/// and writes DIR/bench.csv and DIR/bench.svg (DIR is created when missing).
BenchResult RunBench(const BenchOptions& opt, std::FILE* log);

/// The plot of a run's rows: per table kind, max bake error against bake time for each method
/// with the Pareto front marked (top row), max lookup error against table bytes (bottom row).
std::string BenchSvg(const std::vector<BenchRow>& rows);

/// The conclusions of a run's rows, one line each: per table kind, what 1024-sample Monte Carlo
/// reaches and the time kiln needs for the same error; the baker issue's 128 x 128 comparison;
/// thread scaling; lookup against evaluation and integration cost.
std::vector<std::string> BenchSummary(const std::vector<BenchRow>& rows);

}  // namespace kiln
