// Runtime cost per call: a table lookup (LutView::sample) against evaluating the model
// (Evaluate) and against integrating it directly (DirectionalAlbedo). Each figure is the median
// over `batches` batches of ns per call, on one thread, over fixed-seed inputs (4096 lookup
// points or direction pairs, cycled, so the inputs stay in cache the way a shader's would).
#pragma once
#include "baker/models/registry.h"
#include "kiln/table.h"

namespace kiln {

struct CallTiming {
  double nsPerCall = 0;        ///< median over the batches
  double seconds = 0;          ///< wall time of all batches
  long long calls = 0;         ///< calls per batch
  long long evalsPerCall = 0;  ///< integrand evaluations per call (direct integration only)
};

/// `calls` lookups per batch at random points inside the table's axis ranges.
CallTiming TimeLookups(const Table& table, Filter filter, long long calls, int batches);

/// `calls` evaluations of f(wo, wi) per batch, wo and wi uniform in (mu, phi) above the horizon.
CallTiming TimeEvaluate(const AnyModel& model, long long calls, int batches);

/// `calls` directional albedos per batch at mu spread over (0, 1], to tolerance tol.
CallTiming TimeDirectionalAlbedo(const AnyModel& model, double tol, long long calls, int batches);

}  // namespace kiln
