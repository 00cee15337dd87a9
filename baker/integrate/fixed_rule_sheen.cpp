// The sheen fixed rule (fixed_rule_sheen.h).
//
// Derivation. With psi = pi - phi (phi the azimuth of l from o's),
//     E = 2 int_0^1 dmu_l int_0^pi dpsi f(o, l) mu_l       (mirror symmetry in phi).
// The sheen integrands are analytic inside the hemisphere; what spoils a plain Gauss rule:
//  1. l = -o, where h = (o + l) / |o + l| is undefined: (mu_l, psi) = (-mu_o, 0), at distance
//     mu_o beyond the horizon. Near it every lobe is a function of psi / (mu_l + mu_o) (a cone):
//     with the Charlie NDF ~ exp(-h_z^2 / (2 alpha)) and h_z ~ (mu_l + mu_o) / |o + l|, D is large
//     in the wedge mu_l + mu_o < r psi and small outside. At mu_o = 0 the cone sits on the
//     hemisphere's corner.
//  2. the Neubelt visibility's pole 1 / (mu_l + mu_o - mu_l mu_o) at mu_l = -mu_o / (1 - mu_o):
//     f mu_l ~ mu_l / (mu_l + mu_o), a layer of width mu_o at the horizon.
//  3. the lobes' layer at the horizon: Charlie's D falls like exp(-h_z^2 / (2 alpha)) with
//     h_z ~ mu_l + mu_o, width r = sqrt(alpha); the velvet spike exp(-cot^2 / alpha^2), width
//     alpha.
// Items 1-3 are scales between mu_o (or alpha) and 1 at one corner: the variables
//     t = ln(mu_l + c),  s = ln(psi + c),  c = max(mu_o, kMinLogScale),
// turn the pole (2) into an analytic function and the cone (1) into a function of s - t, both
// with features of width ~ 1 in (t, s); the layer (3) is a feature at t ~ ln r. Panels of at
// most 4 units in t and s, 12 x 8 Gauss-Legendre nodes per panel.
//  4. the mirror direction l = (-sin theta_o, 0, mu_o) (mu_l = mu_o, psi = 0), where h = n:
//     sin(theta_h)^(1/alpha) ~ |theta_h|^(1/alpha), not smooth unless 1/alpha is an even integer
//     (a cone |theta_h| at r = 1): panels graded geometrically (ratio 4, mirrorPanels = 3 of
//     them) towards mu_l = mu_o from both sides, and (psiPanels = 2) towards psi = 0, which also
//     take the cone of item 1 at mu_o -> 0. The velvet NDF, whose exp(-cot^2 / alpha^2) is
//     smooth but not analytic at theta_h = 0, takes the same panels.
//  5. charlie-smith: its Lambda switches form at mu = 1/2 (C1 only): a boundary at mu_l = 1/2;
//     the clamp V <= 1 is a kink where 4 mu_o mu_l (1 + Lambda(mu_o) + Lambda(mu_l)) = 1, a
//     condition on mu_l alone: boundaries at its roots (ClampSwitches; one root for every
//     mu_o > 0 and alpha measured, none at mu_o = 0 where V = 1). Lambda(mu_l) =
//     exp(2 L(1/2) - L(1 - mu_l)) has a (1 - mu_l)^c term at mu_l = 1, but there Lambda(mu_l) <
//     1e-2 next to 1 + Lambda(mu_o): no grading towards mu_l = 1 is needed (measured: the worst
//     error on the test's grid is the same with and without 3 graded panels there).
// Cost: V depends on (mu_o, mu_l) alone and is evaluated once per row of mu_l (charlie-smith's
// two Lambdas included), the NDF once per node. At most 5760 integrand evaluations per texel
// (6912 for charlie-smith; at mu_o -> 0, where t and s span 16 units), fewer at larger mu_o; the
// tables' texels average 2652 (charlie), 3161 (charlie-smith), 2622 (velvet) (kiln bake: the
// manifest's integrand_evaluations over texels). Measured against adaptive
// quadrature at 1e-10 (tests/integrate_fixed_rule_sheen.cpp prints the worst): below 3e-7 on
// 13 mu x 8 r per model.
// charlie-smith's nodes (kCharlieSmithRuleOptions). Its tables start at mu_o = 1e-4, where t
// and s span at most ~9 units, and the items above weigh differently for it: item 4's
// |theta_h|^(1/alpha) is smooth enough for plain panels once 1/alpha > 3.3, so the mirror
// grading is kept only for alpha > 0.3; item 3's layer gets a boundary of its own at
// mu_l = r / 2; and 12 x 6 nodes per panel. Measured (tests/integrate_fixed_rule_charlie_smith.cpp,
// adaptive at 1e-10, 25 mu from 1e-4 with 1/2 +- 1e-9, 15 r with sqrt(0.3) +- 1e-9): 10 x 6 left
// 3.6e-7 there, at 1,250 evaluations per texel on average over its tables (was 3,161), but every
// node of charlie-smith-albedo (10,752, against adaptive at 1e-10; `kiln verify --all-nodes`)
// found two over the bound, 8.0e-7 at (mu, r) = (0.167, 0.299) and 7.8e-7 at (0.187, 0.388),
// where the mirror mu_l = mu_o falls next to the lobe's boundary r / 2 (11 nodes: 6.9e-7): with
// 12, every node within 2.64e-7, at 1,500 evaluations. Below mu_o = 1e-4 it does not hold (4e-5 at
// mu_o = 0).
// Also checked against the closed forms at mu_o = 0 (E(0) = 2 int D sin^2(theta) dtheta: a
// Wallis integral for Charlie, 1/2 + 4 alpha/sqrt(pi) over (1 + 4 alpha^2) for the velvet),
// where the adaptive reference fails below r ~ 0.03 for the velvet (it misses the spike of
// width alpha): the velvet's tables start at r = 0.045 as the Charlie models'.
#include "baker/integrate/fixed_rule_sheen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "baker/integrate/fixed_rule_sheen_row.h"
#include "baker/math/quadrature.h"

