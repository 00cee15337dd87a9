// E_avg_R and E_avg_T of the GGX dielectric: a fixed rule over mu.
//
// Derivation. E(mu) is smooth in mu except (a) the GGX masking layer at mu = 0, of width ~ alpha
// (and the Fresnel layer of width sqrt(eta^2 - 1) for eta > 1, at least 0.46 on the tables'
// domain), and (b) for eta < 1, the critical cosine mu_c = sqrt(1 - eta^2): at alpha = 0, F = 1
// below it and 1 - k sqrt(mu - mu_c) + ... above (total internal reflection ends); at alpha > 0
// the kink is spread over the microfacet cosines, ~ alpha mu_c. The panels: (a) the geometric
// grid of fixed_rule_average.h from clamp(alpha, 1e-4, 1e-2) by 4 to 1; (b) breaks at
// mu_c -+ d, d = d0 16^k, d0 = max(alpha mu_c, 1e-7), and on every panel the variable
// s = sqrt|mu - mu_c| (Gauss-Legendre in s, mu = mu_c +- s^2, dmu = 2 s ds): the square root is
// analytic in s, and a panel [d, 16 d] is [sqrt d, 4 sqrt d] in s, a ratio the 8-node rule
// resolves whatever the softening's scale. Below d0 = 1e-7 the panel's share of the integral is
// below 2e-7 times E's variation across it; the tables' rule of E is within 6e-7 already.
// Two more points, found by the second differences of E(mu) on a fine mu grid
// (alpha 1, eta 0.79, 0.56, 0.91; alpha 0.3, eta 0.79): (c) for eta < 1, mu = eta, i.e.
// sin_o = mu_c: the near-vertical microfacets facing the view (c = o.m -> sin_o at theta_m ->
// pi/2) leave total internal reflection there, so E_T has a power-law point at mu = eta whatever
// alpha (its weight grows with alpha: GGX's tail). Without a break there the 8-node rule was
// 1.8e-5 off the adaptive reference in E_avg_T (alpha 1, eta 0.79). Panels graded in
// sqrt|mu - eta| either side, each reaching half-way to mu_c. (d) mu -> 1, where the rule's
// structures in theta_m (pi/4 -+ theta_o / 2, ...) meet: E follows theta_o ~ sqrt(2 (1 - mu)),
// so the last quarter of the last gap is graded in sqrt(1 - mu). Then 10 nodes per panel
// (kDielectricAverageNodes) stay within 1.3e-7 of 24 over a 12 x 12 sample of the tables' grid
// of both sides, 8 within 9.7e-7 (alpha 0.3, eta 1/1.1: against adaptive too).
// The smooth interface (alpha = 0) takes fresnel-dielectric-avg's route: F_avg by the same
// graded rule for eta > 1, reciprocity for eta < 1.
#include "baker/integrate/dielectric_albedo_avg.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_column_memo.h"
#include "baker/integrate/dielectric_kernel.h"
#include "baker/integrate/fixed_rule_average.h"
#include "baker/math/quadrature.h"
#include "baker/models/fresnel.h"

