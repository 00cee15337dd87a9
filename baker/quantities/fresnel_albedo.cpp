// fresnel-albedo: GGX's directional albedo with exact dielectric Fresnel at index eta, over
// (mu, roughness, eta) -> E (dielectric layering, transmission).
#include "baker/bench/monte_carlo.h"
#include "baker/models/fresnel.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Baked for ggx only: `model` is ignored.
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelAlbedo, std::string("ggx-") + QuantityName(Quantity::FresnelAlbedo),
               "ggx", {"E"}, {"GGX albedo with exact dielectric Fresnel at index eta"},
               std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 48, Warp::Root4}, DefaultRoughnessAxis("ggx"), DefaultEtaAxis()};
}

/// 48 x 48 x 24: a 3D table, smaller per axis than the 2D ones. mu takes root4-layer (coupled
/// to roughness, like the 2D microfacet tables): near grazing E is a function of mu / alpha,
/// which a plain root4 axis does not follow for r below its second node (the roughness-0 rows
/// hold the smooth limit F(mu, eta) and, below Axis::collapsedStart(), the layer's limit). The
/// Fresnel layer of width sqrt(eta^2 - 1) at eta -> 1 is not followed by this warp: E there is a
/// function of mu / alpha and sqrt(eta^2 - 1) / alpha, so the first eta cell still errs.
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<AxisSpec> axes = DefaultAxes("ggx");
  axes[0].warp = Warp::Root4Layer;
  axes[1].size = 48;
  return {MakeSpec("ggx", axes)};
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  return GgxFresnelAlbedoAt(spec, x, tol, false, stats);
}

/// Roughness 0: a smooth dielectric interface, E = FrDielectric(mu, eta).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (!OnSmoothLimit(spec, x)) return false;
  out = {FrDielectric(CoordinateOf(spec, x, "mu", 0), CoordinateOf(spec, x, "eta", 1.5))};
  return true;
}

std::string Method(const TableSpec& spec) { return AdaptiveMethod(true, false, spec.tol); }

std::string SceneProblem(const ModelInfo& m) {
  return m.id == "ggx"
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
    q.fixedRule = FresnelAlbedoFixedRuleAt;
    q.searchRule = FresnelAlbedoSearchRuleAt;
    q.fixedRuleMethod = FresnelAlbedoFixedRuleMethod;
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "ggx";
    q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
    q.sceneProblem = SceneProblem;
    q.readsParams = true;
    q.monteCarlo = &kGgxFresnelAlbedoMonteCarlo;
    return q;
  }();
  return info;
}

}  // namespace kiln
