// The bench's Monte Carlo tables (`kiln bench`): a whole table baked by a table kind's Monte
// Carlo estimator (quantities/monte_carlo.h), the way the peers bake theirs.
#pragma once
#include <string>

#include "baker/bake/bake.h"
#include "baker/quantities/monte_carlo.h"
#include "baker/tables/spec.h"

namespace kiln {

/// Bakes `spec`'s texels (the same nodes, layout and metadata as BakeTable, no lookup-error
/// check) with the estimator over `points`, on `threads` threads (0: all cores) with oneTBB, one
/// task per row. `method` names the estimator in the table's kiln.method. stats->evals counts
/// integrand evaluations (texels x points). Throws std::invalid_argument if !EstimatorSupports.
Table EstimateTable(const TableSpec& spec, const PointSet& points, const std::string& method,
                    int threads, BakeStats* stats = nullptr);

/// The same GGX DFG estimate as EstimateTable with n Hammersley points, written the way engine
/// tools usually write it (Filament's libs/ibl DFV, the UE4 and LearnOpenGL listings): every
/// texel draws its own points and half vectors (radical inverse, cos/sin of the azimuth, the GGX
/// inversion) inside its sample loop, nothing shared between texels. The same sums in double, so
/// the texels agree with EstimateTable's to rounding. Quantity dfg of ggx only (else throws
/// std::invalid_argument); oneTBB over rows on `threads` threads.
Table EstimateDFGTablePerTexel(const TableSpec& spec, int n, int threads,
                               BakeStats* stats = nullptr);

}  // namespace kiln
