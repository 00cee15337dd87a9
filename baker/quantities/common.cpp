#include "baker/quantities/common.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "baker/integrate/fixed_rule_sheen.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>
#include <variant>
#include <stdexcept>

#include "baker/integrate/fixed_rule_average.h"
#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/fixed_rule_microfacet.h"

#include "baker/integrate/fixed_rule_diffuse.h"
#include "baker/models/model_names.h"
#include "baker/models/specular.h"
#include "baker/tables/prepared_reference.h"

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
  if (const ModelInfo* m = FindModel(model); m && m->noTables)
    throw std::invalid_argument("model '" + model + "' has no " + QuantityName(q) +
                                " table: " + m->noTables);
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
  if (!m) throw std::invalid_argument(UnknownModelMessage(model));
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

AnyModel ModelInDomain(const std::string& model, double r) {
  if (!IsSheen(model)) return ModelAt(model, r);
  ModelParams p;
  p.roughness = r;
  return MakeModel(model, p);
}

std::vector<double> RhoChannels(const TableSpec& spec, RhoParts e) {
  return spec.channels.size() == 2 ? std::vector<double>{e.lin, e.quad}
                                   : std::vector<double>{e.lin + e.quad};
}

double Param(const TableSpec& spec, const char* key, double def) {
  auto it = spec.params.find(key);
  return it == spec.params.end() ? def : it->second;
}

const ModelInfo* ModelOf(const TableSpec& spec) { return FindModel(spec.model); }

