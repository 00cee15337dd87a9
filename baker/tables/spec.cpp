#include "baker/tables/spec.h"

#include <array>
#include <cstdio>
#include <stdexcept>

#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/quantities.h"
#include "baker/models/specular.h"

namespace kiln {
namespace {

/// Bump when an integrator changes the texels it produces: every baked file becomes stale.
constexpr const char* kIntegratorVersion = "kiln-integrators-2";

std::string G17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

ModelParams WithRoughness(const std::string& model, double r) {
  ModelParams p;
  const ModelInfo* info = FindModel(model);
  if (!info) throw std::invalid_argument("unknown model '" + model + "'");
  for (const ParamInfo& q : info->params)
    if (q.name == "roughness") p.roughness = Clamp(r, q.lo, q.hi);
  return p;
}

}  // namespace

std::string TableSpec::ParamsText() const {
  std::string s;
  for (const auto& [k, v] : params) s += (s.empty() ? "" : ";") + k + "=" + G17(v);
  return s;
}

/// %g of a value ("6e-07").
std::string Short(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string TableSpec::Method() const {
  auto tolText = " to " + G17(tol) + " abs";
  if (quantity == "fresnel-dielectric" || quantity == "fresnel-conductor" || quantity == "brdf" ||
      quantity == "blinn-phong-normalization")
    return "closed form (exact evaluation at each node)";
  if (quantity == "fresnel-dielectric-avg")
    return "adaptive Gauss-Kronrod 7-15 in mu, split at the critical angle" + tolText;
  if (UsesFixedRule(*this))
    return "visible-normal space (Heitz 2018): fixed Gauss-Legendre rule, panels placed at the "
           "integrand's analytic scales, exact horizon cut; declared error " + Short(kFixedRuleBound) +
           " abs";
  const ModelInfo* info = FindModel(quantity.rfind("fresnel-albedo", 0) == 0 ? "ggx" : model);
  std::string base = info && info->specular()
                         ? "half-vector space: adaptive Gauss-Kronrod 7-15 over the NDF's CDF x "
                           "phi_h, exact horizon cut"
                         : "light space: adaptive Gauss-Kronrod 7-15 over theta_l x phi, panels "
                           "split at theta_o and phi = pi/2";
  if (quantity.find("-avg") != std::string::npos)
    base += "; then 2 int E mu dmu by adaptive Gauss-Kronrod";
  return base + tolText;
}

std::string TableSpec::Hash() const {
  std::string text = std::string(kIntegratorVersion) + "|" + std::to_string(kFormatVersion) + "|" +
                     name + "|" + model + "|" + quantity + "|" + G17(tol) + "|" + ParamsText();
  // The fixed rule's own version (its tuned node counts): its tables re-bake when it changes.
  if (UsesFixedRule(*this)) text += "|fixed-rule:2";
  for (const std::string& c : channels) text += "|c:" + c;
  for (const AxisSpec& a : axes)
    text += "|a:" + a.name + "," + G17(a.lo) + "," + G17(a.hi) + "," + std::to_string(a.size) +
            "," + warpName(a.warp);
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::vector<TableAxis> TableSpec::TableAxes() const {
  std::vector<TableAxis> out;
  for (const AxisSpec& a : axes) out.push_back({a.name, a.ToAxis()});
  return out;
}

size_t TableSpec::TexelCount() const {
  size_t n = 1;
  for (const AxisSpec& a : axes) n *= static_cast<size_t>(a.size);
  return n;
}

Table TableShell(const TableSpec& spec, const std::string& generator, const std::string& method) {
  Table t;
  t.generator = generator;
  t.name = spec.name;
  t.model = spec.model;
  t.quantity = spec.quantity;
  t.channels = spec.channels;
  t.channelMeanings = spec.meanings;
  t.axes = spec.TableAxes();
  t.params = spec.ParamsText();
  t.method = method;
  t.data.assign(spec.TexelCount() * spec.channels.size(), 0.0f);
  return t;
}

TableSpec SpecFromTable(const Table& table) {
  TableSpec s;
  s.name = table.name;
  s.model = table.model;
  s.quantity = table.quantity;
  s.channels = table.channels;
  s.meanings = table.channelMeanings;
  for (const TableAxis& a : table.axes) s.axes.push_back({a.name, a.axis.lo, a.axis.hi, a.axis.size, a.axis.warp});
  for (const std::string& kv : splitList(table.params, ';')) {
    size_t eq = kv.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("table '" + table.name + "': bad params entry '" + kv + "'");
    s.params[kv.substr(0, eq)] = std::stod(kv.substr(eq + 1));
  }
  s.tol = table.tolerance;
  return s;
}

double LayerScaleOf(const TableSpec& spec, const double* x) {
  if (spec.axes.size() < 2 || spec.axes[0].warp != Warp::Root4Layer) return 1e-12;
  return layerScale(spec.axes[1].lo, spec.axes[1].hi, x[1]);
}

void NodeCoordinates(const TableSpec& spec, size_t index, double* x) {
  // A root4-layer axis 0 is placed last, once, by the value of axis 1 (its inverse is iterative).
  const bool layered = !spec.axes.empty() && spec.axes[0].warp == Warp::Root4Layer;
  int i0 = 0;
  for (size_t d = 0; d < spec.axes.size(); ++d) {
    const AxisSpec& a = spec.axes[d];
    int i = static_cast<int>(index % a.size);
    if (d == 0) i0 = i;
    if (d != 0 || !layered) x[d] = a.ToAxis().node(i);
    index /= a.size;
  }
  if (layered) x[0] = spec.axes[0].ToAxis().node(i0, LayerScaleOf(spec, x));
}

bool UsesFixedRule(const TableSpec& spec) {
  return spec.model == "ggx" && (spec.quantity == "dfg" || spec.quantity == "albedo") &&
         spec.axes.size() == 2 && spec.axes[0].name == "mu" && spec.axes[1].name == "roughness";
}

std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (!UsesFixedRule(spec)) return EvaluateSpec(spec, x, spec.tol, stats);
  // alpha as MakeModel("ggx") derives it from the roughness clamped to ggx's range [0, 1]
  // (tests/integrate_fixed_rule.cpp compares against the adaptive path, which calls MakeModel).
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  std::array<double, 2> ab = FixedRuleGGXDFG(Clamp(x[0], 0.0, 1.0), alpha, &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  if (spec.quantity == "albedo") return {ab[0] + ab[1]};  // F = 1: A + B is the albedo
  return {ab[0], ab[1]};
}

std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, double tol,
                                 IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  const std::string& q = spec.quantity;
  auto param = [&](const char* key, double def) {
    auto it = spec.params.find(key);
    return it == spec.params.end() ? def : it->second;
  };
  auto split = [&](RhoParts e) {
    return spec.channels.size() == 2 ? std::vector<double>{e.lin, e.quad}
                                     : std::vector<double>{e.lin + e.quad};
  };
  if (q == "dfg") {
    auto ab = SplitSumDFG(MakeModel(spec.model, WithRoughness(spec.model, x[1])), x[0], opt, stats);
    return {ab[0], ab[1]};
  }
  if (q == "albedo")
    return split(DirectionalAlbedo(MakeModel(spec.model, WithRoughness(spec.model, x[1])), x[0], opt, stats));
  if (q == "albedo-avg")
    return split(AverageAlbedo(MakeModel(spec.model, WithRoughness(spec.model, x[0])), opt, stats));
  if (q == "fresnel-albedo" || q == "fresnel-albedo-avg") {
    // Axes (mu, roughness, eta) or (roughness, eta); an axis fixed by the planner is a param.
    bool avg = q == "fresnel-albedo-avg";
    double mu = 0, r = param("roughness", 0), eta = param("eta", 1.5);
    int i = 0;
    for (const AxisSpec& a : spec.axes) {
      if (a.name == "mu") mu = x[i];
      if (a.name == "roughness") r = x[i];
      if (a.name == "eta") eta = x[i];
      ++i;
    }
    AnyModel m = MakeModel("ggx", WithRoughness("ggx", r));
    SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
    RhoParts e = avg ? AverageAlbedo(m, opt, stats) : DirectionalAlbedo(m, mu, opt, stats);
    return {e.lin};
  }
  if (q == "fresnel-dielectric") {
    ++stats.evals;
    return {FrDielectric(x[0], x[1])};
  }
  if (q == "fresnel-dielectric-avg")
    return {FresnelAverage(Fresnel{Fresnel::Kind::Dielectric, 0, x[0], 0}, opt, stats)};
  if (q == "fresnel-conductor") {
    ++stats.evals;
    return {FrComplex(x[0], x[1], x[2])};
  }
  if (q == "blinn-phong-normalization") {
    ++stats.evals;
    return {NormalizedBlinnPhong::Normalization(x[0]), NormalizedBlinnPhong::NormalizationApprox(x[0])};
  }
  if (q == "brdf") {
    ++stats.evals;
    AnyModel m = MakeModel(spec.model, WithRoughness(spec.model, param("roughness", 0.5)));
    RhoParts f = EvaluateParts(m, ViewDirection(x[1]), DirectionFromMuPhi(x[0], x[2]));
    return split(f);
  }
  throw std::invalid_argument("table '" + spec.name + "': unknown quantity '" + q + "'");
}

}  // namespace kiln
