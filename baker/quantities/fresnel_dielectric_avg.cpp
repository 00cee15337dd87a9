// fresnel-dielectric-avg: the hemispherical average 2 int F(mu) mu dmu of the dielectric Fresnel
// reflectance, over eta -> F_avg. `kiln integrate fresnel-avg` takes it for any --eta (and --k).
#include <stdexcept>

#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelDielectricAvg, QuantityName(Quantity::FresnelDielectricAvg), "none",
               {"F_avg"}, {"2 int F(mu) mu dmu"}, std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) { return {DefaultEtaAxis()}; }

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", {{"eta", 1, 3, 128, Warp::Sqrt}})};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double tol,
                             IntegrationStats& stats) {
  IntegrationOptions opt;
  opt.tol = tol;
  return {FresnelAverage(Fresnel{Fresnel::Kind::Dielectric, 0, x[0], 0}, opt, stats)};
}

std::string Method(const TableSpec& spec) {
  return "adaptive Gauss-Kronrod 7-15 in mu, split at the critical angle to " + Full17(spec.tol) +
         " abs";
}

std::string SceneProblem(const ModelInfo& m) {
  return FindParam(m, "eta") ? ""
                             : std::string(QuantityName(Quantity::FresnelDielectricAvg)) +
                                   " needs a model with eta";
}

/// --eta (and --k: a conductor), nothing else.
std::string Integrate(const IntegrateRequest& req, const ModelParams& p, IntegrationStats& stats) {
  const std::string what = "integrate " + req.name;
  if (!req.model.empty()) throw std::invalid_argument(what + ": takes no --model");
  if (!p.eta) throw std::invalid_argument(what + ": needs --eta");
  if (!(*p.eta > 0 && *p.eta <= 100))
    throw std::invalid_argument(what + ": --eta must be in (0, 100]");
  if (p.k && !(*p.k >= 0 && *p.k <= 100))
    throw std::invalid_argument(what + ": --k must be in [0, 100]");
  if (p.roughness || p.rho || p.f0 || p.rs || p.nu || p.nv)
    throw std::invalid_argument(what + ": takes only --eta and --k");
  return Full17(FresnelAverage(FresnelFromParams(p), RequestOptions(req), stats));
}

}  // namespace

const QuantityInfo& FresnelDielectricAvgQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::FresnelDielectricAvg;
    q.name = "fresnel-dielectric-avg";
    q.description = "average dielectric Fresnel";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.evaluate = Evaluate;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "none";
    q.sceneAxes = {{"eta", "eta"}};
    q.sceneProblem = SceneProblem;
    q.integrateName = "fresnel-avg";
    q.integrateHelp = "fresnel-avg";
    q.integrate = Integrate;
    return q;
  }();
  return info;
}

}  // namespace kiln
