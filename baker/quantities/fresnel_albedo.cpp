// fresnel-albedo: GGX's directional albedo with exact dielectric Fresnel at index eta, over
// (mu, roughness, eta) -> E (dielectric layering, transmission). The domain starts where real
// dielectrics do, eta >= 1.3 (ice 1.31, water 1.33): as eta -> 1 the Fresnel layer at grazing
// (width sqrt(eta^2 - 1)) meets the GGX layer (width alpha) and E depends on both ratios, which
// no table of this size interpolates; eta = 1 exactly has no reflection at all (F = 0).
#include "baker/quantities/monte_carlo.h"
#include "baker/models/fresnel.h"
#include "baker/quantities/common.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// The index domain of the kind: real dielectrics, from below ice (1.31) and water (1.33) to 3.
constexpr double kEtaMin = 1.3, kEtaMax = 3;

/// Baked for ggx only: `model` is ignored.
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelAlbedo, std::string("ggx-") + QuantityName(Quantity::FresnelAlbedo),
               "ggx", {"E"}, {"GGX albedo with exact dielectric Fresnel at index eta"},
               std::move(axes));
}

/// eta in [kEtaMin, kEtaMax] (sqrt: denser near kEtaMin, where the Fresnel layer is narrowest).
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 48, Warp::Root4},
          DefaultRoughnessAxis("ggx"),
          {"eta", kEtaMin, kEtaMax, 24, Warp::Sqrt}};
}

/// 48 x 64 x 18 (55,296 texels, as the 48 x 48 x 24 before), storing E_residual = E -
/// fresnelAlbedoClosedForm (kiln/stored.h): the closed form carries the Fresnel layer (F(mu,
/// eta) at r = 0, a residual of 0 there), the drop of E(0) with alpha and the dip of E inside
/// the GGX layer, so what is left interpolates 7x better than E (docs/models.md "Albedo with
/// exact Fresnel"). mu takes root4-layer (coupled to roughness, like the 2D microfacet tables:
/// the roughness-0 rows hold the smooth limit and, below Axis::collapsedStart(), the layer's
/// limit). With the layer's dip in the closed form, mu needs fewer nodes than roughness and eta
/// (scans of this split and of 40 x 70 x 19, 56 x 58 x 17, 64 x 54 x 16: the axes err alike
/// here).
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<AxisSpec> axes = DefaultAxes("ggx");
  axes[0].warp = Warp::Root4Layer;
  axes[0].size = 48;
  axes[1].size = 64;
  axes[2].size = 18;
  TableSpec s = MakeSpec("ggx", axes);
  s.channels = {"E_residual"};
  s.meanings = {
      "GGX albedo with exact dielectric Fresnel at index eta minus the closed form g = "
      "F(sqrt(mu^2 + alpha^2), eta) h(mu / alpha) / (1 + 10 alpha), h(s) = 1 - 0.211 s / (1 + "
      "0.4 s + 0.3 s^2 + 0.25 s^3), alpha = max(roughness^2, 1e-12), g = F(mu, eta) at "
      "roughness 0 (exact dielectric F, kiln/stored.h fresnelAlbedoClosedForm)"};
  return {s};
}

/// True for a spec that stores E_residual = E - fresnelAlbedoClosedForm (kiln/stored.h): the
/// catalogue's table. A spec of the kind's own makeSpec (kiln integrate, the average's E, the
/// bench) holds E itself.
bool StoresResidual(const TableSpec& spec) {
  return !spec.channels.empty() && spec.channels[0] == "E_residual";
}

/// E at x turned into what `spec` stores: E itself, or E minus the closed form at the same
/// (mu, roughness, eta) (an axis cut to one value is read from the spec's params).
std::vector<double> Stored(const TableSpec& spec, const double* x, std::vector<double> e) {
  if (StoresResidual(spec))
    e[0] -= fresnelAlbedoClosedForm(CoordinateOf(spec, x, "mu", 0),
                                    CoordinateOf(spec, x, "roughness", 0),
                                    CoordinateOf(spec, x, "eta", 1.5));
  return e;
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  return Stored(spec, x, GgxFresnelAlbedoAt(spec, x, tol, false, stats));
}

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  return Stored(spec, x, FresnelAlbedoFixedRuleAt(spec, x, stats));
}

std::vector<double> SearchRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  return Stored(spec, x, FresnelAlbedoSearchRuleAt(spec, x, stats));
}

/// Roughness 0: a smooth dielectric interface, E = FrDielectric(mu, eta) (a residual of 0).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (!OnSmoothLimit(spec, x)) return false;
  out = Stored(spec, x,
               {FrDielectric(CoordinateOf(spec, x, "mu", 0), CoordinateOf(spec, x, "eta", 1.5))});
  return true;
}

std::string Method(const TableSpec& spec) { return AdaptiveMethod(true, false, spec.tol); }

std::string SceneProblem(const ModelInfo& m) {
  return m.fresnelTables
             ? ""
             : std::string(QuantityName(Quantity::FresnelAlbedo)) + " is baked for ggx only";
}

}  // namespace

const QuantityInfo& FresnelAlbedoQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::FresnelAlbedo;
    q.name = "fresnel-albedo";
    q.description = "albedo with exact dielectric Fresnel: dielectric layering, transmission";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.usesFixedRule = FresnelAlbedoFixedRuleApplies;
    q.fixedRule = FixedRule;
    q.searchRule = SearchRule;
    q.fixedRuleMethod = FresnelAlbedoFixedRuleMethod;
    q.fixedRuleVersion = "3";  // the GGX kernel from eta = 1.3
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "ggx";
    q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
    q.sceneProblem = SceneProblem;
    q.sceneDomain =
        "real dielectrics, from below ice (1.31) and water (1.33); eta = 1 has no reflection "
        "(F = 0), and 1 < eta < 1.3 puts the Fresnel layer sqrt(eta^2 - 1) inside the GGX layer";
    q.readsParams = true;
    q.monteCarlo = &kGgxFresnelAlbedoMonteCarlo;
    return q;
  }();
  return info;
}

}  // namespace kiln
