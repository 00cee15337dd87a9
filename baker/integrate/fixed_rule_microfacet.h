// Fixed (non-adaptive) quadrature rules for the split-sum DFG (A, B), the albedo (A + B) of the
// catalogue's microfacet models other than height-correlated GGX (ggx-separable, beckmann,
// beckmann-separable, blinn-phong), and for GGX's albedo with exact dielectric Fresnel
// (ggx-fresnel-albedo). The bake takes ggx-separable and ggx-fresnel-albedo (eta >= 1.3) from the
// GGX kernel's variants instead (fixed_rule_dfg.h: 2.4x fewer evaluations, 4 lanes at a time):
// here they remain the general rules (any eta > 1: kiln integrate, scenes, tests near eta = 1;
// ggx-separable as a cross-check). The GGX rule's variables (fixed_rule_dfg.h: the GGX visible
// normals, the horizon cut exact) with each model's NDF as a smooth, alpha-free factor on the GGX
// one, panels at the integrand's analytic scales. Method and derivation: fixed_rule_microfacet.cpp.
//
// Conventions (those of kiln::SplitSumDFG and kiln::DirectionalAlbedo): view
// o = (sqrt(1 - mu^2), 0, mu), normal +z, alpha the microfacet roughness (alpha = r^2, at least
// MinAlpha), w = 1 - o.h, A = integral f (1 - w^5) mu_l dl, B = integral f w^5 mu_l dl with F = 1.
#pragma once
#include <array>

namespace kiln {

/// The microfacet distribution of a fixed rule.
/// UnityBRDF1: unity-brdf1's capped GGX (the 1e-7 in GGXTerm), Unity's approximate joint
/// visibility (with its 1e-5) and Unity_SafeNormalize's half vector (models/unity.h), in the
/// GGX variables at alpha_q = max(a, 1e-7^(1/4)), a = max(r^2, 0.002).
/// UnityBRDF2: unity-brdf2's GGX with 1.00001 for 1, its visibility-Fresnel term
/// 1 / (4 max(0.1, l.h^2) (a + 0.5)) and Unity_SafeNormalize's half vector, in the GGX variables at
/// alpha_q = max(a, sqrt(1e-5)), a = r^2; rs = 1.
enum class FixedRuleNdf { GGX, Beckmann, BlinnPhong, UnityBRDF1, UnityBRDF2 };

/// A microfacet model the fixed rule takes: its NDF and whether Smith's G2 is separable
/// (G1(o) G1(l)) or height-correlated (1 / (1 + Lambda(o) + Lambda(l))). Blinn-Phong takes
/// Beckmann's Lambda at the same alpha (models/microfacet.h).
struct FixedRuleModel {
  FixedRuleNdf ndf = FixedRuleNdf::GGX;
  bool separable = false;
};

struct ModelInfo;

/// The fixed rule's model for a model descriptor (its microfacetNdf and separableSmith), or
/// false when the model's rule family is not Microfacet.
bool FixedRuleModelFor(const ModelInfo& model, FixedRuleModel* out);
/// The same for a model id (looked up in the registry); false for an unknown id.
bool FixedRuleModelFor(const char* model, FixedRuleModel* out);

/// Node counts of the microfacet fixed rule (the roles of FixedRuleOptions in fixed_rule_dfg.h).
struct MicrofacetRuleOptions {
  int outerNodes = 12;         ///< Gauss nodes in phi_h per half at the strongest grading
  int bulkNodes = 9;           ///< Gauss nodes of the plain inner panel
  int gradedNodes = 5;         ///< base Gauss nodes of the panel graded towards the cut
  double nodesPerEFold = 1.5;  ///< plus this many per e-fold of its grading range
  int deficitNodes = 5;        ///< base Gauss nodes of the panel graded towards the normal
  int lightNodes = 6;          ///< Gauss nodes of an azimuth of negligible weight
};

/// The node counts the bake uses for `model` (fixed_rule_microfacet.cpp, kTuned).
MicrofacetRuleOptions TunedMicrofacetRuleOptions(const FixedRuleModel& model);

/// The node counts the bake uses for ggx-fresnel-albedo.
MicrofacetRuleOptions TunedFresnelRuleOptions();

/// The lookup-error search's node counts for `model` (a verification-grade reference, issue #13):
/// about half the bake's evaluations, within kSearchRuleBound of the bake's rule
/// (tests/lookup_search_reference.cpp holds both on dense grids, corners included).
MicrofacetRuleOptions SearchMicrofacetRuleOptions(const FixedRuleModel& model);

/// The same for ggx-fresnel-albedo.
MicrofacetRuleOptions SearchFresnelRuleOptions();

/// How far a search rule (this one, the diffuse one, the averages over them) may lie from the
/// bake's rule at any point, absolute: the search adds it to the max it finds before it declares.
constexpr double kSearchRuleBound = 2e-6;

/// The bake rule's integrand evaluations per search-rule evaluation of `model`, at most: the
/// search charges each of its evaluations this many, so that its budget, counted in the bake
/// rule's evaluations, buys at least the points it bought with the bake rule
/// (tests/lookup_search_reference.cpp measures the ratio on a grid: 1.69 to 1.72 for beckmann,
/// beckmann-separable and blinn-phong; 1.7 is kept for ggx-separable, whose tables the GGX kernel
/// bakes and searches).
double SearchMicrofacetCharge(const FixedRuleModel& model);
/// The same for ggx-fresnel-albedo (measured 1.72).
constexpr double kSearchFresnelCharge = 1.7;

/// Split-sum DFG (A, B) of `model` at view cosine mu in [0, 1] and alpha > 0 (clamped to
/// MinAlpha), by the fixed rule with node counts `opt`; evals (optional) accumulates the
/// integrand evaluations. Deterministic: the same arguments give the same bits.
std::array<double, 2> FixedRuleMicrofacetDFG(const FixedRuleModel& model, double mu, double alpha,
                                             const MicrofacetRuleOptions& opt,
                                             long long* evals = nullptr);

/// The same with the bake's node counts, TunedMicrofacetRuleOptions(model).
std::array<double, 2> FixedRuleMicrofacetDFG(const FixedRuleModel& model, double mu, double alpha,
                                             long long* evals = nullptr);

/// GGX (height-correlated Smith) directional albedo with exact dielectric Fresnel
/// F = FrDielectric(o.h, eta), at mu in [0, 1], alpha > 0 (clamped to MinAlpha), eta >= 1, by
/// the fixed rule with node counts `opt` (the bake's, TunedFresnelRuleOptions(), by default).
double FixedRuleGGXFresnelAlbedo(double mu, double alpha, double eta,
                                 const MicrofacetRuleOptions& opt, long long* evals = nullptr);
double FixedRuleGGXFresnelAlbedo(double mu, double alpha, double eta, long long* evals = nullptr);

}  // namespace kiln
