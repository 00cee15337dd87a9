// One benchmark measurement and the CSV it becomes (bench/bench.csv).
//
// Sections: "sweep" (error against time per method at the table's base size), "size" (lookup
// error against table size and bytes), "threads" (the same bake on 1 and on all threads),
// "baker-issue" (kiln bake of ggx-dfg at 128 x 128 against 1024-sample Monte Carlo: kiln texels,
// the whole command, texels + EXR write; Monte Carlo, + EXR write, sampled per texel),
// "runtime" (ns per call of a lookup, a model evaluation, a direct integration).
// Errors are absolute, max over channels; NaN (an empty CSV field) where not measured.
#pragma once
#include <cmath>
#include <string>
#include <vector>

namespace kiln {

struct BenchRow {
  std::string section;
  std::string method;  ///< kiln, mc-hammersley, gauss-legendre, lookup-linear, evaluate, ...
  std::string table;   ///< table name (or model id for the runtime's evaluate/integrate rows)
  int dims = 0;
  std::string size;  ///< "64x64", "32x32x16"
  long long texels = 0;
  double setting = NAN;  ///< kiln: tolerance; Monte Carlo and Gauss-Legendre: samples per texel
  int threads = 0;
  double seconds = NAN;  ///< wall time, median of `runs` runs
  int runs = 0;
  long long evals = 0;  ///< integrand evaluations (per call for the runtime rows)
  double bakeMax = NAN, bakeRms = NAN;
  double linearMax = NAN, linearRms = NAN, cubicMax = NAN, cubicRms = NAN;
  double linearMaxOffCorner = NAN;  ///< linear max without the corner cells (reference.h)
  long long bytes = 0;              ///< float32 texels
  double nsPerCall = NAN;
  std::string note;
};

/// The CSV column names, in order.
const std::vector<std::string>& CsvColumns();

/// The CSV text: a header line and one line per row (fields quoted when they hold ',' or '"').
std::string CsvText(const std::vector<BenchRow>& rows);

}  // namespace kiln
