// fresnel-conductor: the exact conductor Fresnel reflectance at eta = n + i k, over
// (mu, n, k), stored as the residual F - conductorFresnelApprox(mu, n, k) (kiln/stored.h): the
// closed form carries the grazing dip (a function of mu |eta|), the residual is smooth and small.
// The domain is that of metals in the visible, n in [0.03, 4] and k in [1.5, 10]: k -> 0 with
// n < 1 is total internal reflection (a kink that moves with n), not a metal, and k = 0 with
// n > 1 is a dielectric (fresnel-dielectric).
#include "baker/models/specular.h"
#include "baker/quantities/common.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// The domain of the default table: the metals in the visible.
constexpr struct { double nLo = 0.03, nHi = 4, kLo = 1.5, kHi = 10; } kConductorDomain;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelConductor, QuantityName(Quantity::FresnelConductor), "none",
               {"F_residual"},
               {"exact conductor Fresnel reflectance F (eta = n + i k) minus the closed form "
                "(r_s + r_p) / 2, r_s = (e - 2 n mu + mu^2) / (e + 2 n mu + mu^2), "
                "r_p = (e mu^2 - 2 n mu + 1) / (e mu^2 + 2 n mu + 1), e = n^2 + k^2"},
               std::move(axes));
}

/// 20 x 40 x 40 (32,000 texels): mu in [0, 1] sqrt, n in [0.03, 4] log, k in [1.5, 10] log,
/// the metals in the visible (silver n 0.05 k 3.3 to chromium n 3.1 k 3.3, aluminium k 6.7).
/// The residual varies more with n and k than with mu, hence the node split.
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 20, Warp::Sqrt},
          {"n", kConductorDomain.nLo, kConductorDomain.nHi, 40, Warp::Log},
          {"k", kConductorDomain.kLo, kConductorDomain.kHi, 40, Warp::Log}};
}

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", DefaultAxes(""))};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  return {FrComplex(x[0], x[1], x[2]) - conductorFresnelApprox(x[0], x[1], x[2])};
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
    q.sceneDomain =
        "metals in the visible; k < 1.5 with n < 1 is total internal reflection, k = 0 with n > 1 "
        "a dielectric: fresnel-dielectric";
    return q;
  }();
  return info;
}

}  // namespace kiln
