// The lookup error of a table: interpolated value against the exact integral, measured at every
// cell centre (where multilinear interpolation errs most) and at fixed-seed random points.
#pragma once
#include <string>

#include "baker/tables/spec.h"
#include "kiln/lut.h"

namespace kiln {

struct LookupErrorReport {
  double max = 0, rms = 0;
  /// Max outside the first cell of the second axis (roughness < r_1 or eta < eta_1) of a table
  /// over mu: there (mu -> 0, roughness -> 0) or (mu -> 0, eta -> 1) is a path-dependent limit
  /// (E ~ g(mu / alpha), F ~ g(mu / sqrt(eta - 1))) that no tensor grid interpolates
  /// (README "Lookup error"). Equal to max for other tables.
  double maxOutsideCorner = 0;
  std::vector<double> where;            ///< the parameter values of the worst point, axis order
  double cubicMax = -1, cubicRms = -1;  ///< with the cubic filter at the same points (alsoCubic)
  long long points = 0;
  std::string WhereText(const TableSpec& spec) const;  ///< "mu=0.0001 roughness=0.01"
};

/// Measures |view.sample(x, filter) - EvaluateSpec(spec, x, refTol)| (max over channels) at every
/// cell centre and `randomPoints` random points (uniform in texel space, fixed seed), with oneTBB;
/// refTol = 0 takes the table's own bake method (EvaluateSpec(spec, x)) as the reference.
/// Deterministic: same result for any thread count. maxCells > 0 checks only that many cell
/// centres, evenly strided (a quick check of a large or costly table). alsoCubic also samples
/// every point with the cubic filter (cubicMax, cubicRms), for the cost of the lookups only.
LookupErrorReport MeasureLookupError(const TableSpec& spec, const LutView& view,
                                     long long randomPoints, double refTol, int threads,
                                     Filter filter = Filter::Linear, long long maxCells = 0,
                                     bool alsoCubic = false);

/// The bound a baked table declares: the measured max times this margin (random points between
/// the measured ones can exceed it slightly; kiln verify checks with 100x more points).
constexpr double kDeclaredBoundMargin = 1.5;

}  // namespace kiln
