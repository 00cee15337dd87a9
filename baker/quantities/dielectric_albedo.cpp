// albedo-r, albedo-t (and their -exit sides): the energy the rough dielectric ggx-dielectric
// (models/dielectric_bsdf.h, Walter 2007) reflects, E_R(mu), and transmits, E_T(mu) (importance
// form: without the 1/eta^2 radiance factor, so E_R + E_T <= 1), over (mu, roughness, eta), the
// 3D tables Cycles bakes for its multiple-scattering glass. Entering: eta in [1, 3]; exit: the
// reciprocal side, eta' = 1/eta in [1/3, 1] (the view inside the denser medium: total internal
// reflection for mu < sqrt(1 - eta'^2)). One family, four kinds that differ in two flags (which
// channel, which side), so they share this file: each has its own descriptor and name.
#include "baker/integrate/dielectric_albedo.h"
#include "baker/models/fresnel.h"
#include "baker/quantities/common.h"
#include "baker/quantities/dielectric_columns.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

constexpr const char* kModel = "ggx-dielectric";

/// What distinguishes the kinds of the family.
struct Kind {
  Quantity id;
  bool transmit;  ///< E_T (else E_R)
  bool exit;      ///< eta in [1/3, 1] (else [1, 3])
};

const Kind kKinds[] = {{Quantity::DielectricAlbedoR, false, false},
                       {Quantity::DielectricAlbedoT, true, false},
                       {Quantity::DielectricAlbedoRExit, false, true},
                       {Quantity::DielectricAlbedoTExit, true, true}};

const Kind& KindOf(Quantity q) {
  for (const Kind& k : kKinds)
    if (k.id == q) return k;
  return kKinds[0];
}

/// Where the domain starts: eta >= kEtaMin entering, eta' <= 1 / kEtaMin exit. At eta -> 1 the
/// Fresnel term at grazing is a layer G(mu / sqrt(eta^2 - 1)) that collapses (F(0, eta) = 1 for
/// every eta > 1, F = 0 at eta = 1), which no tensor grid interpolates: with the domain from
/// eta = 1 the bake's search found a lookup error of 1.5 at (mu, r, eta) -> (0, 0, 1) (bake of
/// ggx-dielectric-albedo-r over [1, 3], `kiln inspect`). Transparent dielectrics against air
/// start near 1.2 (ice 1.31, water 1.33); 1.1 leaves the layer 0.46 wide. The planner refuses
/// an ior outside (sceneDomain).
constexpr double kEtaMin = kDielectricTableEtaMin;

/// The eta axis of a side: entering [1.1, 3], 40 nodes denser near its start (sqrt warp: the
/// Fresnel layer of width sqrt(eta^2 - 1) at grazing; eta nodes are the cheap ones, the
/// (mu, roughness) pairs are what a bake costs), exit [1/3, 1/1.1] angle, 41 nodes (denser
/// towards 1/1.1, where E bends most in eta'; node 18 lies 1.5e-4 from eta' = 1 / sqrt 2, where
/// the exit mu warp's two breaks cross and its node positions have a kink in eta').
/// docs/models.md section 16, "The exit pair below 1e-3".
AxisSpec EtaAxis(bool exit) {
  return exit ? AxisSpec{"eta", 1.0 / 3, 1 / kEtaMin, 41, Warp::Angle}
              : AxisSpec{"eta", kEtaMin, 3, 40, Warp::Sqrt};
}

template <Quantity Q>
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  const Kind& k = KindOf(Q);
  std::string meaning =
      k.transmit ? "E_T(mu): energy transmitted by the rough dielectric, without the 1/eta^2 "
                   "radiance factor (1 - F(mu) at roughness 0)"
                 : "E_R(mu): energy reflected by the rough dielectric (F(mu) at roughness 0)";
  meaning += k.exit ? ", eta = inside / outside < 1: the view leaves the denser medium"
                    : ", eta = inside / outside >= 1: the view enters the denser medium";
  return Shell(Q, std::string(kModel) + "-" + QuantityName(Q), kModel, {k.transmit ? "E_T" : "E_R"},
               {meaning}, std::move(axes));
}

