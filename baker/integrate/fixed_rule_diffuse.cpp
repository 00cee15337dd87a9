// The diffuse fixed rule (fixed_rule_diffuse.h).
//
// Derivation. In light space, E = 2 int_0^{pi/2} dtheta_l sin(theta_l) cos(theta_l)
// int_0^pi dphi g(theta_l, phi), the factor 2 from the mirror symmetry phi -> -phi. The diffuse
// integrands are products and quotients of polynomials in sin and cos of theta_l, theta_o and
// phi (docs/models.md), with three kinds of non-smoothness:
//  1. kinks on the lines theta_l = theta_o (max/min of the angles: Oren-Nayar's alpha and beta,
//     Fujii's and Gotanda's max(mu_l, mu_o)) and phi = pi/2 (max(0, cos phi), |cos phi|, the
//     sign tests on o.l - mu_o mu_l). Panel boundaries there leave each panel analytic.
//  2. poles just outside the hemisphere near grazing views: Hammon's 1 / (n.h) ~ 1/(mu_l + mu_o)
//     at mu_l = -mu_o, full Oren-Nayar's tan((alpha + beta)/2) at theta_l = pi - theta_o, both at
//     theta_l ~ pi/2 + eps with eps = pi/2 - theta_o ~ mu_o, and Hammon's |o + l| (a branch point
//     at l = -o, phi = pi). On [0, theta_o] they sit at distance ~ 2 eps beyond the end of a
//     panel of length ~ pi/2: Gauss-Legendre would converge like (1 + sqrt(eps))^(-2n). Panels
//     graded geometrically towards theta_o (ratio 4, from eps up to theta_o / 2) keep every
//     singularity at least ~ 2/3 of a half panel beyond its panel, where n = 8 nodes converge
//     like 3^(-2n) ~ 1e-8 relative. [theta_o, pi/2] is one panel of length eps with its poles
//     one panel length beyond. For Hammon the azimuth gets the same grading towards phi = pi
//     (where l meets -o), at the same scale; Oren-Nayar's pole does not depend on phi.
//  3. Gotanda's GGX diffuse has (1 - mu_l)^p with non-integer p in [1.1, 5.3]: ~ theta_l^(2p) at
//     the normal, an end-point singularity of the first panel that the weight sin(theta_l) makes
//     theta^(2p+1); Gauss-Legendre errs like n^(-2(2p+2)) on it, 1e-8 at n = 8 for p = 1.1,
//     and one extra geometric panel towards theta_l = 0 takes it well below that.
// At eps = 0 (mu_o = 0) the poles reach the hemisphere's corner; the grading then starts at
// kMinGradingScale. Only Hammon and full Oren-Nayar have item 2's poles: the other models get the
// panels of items 1 and 3 alone. Measured against adaptive quadrature at 1e-10 on a dense (mu, r)
// grid for every catalogue diffuse model: tests/integrate_fixed_rule_diffuse.cpp (the worst is
// printed there).
#include "baker/integrate/fixed_rule_diffuse.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "baker/math/quadrature.h"