namespace kiln {
namespace {

/// One panel of the mu rule: [a, b] in mu, integrated in mu (kink = 0), or in s = sqrt(mu - c)
/// (kink = +1: above the kink c) or s = sqrt(c - mu) (kink = -1: below it).
struct Panel {
  double a, b;
  int kink;
  double c;
};

std::vector<Panel> Panels(double alpha, double eta) {
  std::vector<double> breaks = {0, 1};
  for (double b = std::clamp(alpha, 1e-4, 1e-2); b < 1; b *= 4) breaks.push_back(b);
  double muC = -1;
  if (eta < 1) {
    muC = std::sqrt((1 - eta) * (1 + eta));
    breaks.push_back(muC);
    for (double d = std::max(alpha * muC, 1e-7); d < 1; d *= 16) {
      breaks.push_back(muC - d);
      breaks.push_back(muC + d);
    }
    // mu = eta: sin_o = mu_c, where the near-vertical microfacets facing the view start to
    // transmit (c = o.m reaches the critical cosine at theta_m = pi/2): E_T has a power-law
    // point there, unsoftened by roughness. The panels either side of it, graded towards it,
    // reach half-way to mu_c (and as far on the other side): mu_c's structure, graded towards
    // from the other half, then lies sqrt(2) times the graded variable's range away.
    const double q = std::abs(eta - muC) / 2;
    breaks.push_back(eta);
    breaks.push_back(eta - q);
    breaks.push_back(eta + q);
  }
  breaks.erase(
      std::remove_if(breaks.begin(), breaks.end(), [](double b) { return !(b >= 0 && b <= 1); }),
      breaks.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  // mu = 1: the rule's structures in theta_m meet (pi/4 -+ theta_o / 2, ...) and E follows
  // theta_o = ~sqrt(2 (1 - mu)): a last panel over the last quarter of the last gap, graded in
  // sqrt(1 - mu) (the gap's other three quarters keep their grading, towards mu_c or eta).
  if (breaks.size() >= 2) {
    const double last = breaks[breaks.size() - 2];
    breaks.insert(breaks.end() - 1, 1 - (1 - last) / 4);
  }
  std::vector<Panel> out;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    Panel p{breaks[i], breaks[i + 1], 0, muC};
    if (eta < 1) {
      // A panel ending at mu = eta is graded in sqrt|mu - eta|, every other in sqrt|mu - mu_c|
      // (no panel contains either point).
      if (p.a == eta || p.b == eta) p.c = eta;
      p.kink = p.a >= p.c ? 1 : -1;
    }
    if (p.b == 1) {
      p.c = 1;
      p.kink = -1;
    }
    out.push_back(p);
  }
  return out;
}

/// The point mu and the weight dmu of panel p at t in [0, 1] (Lebesgue measure of t).
inline double PanelPoint(const Panel& p, double t, double* dmu) {
  if (p.kink == 0) {
    *dmu = p.b - p.a;
    return p.a + (p.b - p.a) * t;
  }
  // s from sa to sb (ascending in mu), mu = c +- s^2, dmu = 2 s ds.
  const double sa = std::sqrt(std::abs(p.a - p.c)), sb = std::sqrt(std::abs(p.b - p.c));
  const double s = sa + (sb - sa) * t;
  *dmu = 2 * s * std::abs(sb - sa);
  return p.kink > 0 ? p.c + s * s : p.c - s * s;
}

/// The points PrepareDielectricAverageColumn integrated ahead: {E_avg_R, E_avg_T} at
/// kDielectricAverageNodes, the channels computed and each one's evaluations for one point, by
/// the bits of (alpha, eta).
DielectricChannelMemo& PointMemo() {
  static DielectricChannelMemo memo(1 << 16);
  return memo;
}

DielectricChannelMemo::Key PointKey(double alpha, double eta) {
  return DielectricColumnMemo::KeyOf(alpha, kDielectricAverageNodes, &eta, 1);
}

/// The channels of `asked` that `held` lacks.
int Lacking(DielectricChannels asked, int held) { return static_cast<int>(asked) & ~held; }

/// The evaluations of the channels of `asked` in v; its e with the others NaN into out[0 .. n-1].
long long Read(const DielectricChannelMemo::Value& v, DielectricChannels asked,
               std::array<double, 2>* out) {
  long long evals = 0;
  for (int c = 0; c < 2; ++c)
    if (HasChannel(asked, c)) evals += v.evals[c];
  for (size_t e = 0; e < v.e.size(); ++e)
    for (int c = 0; c < 2; ++c) out[e][c] = HasChannel(asked, c) ? v.e[e][c] : NAN;
  return evals;
}

/// FixedRuleDielectricAlbedoAverageColumn's sums at `nodes` for the channels `channels` (the
/// others NaN) into v.e[0 .. n-1], each channel's evaluations (one eta's) into v.evals, v.has =
/// channels: the E column asked for each channel alone at every mu node (the bits it has in
/// both). Entering (every eta >= kDielectricTableEtaMin, which the E column checks): the mu
/// panels do not depend on eta. The E columns of the mu nodes are independent: they are walked
/// on the calling arena's threads (isolated: a thread waiting for them takes no other task of
/// its arena, which could need this column's memo entry), then summed in the nodes' order (the
/// bits of one thread's sum, for any thread count).
void AverageColumn(double alpha, const double* etas, int n, int nodes, DielectricChannels channels,
                   DielectricChannelMemo::Value& v) {
  if (n < 1 || n > kMaxDielectricColumn)
    throw std::invalid_argument("dielectric average column: " + std::to_string(n) + " etas");
  const GaussRule01& g = CachedGaussLegendre01(nodes);
  const DielectricRuleOptions opt = TunedDielectricRuleOptions();
  const std::vector<Panel> panels = Panels(alpha, etas[0]);
  const size_t K = g.x.size(), count = panels.size() * K;
  std::vector<std::array<double, 2>> cols(count * static_cast<size_t>(n));
  std::vector<double> mus(count), dmus(count);
  std::vector<std::array<long long, 2>> nodeEvals(count, {0, 0});
  const DielectricChannels one[2] = {DielectricChannels::R, DielectricChannels::T};
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        std::array<double, 2> part[kMaxDielectricColumn];
                        for (size_t i = r.begin(); i != r.end(); ++i) {
                          mus[i] = PanelPoint(panels[i / K], g.x[i % K], &dmus[i]);
                          std::array<double, 2>* col = &cols[i * static_cast<size_t>(n)];
                          for (int c = 0; c < 2; ++c) {
                            if (!HasChannel(channels, c)) continue;
                            FixedRuleDielectricAlbedoColumn(mus[i], alpha, etas, n, opt, part,
                                                            &nodeEvals[i][c], one[c]);
                            for (int e = 0; e < n; ++e) col[e][c] = part[e][c];
                          }
                        }
                      });
  });
  v.e.assign(static_cast<size_t>(n), {0, 0});
  v.evals[0] = v.evals[1] = 0;
  v.has = static_cast<int>(channels);
  for (size_t i = 0; i < count; ++i) {
    const double w = g.w[i % K];
    const std::array<double, 2>* col = &cols[i * static_cast<size_t>(n)];
    for (int c = 0; c < 2; ++c) {
      if (!HasChannel(channels, c)) continue;
      for (int e = 0; e < n; ++e) v.e[e][c] += 2 * w * dmus[i] * mus[i] * col[e][c];
      v.evals[c] += nodeEvals[i][c];
    }
  }
  for (int c = 0; c < 2; ++c)
    if (!HasChannel(channels, c))
      for (int e = 0; e < n; ++e) v.e[e][c] = NAN;
}

}  // namespace

