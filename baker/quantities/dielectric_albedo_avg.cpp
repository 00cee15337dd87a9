// albedo-r-avg, albedo-t-avg (and their -exit sides): the hemispherical averages
// E_avg = 2 int E(mu) mu dmu of the rough dielectric's reflected and transmitted energies
// (ggx-dielectric, Walter 2007; E_T in importance form), over (roughness, eta): the 2D tables a
// Turquin-style multiple-scattering compensation of glass reads next to the 3D E tables (Cycles
// bakes them beside its 3D ones). Entering: eta in [1.1, 3]; exit: eta' = 1/eta in [1/3, 1/1.1].
// One family, four kinds (which channel, which side), as quantities/dielectric_albedo.cpp.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/dielectric_kernel.h"
#include "baker/math/quadrature.h"
#include "baker/quantities/common.h"
#include "baker/quantities/dielectric_columns.h"

namespace kiln {
namespace {
using namespace quantity_detail;

constexpr const char* kModel = "ggx-dielectric";
constexpr double kEtaMin = kDielectricTableEtaMin;

struct Kind {
  Quantity id;
  bool transmit;  ///< E_avg_T (else E_avg_R)
  bool exit;      ///< eta in [1/3, 1/1.1] (else [1.1, 3])
};

const Kind kKinds[] = {{Quantity::DielectricAlbedoRAvg, false, false},
                       {Quantity::DielectricAlbedoTAvg, true, false},
                       {Quantity::DielectricAlbedoRExitAvg, false, true},
                       {Quantity::DielectricAlbedoTExitAvg, true, true}};

const Kind& KindOf(Quantity q) {
  for (const Kind& k : kKinds)
    if (k.id == q) return k;
  return kKinds[0];
}

template <Quantity Q>
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  const Kind& k = KindOf(Q);
  std::string meaning = k.transmit ? "E_avg_T = 2 int E_T(mu) mu dmu: the rough dielectric's "
                                     "hemispherical transmittance, without 1/eta^2"
                                   : "E_avg_R = 2 int E_R(mu) mu dmu: the rough dielectric's "
                                     "hemispherical reflectance";
  meaning += k.exit ? ", eta = inside / outside < 1 (leaving the denser medium)"
                    : ", eta = inside / outside >= 1 (entering the denser medium)";
  return Shell(Q, std::string(kModel) + "-" + QuantityName(Q), kModel,
               {k.transmit ? "E_avg_T" : "E_avg_R"}, {meaning}, std::move(axes));
}

/// roughness (linear warp) by eta (entering: sqrt warp from 1.1, exit: linear, as the E tables).
/// The averages are smooth in r, quadratic at r -> 0 (alpha = r^2), and curve most at r ~ 0.7:
/// with the sqrt warp the 24 x 16 grids declared 1.7e-3 (albedo-t-avg, at r = 0.79) and 1.2e-3
/// (albedo-r-exit-avg, r = 0.96); with the linear warp all four stay below 1e-3 (docs/catalogue.md,
/// glass). Exit: 32 x 24, since the search probes every cell's centre (bake/lookup_error.cpp) and
/// found albedo-r-exit-avg's 24 x 16 at 9.8e-4 (declared 1.5e-3; 8.3e-4 from 3 searched cells
/// before), at roughness 0.41, eta' 0.37: 32 x 24 declares 7.3e-4 (24 x 24 1.1e-3, 32 x 20 8.7e-4).
template <Quantity Q>
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  AxisSpec eta = KindOf(Q).exit ? AxisSpec{"eta", 1.0 / 3, 1 / kEtaMin, 24, Warp::Linear}
                                : AxisSpec{"eta", kEtaMin, 3, 16, Warp::Sqrt};
  return {{"roughness", 0, 1, KindOf(Q).exit ? 32 : 24, Warp::Linear}, eta};
}

template <Quantity Q>
std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec<Q>(kModel, DefaultAxes<Q>(kModel))};
}

std::array<double, 2> PointOf(const TableSpec& spec, const double* x) {
  return {CoordinateOf(spec, x, "roughness", 0.5),
          CoordinateOf(spec, x, "eta", KindOf(spec.quantity).exit ? 1 / 1.5 : 1.5)};
}

