// fresnel-albedo-avg: the average over mu of fresnel-albedo, over (roughness, eta) -> E_avg.
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Baked for ggx only: `model` is ignored.
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::FresnelAlbedoAvg,
               std::string("ggx-") + QuantityName(Quantity::FresnelAlbedoAvg), "ggx", {"E_avg"},
               {"average of ggx-fresnel-albedo over mu (2 int E mu dmu)"}, std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {DefaultRoughnessAxis("ggx"), DefaultEtaAxis()};
}

/// 19 x 20 (380 texels): smooth in both. 24 x 16 left 1.04e-3 of declared lookup error in the
/// first eta cell (eta < 1.0089), 16 x 24 1.04e-3 at roughness 0.49; 19 x 20 declares 7.5e-4
/// (the lookup error `kiln bake` measured, baking each size).
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  std::vector<AxisSpec> axes = DefaultAxes("ggx");
  axes[0].size = 19;
  axes[1].size = 20;
  return {MakeSpec("ggx", axes)};
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  return GgxFresnelAlbedoAt(spec, x, tol, true, stats);
}

/// The fresnel-albedo table whose E(mu) the average integrates: axes (mu, roughness, eta), the
/// same tolerance.
TableSpec AlbedoSpecFor(const TableSpec& spec) {
  const QuantityInfo& albedo = Describe(Quantity::FresnelAlbedo);
  TableSpec e = albedo.makeSpec("ggx", albedo.defaultAxes("ggx"));
  e.tol = spec.tol;
  return e;
}

/// Every axis layout (an axis the planner fixed is read from params): the fixed mu rule of
/// AverageFixedRule over fresnel-albedo's E.
bool Always(const TableSpec&) { return true; }

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  double rest[2] = {Param(spec, "roughness", 0), Param(spec, "eta", 1.5)};
  for (size_t i = 0; i < spec.axes.size(); ++i) {
    if (spec.axes[i].name == "roughness") rest[0] = x[i];
    if (spec.axes[i].name == "eta") rest[1] = x[i];
  }
  return AverageFixedRule(AlbedoSpecFor(spec), rest, stats);
}

/// The lookup-error search's form: the same mu rule over fresnel-albedo's search rule.
std::vector<double> SearchRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  double rest[2] = {Param(spec, "roughness", 0), Param(spec, "eta", 1.5)};
  for (size_t i = 0; i < spec.axes.size(); ++i) {
    if (spec.axes[i].name == "roughness") rest[0] = x[i];
    if (spec.axes[i].name == "eta") rest[1] = x[i];
  }
  return AverageFixedRule(AlbedoSpecFor(spec), rest, stats, true);
}

std::string FixedRuleMethod(const TableSpec& spec) {
  return AverageFixedRuleMethod(AlbedoSpecFor(spec));
}

/// Roughness 0: a smooth dielectric interface, E_avg = 2 int FrDielectric(mu, eta) mu dmu (the
/// adaptive average of fresnel-dielectric-avg, to spec.tol).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (!OnSmoothLimit(spec, x)) return false;
  IntegrationOptions opt;
  opt.tol = spec.tol;
  IntegrationStats stats;
  const Fresnel F{Fresnel::Kind::Dielectric, 0, CoordinateOf(spec, x, "eta", 1.5), 0};
  out = {FresnelAverage(F, opt, stats)};
  return true;
}

std::string Method(const TableSpec& spec) { return AdaptiveMethod(true, true, spec.tol); }

std::string SceneProblem(const ModelInfo& m) {
  return m.fresnelTables
             ? ""
             : std::string(QuantityName(Quantity::FresnelAlbedoAvg)) + " is baked for ggx only";
}

}  // namespace

const QuantityInfo& FresnelAlbedoAvgQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::FresnelAlbedoAvg;
    q.name = "fresnel-albedo-avg";
    q.description = "average albedo with exact dielectric Fresnel";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.usesFixedRule = Always;
    q.fixedRule = FixedRule;
    q.searchRule = SearchRule;
    q.parallelPoint = true;  // a point's mu nodes run on the arena's threads
    q.fixedRuleMethod = FixedRuleMethod;
    q.fixedRuleVersion = "3";  // the GGX kernel from eta = 1.3
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    q.sceneKind = true;
    q.sceneModel = "ggx";
    q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
    q.sceneProblem = SceneProblem;
    q.readsParams = true;
    return q;
  }();
  return info;
}

}  // namespace kiln
