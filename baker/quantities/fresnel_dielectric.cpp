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

std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 128, Warp::Root4}, DefaultEtaAxis()};
}

/// 128 x 128: the layer of width sqrt(eta - 1) at mu = 0 needs the root4 mu axis and a dense eta.
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", {{"mu", 0, 1, 128, Warp::Root4}, {"eta", 1, 3, 128, Warp::Sqrt}})};
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
