// The error atlas's table approximations (docs/atlas/tables.md): closed forms and small tables
// engines ship in place of one of kiln's tables, each measured against the exact integrals of
// the kiln table it stands for, by the fit search (fit.h MeasureFitError: a grid uniform in the
// probe warps, edges included, fixed-seed random points, climbs from the worst), plus a plain
// (mu, roughness) grid for its CSV and PNG.
#pragma once
#include <string>
#include <vector>

#include "baker/atlas/atlas.h"
#include "baker/fit/fit.h"

namespace kiln {

/// One approximation: `table` the catalogue table it stands for (its channels and axes
/// (mu, roughness)), `eval` the approximation in float (engine_approximations.h), the warps of
/// the search's probe grid, and words for the README.
struct TableApproximation {
  std::string name;    ///< file names: <name>.csv, <name>.png
  std::string label;   ///< what engines call it
  std::string source;  ///< engine, publication, file, licence
  std::string table;   ///< kiln catalogue table
  FitEvaluator eval = nullptr;
  FitWarp muWarp = FitWarp::Sqrt, roughnessWarp = FitWarp::Sqrt;
  std::string note;  ///< what is compared and how (mappings, clamps, which visibility)
};

/// The lower end of mu of the atlas's second search: at mu_o >= 1/4, Neubelt's visibility
/// 1 / (4 (mu_o + mu_l - mu_o mu_l)) is at most 1 for every light, so three.js's saturate of it
/// never acts and its sheen lobe is kiln's `charlie`; for the other tables, the max off grazing.
constexpr double kTableApproxOffGrazingMu = 0.25;

/// Every table approximation of the atlas, one entry each (baker/atlas/atlas_tables.cpp).
const std::vector<TableApproximation>& TableApproximations();

/// The measurement of one approximation: the search's report and the CSV grid, mu fastest
/// (mu = j / (nMu - 1), roughness from the table's lo to hi, both ends included), exact and
/// approximate channels per point.
struct TableApproximationResult {
  TableApproximation approx;
  std::vector<std::string> channels;
  FitErrorReport report;
  /// The same search over mu >= kTableApproxOffGrazingMu only.
  FitErrorReport offGrazing;
  int nMu = 0, nR = 0;
  std::vector<double> mu, roughness;       ///< per grid point
  std::vector<double> exact, approximate;  ///< per grid point, channels.size() each
  std::string method;                      ///< the exact integrals' method
};

/// Measures `approx` against the exact integrals of its table (opt.muNodes x opt.roughnessNodes
/// grid, opt.threads): the same values for any thread count. Throws std::invalid_argument for
/// an unknown table or one that is not (mu, roughness).
TableApproximationResult ComputeTableApproximation(const TableApproximation& approx,
                                                   const AtlasOptions& opt);

/// The CSV: mu,roughness, then exact_<channel>... , approx_<channel>..., max_abs_err; %.9g.
std::string TableApproximationCsv(const TableApproximationResult& result);

/// The PNG: per channel a heatmap of approx - exact over (mu, roughness), then the max abs error
/// over the channels (log10 where it spans more than three decades).
std::string TableApproximationPng(const TableApproximationResult& result);

/// docs/atlas/tables.md: per approximation its table, max, median and where the max is, the
/// notes, and `command`, the command that regenerated it.
std::string TableApproximationsReadme(const std::vector<TableApproximationResult>& results,
                                      const AtlasOptions& opt, const std::string& command);

}  // namespace kiln
