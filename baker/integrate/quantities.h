// The hemispherical integrals kiln tabulates (docs/models.md "Hemispherical integrals"), for any
// model, deterministic, in double precision, to an absolute tolerance (default 1e-9).
#pragma once
#include <array>

#include "baker/integrate/hemisphere.h"
#include "baker/models/registry.h"

namespace kiln {

/// Directional albedo E(mu_o) = integral f mu_l dl at rho = 1, split in its rho^1 and rho^2
/// parts (E(rho) = rho lin + rho^2 quad). Specular models use their own Fresnel term (F = 1
/// unless the model was built with f0 or eta). mu_o in [0, 1].
RhoParts DirectionalAlbedo(const AnyModel& model, double mu_o, const IntegrationOptions& opt,
                           IntegrationStats& stats);

/// Average albedo E_avg = 2 integral_0^1 E(mu) mu dmu, split like DirectionalAlbedo.
RhoParts AverageAlbedo(const AnyModel& model, const IntegrationOptions& opt,
                       IntegrationStats& stats);

/// Split-sum DFG (Karis 2013) of a specular model with Schlick Fresnel, w = 1 - o.h:
/// A = integral f/F (1 - w^5) mu_l dl, B = integral f/F w^5 mu_l dl, so that the albedo with
/// Schlick F0 (F90 = 1) is F0 A + B. The model's own Fresnel term is replaced by F = 1.
/// Throws std::invalid_argument for a diffuse model.
std::array<double, 2> SplitSumDFG(const AnyModel& model, double mu_o, const IntegrationOptions& opt,
                                  IntegrationStats& stats);

/// Average of the DFG terms, 2 integral_0^1 (A, B)(mu) mu dmu.
std::array<double, 2> AverageSplitSumDFG(const AnyModel& model, const IntegrationOptions& opt,
                                         IntegrationStats& stats);

/// Hemispherical average of a Fresnel term: F_avg = 2 integral_0^1 F(mu) mu dmu.
double FresnelAverage(const Fresnel& fresnel, const IntegrationOptions& opt,
                      IntegrationStats& stats);

}  // namespace kiln