void CheckModel(const TableSpec& spec) {
  if (spec.model != kModel)
    throw std::invalid_argument(std::string(QuantityName(spec.quantity)) + " is baked for " +
                                kModel + " only, not '" + spec.model + "'");
}

bool UsesRule(const TableSpec& spec) { return spec.model == kModel; }

/// The one channel of the entering columns a kind reads: E_avg_T for t-avg and (by reciprocity)
/// t-exit-avg, E_avg_R for r-avg.
DielectricChannels ChannelOf(const TableSpec& spec) {
  return KindOf(spec.quantity).transmit ? DielectricChannels::T : DielectricChannels::R;
}

std::vector<double> FixedRule(const TableSpec& spec, const double* x, IntegrationStats& stats) {
  CheckModel(spec);
  const auto [r, eta] = PointOf(spec, x);
  const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
  stats.errorEstimate = kDielectricRuleBound + kDielectricAverageBound;
  const bool transmit = KindOf(spec.quantity).transmit;
  // The exit side, one channel each: E_avg_R by its own rule, E_avg_T by reciprocity.
  if (1 / eta >= kDielectricTableEtaMin && eta < 1)
    return {transmit
                ? FixedRuleDielectricExitAverageT(alpha, eta, kDielectricAverageNodes, &stats.evals)
                : KernelDielectricExitAverageR(alpha, eta, &stats.evals)};
  // The entering side: only the channel stored (dielectric_albedo_avg.h, DielectricChannels).
  std::array<double, 2> e =
      FixedRuleDielectricAlbedoAverage(alpha, eta, &stats.evals, ChannelOf(spec));
  return {e[transmit ? 1 : 0]};
}

/// The entering side's texels by columns of eta (quantities/dielectric_columns.h): the mu
/// panels and E's walks are shared by the whole eta axis; each texel the bits FixedRule gives.
void BakeTable(const TableSpec& spec, int threads, Table& table, std::vector<long long>& evals,
               std::vector<double>& errors) {
  CheckModel(spec);
  const int c = KindOf(spec.quantity).transmit ? 1 : 0;
  DielectricColumnBake how;
  // The exit side's E_avg_T by reciprocity: the entering column at 1 / eta, times eta^2.
  const bool exitT = KindOf(spec.quantity).exit && c == 1;
  how.columnOf = [&](const double* x, double* a, double* b, double* eta) {
    const auto [r, e] = PointOf(spec, x);
    const double etaIn = exitT && e < 1 ? 1 / e : e;
    if (r == 0 || !(etaIn >= kDielectricTableEtaMin)) return false;
    *a = std::max(AlphaFromPerceptual(r), MinAlpha);
    *b = 0;
    *eta = etaIn;
    return true;
  };
  const DielectricChannels channel = ChannelOf(spec);
  how.column = [channel](double alpha, double, const double* etas, int n,
                         std::array<double, 2>* out, long long* evals) {
    FixedRuleDielectricAlbedoAverageColumn(alpha, etas, n, out, evals, channel);
  };
  how.store = [&, c](const double* x, std::array<double, 2> e) {
    const double eta = PointOf(spec, x)[1];
    return std::vector<double>{exitT ? eta * eta * e[1] : e[c]};
  };
  how.bound = kDielectricRuleBound + kDielectricAverageBound;
  BakeDielectricColumns(spec, threads, how, table, evals, errors);
}

/// QuantityInfo::prepareSearch of the kinds the entering columns give (r-avg, t-avg, and
/// t-exit-avg at 1 / eta'): the search's points of one roughness integrated as columns of
/// entering etas, the columns in parallel, into the memo the fixed rule reads first
/// (PrepareDielectricAverageColumn: the same bits and evaluations as one point at a time). A
/// roughness with one point is left to the fixed rule.
void PrepareSearch(const TableSpec& spec, const double* points, size_t n) {
  if (!UsesRule(spec)) return;
  const bool exitT = KindOf(spec.quantity).exit;
  std::map<double, std::vector<double>> byAlpha;
  for (size_t i = 0; i < n; ++i) {
    const auto [r, e] = PointOf(spec, points + 3 * i);
    const double etaIn = exitT && e < 1 ? 1 / e : e;
    if (r == 0 || !(etaIn >= kDielectricTableEtaMin)) continue;
    byAlpha[std::max(AlphaFromPerceptual(r), MinAlpha)].push_back(etaIn);
  }
  std::vector<std::pair<double, std::vector<double>>> columns;
  for (auto& [alpha, etas] : byAlpha) {
    std::sort(etas.begin(), etas.end());
    etas.erase(std::unique(etas.begin(), etas.end()), etas.end());
    if (etas.size() < 2) continue;
    for (size_t b = 0; b < etas.size(); b += kMaxDielectricColumn)
      columns.push_back(
          {alpha, std::vector<double>(etas.begin() + static_cast<long>(b),
                                      etas.begin() + static_cast<long>(std::min(
                                                         etas.size(), b + kMaxDielectricColumn)))});
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, columns.size(), 1),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t c = range.begin(); c != range.end(); ++c)
                        PrepareDielectricAverageColumn(columns[c].first, columns[c].second.data(),
                                                       static_cast<int>(columns[c].second.size()),
                                                       ChannelOf(spec));
                    });
}

