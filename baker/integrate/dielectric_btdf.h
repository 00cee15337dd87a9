// The split-sum pair of the rough dielectric's transmission (models/dielectric_bsdf.h: GGX,
// height-correlated Smith, exact Fresnel; Walter et al. 2007) for image-based refraction, for a
// view above the interface entering the denser medium (eta = inside / outside >= 1):
//     T_lobe(mu) = integral W_t(wo, wi) |cos_i| dwi          (the lobe's transmittance at F = 0),
//     T_F(mu)    = integral F(wo.m) W_t(wo, wi) |cos_i| dwi  (its Fresnel-weighted part),
// over the lower hemisphere, W_t the importance-form BTDF without its (1 - F) factor
// (fhat_t = (1 - F) W_t: no 1/eta^2 radiance factor). The transmitted energy is
// E_T = T_lobe - T_F; an engine that scales the Fresnel term by s (KHR_materials_specular's
// specular factor) transmits T_lobe - s T_F, and multiplies its prefiltered environment, sampled
// along the refracted direction, by that (docs/models.md, "ggx-dielectric: the split-sum BTDF
// pair"). Both are integrals over the visible microfacet normals (derivation in
// dielectric_btdf.cpp). Two rules with the same panels: adaptive Gauss-Kronrod to a tolerance
// (the reference) and a fixed Gauss rule (the bake), which the tests hold to the reference.
#pragma once
#include <array>

#include "baker/integrate/hemisphere.h"

namespace kiln {

/// {T_lobe, T_F} at view cosine mu in [0, 1], GGX alpha > 0 (at least MinAlpha), eta >= 1
/// (inside / outside: the view enters the denser medium; throws std::invalid_argument below 1),
/// by adaptive quadrature to opt.tol (absolute, per channel). stats.errorEstimate: the outer
/// rule's estimate.
std::array<double, 2> DielectricBtdfPair(double mu, double alpha, double eta,
                                         const IntegrationOptions& opt, IntegrationStats& stats);

/// Node counts of the fixed rule by panel class, as DielectricRuleOptions (dielectric_walk.h,
/// NodeClasses): an outer (v) panel takes outerNodes[k] for the first k with its weight bound
/// W > outerWeight[k] (outerNodes[3] below them all), an inner (phi_m) panel innerNodes[k] by
/// its width in radians against innerWidth. The defaults: 12 x 12 on every panel.
struct DielectricBtdfRuleOptions {
  int outerNodes[4] = {12, 12, 12, 12};
  double outerWeight[3] = {1e-2, 1e-4, 1e-6};
  int innerNodes[4] = {12, 12, 12, 12};
  double innerWidth[3] = {1, 0.1, 0.02};
};

/// The bake's node counts (dielectric_btdf.cpp, kTuned).
DielectricBtdfRuleOptions TunedDielectricBtdfRuleOptions();

/// {T_lobe, T_F} as DielectricBtdfPair, by the fixed rule: deterministic, the same arguments give
/// the same bits. evals (optional) accumulates integrand evaluations.
std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  const DielectricBtdfRuleOptions& opt,
                                                  long long* evals = nullptr);
std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  long long* evals = nullptr);

/// {T_lobe, T_F} by the fixed rule at (mu, alpha) for n etas at once (1 <= n <=
/// kMaxDielectricColumn of dielectric_albedo.h, every eta >= kDielectricTableEtaMin = 1.1; throws
/// std::invalid_argument otherwise), into out[0 .. n-1]: one walk of the microfacet normals (its
/// panels fixed at eta = 1.1's there), per eta only F and the refracted ray (dielectric_btdf.cpp,
/// "Columns"). Each out[e] has the bits FixedRuleDielectricBtdfPair(mu, alpha, etas[e], opt)
/// gives. evals (optional) accumulates one eta's evaluations (every eta takes the same nodes).
void FixedRuleDielectricBtdfColumn(double mu, double alpha, const double* etas, int n,
                                   const DielectricBtdfRuleOptions& opt, std::array<double, 2>* out,
                                   long long* evals = nullptr);
/// The same with the bake's node counts (TunedDielectricBtdfRuleOptions), remembering its recent
/// columns (by the bits of the arguments; dielectric_column_memo.h): the BTDF table and the
/// entering E tables' E_T (FixedRuleDielectricAlbedoColumn) baked in one process walk each
/// column once.
void FixedRuleDielectricBtdfColumn(double mu, double alpha, const double* etas, int n,
                                   std::array<double, 2>* out, long long* evals = nullptr);

/// The declared bound of the fixed rule against the adaptive reference (tests hold it there).
constexpr double kDielectricBtdfRuleBound = 5e-7;

/// The smooth interface (alpha = 0): {1, F(mu, eta)} (all of the lobe refracts; E_T = 1 - F).
std::array<double, 2> SmoothDielectricBtdfPair(double mu, double eta);

}  // namespace kiln
