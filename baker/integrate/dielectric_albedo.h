// The energy a rough dielectric interface (models/dielectric_bsdf.h: GGX, height-correlated Smith,
// exact Fresnel; Walter et al. 2007) reflects and transmits for a view above it:
//     E_R(mu) = integral f_r(wo, wi) |cos_i| dwi   over the upper hemisphere,
//     E_T(mu) = integral fhat_t(wo, wi) |cos_i| dwi over the lower one (importance form: without
//               the 1/eta^2 radiance factor),
// so that E_R + E_T <= 1, with equality for a smooth interface (E_R = F(mu), E_T = 1 - F(mu)).
// Both are integrals over the visible microfacet normals (derivation in dielectric_albedo.cpp).
// Two rules with the same panels: adaptive Gauss-Kronrod to a tolerance (the reference) and a
// fixed Gauss rule (the bake), which the tests hold to the reference.
#pragma once
#include <array>

#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/hemisphere.h"

namespace kiln {

/// {E_R, E_T} of the GGX dielectric at view cosine mu in [0, 1], GGX alpha > 0 (at least
/// MinAlpha), eta = inside / outside in (0, inf), by adaptive quadrature to opt.tol (absolute,
/// per channel). stats.errorEstimate: the outer rule's estimate.
std::array<double, 2> DielectricAlbedo(double mu, double alpha, double eta,
                                       const IntegrationOptions& opt, IntegrationStats& stats);

/// Node counts of the fixed rule (dielectric_albedo.cpp, "The fixed rule"). Gauss nodes of an
/// outer (v) panel by its weight class, the bound W of its share of E: outerNodes[k] for the
/// first k with W > outerWeight[k], outerNodes[3] below them all; of an inner (phi_m) panel by
/// its width in radians against innerWidth. Then the ratios of the geometric panel sequences:
/// the reflected ray's masking layer (maskingRatio), the grazing view's sweep (grazingRatio),
/// the GGX tail in tan theta_m (tailRatio). The adaptive reference keeps ratio 4 everywhere.
/// The exit side (eta < 1) takes exitOuterNodes by the same weight classes and, on the rings of
/// an outer panel of class k, exitInnerNodes[k] by the same width classes (a ring of small
/// weight needs fewer azimuth nodes); exitOuterNodes[0] == 0: the counts above on both sides.
struct DielectricRuleOptions {
  int outerNodes[4] = {24, 24, 24, 24};
  double outerWeight[3] = {1e-2, 1e-4, 1e-6};
  int innerNodes[4] = {16, 16, 16, 16};
  double innerWidth[3] = {1, 0.1, 0.02};
  double maskingRatio = 4, grazingRatio = 4, tailRatio = 4;
  int exitOuterNodes[4] = {0, 0, 0, 0};
  int exitInnerNodes[4][4] = {};
  /// The exit side's E_R as E_1 (GGX's albedo with F = 1) minus the integral of (1 - F) times
  /// the reflected term over the cap c > c_crit: the walk skips what lies under total internal
  /// reflection (dielectric_albedo.cpp).
  bool exitTirComplement = false;
};

/// The bake's node counts (dielectric_albedo.cpp, kTuned).
DielectricRuleOptions TunedDielectricRuleOptions();

/// The node counts of E_1's rule in the exit side's complement form (exitTirComplement): E_1 =
/// A + B of fixed_rule_dfg.h's FixedRuleGGXDFG with these counts, GGX's directional albedo with F
/// = 1 (height-correlated Smith: the walk's reflected term), within 4e-8 of adaptive quadrature.
FixedRuleOptions DielectricExitE1RuleOptions();

/// {E_R, E_T} as DielectricAlbedo, by the fixed rule: deterministic, the same arguments give the
/// same bits. evals (optional) accumulates integrand evaluations. The overload with the bake's
/// node counts (no options) remembers its recent results (about 260,000 points, by the bits of
/// the arguments): albedo-r and albedo-t, or the -exit pair, or the averages, baked in one
/// process share one integration per node; a remembered point returns the same bits and charges
/// the evaluations its integration took.
std::array<double, 2> FixedRuleDielectricAlbedo(double mu, double alpha, double eta,
                                                const DielectricRuleOptions& opt,
                                                long long* evals = nullptr);
std::array<double, 2> FixedRuleDielectricAlbedo(double mu, double alpha, double eta,
                                                long long* evals = nullptr);

/// Most etas of one column (FixedRuleDielectricAlbedoColumn).
constexpr int kMaxDielectricColumn = 64;

/// Which of {E_R, E_T} (or of their averages) a column computes: the two are independent
/// computations (E_R by the reflected ray's moments, E_T by the BTDF pair's column), so either
/// alone has the bits it has in both.
enum class DielectricChannels { R = 1, T = 2, Both = 3 };

/// Whether `set` holds channel c (0: E_R, 1: E_T).
constexpr bool HasChannel(DielectricChannels set, int c) {
  return (static_cast<int>(set) >> c) & 1;
}

/// {E_R, E_T} by the fixed rule at (mu, alpha) for n etas at once (1 <= n <=
/// kMaxDielectricColumn, every eta >= kDielectricTableEtaMin: the entering side), into out[0 ..
/// n-1]: one walk of the microfacet normals (its panels do not depend on eta there), the
/// geometry shared, per eta only F and the refracted ray (dielectric_albedo.cpp, "Columns"). Each
/// out[e] has the bits FixedRuleDielectricAlbedo(mu, alpha, etas[e], opt) gives. evals
/// (optional) accumulates one eta's evaluations (every eta takes the same nodes) of the channels
/// computed. `channels`: only those are computed (E_R alone skips the BTDF column, E_T alone
/// the reflected ray's walk), each with the bits it has in both; a channel not asked is NaN.
void FixedRuleDielectricAlbedoColumn(double mu, double alpha, const double* etas, int n,
                                     const DielectricRuleOptions& opt, std::array<double, 2>* out,
                                     long long* evals = nullptr,
                                     DielectricChannels channels = DielectricChannels::Both);
/// The same with the bake's node counts, remembering its recent columns (by the bits of the
/// arguments): the E_R and E_T tables baked in one process walk each column once.
void FixedRuleDielectricAlbedoColumn(double mu, double alpha, const double* etas, int n,
                                     std::array<double, 2>* out, long long* evals = nullptr);

/// E_R alone by the fixed rule's node counts on the panels of the reflected ray's structures
/// only (the horizon, its masking layer, the critical cosine and the Fresnel layer: none at the
/// refracted ray's): the mu rule of the exit averages' E_R (integrate/dielectric_albedo_avg.cpp;
/// the bake takes one kernel per roughness instead, dielectric_kernel.h, and the tests hold the
/// two together). evals (optional) accumulates.
double FixedRuleDielectricReflectance(double mu, double alpha, double eta,
                                      const DielectricRuleOptions& opt, long long* evals = nullptr);

/// The declared bound of the fixed rule against the adaptive reference (tests hold it there).
constexpr double kDielectricRuleBound = 7e-7;

/// Where the ggx-dielectric tables' domain starts (E tables and averages alike): eta >= this
/// entering, eta' <= 1 / this exiting (quantities/dielectric_albedo.cpp says why: the Fresnel
/// layer at grazing collapses as eta -> 1).
constexpr double kDielectricTableEtaMin = 1.1;

/// The tables' domain in words (QuantityInfo::sceneDomain), for the entering or the exit side.
constexpr const char* DielectricTableDomain(bool exit) {
  return exit ? "glass seen from inside: eta = 1/ior, ior in [1.1, 3]"
              : "glass: eta = ior in [1.1, 3]";
}

/// The smooth interface (alpha = 0): {F(mu, eta), 1 - F(mu, eta)}.
std::array<double, 2> SmoothDielectricAlbedo(double mu, double eta);

}  // namespace kiln