std::string FixedRuleMethod(const TableSpec& spec) {
  if (KindOf(spec.quantity).exit && !KindOf(spec.quantity).transmit)
    return "int_0^1 F(c, eta) c K_alpha(c) dc with K_alpha(c) independent of eta by a fixed "
           "Gauss rule over the visible normals, once per roughness: Gauss on geometric panels "
           "in c below 0.4, Chebyshev interpolation in sqrt(1 - c) above, panels graded in "
           "sqrt|c - c_crit| (integrate/dielectric_kernel.cpp)";
  return "fixed Gauss rule over mu (" + std::to_string(kDielectricAverageNodes) +
         " nodes per panel, panels graded from the GGX layer at mu = 0, in sqrt(1 - mu) towards "
         "mu = 1 and, eta < 1, in sqrt|mu - mu_c| about the critical cosine and sqrt|mu - eta| "
         "about mu = eta) of E by the 3D tables' rule (integrate/dielectric_albedo_avg.cpp)";
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double tol,
                             IntegrationStats& stats) {
  CheckModel(spec);
  const auto [r, eta] = PointOf(spec, x);
  std::array<double, 2> e =
      DielectricAlbedoAverage(std::max(AlphaFromPerceptual(r), MinAlpha), eta, tol, stats);
  return {e[KindOf(spec.quantity).transmit ? 1 : 0]};
}

/// The 3D E table kind whose mu integral kind `q` is.
Quantity AlbedoKindOf(Quantity q) {
  const Kind& k = KindOf(q);
  if (k.exit) return k.transmit ? Quantity::DielectricAlbedoTExit : Quantity::DielectricAlbedoRExit;
  return k.transmit ? Quantity::DielectricAlbedoT : Quantity::DielectricAlbedoR;
}

/// Where kiln verify's mu integral starts its panels (the GGX layer at mu = 0, the middle; the
/// adaptive panels find the exit side's kinks at mu_c and mu = eta).
constexpr double kVerifyMuBreaks[] = {0, 1e-4, 1e-2, 0.1, 0.5, 1};
constexpr int kVerifyMuPanels = 400;

bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out);

/// kiln verify's bake-error reference (QuantityInfo::verifyReference): adaptive Gauss-Kronrod
/// over mu to `tol` of 2 E(mu) mu, E as the matching 3D table bakes it (its rule, which that
/// table's own check holds to adaptive quadrature): independent of this kind's mu rule, where
/// the nested adaptive integral (Evaluate) takes millions of evaluations a node. On the entering
/// side E is this kind's channel alone (the other channel's walk skipped: the same bits).
std::vector<double> VerifyReference(const TableSpec& spec, const double* x, double tol,
                                    IntegrationStats& stats) {
  std::vector<double> smooth;
  if (SmoothLimit(spec, x, smooth)) return smooth;
  CheckModel(spec);
  const auto [r, eta] = PointOf(spec, x);
  const QuantityInfo& albedo = Describe(AlbedoKindOf(spec.quantity));
  const TableSpec e3 = albedo.makeSpec(kModel, albedo.defaultAxes(kModel));
  // The entering side: the 3D table's rule for this kind's channel alone (its column of one eta,
  // the bits it has with both channels, FixedRuleDielectricAlbedo), not the other's walk too.
  const bool transmit = KindOf(spec.quantity).transmit;
  const bool oneChannel = !KindOf(spec.quantity).exit && eta >= kDielectricTableEtaMin;
  const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
  auto e = [&](double mu) {
    if (oneChannel) {
      std::array<double, 2> col;
      FixedRuleDielectricAlbedoColumn(mu, alpha, &eta, 1, TunedDielectricRuleOptions(), &col,
                                      &stats.evals,
                                      transmit ? DielectricChannels::T : DielectricChannels::R);
      return Channels<1>{2 * mu * col[transmit ? 1 : 0]};
    }
    const double xm[3] = {mu, r, eta};
    IntegrationStats st;
    std::vector<double> v = EvaluateSpec(e3, xm, st);
    stats.evals += st.evals;
    return Channels<1>{2 * mu * v[0]};
  };
  const int n = static_cast<int>(std::size(kVerifyMuBreaks));
  return {IntegrateAdaptive<1>(e, kVerifyMuBreaks, n, tol, kVerifyMuPanels)[0]};
}

