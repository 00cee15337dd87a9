// fresnel-dielectric-avg: the hemispherical average 2 int F(mu) mu dmu of the dielectric Fresnel
// reflectance, over eta -> F_avg. `kiln integrate fresnel-avg` takes it for any --eta (and --k).
#include <stdexcept>

#include "baker/integrate/fixed_rule_average.h"
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

/// Over eta (the catalogue's axis): the fixed rule.
bool OverEta(const TableSpec& spec) { return spec.axes.size() == 1 && spec.axes[0].name == "eta"; }

/// F_avg by the fixed mu rule (integrate/fixed_rule_average.h). For eta > 1, F(mu) is analytic
/// on [0, 1] with branch points at mu = +-i sqrt(eta^2 - 1): a layer at mu = 0 of that width,
/// which the rule's panels follow. For eta < 1 (total internal reflection below the critical
/// cosine sqrt(1 - eta^2), a square-root kink there) it takes the reciprocal side instead:
/// transmission is reciprocal, so the hemispherical transmittances satisfy
/// 1 - F_avg(eta) = eta^2 (1 - F_avg(1 / eta)) (tests hold both sides to adaptive quadrature).
double FresnelAverageFixed(double eta, long long* evals) {
  if (eta < 1) return 1 - eta * eta * (1 - FresnelAverageFixed(1 / eta, evals));
  Fresnel F{Fresnel::Kind::Dielectric, 0, eta, 0};
  auto f = [&](double mu) {
    if (evals) ++*evals;
    return F(mu);
  };
  return FixedCosineAverage(f, std::sqrt(eta * eta - 1));
}

std::vector<double> FixedRule(const TableSpec&, const double* x, IntegrationStats& stats) {
  if (!(x[0] > 0 && x[0] <= 100))
    throw std::invalid_argument("fresnel-dielectric-avg: eta must be in (0, 100]");
  stats.errorEstimate = kCosineAverageBound;
  return {FresnelAverageFixed(x[0], &stats.evals)};
}

std::string FixedRuleMethod(const TableSpec&) {
  return "fixed Gauss-Legendre rule in mu (" + std::to_string(kCosineAverageNodes) +
         " nodes per panel, panels graded from the layer sqrt(eta^2 - 1) at mu = 0); eta < 1 "
         "from 1 / eta by reciprocity";
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
    q.usesFixedRule = OverEta;
    q.fixedRule = FixedRule;
    q.fixedRuleMethod = FixedRuleMethod;
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
