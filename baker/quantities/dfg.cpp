// dfg: the split-sum DFG terms (Karis 2013) of a microfacet model, over (mu, roughness) -> A, B.
#include <algorithm>

#include "baker/quantities/monte_carlo.h"
#include "baker/quantities/common.h"
#include "baker/tables/engine_layout.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// A sheen lobe has no Fresnel split (F = 1): its "cloth DFG" is one channel, the integral of
/// D V mu_l over l, which is the same integral as its albedo E(mu) (Filament's DFV_Charlie, the
/// third channel of its DFG LUT; docs/models.md "Sheen").
TableSpec MakeSpec(const std::string& model, std::vector<AxisSpec> axes) {
  if (IsSheen(model))
    return Shell(Quantity::Dfg, model + "-" + QuantityName(Quantity::Dfg), model, {"DFV"},
                 {"cloth DFG: integral D V mu_l dl at F = 1 (Filament's DFG .b, DFV_Charlie), "
                  "the same integral as E of the albedo table"},
                 std::move(axes));
  return Shell(Quantity::Dfg, model + "-" + QuantityName(Quantity::Dfg), model, {"A", "B"},
               {"A = integral f/F (1 - (1 - o.h)^5) mu_l dl (scales F0)",
                "B = integral f/F (1 - o.h)^5 mu_l dl (bias), albedo = F0 A + B"},
               std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string& model) {
  if (IsSheen(model)) return {DiffuseMuAxis(model), DefaultRoughnessAxis(model)};
  return {{"mu", 0, 1, 128, Warp::Root4Layer}, DefaultRoughnessAxis(model)};
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

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<TableSpec> out;
  for (const std::string& m : CatalogueMicrofacetModels())
    out.push_back(MakeSpec(m, DefaultAxes(m)));
  for (const TableSpec& s : SheenSpecs(true)) out.push_back(s);
  return out;
}

/// On request (`kiln bake --only NAME`, scenes): the sheen lobes' tables that
/// SheenTableInDefaultCatalogue leaves out (none today: all nine are in the catalogue).
std::vector<TableSpec> OnRequest(const CatalogueOptions&) { return SheenSpecs(false); }

/// The microfacet fixed rules, and the sheen rule for a sheen lobe's one channel: the same
/// function as its albedo's (SheenFixedRuleAt), so the two tables hold the same bits.
bool DfgUsesFixedRule(const TableSpec& spec) {
  return MicrofacetFixedRuleApplies(spec) || SheenFixedRuleApplies(spec);
}

/// How the cloth channel of a FilamentCloth table is evaluated: as the bake does (the sheen
/// fixed rule), as the lookup-error search does, or by adaptive quadrature to a tolerance.
enum class ClothMethod { Bake, Search, Adaptive };

/// `values` (the microfacet channels) with the cloth channel of a FilamentCloth spec appended:
/// the Charlie sheen's E at (mu, SheenRoughnessFor(r)) (FilamentClothSpec). The declared error
/// is the larger of the two parts'. Other specs: `values` unchanged.
std::vector<double> WithCloth(const TableSpec& spec, const double* x, std::vector<double> values,
                              IntegrationStats& stats, ClothMethod method, double tol = 0) {
  if (!HasFilamentClothChannel(spec)) return values;
  const TableSpec cloth = FilamentClothSpec(spec);
  const double xc[2] = {x[0], SheenRoughnessFor(spec, x[1])};
  IntegrationStats cs;
  double e = 0;
  if (method == ClothMethod::Bake) e = SheenFixedRuleAt(cloth, xc, cs)[0];
  if (method == ClothMethod::Search) e = SheenSearchRuleAt(cloth, xc, cs)[0];
  if (method == ClothMethod::Adaptive) {
    IntegrationOptions opt;
    opt.tol = tol;
    e = DirectionalAlbedo(ModelInDomain(cloth.model, xc[1]), xc[0], opt, cs).lin;
  }
  stats.evals += cs.evals;
  stats.errorEstimate = std::max(stats.errorEstimate, cs.errorEstimate);
  values.push_back(e);
  return values;
}

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (SheenFixedRuleApplies(spec)) return SheenFixedRuleAt(spec, x, stats);
  std::array<double, 2> ab = MicrofacetFixedRuleAt(spec, x, stats);
  return WithCloth(spec, x, DfgLayoutValues(spec, ab[0], ab[1]), stats, ClothMethod::Bake);
}

