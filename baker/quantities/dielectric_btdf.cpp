// btdf-split-sum: the split-sum pair of the rough dielectric's transmission (ggx-dielectric,
// models/dielectric_bsdf.h, Walter 2007) for image-based refraction, over (mu, roughness, eta) for
// a view entering the denser medium: T_lobe (the lobe's transmittance at F = 0) and T_F (its
// Fresnel-weighted part), so that an engine multiplies its prefiltered environment, sampled along
// the refracted direction, by T_lobe - s T_F (s = 1: the model's E_T; s the specular factor of
// KHR_materials_specular). The 3D table EEVEE bakes for refraction (docs/models.md,
// "ggx-dielectric: the split-sum BTDF pair"). Rule: integrate/dielectric_btdf.h.
#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/models/fresnel.h"
#include "baker/quantities/common.h"
#include "baker/quantities/dielectric_columns.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

constexpr const char* kModel = "ggx-dielectric";

TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::DielectricBtdfSplitSum,
               std::string(kModel) + "-" + QuantityName(Quantity::DielectricBtdfSplitSum), kModel,
               {"T_lobe", "T_F_residual"},
               {"T_lobe(mu): energy the rough dielectric's transmission lobe carries at F = 0 "
                "(importance form, without the 1/eta^2 radiance factor, 1 at roughness 0)",
                "T_F(mu) minus the closed form F(sqrt(mu^2 + alpha^2), eta) of kiln/stored.h "
                "btdfFresnelClosedForm (0 at roughness 0), T_F the Fresnel-weighted part of "
                "T_lobe, so that E_T = T_lobe - T_F, eta = inside / outside >= 1: the view enters "
                "the denser medium"},
               std::move(axes));
}

/// mu: root4-layer-angle as the entering glass E tables (the Fresnel layer at grazing, the
/// masking layer mu ~ alpha, T_lobe's grazing slope C(eta) alpha mu ln(1 / mu), and mu -> 1
/// graded in the angle), 80 nodes; roughness: sqrt (alpha = r^2 moves fastest near 0), 50
/// nodes; eta: the E tables' entering domain [kDielectricTableEtaMin, 3], sqrt-warped (the
/// Fresnel layer's width sqrt(eta^2 - 1)), 40 nodes (docs/models.md section 16).
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu", 0, 1, 80, Warp::Root4LayerAngle},
          {"roughness", 0, 1, 50, Warp::Sqrt},
          {"eta", kDielectricTableEtaMin, 3, 40, Warp::Sqrt}};
}

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec(kModel, DefaultAxes(kModel))};
}

/// (mu, r, eta) of x; an axis the planner fixed is read from params.
std::array<double, 3> PointOf(const TableSpec& spec, const double* x) {
  return {CoordinateOf(spec, x, "mu", 1), CoordinateOf(spec, x, "roughness", 0.5),
          CoordinateOf(spec, x, "eta", 1.5)};
}

/// True for a spec that stores T_F's residual (the catalogue's table and scenes' tables).
bool StoresResidual(const TableSpec& spec) {
  return spec.channels.size() > 1 && spec.channels[1] == "T_F_residual";
}

/// {T_lobe, T_F} as the spec stores them (T_F, or T_F minus kiln/stored.h's
/// btdfFresnelClosedForm at the same point).
std::vector<double> Stored(const TableSpec& spec, const double* x, std::array<double, 2> p) {
  if (StoresResidual(spec)) {
    const auto [mu, r, eta] = PointOf(spec, x);
    p[1] -= btdfFresnelClosedForm(mu, r, eta);
  }
  return {p[0], p[1]};
}

void CheckModel(const TableSpec& spec) {
  if (spec.model != kModel)
    throw std::invalid_argument(std::string(QuantityName(spec.quantity)) + " is baked for " +
                                kModel + " only, not '" + spec.model + "'");
}