namespace kiln {
namespace {

/// The smallest scale the logarithmic variables resolve (c at mu_o = 0).
constexpr double kMinLogScale = 1e-7;

template <class M>
constexpr bool kIsSheen = std::is_same_v<M, CharlieSheen> || std::is_same_v<M, CharlieSmithSheen> ||
                          std::is_same_v<M, AshikhminVelvet>;

/// Appends an n-point rule on every panel of `breaks` (each cut into equal panels no longer than
/// `maxLen`) to (x, w).
void PanelRule(std::vector<double> breaks, int n, double maxLen, std::vector<double>& x,
               std::vector<double>& w) {
  if (n < 1 || n > 64) throw std::invalid_argument("sheen fixed rule: node count must be 1..64");
  const GaussRule01& rule = CachedGaussLegendre01(n);
  std::sort(breaks.begin(), breaks.end());
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double a = breaks[k], len = breaks[k + 1] - breaks[k];
    if (!(len > 0)) continue;
    int pieces = std::max(1, static_cast<int>(std::ceil(len / maxLen - 1e-9)));
    double h = len / pieces;
    for (int p = 0; p < pieces; ++p)
      for (int i = 0; i < n; ++i) {
        x.push_back(a + p * h + h * rule.x[i]);
        w.push_back(h * rule.w[i]);
      }
  }
}

/// Lambda(mu_o) of charlie-smith (0 for the others): constant over a texel.
/// The azimuth nodes of a view: -cos(psi), sin(psi) and the weight ws = w e^s of each node in
/// s = ln(psi + c2), psi = pi - phi. They depend on (c2, the s panels' options) alone.
struct AzimuthNodes {
  std::vector<double> cosPhi, sinPhi, ws;
};

/// AzimuthNodes of (c2, opt), computed.
AzimuthNodes MakeAzimuthNodes(double c2, const SheenRuleOptions& opt) {
  auto S = [&](double psi) { return std::log(psi + c2); };
  std::vector<double> sBreaks = {S(0), S(Pi)};
  for (int k = 1; k <= opt.psiPanels; ++k) sBreaks.push_back(S(Pi * std::pow(0.25, k)));
  std::vector<double> sx, sw;
  PanelRule(sBreaks, opt.sNodes, opt.sPanel, sx, sw);
  AzimuthNodes a;
  a.cosPhi.resize(sx.size());
  a.sinPhi.resize(sx.size());
  a.ws.resize(sx.size());
  for (size_t j = 0; j < sx.size(); ++j) {
    double e = std::exp(sx[j]), psi = e - c2;
    a.cosPhi[j] = -std::cos(psi);
    a.sinPhi[j] = std::sin(psi);
    a.ws[j] = sw[j] * e;
  }
  return a;
}

/// Most views a thread keeps (an average's mu nodes, a table's mu axis: a few dozen each).
constexpr size_t kAzimuthMemoSize = 512;

/// The AzimuthNodes of (c2, opt), kept per thread: an average's points evaluate E at the same mu
/// nodes for every roughness, a table's texels at the same mu for every row. The same bits as
/// computing them (MakeAzimuthNodes is deterministic); the memo is cleared when full.
const AzimuthNodes& AzimuthNodesOf(double c2, const SheenRuleOptions& opt) {
  using Key = std::array<uint64_t, 4>;  // the bits of c2, sPanel; sNodes, psiPanels
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h = 0x9E3779B97F4A7C15ull;
      for (uint64_t v : k) h = (h ^ v) * 0xBF58476D1CE4E5B9ull;
      return static_cast<size_t>(h ^ (h >> 31));
    }
  };
  Key key{};
  std::memcpy(&key[0], &c2, sizeof c2);
  std::memcpy(&key[1], &opt.sPanel, sizeof opt.sPanel);
  key[2] = static_cast<uint64_t>(static_cast<uint32_t>(opt.sNodes));
  key[3] = static_cast<uint64_t>(static_cast<uint32_t>(opt.psiPanels));
  thread_local std::unordered_map<Key, AzimuthNodes, Hash> memo;
  auto it = memo.find(key);
  if (it != memo.end()) return it->second;
  AzimuthNodes a = MakeAzimuthNodes(c2, opt);  // (throws on a bad node count: nothing kept)
  if (memo.size() >= kAzimuthMemoSize) memo.clear();
  return memo.emplace(key, std::move(a)).first->second;
}