/// The lookup-error search's form of FixedRule (MicrofacetSearchRuleAt).
std::vector<double> SearchRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (SheenFixedRuleApplies(spec)) return SheenSearchRuleAt(spec, x, stats);
  std::array<double, 2> ab = MicrofacetSearchRuleAt(spec, x, stats);
  return WithCloth(spec, x, DfgLayoutValues(spec, ab[0], ab[1]), stats, ClothMethod::Search);
}

std::string DfgFixedRuleMethod(const TableSpec& spec) {
  return SheenFixedRuleApplies(spec) ? SheenFixedRuleMethod(spec) : MicrofacetFixedRuleMethod(spec);
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  if (IsSheen(spec.model))
    return {DirectionalAlbedo(ModelInDomain(spec.model, x[1]), x[0], opt, stats).lin};
  auto ab = SplitSumDFG(ModelAt(spec.model, x[1]), x[0], opt, stats);
  return WithCloth(spec, x, DfgLayoutValues(spec, ab[0], ab[1]), stats, ClothMethod::Adaptive, tol);
}

/// Roughness 0 of a microfacet lobe: the mirror reflects at o.h = mu (SmoothDfg).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (!OnSmoothLimit(spec, x)) return false;
  std::array<double, 2> ab = SmoothDfg(x[0]);
  IntegrationStats clothStats;  // the smooth limit declares no error of its own
  out = WithCloth(spec, x, DfgLayoutValues(spec, ab[0], ab[1]), clothStats, ClothMethod::Bake);
  return true;
}

std::string Method(const TableSpec& spec) {
  return AdaptiveMethod(IsSpecular(spec.model), false, spec.tol);
}

std::string SceneProblem(const ModelInfo& m) {
  return m.specular() || IsSheen(m.id)
             ? ""
             : std::string(QuantityName(Quantity::Dfg)) + " needs a microfacet or sheen model";
}

std::string Integrate(const IntegrateRequest& req, const ModelParams& p, IntegrationStats& stats) {
  if (SmoothRequest(req, p)) {
    std::array<double, 2> ab = SmoothDfg(req.mu);
    return Full17(ab[0]) + " " + Full17(ab[1]);
  }
  if (IsSheen(req.model))
    return Full17(DirectionalAlbedo(RequestModel(req, p), req.mu, RequestOptions(req), stats).lin);
  auto ab = SplitSumDFG(RequestModel(req, p), req.mu, RequestOptions(req), stats);
  return Full17(ab[0]) + " " + Full17(ab[1]);
}

}  // namespace

const QuantityInfo& DfgQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::Dfg;
    q.name = "dfg";
    q.description = "split-sum specular: F0 A + F90 B";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.onRequest = OnRequest;
    q.usesFixedRule = DfgUsesFixedRule;
    q.fixedRule = FixedRule;
    q.searchRule = SearchRule;
    q.fixedRuleMethod = DfgFixedRuleMethod;
    q.fixedRuleVersionOf = MicrofacetFixedRuleVersion;
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneAxes = {{"roughness", "roughness"}};
    q.sceneProblem = SceneProblem;
    q.integrateName = q.name;
    q.integrateHelp = "dfg (A B; a sheen model: its one channel DFV)";
    q.integrateNeedsMu = true;
    q.integrate = Integrate;
    q.monteCarlo = &kGgxDfgMonteCarlo;
    return q;
  }();
  return info;
}

}  // namespace kiln