/// The mu axis of a kind: entering, root4-layer-angle (the grazing layer graded as by
/// root4-layer, and mu -> 1 graded in the angle, where E_T has a (1 - mu)^(3/2) point at high
/// roughness), 80 nodes for both E_R and E_T (E_T's grazing slope C(eta) alpha mu ln(1 / mu)
/// needs them; one walk over the microfacets gives both at a (mu, roughness) pair, so the
/// pair shares its grid: docs/models.md section 16); exit, root4-layer-split2 (97 nodes: the
/// critical cosine sqrt(1 - eta'^2), where E has the kink of total internal reflection, and
/// mu = eta', where E_T has a one-sided point at high roughness (theta_o + theta_c = pi / 2),
/// are grid lines in every eta' layer, nodes graded on both sides of each).
AxisSpec MuAxis(const Kind& k) {
  if (k.exit) return AxisSpec{"mu", 0, 1, 97, Warp::Root4LayerSplit2};
  return AxisSpec{"mu", 0, 1, 80, Warp::Root4LayerAngle};
}

/// The roughness axis of a kind: entering 50 nodes sqrt; exit 50 arcsine (dense at both ends:
/// the exit E bends most near roughness 1, where sqrt is sparse, and the first cell must stay
/// thin for the grazing layer's corner, which linear is not; 50 nodes, not 56: 11% fewer
/// walks, `albedo-r-exit` declares 9.4e-4, 48 nodes 1.0e-3: docs/models.md section 16).
AxisSpec RoughnessAxis(const Kind& k) {
  if (k.exit) return {"roughness", 0, 1, 50, Warp::Arcsine};
  return {"roughness", 0, 1, 50, Warp::Sqrt};
}

template <Quantity Q>
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {MuAxis(KindOf(Q)), RoughnessAxis(KindOf(Q)), EtaAxis(KindOf(Q).exit)};
}

/// The catalogue's table stores E - dielectricAlbedoClosedForm (kiln/stored.h,
/// StoredForm::DielectricAlbedoResidual): the closed form is the smooth interface's F or 1 - F
/// at roughness 0 (a residual of 0 on that row: the Fresnel layer at grazing and the kink of
/// total internal reflection are not interpolated) and follows both, softened, as roughness
/// grows (docs/models.md, ggx-dielectric: the forms measured). The exit kinds store E -
/// dielectricExitClosedForm (StoredForm::DielectricExitResidual): F averaged over GGX's slope
/// spread follows E across the kink of total internal reflection, which the softened form does
/// not (declared 1.3e-2 with it, 3.5e-3 / 4.3e-3 with this one on the 49 x 40 x 24 grid, 8.1e-4 /
/// 6.9e-4 on mu 97 root4-layer-split2 x roughness 56 arcsine x eta' 41 angle, 9.4e-4 / 7.3e-4
/// with roughness 50 arcsine; docs/catalogue.md, glass).
template <Quantity Q>
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  const Kind& k = KindOf(Q);
  TableSpec s = MakeSpec<Q>(kModel, DefaultAxes<Q>(kModel));
  if (k.exit) {
    s.channels = {k.transmit ? "E_T_tir_residual" : "E_R_tir_residual"};
    s.meanings[0] = (k.transmit ? "E_T" : "E_R") + std::string(" minus the closed form g_") +
                    (k.transmit ? "T" : "R") +
                    "(mu, roughness, eta) of kiln/stored.h dielectricExitClosedForm (" +
                    (k.transmit ? "1 - F" : "F") +
                    " averaged over GGX's microfacet slopes, at roughness 0 the smooth " +
                    (k.transmit ? "1 - F" : "F") + "), for " + s.meanings[0];
    return {s};
  }
  s.channels = {k.transmit ? "E_T_residual" : "E_R_residual"};
  s.meanings[0] = (k.transmit ? "E_T" : "E_R") + std::string(" minus the closed form g_") +
                  (k.transmit ? "T" : "R") +
                  "(mu, roughness, eta) of kiln/stored.h dielectricAlbedoClosedForm (" +
                  (k.transmit ? "1 - F" : "F") + " at roughness 0), for " + s.meanings[0];
  return {s};
}

/// True for a spec that stores the residual (the catalogue's table; the kind's own makeSpec,
/// for kiln integrate and the averages' E, holds E itself).
bool StoresResidual(const TableSpec& spec) {
  return !spec.channels.empty() &&
         (spec.channels[0] == "E_R_residual" || spec.channels[0] == "E_T_residual");
}

