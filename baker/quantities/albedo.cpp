// albedo: the directional albedo E(mu) of any model at rho = 1, F = 1, over (mu, roughness);
// E_rho, E_rho2 for a model with a rho^2 term (E = rho E_rho + rho^2 E_rho2).
#include "baker/quantities/monte_carlo.h"
#include "baker/quantities/common.h"
#include "baker/quantities/unity_tables.h"
#include "baker/quantities/ward_tables.h"

namespace kiln {
namespace {
using namespace quantity_detail;

TableSpec MakeSpec(const std::string& model, std::vector<AxisSpec> axes) {
  std::string name = model + "-" + QuantityName(Quantity::Albedo);
  if (HasRho2(model))
    return Shell(Quantity::Albedo, name, model, {"E_rho", "E_rho2"},
                 {"directional albedo, rho^1 part", "rho^2 part: E = rho E_rho + rho^2 E_rho2"},
                 std::move(axes));
  if (IsWardModel(model))  // E_sqrt_mu, E_mu, E_layer: stored forms of E (ward_tables.h)
    return Shell(Quantity::Albedo, name, model, {WardAlbedoChannel(model)},
                 {WardAlbedoChannelMeaning(model)}, std::move(axes));
  return Shell(Quantity::Albedo, name, model, {"E"}, {"directional albedo E(mu) at rho = 1, F = 1"},
               std::move(axes));
}

/// Microfacet models: the root4-layer mu axis (catalogue.cpp); diffuse ones: DiffuseMuAxis.
std::vector<AxisSpec> DefaultAxes(const std::string& model) {
  AxisSpec mu =
      IsSpecular(model) ? AxisSpec{"mu", 0, 1, 128, Warp::Root4Layer} : DiffuseMuAxis(model);
  return {mu, DefaultRoughnessAxis(model)};
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
  for (const std::string& m : CatalogueDiffuseModels()) out.push_back(MakeSpec(m, DefaultAxes(m)));
  for (const TableSpec& s : SheenSpecs(true)) out.push_back(s);
  return out;
}

/// On request (`kiln bake --only NAME`, scenes): the sheen lobes' tables that
/// SheenTableInDefaultCatalogue leaves out (none today), and the Unity / Lafortune ones
/// (unity_tables.h).
std::vector<TableSpec> OnRequest(const CatalogueOptions& opt) {
  std::vector<TableSpec> out = OnRequestAlbedoTables(opt);
  for (const TableSpec& s : SheenSpecs(false)) out.push_back(s);
  return out;
}

/// A fixed rule for every microfacet model with one (visible-normal space), for every diffuse
/// model (light space) and the sheen lobes (light space, integrate/fixed_rule_sheen.h).
bool AlbedoUsesFixedRule(const TableSpec& spec) {
  return MicrofacetFixedRuleApplies(spec) || DiffuseFixedRuleApplies(spec) ||
         MirrorLobeRuleApplies(spec) || SheenFixedRuleApplies(spec) || WardRuleApplies(spec);
}

/// Microfacet at F = 1: A + B of the microfacet fixed rule is the albedo. Diffuse: the diffuse
/// fixed rule.
std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (WardRuleApplies(spec)) return WardRuleAt(spec, x, stats);
  if (MirrorLobeRuleApplies(spec)) return MirrorLobeRuleAt(spec, x, stats);
  if (SheenFixedRuleApplies(spec)) return SheenFixedRuleAt(spec, x, stats);
  if (DiffuseFixedRuleApplies(spec)) return DiffuseFixedRuleAt(spec, x, stats);
  std::array<double, 2> ab = MicrofacetFixedRuleAt(spec, x, stats);
  return {ab[0] + ab[1]};
}

/// The lookup-error search's form of FixedRule (DiffuseSearchRuleAt, MicrofacetSearchRuleAt).
std::vector<double> SearchRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  if (WardRuleApplies(spec)) return WardRuleAt(spec, x, stats, true);  // the bake's own rule
  if (MirrorLobeRuleApplies(spec)) {
    std::vector<double> v = MirrorLobeRuleAt(spec, x, stats);
    stats.errorEstimate = 0;  // the bake's own rule
    return v;
  }
  if (SheenFixedRuleApplies(spec)) return SheenSearchRuleAt(spec, x, stats);
  if (DiffuseFixedRuleApplies(spec)) return DiffuseSearchRuleAt(spec, x, stats);
  std::array<double, 2> ab = MicrofacetSearchRuleAt(spec, x, stats);
  return {ab[0] + ab[1]};
}

std::string FixedRuleMethod(const TableSpec& spec) {
  if (WardRuleApplies(spec)) return WardRuleMethod(spec);
  if (MirrorLobeRuleApplies(spec)) return MirrorLobeRuleMethod(spec);
  if (SheenFixedRuleApplies(spec)) return SheenFixedRuleMethod(spec);
  return DiffuseFixedRuleApplies(spec) ? DiffuseFixedRuleMethod(spec)
                                       : MicrofacetFixedRuleMethod(spec);
}