int PrepareDielectricAverageColumn(double alpha, const double* etas, int n,
                                   DielectricChannels channels) {
  // Only the etas the memo does not hold yet with every channel asked, for the channels some of
  // them lack (a column gives each eta the bits and evaluations it gets alone, whatever else
  // the column holds; a channel an entry holds already is kept, not replaced).
  if (n < 1 || n > kMaxDielectricColumn)
    throw std::invalid_argument("dielectric average column: " + std::to_string(n) + " etas");
  double todo[kMaxDielectricColumn];
  int m = 0, need = 0;
  for (int e = 0; e < n; ++e) {
    DielectricChannelMemo::Value held;
    PointMemo().Find(PointKey(alpha, etas[e]), held);
    const int lack = Lacking(channels, held.has);
    if (lack == 0) continue;
    todo[m++] = etas[e];
    need |= lack;
  }
  if (m == 0) return 0;
  DielectricChannelMemo::Value col;
  AverageColumn(alpha, todo, m, kDielectricAverageNodes, static_cast<DielectricChannels>(need),
                col);
  for (int e = 0; e < m; ++e) {
    DielectricChannelMemo::Value point;
    point.e = {col.e[e]};
    point.evals[0] = col.evals[0];
    point.evals[1] = col.evals[1];
    point.has = col.has;
    PointMemo().Merge(PointKey(alpha, todo[e]), point);
  }
  return m;
}

std::array<double, 2> SmoothDielectricAlbedoAverage(double eta) {
  if (eta < 1) {
    const double tIn = SmoothDielectricAlbedoAverage(1 / eta)[1];
    return {1 - eta * eta * tIn, eta * eta * tIn};
  }
  auto f = [&](double mu) { return FrDielectric(mu, eta); };
  const double F = FixedCosineAverage(f, std::sqrt((eta - 1) * (eta + 1)));
  return {F, 1 - F};
}

