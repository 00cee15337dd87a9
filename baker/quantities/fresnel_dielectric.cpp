// fresnel-dielectric: the exact unpolarized dielectric Fresnel reflectance, over (mu, eta) -> F.
#include "baker/models/specular.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelDielectric, QuantityName(Quantity::FresnelDielectric), "none",
               {"F"}, {"exact unpolarized dielectric Fresnel reflectance"}, std::move(axes));
}

/// The mu axis follows the layer of width c = sqrt(|eta^2 - 1|) at mu = 0 (F -> G(mu / c) as
/// eta -> 1; for eta < 1, c is the critical cosine): the layer-eta warp (kiln/lut.h).
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 128, Warp::LayerEta}, DefaultEtaAxis()};
}

/// 128 x 128, mu layer-eta x eta sqrt: the eta = 1 row holds the layer's limit G(t / (1 - t)).
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", {{"mu", 0, 1, 128, Warp::LayerEta}, {"eta", 1, 3, 128, Warp::Sqrt}})};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  return {FrDielectric(x[0], x[1])};
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

std::string SceneProblem(const ModelInfo& m) {
  return FindParam(m, "eta")
             ? ""
             : std::string(QuantityName(Quantity::FresnelDielectric)) + " needs a model with eta";
}

}  // namespace

const QuantityInfo& FresnelDielectricQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::FresnelDielectric;
    q.name = "fresnel-dielectric";
    q.description = "exact dielectric Fresnel F(mu)";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.evaluate = Evaluate;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "none";
    q.sceneAxes = {{"eta", "eta"}};
    q.sceneProblem = SceneProblem;
    return q;
  }();
  return info;
}

}  // namespace kiln
