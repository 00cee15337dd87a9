// Helpers the quantity descriptors share (baker/quantities/*.cpp): spec shells, the method texts,
// the GGX fixed rule's applicability, model lookups. Not for use outside baker/quantities/.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/quantities/quantity.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

namespace kiln::quantity_detail {

/// A spec of kind `q` named `name` with the given model, channels, meanings and axes.
TableSpec Shell(Quantity q, const std::string& name, const std::string& model,
                std::vector<std::string> channels, std::vector<std::string> meanings,
                std::vector<AxisSpec> axes);

/// The model's info; throws std::invalid_argument("unknown model '...'") when there is none.
const ModelInfo& Info(const std::string& model);

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
