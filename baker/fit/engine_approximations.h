// Closed forms engines ship in place of the split-sum DFG table, measured against kiln's exact
// integrals by the fit search (fit.h MeasureFitError) like kiln's own fits (docs/fits.md
// "Engine approximations"). Each is written here from its published formula (facts, not code).
#pragma once
#include "baker/fit/fit.h"

namespace kiln {

/// Karis 2014, "Physically Based Shading on Mobile" (Unreal Engine 4's EnvBRDFApprox, three.js's
/// former DFGApprox): (A, B) of GGX at x = (mu, roughness), roughness the perceptual one
/// (alpha = roughness^2), in float:
///   r = roughness (-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04),
///   a = min(r.x^2, 2^(-9.28 mu)) r.x + r.y,  (A, B) = (-1.04 a + r.z, 1.04 a + r.w).
/// `form` is ignored (the FitEvaluator signature).
void KarisEnvBrdfApprox(const FitForm& form, const float* x, float* out);

/// The measuring form of the (mu, roughness) DFG table `spec` for an approximation: the axes
/// with the warps the search grid is uniform in (layer mu, sqrt roughness), so the grazing,
/// low-roughness corner is probed as densely as kiln's own fits.
FitForm DfgProbeForm(const TableSpec& spec);

}  // namespace kiln
