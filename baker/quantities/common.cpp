#include "baker/quantities/common.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <type_traits>
#include <variant>
#include <stdexcept>

#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/models/specular.h"

namespace kiln::quantity_detail {

std::string Full17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

namespace {

/// %g of a value ("6e-07").
std::string Short(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

TableSpec Shell(Quantity q, const std::string& name, const std::string& model,
                std::vector<std::string> channels, std::vector<std::string> meanings,
                std::vector<AxisSpec> axes) {
  TableSpec s;
  s.name = name;
  s.model = model;
  s.quantity = q;
  s.channels = std::move(channels);
  s.meanings = std::move(meanings);
  s.axes = std::move(axes);
  return s;
}

const ModelInfo& Info(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (!m) throw std::invalid_argument("unknown model '" + model + "'");
  return *m;
}

bool HasRho2(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  return m && m->hasRho2;
}

bool IsSpecular(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  return m && m->specular();
}

const ParamInfo* FindParam(const ModelInfo& model, const std::string& name) {
  for (const ParamInfo& p : model.params)
    if (p.name == name) return &p;
  return nullptr;
}

ModelParams WithRoughness(const std::string& model, double r) {
  ModelParams p;
  if (const ParamInfo* q = FindParam(Info(model), "roughness"))
    p.roughness = Clamp(r, q->lo, q->hi);
  return p;
}

AnyModel ModelAt(const std::string& model, double r) {
  return MakeModel(model, WithRoughness(model, r));
}

std::vector<double> RhoChannels(const TableSpec& spec, RhoParts e) {
  return spec.channels.size() == 2 ? std::vector<double>{e.lin, e.quad}
                                   : std::vector<double>{e.lin + e.quad};
}

double Param(const TableSpec& spec, const char* key, double def) {
  auto it = spec.params.find(key);
  return it == spec.params.end() ? def : it->second;
}

std::string ClosedFormMethod() { return "closed form (exact evaluation at each node)"; }

std::string AdaptiveMethod(bool specular, bool averaged, double tol) {
  std::string base = specular
                         ? "half-vector space: adaptive Gauss-Kronrod 7-15 over the NDF's CDF x "
                           "phi_h, exact horizon cut"
                         : "light space: adaptive Gauss-Kronrod 7-15 over theta_l x phi, panels "
                           "split at theta_o and phi = pi/2";
  if (averaged) base += "; then 2 int E mu dmu by adaptive Gauss-Kronrod";
  return base + " to " + Full17(tol) + " abs";
}

bool GgxFixedRuleApplies(const TableSpec& spec) {
  return spec.model == "ggx" && spec.axes.size() == 2 && spec.axes[0].name == "mu" &&
         spec.axes[1].name == "roughness";
}

std::array<double, 2> GgxFixedRuleAt(const double* x, IntegrationStats& stats) {
  // alpha as MakeModel("ggx") derives it from the roughness clamped to ggx's range [0, 1]
  // (tests/integrate_fixed_rule.cpp compares against the adaptive path, which calls MakeModel).
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  std::array<double, 2> ab = FixedRuleGGXDFG(Clamp(x[0], 0.0, 1.0), alpha, &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  return ab;
}

std::string GgxFixedRuleMethod(const TableSpec&) {
  return "visible-normal space (Heitz 2018): fixed Gauss-Legendre rule, panels placed at the "
         "integrand's analytic scales, exact horizon cut; declared error " +
         Short(kFixedRuleBound) + " abs";
}

std::vector<double> GgxFresnelAlbedoAt(const TableSpec& spec, const double* x, double tol,
                                       bool averaged, IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  double mu = 0, r = Param(spec, "roughness", 0), eta = Param(spec, "eta", 1.5);
  int i = 0;
  for (const AxisSpec& a : spec.axes) {
    if (a.name == "mu") mu = x[i];
    if (a.name == "roughness") r = x[i];
    if (a.name == "eta") eta = x[i];
    ++i;
  }
  AnyModel m = ModelAt("ggx", r);
  SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
  RhoParts e = averaged ? AverageAlbedo(m, opt, stats) : DirectionalAlbedo(m, mu, opt, stats);
  return {e.lin};
}

namespace {
template <class T>
struct IsMicrofacetLobe : std::false_type {};
template <class D>
struct IsMicrofacetLobe<MicrofacetBRDF<D>> : std::true_type {};
}  // namespace

bool HasSmoothLimit(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (!m || !FindParam(*m, "roughness")) return false;
  AnyModel a = MakeModel(model, {});
  return std::visit([](const auto& v) { return IsMicrofacetLobe<std::decay_t<decltype(v)>>::value; },
                    a);
}

double CoordinateOf(const TableSpec& spec, const double* x, const char* name, double def) {
  for (size_t i = 0; i < spec.axes.size(); ++i)
    if (spec.axes[i].name == name) return x[i];
  return Param(spec, name, def);
}

bool OnSmoothLimit(const TableSpec& spec, const double* x) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return CoordinateOf(spec, x, "roughness", nan) == 0.0 && HasSmoothLimit(spec.model);
}

bool SmoothRequest(const IntegrateRequest& request, const ModelParams& params) {
  return params.roughness && *params.roughness == 0.0 && HasSmoothLimit(request.model);
}

std::array<double, 2> SmoothDfg(double mu) {
  const double b = Pow5(1 - Clamp(mu, 0.0, 1.0));
  return {1 - b, b};
}

AnyModel RequestModel(const IntegrateRequest& request, const ModelParams& params) {
  if (request.model.empty())
    throw std::invalid_argument("integrate " + request.name + ": needs --model");
  return MakeModel(request.model, params);
}

IntegrationOptions RequestOptions(const IntegrateRequest& request) {
  IntegrationOptions opt;
  opt.tol = request.tol;
  return opt;
}

}  // namespace kiln::quantity_detail