/// Roughness 0: the smooth interface's F_avg or 1 - F_avg.
bool SmoothLimit(const TableSpec& spec, const double* x, std::vector<double>& out) {
  if (spec.model != kModel) return false;
  const auto [r, eta] = PointOf(spec, x);
  if (r != 0.0) return false;
  out = {SmoothDielectricAlbedoAverage(eta)[KindOf(spec.quantity).transmit ? 1 : 0]};
  return true;
}

std::string Method(const TableSpec& spec) {
  return "adaptive Gauss-Kronrod over mu of E by adaptive quadrature, to " + Full17(spec.tol) +
         " abs";
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
  q.inDefaultCatalogue = true;  // below the 1e-3 contract, ~1-3 s each (docs/catalogue.md, glass)
  q.usesFixedRule = UsesRule;
  q.fixedRule = FixedRule;
  q.fixedRuleMethod = FixedRuleMethod;
  // 4: mu panels at mu = eta and towards 1, 10 nodes (integrate/dielectric_albedo_avg.cpp); 5,
  // entering: E by the eta columns' rule (integrate/dielectric_albedo.cpp).
  // 6, exit: E_avg_R by E_R's own panels, E_avg_T by reciprocity from the entering side.
  // 7, exit E_avg_R: by one kernel K_alpha(c) per roughness (integrate/dielectric_kernel.cpp).
  const bool kernel = KindOf(Q).exit && !KindOf(Q).transmit;
  q.fixedRuleVersion = kernel ? "7" : KindOf(Q).exit ? "6" : "5";
  if (!kernel) {
    q.bakeTable = BakeTable;
    q.prepareSearch = PrepareSearch;
  }
  // The mu nodes' E columns (integrate/dielectric_albedo_avg.cpp) and the kernel row's nodes
  // (integrate/dielectric_kernel.cpp) on the arena's threads.
  q.parallelPoint = true;
  q.evaluate = Evaluate;
  q.verifyReference = VerifyReference;
  q.smoothLimit = SmoothLimit;
  q.method = Method;
  q.sceneKind = true;
  q.sceneModel = kModel;
  q.sceneAxes = {{"roughness", "roughness"}, {"eta", "eta"}};
  q.sceneDomain = DielectricTableDomain(KindOf(Q).exit);
  q.readsParams = true;
  return q;
}

}  // namespace

const QuantityInfo& DielectricAlbedoRAvgQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoRAvg>(
      "albedo-r-avg", "rough dielectric's average reflected energy E_avg_R: glass compensation");
  return info;
}

const QuantityInfo& DielectricAlbedoTAvgQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoTAvg>(
      "albedo-t-avg", "rough dielectric's average transmitted energy E_avg_T: glass compensation");
  return info;
}

const QuantityInfo& DielectricAlbedoRExitAvgQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoRExitAvg>(
      "albedo-r-exit-avg", "E_avg_R seen from inside the denser medium (eta < 1): glass");
  return info;
}

const QuantityInfo& DielectricAlbedoTExitAvgQuantity() {
  static const QuantityInfo info = MakeInfo<Quantity::DielectricAlbedoTExitAvg>(
      "albedo-t-exit-avg", "E_avg_T seen from inside the denser medium (eta < 1): glass");
  return info;
}

}  // namespace kiln
