// A fixed (non-adaptive) quadrature rule for the split-sum DFG terms of GGX with height-correlated
// Smith masking, built from the analytic structure of the integrand so that a few hundred
// integrand evaluations reach an absolute error far below 1e-6 at every (mu, alpha), including
// mu = 0, mu = 1 and alpha -> 0. Method and derivation: fixed_rule_dfg.cpp.
//
// Conventions (the same as kiln::SplitSumDFG for model "ggx"): view o = (sqrt(1 - mu^2), 0, mu),
// normal +z, alpha the GGX roughness (alpha = r^2 from perceptual r, at least MinAlpha),
// G2 = 1 / (1 + Lambda(o) + Lambda(l)), F = 1, w = 1 - o.h,
//     A = integral f (1 - w^5) mu_l dl,   B = integral f w^5 mu_l dl,
// so that the albedo with Schlick F0 (F90 = 1) is F0 A + B, and A + B is the F = 1 albedo.
// The same rule and kernel also take ggx-separable (G2 = G1(o) G1(l)) and GGX's albedo with
// exact dielectric Fresnel for eta >= 1.3 (declarations at the end of this file).
#pragma once
#include <array>

namespace kiln {

/// Which SIMD path evaluates the kernel: the widest the CPU runs (the bake's), or one forced
/// (tests: all paths give the same bits). A path the CPU or the build lacks runs as Widest.
enum class SimdPath { Widest, AVX2, SSE2, Portable };

/// Whether `path` runs as itself on this CPU and build (Widest and Portable always do on x86-64).
bool SimdPathAvailable(SimdPath path);

/// Node counts of the fixed rule. The default values are one uniform rule (the first tuning, over
/// all roughness); the bake uses TunedFixedRuleOptions(alpha). Tests and experiments vary them to
/// show convergence. Inner counts are rounded up to a multiple of 4 (the kernel's lanes).
struct FixedRuleOptions {
  int outerNodes = 12;         ///< Gauss nodes in phi_h per half (front, back) of the azimuth,
                               ///< at the strongest grading (grazing views); fewer for milder
  int bulkNodes = 9;           ///< Gauss nodes of the plain inner panel ...
  int gradedNodes = 5;         ///< ... (plus these when nothing is graded); base Gauss nodes of
                               ///< the panel graded towards the cut ...
  double nodesPerEFold = 1.5;  ///< ... plus this many per e-fold of its grading range
  int deficitNodes = 4;        ///< base Gauss nodes of the panel graded towards the normal (the
                               ///< opposite cut's masking layer), and of the panel between
  int lightNodes = 6;          ///< Gauss nodes of an azimuth of negligible weight (no grading)
  SimdPath simd = SimdPath::Widest;  ///< the kernel's path (the same bits on every path)
};

/// The node counts the bake uses at GGX roughness alpha: one set per band of alpha, each the
/// fewest nodes that keep the band's worst error on the 128 x 128 catalogue grid at or below
/// the uniform rule's (2.9e-7; fixed_rule_dfg.cpp, kTunedBands).
FixedRuleOptions TunedFixedRuleOptions(double alpha);

/// Split-sum DFG (A, B) of GGX at view cosine mu in [0, 1] and alpha > 0 (clamped to MinAlpha),
/// by the fixed rule with the node counts `opt`; evals (optional) accumulates the integrand
/// evaluations.
std::array<double, 2> FixedRuleGGXDFG(double mu, double alpha, const FixedRuleOptions& opt,
                                      long long* evals = nullptr);

/// The same with the bake's node counts, TunedFixedRuleOptions(alpha).
std::array<double, 2> FixedRuleGGXDFG(double mu, double alpha, long long* evals = nullptr);

}  // namespace kiln

namespace kiln {

/// The node counts the bake uses for ggx-separable at alpha (fixed_rule_dfg.cpp,
/// kSeparableBands).
FixedRuleOptions TunedSeparableRuleOptions(double alpha);

/// Split-sum DFG (A, B) of GGX with separable Smith masking, G2 = G1(o) G1(l) (model
/// "ggx-separable"; otherwise the conventions above), by the same rule and kernel with
/// g = G2 / G1(o) = G1(l); node counts `opt`, or the bake's, TunedSeparableRuleOptions(alpha).
std::array<double, 2> FixedRuleGGXSeparableDFG(double mu, double alpha, const FixedRuleOptions& opt,
                                               long long* evals = nullptr);
std::array<double, 2> FixedRuleGGXSeparableDFG(double mu, double alpha, long long* evals = nullptr);

/// The smallest eta the kernel's exact-Fresnel rule is used for (ggx-fresnel-albedo's domain
/// starts there; below, the Fresnel layer sqrt(eta^2 - 1) needs the panels of
/// fixed_rule_microfacet.h's FixedRuleGGXFresnelAlbedo).
constexpr double kFresnelKernelEtaMin = 1.3;

/// The node counts the bake uses for the exact-Fresnel albedo at alpha (kFresnelBands), and the
/// lookup-error search's (kSearchFresnelBands: within kSearchRuleBound of the bake's, fewer
/// evaluations; tests/lookup_search_reference.cpp).
FixedRuleOptions TunedFresnelKernelOptions(double alpha);
FixedRuleOptions SearchFresnelKernelOptions(double alpha);

/// The bake rule's evaluations per search-rule evaluation of the exact-Fresnel kernel rule, at
/// most (the role of kSearchFresnelCharge in fixed_rule_microfacet.h): measured 2.01 by
/// tests/lookup_search_reference.cpp.
constexpr double kSearchFresnelKernelCharge = 2.0;

/// GGX (height-correlated Smith) directional albedo with exact dielectric Fresnel,
/// E = integral f F mu_l dl with F = FrDielectric(o.h, eta) (not Schlick's), at mu in [0, 1],
/// alpha > 0 (clamped to MinAlpha), eta > 1 (0 at eta <= 1), by the kernel's rule with the node
/// counts `opt`, or the bake's, TunedFresnelKernelOptions(alpha). Meant for eta >=
/// kFresnelKernelEtaMin, where F is smooth in o.h on the visible domain.
double FixedRuleGGXFresnelKernel(double mu, double alpha, double eta, const FixedRuleOptions& opt,
                                 long long* evals = nullptr);
double FixedRuleGGXFresnelKernel(double mu, double alpha, double eta, long long* evals = nullptr);

}  // namespace kiln
