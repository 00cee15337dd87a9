// Helpers the quantity descriptors share (baker/quantities/*.cpp): spec shells, the method texts,
// the GGX fixed rule's applicability, model lookups. Not for use outside baker/quantities/.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

namespace kiln::quantity_detail {

/// A spec of kind `q` named `name` with the given model, channels, meanings and axes.
TableSpec Shell(Quantity q, const std::string& name, const std::string& model,
                std::vector<std::string> channels, std::vector<std::string> meanings,
                std::vector<AxisSpec> axes);

/// The model's info; throws std::invalid_argument("unknown model '...'") when there is none.
const ModelInfo& Info(const std::string& model);
/// The descriptor of the spec's model, or nullptr ("none", an unknown id).
const ModelInfo* ModelOf(const TableSpec& spec);
/// The fixed-rule family the spec's model names (None for no model or an unknown one).
RuleFamily RuleOf(const TableSpec& spec);

/// True when `model` is known and has a rho^2 term (its tables get a second channel).
bool HasRho2(const std::string& model);

/// True when `model` is known and integrated in half-vector space (a microfacet-like lobe).
bool IsSpecular(const std::string& model);

/// The parameter `name` of a model, or nullptr.
const ParamInfo* FindParam(const ModelInfo& model, const std::string& name);

/// Parameters with the roughness r (clamped to the model's range; ignored without roughness).
ModelParams WithRoughness(const std::string& model, double r);

/// The model of `spec` at roughness r (WithRoughness).
AnyModel ModelAt(const std::string& model, double r);

/// The model of `spec` at roughness r; r outside a sheen model's domain throws (MakeModel's
/// one-line error) instead of being clamped; other models as ModelAt.
AnyModel ModelInDomain(const std::string& model, double r);

/// RhoParts as the table's channels: (lin, quad) for a 2-channel table, lin + quad otherwise.
std::vector<double> RhoChannels(const TableSpec& spec, RhoParts e);

/// params[key] of the spec, or `def`.
double Param(const TableSpec& spec, const char* key, double def);

/// The method text of a closed form evaluated at each node.
std::string ClosedFormMethod();

/// The adaptive method text: half-vector space (specular) or light space, "; then 2 int E mu
/// dmu ..." when averaged over mu, and " to TOL abs".
std::string AdaptiveMethod(bool specular, bool averaged, double tol);

/// True when the GGX visible-normal fixed rule (integrate/fixed_rule_dfg.h) applies: model ggx,
/// axes (mu, roughness).
bool GgxFixedRuleApplies(const TableSpec& spec);

/// (A, B) of the GGX fixed rule at x = (mu, roughness); sets stats.errorEstimate to its bound.
std::array<double, 2> GgxFixedRuleAt(const double* x, IntegrationStats& stats);

/// The method text of the GGX fixed rule.
std::string GgxFixedRuleMethod(const TableSpec& spec);

/// (A, B) of ggx-separable at x = (mu, roughness) by the GGX kernel's separable variant
/// (FixedRuleGGXSeparableDFG); errorEstimate kFixedRuleBound.
std::array<double, 2> GgxSeparableFixedRuleAt(const double* x, IntegrationStats& stats);

/// The fixed-rule version of a microfacet spec of the dfg, albedo and albedo-avg kinds
/// (QuantityInfo::fixedRuleVersionOf): "3" for ggx-separable (the GGX kernel's separable
/// variant) and beckmann, beckmann-separable, blinn-phong (fewer nodes), "2" for every other
/// model.
const char* MicrofacetFixedRuleVersion(const TableSpec& spec);

/// True when a microfacet fixed rule applies: axes (mu, roughness) and a model with one (ggx: the
/// GGX rule, fixed_rule_dfg.h; ggx-separable, beckmann, beckmann-separable, blinn-phong:
/// fixed_rule_microfacet.h).
bool MicrofacetFixedRuleApplies(const TableSpec& spec);

/// (A, B) of the spec's microfacet fixed rule at x = (mu, roughness); sets stats.errorEstimate.
std::array<double, 2> MicrofacetFixedRuleAt(const TableSpec& spec, const double* x,
                                            IntegrationStats& stats);

/// (A, B) at x by the search's verification-grade form of MicrofacetFixedRuleAt (QuantityInfo::
/// searchRule: SearchMicrofacetRuleOptions, errorEstimate kSearchRuleBound, evals charged
/// SearchMicrofacetCharge each); GGX (height-correlated) keeps its bake rule (errorEstimate 0).
std::array<double, 2> MicrofacetSearchRuleAt(const TableSpec& spec, const double* x,
                                             IntegrationStats& stats);

/// The method text of the spec's microfacet fixed rule.
std::string MicrofacetFixedRuleMethod(const TableSpec& spec);

/// True when the exact-Fresnel GGX fixed rule applies: model ggx, a mu axis, every eta >= 1.
bool FresnelAlbedoFixedRuleApplies(const TableSpec& spec);

/// E of the exact-Fresnel GGX fixed rule at x (axes as GgxFresnelAlbedoAt).
std::vector<double> FresnelAlbedoFixedRuleAt(const TableSpec& spec, const double* x,
                                             IntegrationStats& stats);

/// The search's verification-grade form of FresnelAlbedoFixedRuleAt (SearchFresnelRuleOptions,
/// errorEstimate kSearchRuleBound, evals charged kSearchFresnelCharge each).
std::vector<double> FresnelAlbedoSearchRuleAt(const TableSpec& spec, const double* x,
                                              IntegrationStats& stats);

/// The method text of the exact-Fresnel GGX fixed rule.
std::string FresnelAlbedoFixedRuleMethod(const TableSpec& spec);

/// True when the diffuse fixed rule (integrate/fixed_rule_diffuse.h) applies: a light-space
/// model, axes (mu, roughness).
bool DiffuseFixedRuleApplies(const TableSpec& spec);

/// E(mu) of the diffuse fixed rule at x = (mu, roughness) as the spec's channels; sets
/// stats.errorEstimate to its bound (kDiffuseRuleBound).
std::vector<double> DiffuseFixedRuleAt(const TableSpec& spec, const double* x,
                                       IntegrationStats& stats);

/// The search's verification-grade form of DiffuseFixedRuleAt (kSearchDiffuseRuleOptions,
/// errorEstimate kSearchRuleBound, evals charged kSearchDiffuseCharge each).
std::vector<double> DiffuseSearchRuleAt(const TableSpec& spec, const double* x,
                                        IntegrationStats& stats);

/// The method text of the diffuse fixed rule.
std::string DiffuseFixedRuleMethod(const TableSpec& spec);

/// True when the sheen fixed rule (integrate/fixed_rule_sheen.h) applies: a sheen model (IsSheen),
/// axes (mu, roughness).
bool SheenFixedRuleApplies(const TableSpec& spec);
/// The sheen rule's node counts the spec's model names (Neubelt for a non-sheen one).
SheenRule SheenRuleOf(const TableSpec& spec);

/// E(mu) of the sheen fixed rule at x = (mu, roughness) (cosine included, F = 1; also the cloth
/// DFG); sets stats.errorEstimate to kSheenRuleBound. A roughness outside the model's domain
/// throws (ModelInDomain).
std::vector<double> SheenFixedRuleAt(const TableSpec& spec, const double* x,
                                     IntegrationStats& stats);

/// The search's form of SheenFixedRuleAt (kSearchSheenRuleOptions, errorEstimate
/// kSearchRuleBound, evals charged kSearchSheenCharge each).
std::vector<double> SheenSearchRuleAt(const TableSpec& spec, const double* x,
                                      IntegrationStats& stats);

/// The method text of the sheen fixed rule.
std::string SheenFixedRuleMethod(const TableSpec& spec);

/// E_avg = 2 int_0^1 E(mu) mu dmu (per channel) of the albedo table `albedo` (axis 0 is mu) at
/// the coordinates `rest` of its other axes, by a fixed one-dimensional rule over mu
/// (integrate/fixed_rule_average.h) of E as the albedo table bakes it (EvaluateSpec: its fixed
/// rule where it has one, adaptive quadrature to albedo.tol otherwise). Microfacet models: the
/// mu rule with the layer alpha (and sqrt(|eta - 1|) with an eta axis); diffuse models: the angle
/// rule. Sets stats.errorEstimate to the declared bound: the inner one plus kCosineAverageBound.
/// With `search`: the search's form (QuantityInfo::searchRule), the same panels with
/// kSearchAverageNodes per panel over E by SearchReference(albedo), each inner evaluation charged
/// kCosineAverageNodes / kSearchAverageNodes times; errorEstimate is then the inner rule's distance
/// bound from the bake's (the mu rule's weights sum to 1), evals as the inner rule charges them.
/// The mu nodes' E run on the calling oneTBB arena's threads and are summed in the nodes' order:
/// the same bits for any thread count.
std::vector<double> AverageFixedRule(const TableSpec& albedo, const double* rest,
                                     IntegrationStats& stats, bool search = false);

/// The method text of AverageFixedRule over `albedo`.
std::string AverageFixedRuleMethod(const TableSpec& albedo);

/// GGX with exact dielectric Fresnel at index eta: E(mu) (averaged: E_avg) at x, whose axes are
/// (mu, roughness, eta) or (roughness, eta); an axis the planner fixed is read from params.
std::vector<double> GgxFresnelAlbedoAt(const TableSpec& spec, const double* x, double tol,
                                       bool averaged, IntegrationStats& stats);

/// True when `model` is a microfacet lobe with a roughness (MicrofacetBRDF: ggx, ggx-separable,
/// ggx-vcavity, beckmann, beckmann-separable, blinn-phong): at roughness exactly 0 its alpha is 0,
/// a mirror, whose integrals have exact values (the smooth limit). Diffuse models are not.
bool HasSmoothLimit(const std::string& model);

/// The value of the axis named `name` at x, else params[name] of the spec, else `def`.
double CoordinateOf(const TableSpec& spec, const double* x, const char* name, double def);

/// True when x lies on the smooth limit of `spec`: roughness exactly 0 (an axis or a param)
/// and HasSmoothLimit(spec.model).
bool OnSmoothLimit(const TableSpec& spec, const double* x);

/// True when a `kiln integrate` request is on the smooth limit: --roughness exactly 0 and a
/// model with HasSmoothLimit.
bool SmoothRequest(const IntegrateRequest& request, const ModelParams& params);

/// The smooth-limit DFG terms at view cosine mu: a mirror reflects at o.h = mu, so
/// A = 1 - (1 - mu)^5 and B = (1 - mu)^5.
std::array<double, 2> SmoothDfg(double mu);

/// The model of a `kiln integrate` request: throws "integrate NAME: needs --model" when none.
AnyModel RequestModel(const IntegrateRequest& request, const ModelParams& params);

/// %.17g of x (round-trips exactly), as `kiln integrate` prints.
std::string Full17(double x);

/// The request's tolerance as integration options.
IntegrationOptions RequestOptions(const IntegrateRequest& request);

}  // namespace kiln::quantity_detail