/// True for a spec that stores the exit side's residual against dielectricExitClosedForm.
bool StoresExitResidual(const TableSpec& spec) {
  return !spec.channels.empty() &&
         (spec.channels[0] == "E_R_tir_residual" || spec.channels[0] == "E_T_tir_residual");
}

/// (mu, r, eta) of x; an axis the planner fixed is read from params.
std::array<double, 3> PointOf(const TableSpec& spec, const double* x) {
  const Kind& k = KindOf(spec.quantity);
  return {CoordinateOf(spec, x, "mu", 1), CoordinateOf(spec, x, "roughness", 0.5),
          CoordinateOf(spec, x, "eta", k.exit ? 1 / 1.5 : 1.5)};
}

/// The channel of {E_R, E_T} the spec's kind holds, as the spec stores it (E, or E minus the
/// closed form at the same point).
std::vector<double> Stored(const TableSpec& spec, const double* x, std::array<double, 2> e) {
  const bool transmit = KindOf(spec.quantity).transmit;
  double v = e[transmit ? 1 : 0];
  if (StoresResidual(spec)) {
    const auto [mu, r, eta] = PointOf(spec, x);
    v -= dielectricAlbedoClosedForm(mu, r, eta, transmit);
  } else if (StoresExitResidual(spec)) {
    const auto [mu, r, eta] = PointOf(spec, x);
    v -= dielectricExitClosedForm(mu, r, eta, transmit);
  }
  return {v};
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
  std::array<double, 2> e =
      FixedRuleDielectricAlbedo(mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta, &stats.evals);
  stats.errorEstimate = kDielectricRuleBound;
  return Stored(spec, x, e);
}

/// The entering side's texels by columns of eta (quantities/dielectric_columns.h): one walk per
/// (mu, roughness) for the whole eta axis, each texel the bits FixedRule gives it.
void BakeTable(const TableSpec& spec, int threads, Table& table, std::vector<long long>& evals,
               std::vector<double>& errors) {
  CheckModel(spec);
  DielectricColumnBake how;
  how.columnOf = [&](const double* x, double* a, double* b, double* eta) {
    return MuRoughnessColumnOf(PointOf(spec, x), a, b, eta);
  };
  how.column = [](double mu, double alpha, const double* etas, int n, std::array<double, 2>* out,
                  long long* evals) {
    FixedRuleDielectricAlbedoColumn(mu, alpha, etas, n, out, evals);
  };
  how.store = [&](const double* x, std::array<double, 2> e) { return Stored(spec, x, e); };
  how.bound = kDielectricRuleBound;
  BakeDielectricColumns(spec, threads, how, table, evals, errors);
}

std::string FixedRuleMethod(const TableSpec&) {
  DielectricRuleOptions o = TunedDielectricRuleOptions();
  return "fixed Gauss rule over the visible microfacet normals (v, phi_m), " +
         std::to_string(o.outerNodes[0]) + " x " + std::to_string(o.innerNodes[0]) +
         " nodes per panel at most, fewer by the panel's weight, panels at the horizons, the "
         "critical angle and the Fresnel and masking layers, smoothstep-mapped "
         "(integrate/dielectric_albedo.cpp)";
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  CheckModel(spec);
  const auto [mu, r, eta] = PointOf(spec, x);
  IntegrationOptions opt;
  opt.tol = tol;
  opt.maxPanels = 2000;
  std::array<double, 2> e =
      DielectricAlbedo(mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta, opt, stats);
  return Stored(spec, x, e);
}

/// Roughness 0: the smooth interface, E_R = F(mu, eta), E_T = 1 - F(mu, eta).
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (spec.model != kModel) return false;
  const auto [mu, r, eta] = PointOf(spec, x);
  if (r != 0.0) return false;
  out = Stored(spec, x, SmoothDielectricAlbedo(mu, eta));
  return true;
}

std::string Method(const TableSpec& spec) {
  return "adaptive Gauss-Kronrod over the visible microfacet normals (v, phi_m) to " +
         Full17(spec.tol) + " abs";
}

