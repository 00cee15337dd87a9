// albedo-avg: the average albedo E_avg = 2 int E(mu) mu dmu of any model, over roughness;
// E_avg_rho, E_avg_rho2 for a model with a rho^2 term.
#include <iterator>

#include "baker/math/quadrature.h"
#include "baker/quantities/common.h"
#include "baker/quantities/unity_tables.h"
#include "baker/quantities/ward_tables.h"

namespace kiln {
namespace {
using namespace quantity_detail;

TableSpec MakeSpec(const std::string& model, std::vector<AxisSpec> axes) {
  std::string name = model + "-" + QuantityName(Quantity::AlbedoAvg);
  if (HasRho2(model))
    return Shell(Quantity::AlbedoAvg, name, model, {"E_avg_rho", "E_avg_rho2"},
                 {"average albedo, rho^1 part", "rho^2 part"}, std::move(axes));
  return Shell(Quantity::AlbedoAvg, name, model, {"E_avg"},
               {"average albedo 2 int E(mu) mu dmu at rho = 1, F = 1"}, std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string& model) {
  return {DefaultRoughnessAxis(model)};
}

/// The sheen models' specs in (inDefault) or out of the default catalogue.
std::vector<TableSpec> SheenSpecs(bool inDefault) {
  std::vector<TableSpec> out;
  for (const std::string& m : CatalogueSheenModels()) {
    TableSpec s = MakeSpec(m, DefaultAxes(m));
    if (SheenTableInDefaultCatalogue(s.name) == inDefault) out.push_back(s);
  }
  return out;
}

/// The microfacet models' average albedo is smooth in roughness: 64 nodes (their 2D tables 128).
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<TableSpec> out;
  for (const std::string& m : CatalogueMicrofacetModels()) {
    AxisSpec rAvg = DefaultRoughnessAxis(m);
    rAvg.size = 64;
    out.push_back(MakeSpec(m, {rAvg}));
  }
  for (const std::string& m : CatalogueDiffuseModels()) out.push_back(MakeSpec(m, DefaultAxes(m)));
  for (const TableSpec& s : SheenSpecs(true)) out.push_back(s);
  return out;
}

/// On request (`kiln bake --only NAME`, scenes): the sheen lobes' tables that
/// SheenTableInDefaultCatalogue leaves out (none today), and the Unity / Lafortune ones
/// (unity_tables.h).
std::vector<TableSpec> OnRequest(const CatalogueOptions& opt) {
  std::vector<TableSpec> out = OnRequestAlbedoAvgTables(opt);
  for (const TableSpec& s : SheenSpecs(false)) out.push_back(s);
  return out;
}

/// The albedo table whose E(mu) the average integrates: the albedo kind's spec of the same
/// model, its default axes, the same tolerance.
TableSpec AlbedoSpecFor(const TableSpec& spec) {
  const QuantityInfo& albedo = Describe(Quantity::Albedo);
  TableSpec e = albedo.makeSpec(spec.model, albedo.defaultAxes(spec.model));
  e.tol = spec.tol;
  return e;
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  return RhoChannels(spec, AverageAlbedo(ModelInDomain(spec.model, x[0]), opt, stats));
}

/// Over roughness alone (the catalogue's axes): a fixed rule for every model (AverageFixedRule).
bool OverRoughness(const TableSpec& spec) {
  return spec.axes.size() == 1 && spec.axes[0].name == "roughness";
}

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (WardRuleApplies(spec)) return WardRuleAt(spec, x, stats);  // over E, not the stored m E
  return AverageFixedRule(AlbedoSpecFor(spec), x, stats);
}

/// The lookup-error search's form: the same mu rule over the albedo's search rule.
std::vector<double> SearchRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (WardRuleApplies(spec)) return WardRuleAt(spec, x, stats, true);
  return AverageFixedRule(AlbedoSpecFor(spec), x, stats, true);
}

bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out);

/// Where kiln verify's mu integral starts its panels: the layer at mu = 0, the middle, mu = 1.
constexpr double kVerifyMuBreaks[] = {0, 1e-4, 1e-2, 0.1, 0.5, 1};
/// The most panels of that integral.
constexpr int kVerifyMuPanels = 400;