/// A microfacet albedo at F = 1 is A + B of the model's dfg table at the same nodes: the bits
/// FixedRule computes (it sums the same rule's A and B) and, at roughness 0, 1 - w^5 + w^5
/// within an ulp of SmoothLimit's 1, the same float32 texel. A sheen lobe's dfg is its albedo
/// (one channel, the same SheenFixedRuleAt): the texels are copied.
bool DerivedFrom(const TableSpec& spec, TableSpec& source) {
  const bool sheen = SheenFixedRuleApplies(spec);
  if (!(sheen || MicrofacetFixedRuleApplies(spec)) || spec.channels.size() != 1 ||
      !spec.params.empty())
    return false;
  const QuantityInfo& dfg = Describe(Quantity::Dfg);
  source = dfg.makeSpec(spec.model, spec.axes);
  source.tol = spec.tol;
  return source.channels.size() == (sheen ? 1u : 2u);
}

/// A sheen albedo has its cloth DFG's texels, axes and search reference (SheenSearchRuleAt at
/// every point): the same lookup-error report (QuantityInfo::sharesSourceLookupError).
bool SharesSourceLookupError(const TableSpec& spec) { return SheenFixedRuleApplies(spec); }

/// A microfacet albedo's search reference is the sum of its DFG's (SearchRule: A + B of the same
/// MicrofacetSearchRuleAt, the same stats) off roughness 0 (SmoothLimit: 1, not SmoothDfg's sum).
bool SearchDerivesFromSource(const TableSpec& spec) {
  TableSpec source;
  return !SheenFixedRuleApplies(spec) && DerivedFrom(spec, source);
}

void Derive(const TableSpec& spec, const double* source, double* out) {
  out[0] = IsSheen(spec.model) ? source[0] : source[0] + source[1];
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  if (IsWardModel(spec.model)) {
    // m(mu) E (ward_tables.h); at mu = 0 the limit mu -> 0+, read at mu = 1e-12 (E(0) is the
    // horizon convention's 0).
    const double mu = std::max(x[0], 1e-12);
    RhoParts e = DirectionalAlbedo(ModelInDomain(spec.model, x[1]), mu, opt, stats);
    return {WardStoredFactorOf(spec.model, mu) * e.lin +
            WardStoredOffsetOf(spec.model, x[0], std::clamp(x[1], 0.0, 1.0))};
  }
  return RhoChannels(spec, DirectionalAlbedo(ModelInDomain(spec.model, x[1]), x[0], opt, stats));
}

/// Roughness 0 of a microfacet lobe: a mirror reflects all of it, E = F = 1 at every mu.
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (MirrorLobeLimitAt(spec, x, out)) return true;  // lafortune at r = 1
  if (!OnSmoothLimit(spec, x)) return false;
  out = RhoChannels(spec, RhoParts{1.0, 0.0});
  return true;
}

std::string Method(const TableSpec& spec) {
  return AdaptiveMethod(IsSpecular(spec.model), false, spec.tol);
}

/// Albedo tables use F = 1 and rho = 1 unless a Fresnel parameter is given explicitly. At
/// roughness 0 (a microfacet lobe's mirror) E = F(mu), the model's Fresnel term at o.h = mu.
std::string Integrate(const IntegrateRequest& req, const ModelParams& p, IntegrationStats& stats) {
  if (SmoothRequest(req, p)) return Full17(FresnelFromParams(p)(Clamp(req.mu, 0.0, 1.0)));
  RhoParts e = DirectionalAlbedo(RequestModel(req, p), req.mu, RequestOptions(req), stats);
  return Full17(e.At(p.rho.value_or(1)));
}

}  // namespace

const QuantityInfo& AlbedoQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::Albedo;
    q.name = "albedo";
    q.description = "directional albedo E(mu): multiple-scattering compensation";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.onRequest = OnRequest;
    q.usesFixedRule = AlbedoUsesFixedRule;
    q.fixedRule = FixedRule;
    q.searchRule = SearchRule;
    q.fixedRuleMethod = FixedRuleMethod;
    q.fixedRuleVersionOf = MicrofacetFixedRuleVersion;
    q.derivedFrom = DerivedFrom;
    q.derive = Derive;
    q.sharesSourceLookupError = SharesSourceLookupError;
    q.searchDerivesFromSource = SearchDerivesFromSource;
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneAxes = {{"roughness", "roughness"}};
    q.integrateName = q.name;
    q.integrateHelp = "albedo (E at rho = 1, F = 1)";
    q.integrateNeedsMu = true;
    q.integrate = Integrate;
    q.monteCarlo = &kDiffuseAlbedoMonteCarlo;
    return q;
  }();
  return info;
}

}  // namespace kiln