/// kiln integrate albedo-r|albedo-t --model ggx-dielectric --mu M --roughness R --eta E: any eta
/// (entering or exit), the adaptive reference.
template <Quantity Q>
std::string Integrate(const IntegrateRequest& req, const ModelParams& p, IntegrationStats& stats) {
  const std::string cmd = "integrate " + req.name;
  if (req.model.empty()) throw std::invalid_argument(cmd + ": needs --model " + kModel);
  if (req.model != kModel)
    throw std::invalid_argument(cmd + ": offered for --model " + kModel + " only, not '" +
                                req.model + "'");
  if (p.rho || p.f0 || p.k || p.rs || p.nu || p.nv)
    throw std::invalid_argument(cmd + ": " + kModel + " takes only --roughness and --eta");
  const ModelInfo& m = AllBsdfModels()[0];
  double r = p.roughness.value_or(m.params[0].def), eta = p.eta.value_or(m.params[1].def);
  if (!(r >= 0 && r <= 1))
    throw std::invalid_argument(cmd + ": --roughness = " + Full17(r) + " is outside [0, 1]");
  if (!(eta >= m.params[1].lo && eta <= m.params[1].hi))
    throw std::invalid_argument(cmd + ": --eta = " + Full17(eta) + " is outside [0.01, 100]");
  const int c = KindOf(Q).transmit ? 1 : 0;
  if (r == 0) return Full17(SmoothDielectricAlbedo(req.mu, eta)[c]);
  IntegrationOptions opt = RequestOptions(req);
  opt.maxPanels = 2000;
  return Full17(DielectricAlbedo(req.mu, AlphaFromPerceptual(r), eta, opt, stats)[c]);
}

template <Quantity Q>
QuantityInfo MakeInfo(const char* name, const char* description) {
  QuantityInfo q;
  q.id = Q;
  q.name = name;
  q.description = description;
  q.makeSpec = MakeSpec<Q>;
  q.defaultAxes = DefaultAxes<Q>;
  q.catalogue = Catalogue<Q>;
  // In the default catalogue: all four below the 1e-3 contract (docs/catalogue.md, glass).
  q.inDefaultCatalogue = true;
  q.usesFixedRule = UsesRule;
  q.fixedRule = FixedRule;
  q.fixedRuleMethod = FixedRuleMethod;
  // Entering: one walk per eta column, the Fresnel layer's panels at eta = 1.1's (integrate/
  // dielectric_albedo.cpp); the exit side's rule is unchanged (its grid is not: mu 97
  // root4-layer-split2 x roughness 50 arcsine x eta' 41 angle).
  q.fixedRuleVersion = KindOf(Q).exit ? "3" : "4";
  if (!KindOf(Q).exit) q.bakeTable = BakeTable;
  q.evaluate = Evaluate;
  q.smoothLimit = SmoothLimit;
  q.method = Method;
  // Scenes: KHR_materials_transmission (entering, eta = ior) and KHR_materials_volume (the exit
  // side too, eta = 1 / ior); the eta axis is the whole domain (refused outside, not extended).
  q.sceneKind = true;
  q.sceneModel = kModel;
  q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
  q.sceneDomain = DielectricTableDomain(KindOf(Q).exit);
  q.readsParams = true;
  if (!KindOf(Q).exit) {  // kiln integrate takes any eta: one command per channel
    q.integrateName = name;
    q.integrateHelp = KindOf(Q).transmit ? "albedo-t (ggx-dielectric: E_T, --eta)"
                                         : "albedo-r (ggx-dielectric: E_R, --eta)";
    q.integrateNeedsMu = true;
    q.integrate = Integrate<Q>;
  }
  return q;
}

}  // namespace

const QuantityInfo& DielectricAlbedoRQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoR>(
      "albedo-r", "rough dielectric's reflected energy E_R: glass, multiple scattering");
  return info;
}

const QuantityInfo& DielectricAlbedoTQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoT>(
      "albedo-t", "rough dielectric's transmitted energy E_T: glass, multiple scattering");
  return info;
}

const QuantityInfo& DielectricAlbedoRExitQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoRExit>(
      "albedo-r-exit", "E_R seen from inside the denser medium (eta < 1): glass");
  return info;
}

const QuantityInfo& DielectricAlbedoTExitQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoTExit>(
      "albedo-t-exit", "E_T seen from inside the denser medium (eta < 1): glass");
  return info;
}

}  // namespace kiln