namespace kiln {
namespace {

/// The smallest grading scale: what the panels next to theta_o and phi = pi resolve at mu_o = 0.
constexpr double kMinGradingScale = 1e-4;
/// Geometric ratio of the graded panels.
constexpr double kRatio = 4;

/// Gauss-Legendre nodes and weights on [0, 1] for n = 1..64 (CachedGaussLegendre01).
const GaussRule01& Rule01(int n) {
  if (n < 1 || n > 64) throw std::invalid_argument("diffuse fixed rule: node count must be 1..64");
  return CachedGaussLegendre01(n);
}

/// Appends the nodes and weights of an n-point rule on every panel of `breaks` to (x, w).
void PanelRule(const std::vector<double>& breaks, int n, std::vector<double>& x,
               std::vector<double>& w) {
  const auto& rule = Rule01(n);
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double a = breaks[k], h = breaks[k + 1] - breaks[k];
    if (!(h > 0)) continue;
    for (int i = 0; i < n; ++i) {
      x.push_back(a + h * rule.x[i]);
      w.push_back(h * rule.w[i]);
    }
  }
}

/// Panel boundaries of [lo, hi] graded geometrically towards hi: hi - s, hi - 4 s, ... while the
/// distance stays below (hi - lo) / 2; ascending, lo and hi included.
std::vector<double> GradedTowardsEnd(double lo, double hi, double s) {
  std::vector<double> dists;
  for (double d = s; d < (hi - lo) / 2; d *= kRatio) dists.push_back(d);
  std::vector<double> b = {lo};
  for (size_t k = dists.size(); k-- > 0;) b.push_back(hi - dists[k]);
  b.push_back(hi);
  return b;
}

/// The models with item 2's poles.
template <class M>
constexpr bool kGrazingPoles = std::is_same_v<M, HammonDiffuse> || std::is_same_v<M, OrenNayar>;

/// Models whose Parts splits into factors of the polar angles (PolarFactors) and the rest
/// (PartsAt): Oren-Nayar (full, qualitative) and Gotanda's GGX diffuse, whose polar factors
/// (acos, sin, tan, pow) are most of an evaluation.
template <class M, class = void>
constexpr bool kHasPolarFactors = false;
template <class M>
constexpr bool kHasPolarFactors<
    M, std::void_t<decltype(std::declval<const M&>().PolarFactors(std::declval<PairGeometry>()))>> =
    true;

/// Which panels a model's view takes (item 2): none, graded towards theta_o (full Oren-Nayar),
/// or towards theta_o and phi = pi (Hammon).
enum class Grading { None, Theta, ThetaPhi };

template <class M>
constexpr Grading kGrading = std::is_same_v<M, HammonDiffuse> ? Grading::ThetaPhi
                             : kGrazingPoles<M>               ? Grading::Theta
                                                              : Grading::None;

/// The nodes of one view: per theta_l node its sin, cos and row weight 2 sin cos w, per azimuth
/// node its cos, sin and weight. They depend on (mu_o, grading, node counts) alone.
struct ViewNodes {
  std::vector<double> sinT, cosT, rowW, cosPhi, sinPhi, pw;
};

/// ViewNodes of (mu_o, g, opt), computed.
ViewNodes MakeViewNodes(double mu_o, Grading g, const DiffuseRuleOptions& opt) {
  double theta_o = std::acos(mu_o);
  // Item 2's poles: Hammon and full Oren-Nayar only; the others need no grading (eps = pi/2
  // leaves a single panel on each side of theta_o and of phi = pi/2).
  double eps = g != Grading::None ? std::max(Pi / 2 - theta_o, kMinGradingScale) : Pi / 2;
  // theta_l: [0, g0] towards the normal (item 3), then graded towards theta_o, then
  // [theta_o, pi/2].
  std::vector<double> thetaBreaks;
  if (theta_o > 0) {
    thetaBreaks = GradedTowardsEnd(0, theta_o, eps);
    if (thetaBreaks.size() > 1 && thetaBreaks[1] > 0.25 * theta_o)
      thetaBreaks.insert(thetaBreaks.begin() + 1, 0.25 * std::min(thetaBreaks[1], theta_o));
  } else {
    thetaBreaks = {0, 0.25};
  }
  // [theta_o, pi/2]: halved when longer than pi/4 (the polynomial models' (1 - mu_l)^5 factors
  // are degree ~12 in theta_l: two panels of n nodes take them to rounding).
  if (Pi / 2 - theta_o > Pi / 4) thetaBreaks.push_back((theta_o + Pi / 2) / 2);
  if (theta_o < Pi / 2) thetaBreaks.push_back(Pi / 2);
  // phi: graded towards pi only for Hammon's |o + l| (Oren-Nayar's pole does not depend on phi).
  std::vector<double> phiBreaks =
      GradedTowardsEnd(Pi / 2, Pi, g == Grading::ThetaPhi ? eps : Pi / 2);
  phiBreaks.insert(phiBreaks.begin(), 0.0);

  std::vector<double> tx, tw, px;
  ViewNodes v;
  PanelRule(thetaBreaks, opt.thetaNodes, tx, tw);
  PanelRule(phiBreaks, opt.phiNodes, px, v.pw);
  v.cosPhi.resize(px.size());
  v.sinPhi.resize(px.size());
  for (size_t j = 0; j < px.size(); ++j) {
    v.cosPhi[j] = std::cos(px[j]);
    v.sinPhi[j] = std::sin(px[j]);
  }
  v.sinT.resize(tx.size());
  v.cosT.resize(tx.size());
  v.rowW.resize(tx.size());
  for (size_t i = 0; i < tx.size(); ++i) {
    v.sinT[i] = std::sin(tx[i]);
    v.cosT[i] = std::cos(tx[i]);
    v.rowW[i] = 2 * v.sinT[i] * v.cosT[i] * tw[i];
  }
  return v;
}

/// Most views a thread keeps (an average's mu nodes, a table's mu axis: a few dozen each).
constexpr size_t kViewMemoSize = 512;

/// The ViewNodes of (mu_o, g, opt), kept per thread: an average's points evaluate E at the same
/// mu nodes for every roughness, a table's texels at the same mu for every row. The same bits as
/// computing them (MakeViewNodes is deterministic); the memo is cleared when full.
const ViewNodes& ViewNodesOf(double mu_o, Grading g, const DiffuseRuleOptions& opt) {
  struct Key {
    double mu;
    int g, thetaNodes, phiNodes;
    bool operator==(const Key& o) const {
      return std::memcmp(&mu, &o.mu, sizeof mu) == 0 && g == o.g && thetaNodes == o.thetaNodes &&
             phiNodes == o.phiNodes;
    }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h;
      std::memcpy(&h, &k.mu, sizeof h);
      h ^= (static_cast<uint64_t>(k.g) << 56) ^ (static_cast<uint64_t>(k.thetaNodes) << 40) ^
           (static_cast<uint64_t>(k.phiNodes) << 24);
      h *= 0x9E3779B97F4A7C15ull;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  thread_local std::unordered_map<Key, ViewNodes, Hash> memo;
  const Key key{mu_o, static_cast<int>(g), opt.thetaNodes, opt.phiNodes};
  auto it = memo.find(key);
  if (it != memo.end()) return it->second;
  ViewNodes v = MakeViewNodes(mu_o, g, opt);  // (throws on a bad node count: nothing kept)
  if (memo.size() >= kViewMemoSize) memo.clear();
  return memo.emplace(key, std::move(v)).first->second;
}

template <class M>
RhoParts Albedo(const M& m, double mu_o, const DiffuseRuleOptions& opt, long long* evals) {
  Vec3 wo = ViewDirection(mu_o);
  const ViewNodes& v = ViewNodesOf(mu_o, kGrading<M>, opt);
  const size_t nt = v.sinT.size(), np = v.cosPhi.size();
  double lin = 0, quad = 0;
  for (size_t i = 0; i < nt; ++i) {
    const double sinT = v.sinT[i], cosT = v.cosT[i];
    double rowLin = 0, rowQuad = 0;
    if constexpr (kHasPolarFactors<M>) {
      // A row has one theta_l: the model's polar factors once, then each azimuth's (Parts' own
      // operations, so Parts' bits). Below the horizon Parts is 0 at every azimuth: the row's
      // sums stay 0.
      const PairGeometry first(wo, Vec3{sinT * v.cosPhi[0], sinT * v.sinPhi[0], cosT});
      if (!first.Below()) {
        const auto polar = m.PolarFactors(first);
        for (size_t j = 0; j < np; ++j) {
          RhoParts p = m.PartsAt(
              polar, PairGeometry(wo, Vec3{sinT * v.cosPhi[j], sinT * v.sinPhi[j], cosT}));
          rowLin += v.pw[j] * p.lin;
          rowQuad += v.pw[j] * p.quad;
        }
      }
    } else {
      for (size_t j = 0; j < np; ++j) {
        RhoParts p = m.Parts(wo, Vec3{sinT * v.cosPhi[j], sinT * v.sinPhi[j], cosT});
        rowLin += v.pw[j] * p.lin;
        rowQuad += v.pw[j] * p.quad;
      }
    }
    lin += v.rowW[i] * rowLin;
    quad += v.rowW[i] * rowQuad;
  }
  if (evals) *evals += static_cast<long long>(nt * np);
  return {lin, quad};
}

}  // namespace

bool DiffuseRuleGradesGrazing(const AnyModel& model) {
  return std::visit([](const auto& m) { return kGrazingPoles<std::decay_t<decltype(m)>>; }, model);
}

RhoParts FixedRuleDiffuseAlbedo(const AnyModel& model, double mu_o, const DiffuseRuleOptions& opt,
                                long long* evals) {
  mu_o = Clamp(mu_o, 0.0, 1.0);
  return std::visit(
      [&](const auto& m) -> RhoParts {
        if constexpr (std::decay_t<decltype(m)>::kDomain == IntegrationDomain::HalfVector) {
          throw std::invalid_argument("diffuse fixed rule: needs a light-space (diffuse) model");
        } else {
          return Albedo(m, mu_o, opt, evals);
        }
      },
      model);
}

}  // namespace kiln