std::array<double, 2> FixedRuleDielectricAlbedoAverage(double alpha, double eta, long long* evals,
                                                       DielectricChannels channels) {
  // The entering side through the search's points and the bake's memo of columns, as a column
  // of one (the same bits and evaluations): the lookup-error searches of r-avg and t-avg
  // integrate each point (and channel) they share once.
  if (eta >= kDielectricTableEtaMin) {
    DielectricChannelMemo::Value v;
    std::array<double, 2> e;
    if (PointMemo().Find(PointKey(alpha, eta), v) && Lacking(channels, v.has) == 0) {
      const long long read = Read(v, channels, &e);
      if (evals) *evals += read;
      return e;
    }
    FixedRuleDielectricAlbedoAverageColumn(alpha, &eta, 1, &e, evals, channels);
    return e;
  }
  return FixedRuleDielectricAlbedoAverage(alpha, eta, kDielectricAverageNodes, evals);
}

void FixedRuleDielectricAlbedoAverageColumn(double alpha, const double* etas, int n, int nodes,
                                            std::array<double, 2>* out, long long* evals,
                                            DielectricChannels channels) {
  DielectricChannelMemo::Value v;
  AverageColumn(alpha, etas, n, nodes, channels, v);
  const long long read = Read(v, channels, out);
  if (evals) *evals += read;
}

void FixedRuleDielectricAlbedoAverageColumn(double alpha, const double* etas, int n,
                                            std::array<double, 2>* out, long long* evals,
                                            DielectricChannels channels) {
  static DielectricChannelMemo memo(1 << 15);
  const DielectricChannelMemo::Key key =
      DielectricColumnMemo::KeyOf(alpha, kDielectricAverageNodes, etas, n);
  DielectricChannelMemo::Value v;
  memo.Find(key, v);
  const int lack = Lacking(channels, v.has);
  if (lack != 0) {
    DielectricChannelMemo::Value added;
    AverageColumn(alpha, etas, n, kDielectricAverageNodes, static_cast<DielectricChannels>(lack),
                  added);
    memo.Merge(key, added);
    if (v.has == 0)
      v = added;
    else
      DielectricChannelMemo::AddChannels(v, added);
  }
  const long long read = Read(v, channels, out);
  if (evals) *evals += read;
}

double FixedRuleDielectricExitAverageR(double alpha, double eta, int nodes, long long* evals) {
  return FixedRuleDielectricExitAverageR(alpha, eta, nodes, TunedDielectricRuleOptions(), evals);
}

double FixedRuleDielectricExitAverageR(double alpha, double eta, int nodes,
                                       const DielectricRuleOptions& opt, long long* evals) {
  const GaussRule01& g = CachedGaussLegendre01(nodes);
  double sum = 0;
  for (const Panel& p : Panels(alpha, eta))
    for (size_t k = 0; k < g.x.size(); ++k) {
      double dmu;
      const double mu = PanelPoint(p, g.x[k], &dmu);
      sum += 2 * g.w[k] * dmu * mu * FixedRuleDielectricReflectance(mu, alpha, eta, opt, evals);
    }
  return sum;
}

double FixedRuleDielectricExitAverageT(double alpha, double eta, int nodes, long long* evals) {
  // E_T alone: the entering column's E_T at 1 / eta (the search's point if it holds E_T).
  const double etaIn = 1 / eta;
  DielectricChannelMemo::Value v;
  std::array<double, 2> e;
  if (nodes == kDielectricAverageNodes && PointMemo().Find(PointKey(alpha, etaIn), v) &&
      HasChannel(static_cast<DielectricChannels>(v.has), 1)) {
    const long long read = Read(v, DielectricChannels::T, &e);
    if (evals) *evals += read;
    return eta * eta * e[1];
  }
  FixedRuleDielectricAlbedoAverageColumn(alpha, &etaIn, 1, nodes, &e, evals, DielectricChannels::T);
  return eta * eta * e[1];
}

std::array<double, 2> FixedRuleDielectricAlbedoAverage(double alpha, double eta, int nodes,
                                                       long long* evals) {
  if (eta >= kDielectricTableEtaMin) {  // the entering tables' rule: a column of one
    std::array<double, 2> e;
    FixedRuleDielectricAlbedoAverageColumn(alpha, &eta, 1, nodes, &e, evals);
    return e;
  }
  if (1 / eta >= kDielectricTableEtaMin)  // the exit tables' rule
    return {KernelDielectricExitAverageR(alpha, eta, evals),
            FixedRuleDielectricExitAverageT(alpha, eta, nodes, evals)};
  const GaussRule01& g = CachedGaussLegendre01(nodes);
  std::array<double, 2> sum{0, 0};
  for (const Panel& p : Panels(alpha, eta))
    for (size_t k = 0; k < g.x.size(); ++k) {
      double dmu;
      const double mu = PanelPoint(p, g.x[k], &dmu);
      const std::array<double, 2> e = FixedRuleDielectricAlbedo(mu, alpha, eta, evals);
      for (int c = 0; c < 2; ++c) sum[c] += 2 * g.w[k] * dmu * mu * e[c];
    }
  return sum;
}

