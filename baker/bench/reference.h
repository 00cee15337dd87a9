// What the benchmark measures every table against: kiln's integrator at a tighter tolerance
// (default 1e-10), in double, at every node and at a fixed set of lookup points.
//
// Bake error: stored texel (float32) against the reference at the same node. Lookup error: a
// LutView::sample (linear or cubic) against the reference at a point between the nodes. Both are
// the max over channels per texel or point; a table's figures are the max and the rms of those.
// Lookup points (DESIGN.md "What accurate means"): cell centres in texel space, where
// interpolation errs most (a fixed even-stride subsample when a table has more cells than
// maxCellCentres), and fixed-seed uniform random points in texel space.
// Corner: in a table over mu, the points in the first cell of its second axis or of an eta axis.
// There (mu -> 0, roughness -> 0) and (mu -> 0, eta -> 1) are path-dependent limits
// (E ~ g(mu / alpha), F ~ g(mu / sqrt(eta - 1))) that no tensor grid interpolates, so the
// lookup error is also reported without them (as baker/bake/lookup_error.h does).
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"
#include "kiln/table.h"

namespace kiln {

struct ReferenceOptions {
  double tol = 1e-10;         ///< integration tolerance of the reference values
  int maxCellCentres = 4096;  ///< cell centres beyond this are subsampled (even stride)
  int randomPoints = 1000;    ///< fixed-seed random points in texel space
  int threads = 0;            ///< 0: all cores
};

/// The reference values of one table spec (one set of axes).
struct Reference {
  std::vector<double> nodes;        ///< channel-interleaved, in the LutView texel order
  std::vector<double> points;       ///< dims coordinates per lookup point (axis units)
  std::vector<double> pointValues;  ///< channels per lookup point
  std::vector<char> inCorner;       ///< per lookup point: inside the corner (see above)
  std::vector<Axis> axes;           ///< the spec's axes (node positions)
  size_t dims = 0, channels = 0;
  size_t cellCentres = 0, totalCells = 0, randomPoints = 0;
  double seconds = 0;   ///< wall time to compute it
  long long evals = 0;  ///< integrand evaluations
  size_t PointCount() const { return dims ? points.size() / dims : 0; }
};

/// Computes the reference of `spec` with oneTBB (one task per node or point).
Reference ComputeReference(const TableSpec& spec, const ReferenceOptions& opt);

struct ErrorStats {
  double max = 0, rms = 0;
  double maxOffCorner = 0;      ///< LookupError: max over the points outside the corner
  std::vector<double> worstAt;  ///< the node or point (axis units) where the max was found
};

/// Texels of `table` (same axes as the reference) against the reference nodes.
ErrorStats BakeError(const Table& table, const Reference& ref);

/// Lookups of `table` with `filter` at the reference's points.
ErrorStats LookupError(const Table& table, const Reference& ref, Filter filter);

/// The parameter value at a fractional node index s in [0, N - 1]: the inverse of Axis::texel.
double AxisValueAtTexel(const Axis& axis, double s);

}  // namespace kiln
