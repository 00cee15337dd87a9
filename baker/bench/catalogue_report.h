// kiln bench --catalogue: every table of the default catalogue baked as `kiln bake` bakes it
// (texels only, no lookup-error check), with what it cost and how far its stored texels are from
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
  std::vector<std::string> only;  ///< table names; empty: the whole default catalogue
};

/// One table of the report.
struct CatalogueBenchRow {
  std::string table;
  std::string method;  ///< "fixed rule", "adaptive" or "closed form"
  long long texels = 0;
  double seconds = 0;           ///< wall time of the texels (BakeStats::seconds)
  double evalsPerTexel = 0;     ///< integrand evaluations per texel
  double declared = 0;          ///< the table's declared bake error (kiln.bake_error)
  double sampledError = 0;      ///< max over the sampled texels and channels of
                                ///< |float32 texel - reference| / max(1, |reference|)
  int sampled = 0;              ///< texels re-integrated
  double referenceSeconds = 0;  ///< wall time of those references
};

/// The sampled texel indices of a table of n texels: k (n - 1) / (samples - 1), k = 0..samples-1
/// (both ends included; fewer when n is smaller).
std::vector<size_t> SampledTexels(size_t n, int samples);

/// Bakes and checks every table of `opt.only` (or the default catalogue), in catalogue order,
/// printing one line per table to `log` (when not null) and a total. Throws
/// std::invalid_argument("unknown table '...'") for a name the catalogue lacks.
std::vector<CatalogueBenchRow> RunCatalogueBench(const CatalogueBenchOptions& opt, std::FILE* log);

/// The rows as CSV: table, method, texels, seconds, evals_per_texel, declared_bake_error,
/// sampled_bake_error, sampled_texels, reference_seconds.
std::string CatalogueCsv(const std::vector<CatalogueBenchRow>& rows);

}  // namespace kiln