/// kiln verify's bake-error reference (QuantityInfo::verifyReference): adaptive Gauss-Kronrod
/// over mu to `tol` of 2 E(mu) mu, E as the albedo table bakes it (its fixed rule, which that
/// table's own check holds to adaptive quadrature): independent of this kind's mu rule, at about
/// 1e5 integrand evaluations a node where the nested adaptive integral (Evaluate) takes 2e6-1e7.
std::vector<double> VerifyReference(const TableSpec& spec, const double* x, double tol,
                                    IntegrationStats& stats) {
  std::vector<double> smooth;
  if (SmoothLimit(spec, x, smooth)) return smooth;
  if (WardRuleApplies(spec) || !OverRoughness(spec)) return Evaluate(spec, x, tol, stats);
  const TableSpec albedo = AlbedoSpecFor(spec);
  const size_t nc = spec.channels.size();
  auto e = [&](double mu) {
    const double xm[3] = {mu, x[0], 0};
    IntegrationStats st;
    std::vector<double> v = EvaluateSpec(albedo, xm, st);
    stats.evals += st.evals;
    Channels<2> c{};
    for (size_t k = 0; k < nc && k < 2; ++k) c[k] = 2 * mu * v[k];
    return c;
  };
  const int n = static_cast<int>(std::size(kVerifyMuBreaks));
  Channels<2> r = IntegrateAdaptive<2>(e, kVerifyMuBreaks, n, tol, kVerifyMuPanels);
  return std::vector<double>(r.begin(), r.begin() + static_cast<long>(nc));
}

std::string FixedRuleMethod(const TableSpec& spec) {
  if (WardRuleApplies(spec)) return WardRuleMethod(spec);
  return AverageFixedRuleMethod(AlbedoSpecFor(spec));
}

/// The rule's version: the model's own (ModelInfo::averageRuleVersion: the Charlie pair's mu
/// panels "3", unity-brdf2's panels about E's kink), else its E's (MicrofacetFixedRuleVersion).
const char* AvgFixedRuleVersion(const TableSpec& spec) {
  const ModelInfo* m = ModelOf(spec);
  if (m && m->averageRuleVersion) return m->averageRuleVersion;
  return MicrofacetFixedRuleVersion(spec);
}

std::string Method(const TableSpec& spec) {
  return AdaptiveMethod(IsSpecular(spec.model), true, spec.tol);
}

/// Roughness 0 of a microfacet lobe: E = 1 at every mu, so E_avg = 1.
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (MirrorLobeLimitAt(spec, x, out)) return true;  // lafortune at r = 1
  if (!OnSmoothLimit(spec, x)) return false;
  out = RhoChannels(spec, RhoParts{1.0, 0.0});
  return true;
}

/// At roughness 0 (a microfacet lobe's mirror) E_avg = 2 int F(mu) mu dmu of the model's
/// Fresnel term (1 for F = 1).
std::string Integrate(const IntegrateRequest& req, const ModelParams& p, IntegrationStats& stats) {
  if (SmoothRequest(req, p)) {
    Fresnel F = FresnelFromParams(p);
    return Full17(F.kind == Fresnel::Kind::One ? 1.0
                                               : FresnelAverage(F, RequestOptions(req), stats));
  }
  RhoParts e = AverageAlbedo(RequestModel(req, p), RequestOptions(req), stats);
  return Full17(e.At(p.rho.value_or(1)));
}

}  // namespace

const QuantityInfo& AlbedoAvgQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::AlbedoAvg;
    q.name = "albedo-avg";
    q.description = "average albedo E_avg: multiple-scattering compensation";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.onRequest = OnRequest;
    q.usesFixedRule = OverRoughness;
    q.fixedRule = FixedRule;
    q.searchRule = SearchRule;
    q.parallelPoint = true;  // a point's mu nodes run on the arena's threads
    q.fixedRuleMethod = FixedRuleMethod;
    q.fixedRuleVersionOf = AvgFixedRuleVersion;
    q.evaluate = Evaluate;
    q.verifyReference = VerifyReference;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneAxes = {{"roughness", "roughness"}};
    q.integrateName = q.name;
    q.integrateHelp = "albedo-avg";
    q.integrate = Integrate;
    return q;
  }();
  return info;
}

}  // namespace kiln