bool UsesRule(const TableSpec& spec) { return spec.model == kModel; }

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  CheckModel(spec);
  const auto [mu, r, eta] = PointOf(spec, x);
  std::array<double, 2> p = FixedRuleDielectricBtdfPair(
      mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta, &stats.evals);
  stats.errorEstimate = kDielectricBtdfRuleBound;
  return Stored(spec, x, p);
}

/// The texels by columns of eta (quantities/dielectric_columns.h): one walk per (mu, roughness)
/// for the whole eta axis, each texel the bits FixedRule gives it.
void BakeTable(const TableSpec& spec, int threads, Table& table, std::vector<long long>& evals,
               std::vector<double>& errors) {
  CheckModel(spec);
  DielectricColumnBake how;
  how.columnOf = [&](const double* x, double* a, double* b, double* eta) {
    return MuRoughnessColumnOf(PointOf(spec, x), a, b, eta);
  };
  how.column = [](double mu, double alpha, const double* etas, int n, std::array<double, 2>* out,
                  long long* evals) {
    FixedRuleDielectricBtdfColumn(mu, alpha, etas, n, out, evals);
  };
  how.store = [&](const double* x, std::array<double, 2> p) { return Stored(spec, x, p); };
  how.bound = kDielectricBtdfRuleBound;
  BakeDielectricColumns(spec, threads, how, table, evals, errors);
}

std::string FixedRuleMethod(const TableSpec&) {
  DielectricBtdfRuleOptions o = TunedDielectricBtdfRuleOptions();
  return "fixed Gauss rule over the visible microfacet normals (v, phi_m), " +
         std::to_string(o.outerNodes[0]) + " x " + std::to_string(o.innerNodes[0]) +
         " nodes per panel at most, fewer by the panel's weight, panels at the horizon, the "
         "Fresnel "
         "layer and GGX's tail, "
         "smoothstep-mapped (integrate/dielectric_btdf.cpp)";
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  CheckModel(spec);
  const auto [mu, r, eta] = PointOf(spec, x);
  IntegrationOptions opt;
  opt.tol = tol;
  opt.maxPanels = 2000;
  return Stored(
      spec, x, DielectricBtdfPair(mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta, opt, stats));
}

/// Roughness 0: the smooth interface refracts all of the lobe, T_lobe = 1, T_F = F(mu, eta).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (spec.model != kModel) return false;
  const auto [mu, r, eta] = PointOf(spec, x);
  if (r != 0.0) return false;
  out = Stored(spec, x, SmoothDielectricBtdfPair(mu, eta));
  return true;
}

std::string Method(const TableSpec& spec) {
  return "adaptive Gauss-Kronrod over the visible microfacet normals (v, phi_m) to " +
         Full17(spec.tol) + " abs";
}

}  // namespace

const QuantityInfo& DielectricBtdfSplitSumQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::DielectricBtdfSplitSum;
    q.name = "btdf-split-sum";
    q.description = "image-based refraction through rough glass: env(refracted) (T_lobe - T_F)";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    // In the default catalogue since its lookup bound is below 1e-3 (the 80 x 50 x 40 grid) and
    // its texels cost ~1-2 s (eta columns): docs/catalogue.md.
    q.usesFixedRule = UsesRule;
    q.fixedRule = FixedRule;
    q.fixedRuleMethod = FixedRuleMethod;
    // Node counts by panel weight, the shared walk (dielectric_walk.h); from eta = 1.1 up one walk
    // per eta column, the Fresnel layer's panels at eta = 1.1's (integrate/dielectric_btdf.cpp).
    q.fixedRuleVersion = "4";
    q.bakeTable = BakeTable;
    q.evaluate = Evaluate;
    q.smoothLimit = SmoothLimit;
    q.method = Method;
    // Scenes: KHR_materials_transmission, eta = ior, the whole entering domain (refused outside).
    q.sceneKind = true;
    q.sceneModel = kModel;
    q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
    q.sceneDomain = DielectricTableDomain(false);
    q.readsParams = true;
    return q;
  }();
  return info;
}

}  // namespace kiln