std::array<double, 2> DielectricAlbedoAverage(double alpha, double eta, double tol,
                                              IntegrationStats& stats) {
  NestedAverageTolerance split;
  split.outer = tol / 2;
  split.inner = tol / 10;
  return DielectricAlbedoAverage(alpha, eta, split, stats);
}

namespace {

/// An adaptive average: E_avg, the evaluations and the error estimate its integration had.
struct AdaptiveAverageValue {
  std::array<double, 2> e{};
  long long evals = 0;
  double errorEstimate = 0;
};

/// The adaptive averages integrated so far (at most kAdaptiveMemoSize, then forgotten), by the
/// bits of (alpha, eta, outer, inner, graded): each gives both channels, so the r and t kinds at
/// one point (EvaluateSpec: one channel each) take one integration, seconds of one core.
class AdaptiveAverageMemo : public DielectricBitsMap<AdaptiveAverageValue> {
 public:
  using Value = AdaptiveAverageValue;
  static Key KeyOf(double alpha, double eta, const NestedAverageTolerance& tol) {
    const double split[3] = {tol.outer, tol.inner, tol.gradedByWeight ? 1.0 : 0.0};
    return DielectricBitsMap::KeyOf(alpha, eta, split, 3);
  }
  void Keep(const Key& key, const Value& v) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.size() >= kAdaptiveMemoSize) map_.clear();
    map_.emplace(key, v);
  }

 private:
  static constexpr size_t kAdaptiveMemoSize = 4096;
};

/// DielectricAlbedoAverage's integration itself: E_avg, its evaluations and error estimate.
AdaptiveAverageMemo::Value IntegrateDielectricAverage(double alpha, double eta,
                                                      const NestedAverageTolerance& tol) {
  AdaptiveAverageMemo::Value out;
  const std::vector<Panel> panels = Panels(alpha, eta);
  IntegrationOptions opt;
  opt.tol = tol.inner;
  opt.maxPanels = 2000;
  // x in [i, i + 1] is panel i at t = x - i.
  auto f = [&](double x) -> Channels<2> {
    const int i = std::min(static_cast<int>(x), static_cast<int>(panels.size()) - 1);
    double dmu;
    const double mu = PanelPoint(panels[i], x - i, &dmu);
    IntegrationStats s;
    IntegrationOptions at = opt;
    // An error d(mu) in E moves E_avg by int 2 mu d(mu) dmu: tol.inner / (2 mu) in all of it.
    if (tol.gradedByWeight) at.tol = std::min(tol.inner / (2 * mu), kMaxGradedInnerTol);
    const std::array<double, 2> e = DielectricAlbedo(mu, alpha, eta, at, s);
    out.evals += s.evals;
    return {2 * dmu * mu * e[0], 2 * dmu * mu * e[1]};
  };
  std::vector<double> xs(panels.size() + 1);
  for (size_t i = 0; i < xs.size(); ++i) xs[i] = static_cast<double>(i);
  const Channels<2> r = IntegrateAdaptive<2>(f, xs.data(), static_cast<int>(xs.size()), tol.outer,
                                             400, &out.errorEstimate);
  out.e = {r[0], r[1]};
  return out;
}

}  // namespace

std::array<double, 2> DielectricAlbedoAverage(double alpha, double eta,
                                              const NestedAverageTolerance& tol,
                                              IntegrationStats& stats) {
  static AdaptiveAverageMemo memo;
  const AdaptiveAverageMemo::Key key = AdaptiveAverageMemo::KeyOf(alpha, eta, tol);
  AdaptiveAverageMemo::Value v;
  if (!memo.Find(key, v)) {
    v = IntegrateDielectricAverage(alpha, eta, tol);
    memo.Keep(key, v);
  }
  stats.evals += v.evals;
  stats.errorEstimate = v.errorEstimate;
  return v.e;
}

}  // namespace kiln
