// kiln bench --catalogue: every table of the default catalogue baked as `kiln bake` bakes it
// (texels and their lookup-error search), with what each cost, a row per table kind, the total
// as a multiple of a yardstick measured in the same run, and how far the stored texels are from
// adaptive quadrature at a tight tolerance at sampled texels.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

struct CatalogueBenchOptions {
  int threads = 2;                ///< bake threads (the reference runs on the same number)
  int samples = 6;                ///< texels re-integrated per table, spread over its index range
  double refTol = 1e-10;          ///< tolerance of the adaptive reference
  bool reference = true;          ///< re-integrate the sampled texels (false: sampled = 0)
  bool lookupError = true;        ///< run each table's lookup-error search, as `kiln bake` does
  int yardstickRuns = 3;          ///< runs of the yardstick (0: none, the multiples are 0)
  std::vector<std::string> only;  ///< table names; empty: the whole default catalogue
};

/// One table of the report.
struct CatalogueBenchRow {
  std::string table;
  std::string kind;    ///< its table kind (QuantityName)
  std::string method;  ///< "fixed rule", "adaptive", "closed form" or "derived"
  long long texels = 0;
  double seconds = 0;           ///< wall time of the texels (BakeStats::seconds)
  double evalsPerTexel = 0;     ///< integrand evaluations per texel
  double searchSeconds = 0;     ///< wall time of the lookup-error search (BakeStats)
  long long searchPoints = 0;   ///< its reference evaluations (0: shared with its source)
  double declared = 0;          ///< the table's declared bake error (kiln.bake_error)
  double sampledError = 0;      ///< max over the sampled texels and channels of
                                ///< |float32 texel - reference| / max(1, |reference|)
  int sampled = 0;              ///< texels re-integrated
  double referenceSeconds = 0;  ///< wall time of those references
};

/// The tables of one kind summed (or of the whole catalogue: kind "total").
struct CatalogueKindRow {
  std::string kind;
  int tables = 0;
  long long texels = 0, searchPoints = 0;
  double seconds = 0, searchSeconds = 0;  ///< texels, searches (sums of the tables' wall times)
  double TexelsPerSecond() const { return seconds > 0 ? texels / seconds : 0; }
  double SearchesPerSecond() const { return searchSeconds > 0 ? searchPoints / searchSeconds : 0; }
  /// (seconds + searchSeconds) / yardstick, 0 without a yardstick.
  double Times(double yardstick) const {
    return yardstick > 0 ? (seconds + searchSeconds) / yardstick : 0;
  }
};

/// What the yardstick is: the per-texel Monte Carlo DFG bake engine tools ship
/// (EstimateDFGTablePerTexel: 1024 Hammersley samples per texel of a 128 x 128 GGX DFG), on the
/// bench's threads.
constexpr const char* kCatalogueYardstick = "1024-sample Monte Carlo of one 128 x 128 GGX DFG";

/// A run: its tables in catalogue order, its kinds in order of first appearance, the total, and
/// the yardstick's median wall time over its runs (spread before, between and after the tables).
struct CatalogueBenchResult {
  std::vector<CatalogueBenchRow> rows;
  std::vector<CatalogueKindRow> kinds;
  CatalogueKindRow total;
  double yardstickSeconds = 0;
  std::vector<double> yardstickRuns;  ///< each run's wall time, in the order they ran
};

/// The sampled texel indices of a table of n texels: k (n - 1) / (samples - 1), k = 0..samples-1
/// (both ends included; fewer when n is smaller).
std::vector<size_t> SampledTexels(size_t n, int samples);

/// Wall seconds of one run of the yardstick (kCatalogueYardstick) on `threads` threads.
double RunCatalogueYardstick(int threads);

/// The kind rows of `rows` (in order of each kind's first table) and their total.
void SumCatalogueKinds(const std::vector<CatalogueBenchRow>& rows,
                       std::vector<CatalogueKindRow>& kinds, CatalogueKindRow& total);

/// Bakes and checks every table of `opt.only` (or the default catalogue), in catalogue order,
/// printing one line per table to `log` (when not null), then the yardstick, a line per kind and
/// the total. Throws std::invalid_argument("unknown table '...'") for a name the catalogue lacks.
CatalogueBenchResult RunCatalogueBench(const CatalogueBenchOptions& opt, std::FILE* log);

/// The run as CSV, one row per line; column `row` says what the line is: "table" (per table),
/// "kind" (per table kind), "total" (the catalogue or the --only tables) or "yardstick". Columns:
/// row, name, method, texels, seconds, evals_per_texel, search_points, search_seconds,
/// texels_per_second, searches_per_second, x_yardstick, declared_bake_error, sampled_bake_error,
/// sampled_texels, reference_seconds (empty where they do not apply).
std::string CatalogueCsv(const CatalogueBenchResult& run);

}  // namespace kiln
