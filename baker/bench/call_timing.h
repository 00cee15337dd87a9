// Runtime cost per call: a table lookup (LutView::sample) against evaluating the model
// (Evaluate) and against integrating it directly (DirectionalAlbedo). Each figure is the median
// over `batches` batches of ns per call in the thread's CPU time, on one thread, over fixed-seed
// inputs (4096 lookup points or direction pairs, cycled, so the inputs stay in cache the way a
// shader's would).
#pragma once
#include "baker/fit/fit_form.h"
#include "baker/models/registry.h"
#include "kiln/table.h"

namespace kiln {

struct CallTiming {
  double nsPerCall = 0;        ///< median over the batches
  double seconds = 0;          ///< wall time of all batches
  long long calls = 0;         ///< calls per batch
  long long evalsPerCall = 0;  ///< integrand evaluations per call (direct integration only)
};

/// How a lookup timing calls the runtime.
enum class LookupCall {
  View,     ///< LutView::sample per point (prepares a LutSampler every call)
  Sampler,  ///< one LutSampler, LutSampler::sample per point
  Batch     ///< one LutSampler, the batch call over the 4096 points at once
};

/// `calls` lookups per batch at random points inside the table's axis ranges.
CallTiming TimeLookups(const Table& table, Filter filter, long long calls, int batches,
                       LookupCall how = LookupCall::View);

/// The side of the plain bilinear table of TimePlainBilinear.
constexpr int kPlainTableSize = 128;

/// `calls` lookups per batch in a plain bilinear table, the way Cycles' lookup_table_read_2D
/// reads its tables: kPlainTableSize^2 texels of two float channels (RG), x linear in mu, y
/// linear in sqrt(roughness), float arithmetic, clamp to edge, no warp and no validation. The
/// floor a table lookup is measured against (random mu and roughness in [0, 1]).
CallTiming TimePlainBilinear(long long calls, int batches);

/// `calls` lookups per batch in a plain trilinear table of n0 x n1 x n2 texels of `channels`
/// interleaved float channels: x linear in mu, y linear in sqrt(roughness), z linear, float
/// arithmetic, clamp to edge, no warp and no validation. The floor a 3D table lookup of the
/// same size is measured against (random coordinates in [0, 1]).
CallTiming TimePlainTrilinear(int n0, int n1, int n2, int channels, long long calls, int batches);

/// `calls` evaluations per batch of a closed-form fit (fit/fit_form.h EvaluateFit, the float
/// arithmetic of the emitted code) at random points inside its axes.
CallTiming TimeFit(const FitForm& form, long long calls, int batches);

/// `calls` evaluations of f(wo, wi) per batch, wo and wi uniform in (mu, phi) above the horizon.
CallTiming TimeEvaluate(const AnyModel& model, long long calls, int batches);

/// `calls` directional albedos per batch at mu spread over (0, 1], to tolerance tol.
CallTiming TimeDirectionalAlbedo(const AnyModel& model, double tol, long long calls, int batches);

}  // namespace kiln