template <class M>
double LambdaOf(const M& m, double mu_o) {
  if constexpr (std::is_same_v<M, CharlieSmithSheen>) return CharlieSheenLambda(mu_o, m.alpha);
  return 0;
}

/// The model's visibility V(mu_o, mu_l) as its Parts computes it (lambdaO = LambdaOf(mu_o)).
template <class M>
double Visibility(const M& m, double mu_o, double mu_l, double lambdaO) {
  if constexpr (std::is_same_v<M, CharlieSmithSheen>) {
    double inv = 4 * mu_o * mu_l * (1 + lambdaO + CharlieSheenLambda(mu_l, m.alpha));
    return inv > 1 ? 1 / inv : 1.0;
  } else {
    return NeubeltVisibility(mu_o, mu_l);
  }
}

/// The model's NDF for the rows (fixed_rule_sheen_row.h: CharlieD or VelvetD with the inline exp
/// and log).
template <class M>
SheenRowNdf RowNdf(const M& m) {
  return SheenRowNdf{std::is_same_v<M, AshikhminVelvet>, m.alpha};
}

template <class M>
double Albedo(const M& m, double mu_o, const SheenRuleOptions& opt, long long* evals) {
  Vec3 wo = ViewDirection(mu_o);
  const double c = std::max(mu_o, kMinLogScale), c2 = std::max(mu_o, kMinLogScale);
  auto T = [&](double mu_l) { return std::log(mu_l + c); };
  std::vector<double> tBreaks = {T(0), T(1)};
  auto addMu = [&](double mu_l) {
    if (mu_l > 0 && mu_l < 1) tBreaks.push_back(T(mu_l));
  };
  addMu(mu_o);
  if (opt.lobeBreak > 0) addMu(opt.lobeBreak * std::sqrt(m.alpha));
  const int mirror = m.alpha > opt.mirrorMinAlpha ? opt.mirrorPanels : 0;
  for (int k = 1; k <= mirror; ++k) {
    double d = std::pow(0.25, k);
    addMu(mu_o * (1 - d));
    addMu(mu_o + (1 - mu_o) * d);
  }
  if constexpr (std::is_same_v<M, CharlieSmithSheen>) {
    addMu(0.5);
    for (double mu_l : m.ClampSwitches(mu_o)) addMu(mu_l);
  }
  const AzimuthNodes& az = AzimuthNodesOf(c2, opt);
  const std::vector<double>&cosPhi = az.cosPhi, &sinPhi = az.sinPhi, &ws = az.ws;

  std::vector<double> tx, tw;
  PanelRule(tBreaks, opt.tNodes, opt.tPanel, tx, tw);
  // The visibility depends on (mu_o, mu_l) alone and the NDF on sin^2(theta_h) alone: V (with
  // charlie-smith's Lambda(mu_o) and Lambda(mu_l)) is evaluated once per row of mu_l, the NDF
  // once per node (fixed_rule_sheen_row.h: the model's Parts' products D * V with the inline exp
  // and log, eight or four nodes at a time).
  // The rows are summed two at a time (SheenRowSum2: two independent chains of additions), their
  // terms added to the texel's sum in row order.
  const double lambdaO = LambdaOf(m, mu_o);
  const SheenRowNdf ndf = RowNdf(m);
  struct Row {
    SheenRow in;
    double scale;  ///< 2 mu_l tw_i e_i
  };
  std::vector<Row> rows;
  rows.reserve(tx.size());
  for (size_t i = 0; i < tx.size(); ++i) {
    double e = std::exp(tx[i]), mu_l = Clamp(e - c, 0.0, 1.0);
    if (!(mu_o + mu_l > 0)) continue;
    double sinT = std::sqrt(std::max(0.0, 1 - mu_l * mu_l));
    const double v = Visibility(m, mu_o, mu_l, lambdaO);
    rows.push_back({{wo.x, wo.z, sinT, mu_l, v, cosPhi.data(), sinPhi.data(), ws.data(), ws.size()},
                    2 * mu_l * tw[i] * e});
  }
  double sum = 0;
  for (size_t k = 0; k < rows.size(); k += 2) {
    double a = 0, b = 0;
    if (k + 1 < rows.size()) {
      SheenRowSum2(ndf, rows[k].in, rows[k + 1].in, &a, &b);
      sum += rows[k].scale * a;
      sum += rows[k + 1].scale * b;
    } else {
      sum += rows[k].scale * SheenRowSum(ndf, rows[k].in);
    }
  }
  if (evals) *evals += static_cast<long long>(tx.size() * ws.size());
  return sum;
}

}  // namespace

SheenRuleOptions SheenRuleOptionsFor(SheenRule rule, bool search) {
  if (rule == SheenRule::FittedSmith)
    return search ? kCharlieSmithSearchRuleOptions : kCharlieSmithRuleOptions;
  return search ? kSearchSheenRuleOptions : SheenRuleOptions{};
}

SheenRuleOptions SheenRuleOptionsFor(const std::string& model, bool search) {
  const ModelInfo* m = FindModel(model);
  return SheenRuleOptionsFor(m ? m->sheenRule : SheenRule::Neubelt, search);
}

bool IsSheenModel(const AnyModel& model) {
  return std::visit([](const auto& m) { return kIsSheen<std::decay_t<decltype(m)>>; }, model);
}

double FixedRuleSheenAlbedo(const AnyModel& model, double mu_o, const SheenRuleOptions& opt,
                            long long* evals) {
  mu_o = Clamp(mu_o, 0.0, 1.0);
  return std::visit(
      [&](const auto& m) -> double {
        if constexpr (kIsSheen<std::decay_t<decltype(m)>>) {
          return Albedo(m, mu_o, opt, evals);
        } else {
          throw std::invalid_argument("sheen fixed rule: needs a sheen model");
        }
      },
      model);
}

}  // namespace kiln
