// `kiln fit`: a closed form of a table's exact integrals (fit_form.h), fitted by weighted least
// squares with Lawson's minimax reweighting on Chebyshev samples of the exact integral in warped
// axes, and its max error over the table's whole declared domain found by a search against the
// exact integrals (EvaluateSpec: kiln's integrators, never the table's interpolation).
// Deterministic: the samples are evaluated in parallel into fixed slots, everything else runs
// in one thread, so any thread count gives the same coefficients.
#pragma once
#include <string>
#include <vector>

#include "baker/fit/fit_form.h"
#include "baker/tables/spec.h"

namespace kiln {

/// The roughness of kiln's smallest alpha (1e-12 = r^2): a microfacet lobe's grazing layer
/// keeps this width below it, and jumps to the mirror at roughness exactly 0 for mu below about
/// kLayerJumpMu. No continuous form follows that jump; a fit's report gives its max error off it
/// (FitErrorReport::maxOffJump) besides the max over the whole domain.
constexpr double kLayerRoughnessFloor = 1e-6;
constexpr double kLayerJumpMu = 1e-9;

/// The dielectric Fresnel's counterpart (a (mu, eta) table, the LayerEta warp): at eta exactly 1
/// there is no interface and F = 0 for mu > 0, while at the next float, kEtaLayerFloor =
/// 1 + 2^-23, a grazing layer of width sqrt(eta^2 - 1) = 4.88e-4 remains, where F rises to 1.
/// A LayerEta fit samples eta at or above kEtaLayerFloor (the float axis has nothing between),
/// and its max off the jump leaves out eta = 1 with mu < kEtaJumpMu (beyond it the layer's F at
/// 1 + 2^-23 is below 1e-5).
constexpr double kEtaLayerFloor = 1.0 + 1.0 / 8388608.0;
constexpr double kEtaJumpMu = 0.02;

/// What `kiln fit` asks for: a bound (the smallest form meeting it) or a number of terms.
struct FitOptions {
  /// > 0: the cheapest form (fewest operations) whose searched max off the mirror's jump
  /// (FitErrorReport::maxOffJump) is at most this.
  double maxError = 0;
  int terms = 0;    ///< > 0: the best form with at most this many coefficients per channel
  int threads = 0;  ///< 0: all cores
};

/// The result of the max-error search of a fit.
struct FitErrorReport {
  double max = 0;     ///< largest |fit - exact| found, over channels
  double median = 0;  ///< median over the search grid's points of the max over channels
  /// The max off the jump of a (mu, roughness) table: points with roughness exactly 0 and
  /// mu < kLayerJumpMu left out (equal to max for other tables).
  double maxOffJump = 0;
  std::vector<double> where;  ///< axis values of the worst point
  long long points = 0;       ///< exact evaluations
};

/// One fitted table.
struct FitResult {
  FitForm form;
  FitErrorReport error;
  std::string specHash;  ///< TableSpec::Hash() of the table fitted
};

/// The form's skeleton for `spec`: its name, channels and axes (domain), degrees 0, no warp.
FitForm Skeleton(const TableSpec& spec);

/// The table kinds kiln fits: a table of one or two axes with every channel an integral.
bool Fittable(const TableSpec& spec);

/// Fits `spec` (one or two axes). Throws std::invalid_argument when the table is not fittable
/// or no form up to the largest degree meets opt.maxError (naming the best max found).
FitResult FitTable(const TableSpec& spec, const FitOptions& opt);

/// The max error of `form` against the exact integrals of `spec` over its whole declared
/// domain: a grid uniform in the fit's warped coordinates (edges included), fixed-seed random
/// points, then a pattern search climbing from each of the worst points. `f` evaluates the
/// closed form (the fit's own float evaluation, or the emitted header compiled).
using FitEvaluator = void (*)(const FitForm& form, const float* x, float* out);
FitErrorReport MeasureFitError(const TableSpec& spec, const FitForm& form, int threads,
                               FitEvaluator f = EvaluateFit);

}  // namespace kiln
