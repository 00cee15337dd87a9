// fresnel-conductor: the exact conductor Fresnel reflectance at eta = n + i k, over
// (mu, n, k) -> F.
#include "baker/models/specular.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelConductor, QuantityName(Quantity::FresnelConductor), "none", {"F"},
               {"exact conductor Fresnel reflectance, eta = n + i k"}, std::move(axes));
}

/// 32^3, n in [0.1, 4], k in [0, 8]: the metals of the usual tables.
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 32, Warp::Root4},
          {"n", 0.1, 4, 32, Warp::Linear},
          {"k", 0, 8, 32, Warp::Linear}};
}

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", DefaultAxes(""))};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  return {FrComplex(x[0], x[1], x[2])};
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

std::string SceneProblem(const ModelInfo& m) {
  return FindParam(m, "eta") && FindParam(m, "k")
             ? ""
             : std::string(QuantityName(Quantity::FresnelConductor)) +
                   " needs a model with eta and k";
}

}  // namespace

const QuantityInfo& FresnelConductorQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::FresnelConductor;
    q.name = "fresnel-conductor";
    q.description = "exact conductor Fresnel F(mu)";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.evaluate = Evaluate;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "none";
    q.sceneAxes = {{"n", "eta"}, {"k", "k"}};
    q.sceneProblem = SceneProblem;
    return q;
  }();
  return info;
}

}  // namespace kiln