RuleFamily RuleOf(const TableSpec& spec) {
  const ModelInfo* m = ModelOf(spec);
  return m ? m->rule : RuleFamily::None;
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

namespace {

/// The dfg kernel of a Microfacet-family model (Generic for any other).
MicrofacetKernel KernelOf(const TableSpec& spec) {
  const ModelInfo* m = ModelOf(spec);
  return m && m->rule == RuleFamily::Microfacet ? m->kernel : MicrofacetKernel::Generic;
}

/// A mu x roughness table.
bool OverMuAndRoughness(const TableSpec& spec) {
  return spec.axes.size() == 2 && spec.axes[0].name == "mu" && spec.axes[1].name == "roughness";
}

/// The microfacet fixed rule's model of a Microfacet-family spec.
FixedRuleModel RuleModelOf(const TableSpec& spec) {
  FixedRuleModel m;
  if (const ModelInfo* info = ModelOf(spec)) FixedRuleModelFor(*info, &m);
  return m;
}

}  // namespace

bool GgxFixedRuleApplies(const TableSpec& spec) {
  return KernelOf(spec) == MicrofacetKernel::GgxHeightCorrelated && spec.axes.size() == 2 &&
         spec.axes[0].name == "mu" && spec.axes[1].name == "roughness";
}

std::array<double, 2> GgxFixedRuleAt(const double* x, IntegrationStats& stats) {
  // alpha as MakeModel("ggx") derives it from the roughness clamped to ggx's range [0, 1]
  // (tests/integrate_fixed_rule.cpp compares against the adaptive path, which calls MakeModel).
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  std::array<double, 2> ab = FixedRuleGGXDFG(Clamp(x[0], 0.0, 1.0), alpha, &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  return ab;
}

std::array<double, 2> GgxSeparableFixedRuleAt(const double* x, IntegrationStats& stats) {
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  std::array<double, 2> ab = FixedRuleGGXSeparableDFG(Clamp(x[0], 0.0, 1.0), alpha, &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  return ab;
}

std::string GgxFixedRuleMethod(const TableSpec&) {
  return "visible-normal space (Heitz 2018): fixed Gauss-Legendre rule, panels placed at the "
         "integrand's analytic scales, exact horizon cut; declared error " +
         Short(kFixedRuleBound) + " abs";
}

const char* MicrofacetFixedRuleVersion(const TableSpec& spec) {
  // 3: ggx-separable by the GGX kernel; beckmann, beckmann-separable, blinn-phong at fewer nodes;
  // charlie-smith by its own node counts (kCharlieSmithRuleOptions).
  const ModelInfo* m = ModelOf(spec);
  return m ? m->fixedRuleVersion : "2";
}

bool MicrofacetFixedRuleApplies(const TableSpec& spec) {
  return RuleOf(spec) == RuleFamily::Microfacet && OverMuAndRoughness(spec);
}

std::array<double, 2> MicrofacetFixedRuleAt(const TableSpec& spec, const double* x,
                                            IntegrationStats& stats) {
  const MicrofacetKernel kernel = KernelOf(spec);
  if (kernel == MicrofacetKernel::GgxHeightCorrelated) return GgxFixedRuleAt(x, stats);
  if (kernel == MicrofacetKernel::GgxSeparable) return GgxSeparableFixedRuleAt(x, stats);
  const FixedRuleModel m = RuleModelOf(spec);
  // alpha as MakeModel derives it from the roughness clamped to the model's range [0, 1].
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  std::array<double, 2> ab = FixedRuleMicrofacetDFG(m, Clamp(x[0], 0.0, 1.0), alpha, &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  return ab;
}

std::array<double, 2> MicrofacetSearchRuleAt(const TableSpec& spec, const double* x,
                                             IntegrationStats& stats) {
  const MicrofacetKernel kernel = KernelOf(spec);
  if (kernel != MicrofacetKernel::Generic) {  // the kernel: the bake's rule
    std::array<double, 2> ab = kernel == MicrofacetKernel::GgxHeightCorrelated
                                   ? GgxFixedRuleAt(x, stats)
                                   : GgxSeparableFixedRuleAt(x, stats);
    stats.errorEstimate = 0;
    return ab;
  }
  const FixedRuleModel m = RuleModelOf(spec);
  double alpha = std::max(AlphaFromPerceptual(Clamp(x[1], 0.0, 1.0)), MinAlpha);
  long long evals = 0;
  std::array<double, 2> ab = FixedRuleMicrofacetDFG(m, Clamp(x[0], 0.0, 1.0), alpha,
                                                    SearchMicrofacetRuleOptions(m), &evals);
  stats.evals += std::llround(static_cast<double>(evals) * SearchMicrofacetCharge(m));
  stats.errorEstimate = kSearchRuleBound;
  return ab;
}

std::string MicrofacetFixedRuleMethod(const TableSpec& spec) {
  const MicrofacetKernel kernel = KernelOf(spec);
  if (kernel == MicrofacetKernel::GgxHeightCorrelated) return GgxFixedRuleMethod(spec);
  if (kernel == MicrofacetKernel::GgxSeparable)
    return "visible-normal space (Heitz 2018), separable Smith as G1(l): fixed Gauss-Legendre "
           "rule, panels placed at the integrand's analytic scales, exact horizon cut; declared "
           "error " +
           Short(kFixedRuleBound) + " abs";
  return "GGX visible-normal space (Heitz 2018) with the model's NDF and Smith term as smooth "
         "weights: fixed Gauss-Legendre rule, panels placed at the integrand's analytic scales, "
         "exact horizon cut; declared error " +
         Short(kFixedRuleBound) + " abs";
}

namespace {

/// (mu, roughness, eta) of a fresnel-albedo texel: from the axes, else the params.
std::array<double, 3> FresnelAlbedoPoint(const TableSpec& spec, const double* x) {
  double mu = 0, r = Param(spec, "roughness", 0), eta = Param(spec, "eta", 1.5);
  int i = 0;
  for (const AxisSpec& a : spec.axes) {
    if (a.name == "mu") mu = x[i];
    if (a.name == "roughness") r = x[i];
    if (a.name == "eta") eta = x[i];
    ++i;
  }
  return {mu, r, eta};
}

}  // namespace

bool FresnelAlbedoFixedRuleApplies(const TableSpec& spec) {
  // The GGX kernel with exact Fresnel: the models whose exact-Fresnel albedo kinds are baked.
  const ModelInfo* m = ModelOf(spec);
  if (!m || !m->fresnelTables) return false;
  bool hasMu = false, etaAxis = false;
  for (const AxisSpec& a : spec.axes) {
    if (a.name == "mu") hasMu = true;
    if (a.name == "eta") {
      etaAxis = true;
      if (!(std::min(a.lo, a.hi) >= 1)) return false;
    }
  }
  return hasMu && (etaAxis || Param(spec, "eta", 1.5) >= 1);
}

std::vector<double> FresnelAlbedoFixedRuleAt(const TableSpec& spec, const double* x,
                                             IntegrationStats& stats) {
  std::array<double, 3> p = FresnelAlbedoPoint(spec, x);
  double alpha = std::max(AlphaFromPerceptual(Clamp(p[1], 0.0, 1.0)), MinAlpha);
  // The GGX kernel where F is smooth in o.h (eta >= 1.3: the table's domain), else the generic
  // rule with the Fresnel layer's panels (kiln integrate and tests reach eta near 1).
  double e = p[2] >= kFresnelKernelEtaMin
                 ? FixedRuleGGXFresnelKernel(Clamp(p[0], 0.0, 1.0), alpha, p[2], &stats.evals)
                 : FixedRuleGGXFresnelAlbedo(Clamp(p[0], 0.0, 1.0), alpha, p[2], &stats.evals);
  stats.errorEstimate = kFixedRuleBound;
  return {e};
}

std::vector<double> FresnelAlbedoSearchRuleAt(const TableSpec& spec, const double* x,
                                              IntegrationStats& stats) {
  std::array<double, 3> p = FresnelAlbedoPoint(spec, x);
  double alpha = std::max(AlphaFromPerceptual(Clamp(p[1], 0.0, 1.0)), MinAlpha);
  long long evals = 0;
  const double mu = Clamp(p[0], 0.0, 1.0);
  const bool kernel = p[2] >= kFresnelKernelEtaMin;
  double e =
      kernel ? FixedRuleGGXFresnelKernel(mu, alpha, p[2], SearchFresnelKernelOptions(alpha), &evals)
             : FixedRuleGGXFresnelAlbedo(mu, alpha, p[2], SearchFresnelRuleOptions(), &evals);
  stats.evals += std::llround(static_cast<double>(evals) *
                              (kernel ? kSearchFresnelKernelCharge : kSearchFresnelCharge));
  stats.errorEstimate = kSearchRuleBound;
  return {e};
}

std::string FresnelAlbedoFixedRuleMethod(const TableSpec& spec) {
  // The kernel's rule where every eta of the spec is at least kFresnelKernelEtaMin.
  double etaLo = Param(spec, "eta", 1.5);
  for (const AxisSpec& a : spec.axes)
    if (a.name == "eta") etaLo = std::min(a.lo, a.hi);
  if (etaLo >= kFresnelKernelEtaMin)
    return "visible-normal space (Heitz 2018): fixed Gauss-Legendre rule, panels placed at the "
           "integrand's analytic scales, exact horizon cut, exact Fresnel as a weight in o.h "
           "(GGX kernel, eta >= 1.3); declared error " +
           Short(kFixedRuleBound) + " abs";
  return "visible-normal space (Heitz 2018): fixed Gauss-Legendre rule, panels placed at the "
         "integrand's analytic scales and at the Fresnel layer (o.h ~ sqrt(eta^2 - 1)), exact "
         "horizon cut; declared error " +
         Short(kFixedRuleBound) + " abs";
}

bool DiffuseFixedRuleApplies(const TableSpec& spec) {
  // Only a model that names the diffuse rule: never one chosen by what it is not.
  return RuleOf(spec) == RuleFamily::Diffuse && OverMuAndRoughness(spec);
}

namespace {

/// ModelAt(model, r), kept per thread for the last (model, r) asked: the points of an average
/// (every mu node at one roughness) and of a table's row take the model built once instead of
/// building it again at each point (its parameters checked, its factory called). The same
/// model: MakeModel is a function of its arguments and of the registry, which does not change
/// while a bake runs (registry.h: RegisterModel before any bake starts). The registry's entry is
/// looked up each time (one map look-up, no parameter checks, no factory call) and must be the
/// one the kept model was built from.
const AnyModel& LastModelAt(const std::string& model, double r) {
  struct Last {
    const ModelInfo* info = nullptr;
    double r = 0;
    AnyModel m;
    bool valid = false;
  };
  thread_local Last last;
  const ModelInfo* info = FindModel(model);
  if (!last.valid || info != last.info || std::memcmp(&last.r, &r, sizeof r) != 0) {
    last.valid = false;
    last.m = ModelAt(model, r);  // (throws for an unknown model: nothing kept)
    last.info = info;
    last.r = r;
    last.valid = true;
  }
  return last.m;
}

}  // namespace

std::vector<double> DiffuseFixedRuleAt(const TableSpec& spec, const double* x,
                                       IntegrationStats& stats) {
  RhoParts e = FixedRuleDiffuseAlbedo(LastModelAt(spec.model, x[1]), x[0], {}, &stats.evals);
  stats.errorEstimate = kDiffuseRuleBound;
  return RhoChannels(spec, e);
}

std::vector<double> DiffuseSearchRuleAt(const TableSpec& spec, const double* x,
                                        IntegrationStats& stats) {
  long long evals = 0;
  RhoParts e = FixedRuleDiffuseAlbedo(LastModelAt(spec.model, x[1]), x[0],
                                      kSearchDiffuseRuleOptions, &evals);
  stats.evals += std::llround(static_cast<double>(evals) * kSearchDiffuseCharge);
  stats.errorEstimate = kSearchRuleBound;
  return RhoChannels(spec, e);
}

std::string DiffuseFixedRuleMethod(const TableSpec& spec) {
  DiffuseRuleOptions opt;
  bool graded = DiffuseRuleGradesGrazing(ModelAt(spec.model, 0));
  return "light space: fixed tensor Gauss-Legendre rule over theta_l x phi (" +
         std::to_string(opt.thetaNodes) + " x " + std::to_string(opt.phiNodes) +
         " nodes per panel), panels split at theta_o, phi = pi/2 and towards the normal" +
         (graded ? ", graded towards theta_o and phi = pi at the grazing scale" : "") +
         "; declared error " + Short(kDiffuseRuleBound) + " abs";
}

bool SheenFixedRuleApplies(const TableSpec& spec) {
  return RuleOf(spec) == RuleFamily::Sheen && OverMuAndRoughness(spec);
}

SheenRule SheenRuleOf(const TableSpec& spec) {
  const ModelInfo* m = ModelOf(spec);
  return m ? m->sheenRule : SheenRule::Neubelt;
}

std::vector<double> SheenFixedRuleAt(const TableSpec& spec, const double* x,
                                     IntegrationStats& stats) {
  double e = FixedRuleSheenAlbedo(ModelInDomain(spec.model, x[1]), x[0],
                                  SheenRuleOptionsFor(SheenRuleOf(spec), false), &stats.evals);
  stats.errorEstimate = kSheenRuleBound;
  return {e};
}

std::vector<double> SheenSearchRuleAt(const TableSpec& spec, const double* x,
                                      IntegrationStats& stats) {
  long long evals = 0;
  double e = FixedRuleSheenAlbedo(ModelInDomain(spec.model, x[1]), x[0],
                                  SheenRuleOptionsFor(SheenRuleOf(spec), true), &evals);
  const double charge =
      SheenRuleOf(spec) == SheenRule::FittedSmith ? kCharlieSmithSearchCharge : kSearchSheenCharge;
  stats.evals += std::llround(static_cast<double>(evals) * charge);
  stats.errorEstimate = kSearchRuleBound;
  return {e};
}

std::string SheenFixedRuleMethod(const TableSpec& spec) {
  SheenRuleOptions opt = SheenRuleOptionsFor(SheenRuleOf(spec), false);
  return "light space: fixed tensor Gauss-Legendre rule over ln(mu_l + c) x ln(pi - phi + c), "
         "c = max(mu_o, 1e-7) (" +
         std::to_string(opt.tNodes) + " x " + std::to_string(opt.sNodes) +
         " nodes per panel), panels graded towards the mirror direction" +
         (opt.mirrorMinAlpha > 0 ? " where alpha > " + Short(opt.mirrorMinAlpha) : std::string()) +
         " and split at the model's kinks" +
         (opt.lobeBreak > 0 ? " and at mu_l = " + Short(opt.lobeBreak) + " r" : std::string()) +
         "; declared error " + Short(kSheenRuleBound) + " abs";
}

std::vector<double> AverageFixedRule(const TableSpec& albedo, const double* rest,
                                     IntegrationStats& stats, bool search) {
  const size_t dims = albedo.axes.size();
  double x[4] = {0, 0, 0, 0};
  double layer = 1;
  for (size_t i = 1; i < dims; ++i) {
    x[i] = rest[i - 1];
    if (albedo.axes[i].name == "roughness")
      layer = std::min(layer, std::max(AlphaFromPerceptual(Clamp(x[i], 0.0, 1.0)), MinAlpha));
    if (albedo.axes[i].name == "eta") layer = std::min(layer, std::sqrt(std::abs(x[i] - 1)));
  }
  // Sheen: E(mu) has a layer of width ~ r at mu = 0 (the Charlie lobe at grazing): the mu rule
  // graded from its finest layer (the velvet's); the Charlie pair's layer is no narrower than
  // r = 0.045, so their panels start at 1e-2 (40 nodes instead of 64, within 1e-9 for charlie,
  // 2.5e-7 for charlie-smith, of 20 nodes per panel from 1e-4), and charlie-smith's E has
  // Lambda(mu)'s C1 switch at mu = 1/2: a panel boundary there (SheenAverageKink).
  const int nodes = search ? kSearchAverageNodes : kCosineAverageNodes;
  // A specular model's kink of E (ModelInfo::averageKink, unity-brdf2's at mu = sqrt(0.1)),
  // smoothed over ~alpha: panels graded on both sides of it from alpha.
  const ModelInfo& m = Info(albedo.model);
  const bool kink = m.averageKink > 0;
  const std::vector<CosineAverageNode> mus =
      m.specular() ? CosineAverageNodeList(layer, nodes, m.averageKink, kink ? layer : 0)
      : m.rule == RuleFamily::Sheen
          ? CosineAverageNodeList(m.averageSheenLayer, nodes, m.averageKink)
          : CosineAverageAngleNodeList(kMinAngleLayer, nodes);
  const bool fixed = UsesFixedRule(albedo);
  const PreparedReference reference(albedo);
  // The mu nodes' E are independent: evaluated on the calling arena's threads (isolated: a
  // thread waiting for them takes no other task of its arena), then summed in the nodes' order,
  // so a point has the bits of one thread's sum for any thread count.
  std::vector<std::vector<double>> values(mus.size());
  std::vector<IntegrationStats> nodeStats(mus.size());
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, mus.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i != r.end(); ++i) {
            double xi[4] = {mus[i].mu, x[1], x[2], x[3]};
            values[i] =
                search ? reference.Search(xi, nodeStats[i]) : reference.Bake(xi, nodeStats[i]);
          }
        });
  });
  double innerBound = 0;
  for (const IntegrationStats& st : nodeStats) {
    // The search's form takes kSearchAverageNodes per panel: each inner evaluation is charged
    // for the kCosineAverageNodes / kSearchAverageNodes the bake's rule takes in its place.
    stats.evals += search ? std::llround(static_cast<double>(st.evals) * kCosineAverageNodes /
                                         kSearchAverageNodes)
                          : st.evals;
    innerBound = std::max(innerBound, search  ? st.errorEstimate
                                      : fixed ? st.errorEstimate
                                              : 10 * std::max(st.errorEstimate, albedo.tol));
  }
  stats.errorEstimate = search ? innerBound : innerBound + kCosineAverageBound;
  return SumCosineAverage(mus, values);
}

std::string AverageFixedRuleMethod(const TableSpec& albedo) {
  return "2 int E mu dmu by a fixed Gauss-Legendre rule in " +
         std::string(IsSpecular(albedo.model) || IsSheen(albedo.model) ? "mu" : "asin(mu)") + " (" +
         std::to_string(kCosineAverageNodes) +
         " nodes per panel, panels graded from the layer at mu = 0) of E by: " + albedo.Method();
}

std::vector<double> GgxFresnelAlbedoAt(const TableSpec& spec, const double* x, double tol,
                                       bool averaged, IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  const auto [mu, r, eta] = FresnelAlbedoPoint(spec, x);
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
  return std::visit(
      [](const auto& v) { return IsMicrofacetLobe<std::decay_t<decltype(v)>>::value; }, a);
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
  if (const ModelInfo* m = FindModel(request.model); m && m->noTables)
    throw std::invalid_argument("integrate " + request.name + ": model '" + request.model +
                                "' has no hemispherical integral: " + m->noTables);
  return MakeModel(request.model, params);
}

IntegrationOptions RequestOptions(const IntegrateRequest& request) {
  IntegrationOptions opt;
  opt.tol = request.tol;
  return opt;
}

}  // namespace kiln::quantity_detail
