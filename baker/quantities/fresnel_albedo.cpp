// fresnel-albedo: GGX's directional albedo with exact dielectric Fresnel at index eta, over
// (mu, roughness, eta) -> E (dielectric layering, transmission). The domain starts where real
// dielectrics do, eta >= 1.3 (ice 1.31, water 1.33): as eta -> 1 the Fresnel layer at grazing
// (width sqrt(eta^2 - 1)) meets the GGX layer (width alpha) and E depends on both ratios, which
// no table of this size interpolates; eta = 1 exactly has no reflection at all (F = 0).
#include "baker/bench/monte_carlo.h"
#include "baker/models/fresnel.h"
#include "baker/quantities/common.h"

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

/// 96 x 36 x 16 (55,296 texels, as many as the 48 x 48 x 24 before). mu takes root4-layer
/// (coupled to roughness, like the 2D microfacet tables): near grazing E is a function of
/// mu / alpha, which a plain root4 axis does not follow for r below its second node (the
/// roughness-0 rows hold the smooth limit F(mu, eta) and, below Axis::collapsedStart(), the
/// layer's limit); half of mu's nodes lie in that layer, hence the most nodes on mu. The three
/// axes err about alike at this split (README "Why these sizes and warps").
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<AxisSpec> axes = DefaultAxes("ggx");
  axes[0].warp = Warp::Root4Layer;
  axes[0].size = 96;
  axes[1].size = 36;
  axes[2].size = 16;
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
    q.fixedRuleMethod = FresnelAlbedoFixedRuleMethod;
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
