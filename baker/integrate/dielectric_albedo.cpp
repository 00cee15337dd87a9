// E_R and E_T of the GGX dielectric over the visible microfacet normals.
//
// Derivation. For a view o = (sin_o, 0, mu) above the interface, every microfacet normal m with
// c = o.m > 0 either reflects o to i_r = 2 c m - o (weight F(c)) or refracts it to
// i_t = -o / eta + (c / eta - cos_t) m, cos_t = sqrt(c^2 + eta^2 - 1) / eta (weight 1 - F(c); none
// under total internal reflection, c < c_crit = sqrt(1 - eta^2) when eta < 1). With the Jacobians
// of the two maps (Walter 2007 eq. 14 and 17) the integrals over i become, in both cases,
//     E = integral D(m) c G2(o, i) w / mu dm,   w = F [mu_i > 0] or (1 - F) [mu_i < 0]
// (a ray sent to the wrong side is lost: single scattering). Walk m by (v, phi): v = a^2 / (a^2 +
// tan^2 theta_m) is GGX's complementary CDF of D cos, so D cos dm = dv dphi / (2 pi), and by the
// mirror symmetry phi -> -phi
//     E = (1 / pi) int_0^1 dv int_0^pi dphi (c / cos_m) / (mu + mu Lambda(o) + mu Lambda(i)) w,
// the integrand bounded except for the 1 / cos_m of the GGX tail (v -> 0, handled by the smoothstep
// below). Along an azimuth circle (theta_m fixed), c = mu cos_m + sin_o sin_m cos(phi) is monotone,
// so every structure is a threshold c = c0, at cos(phi) = (c0 - mu cos_m) / (sin_o sin_m):
//   c0 = 0                  visibility (the end of the range),
//   c0 = mu / (2 cos_m)     the reflected ray's horizon,
//   c0 = c_crit             total internal reflection (eta < 1: F has a square-root kink),
//   c0 = (k^2 eta^2 - eta^2 + 1) / (2 k eta), k = mu / (eta cos_m)
//                           the refracted ray's horizon (eta < 1 only: for eta > 1 it always goes
//                           down; derived from mu_t = 0 and the decrease of c / eta - cos_t in c),
//   c0 = eps, 4 eps         eps = sqrt(|eta^2 - 1|): the Fresnel layer near eta = 1 (F has branch
//                           points at c = +-i eps), a smooth but steep structure.
// Those are the inner panel boundaries; the outer ones (in theta_m) are where a threshold curve
// meets phi = 0 or pi (cos(theta_m -+ theta_o) = c0: closed forms, and a scan with bisection for
// the refracted horizon). Every panel maps t in [0, 1] through the smoothstep 3t^2 - 2t^3, which
// turns the square-root and x^(3/2) behaviour at the thresholds (and the cos_m^-1 ~ v^(-1/2) of
// the tail) into analytic functions of t: Gauss converges fast on each panel.
// The adaptive rule bisects those panels (Gauss-Kronrod 15, to the tolerance), a panel's 15
// azimuth nodes in one call: in AVX-512F lanes where the CPU has them, with this file's scalar
// Integrand's bits (View::RingOf, dielectric_adaptive_nodes.h).
// The fixed rule (the bake's) takes the same panels, with two changes that cut its evaluations
// per point fourfold (27,000 -> 6,700 on the tuning grid, kTuned below):
//  - Gauss nodes per panel by weight class, not one count for all. An outer panel [v_a, v_b]
//    contributes at most W = (v_a - v_b) (mu + sin_o tan theta_m(v_b)) / gDen to E (the integrand
//    is bounded by (c / cos_m) / gDen and c <= mu cos_m + sin_o sin_m), so the many panels the
//    geometric sequences put into the GGX tail and the masking layer, of W ~ 1e-4 .. 1e-9, take
//    4 or 2 nodes instead of the bulk's 24; an inner panel takes nodes by its width in phi.
//  - The grazing sweep's panels grow by 16 instead of 4 (the smoothstep of a panel already
//    grades towards both ends); masking and tail sequences keep ratio 4.
// Every panel sums its nodes in order and the panels in order: deterministic. Both rules walk
// the panels with dielectric_walk.h (shared with the BTDF pair's rules, dielectric_btdf.cpp);
// this file supplies the thresholds and the integrand. The bake's entry point remembers its
// recent {E_R, E_T} (RuleMemo below): the E_R and E_T tables of one bake integrate each node once.
// Columns (the entering side, eta >= kDielectricTableEtaMin = 1.1). The panels above depend on
// eta only through the Fresnel layer's thresholds c0 = eps, 4 eps (eps = sqrt(eta^2 - 1)); the
// reflected ray's geometry (c, i_r, Lambda(i_r)) and the weight c / cos_m not at all. So the rule
// there fixes those thresholds at eta = 1.1's (eps = 0.458, 4 eps > 1: one threshold), whatever
// eta, and takes each channel where it is cheapest:
//  - E_R by Fresnel moments. The reflected term is wR F(c, eta), wR = w (c / cos_m) / (gDen +
//    mu Lambda(i_r)) independent of eta, and F(., eta) is a Chebyshev series of degree 26 in
//    2c - 1 within 1.1e-11 (dielectric_fresnel_moments.h: analytic on [0, 1], its nearest
//    singularities the branch points c = +-i eps and, for large eta, the pole c = -1 /
//    sqrt(eta^2 + 1)). So one walk of (v, phi_m) gathers the moments M_k = sum of wR T_k(2c - 1)
//    (ReflectedMoments: per node the geometry and 27 terms of the recurrence, eight nodes per
//    instruction), and E_R(eta) = sum_k a_k(eta) M_k: 27 multiply-adds per eta. By linearity this
//    is the rule applied to F_N, within 1.1e-11 E_1 of the rule applied to F (E_1 <= 1).
//  - E_T = T_lobe - T_F by the BTDF pair's column (dielectric_btdf.h: the refracted ray's panels
//    only, 2,083 evaluations a texel against the walk's 10,354; its memo lets the BTDF table and
//    these share one walk per column). Per eta there, with g = sqrt(c^2 + eta^2 - 1) = eta cos_t,
//    a = c + g, b = eta^2 c + g: 1 - F = 2 c g (b^2 + eta^2 a^2) / (a^2 b^2) and the refracted
//    ray's masking folded into one division (dielectric_lanes::EtaTerms).
// Each eta's value depends on that eta alone: a column of one (a single point: the lookup-error
// search, kiln verify) gives the bits the column gives. Evaluations per texel: the walk's 10,354
// plus the BTDF column's 2,083. On the held-out grid (tests/integrate_dielectric_rule_heldout.cpp)
// the entering points stay within 3e-7 of adaptive; on 1,100 entering points (10 eta 1.1 .. 3,
// 11 mu 0 .. 1, 10 roughness 1e-3 .. 1) E_R within 1.8e-8 and E_T within 6.2e-8 of adaptive at
// 1e-10 (docs/design/glass-tables.md, "The entering columns by Fresnel moments").
// The exit side (eta < 1.1) keeps the per-point walk, with the same integrand in fewer
// operations (FastView: F and mu_t from one g, each ray's masking folded into one division) and
// every walk's cos phi_m by a polynomial (dielectric_walk.h, CosHalfTurn). The exit averages'
// mu rule (the cross-check of their kernel route, dielectric_kernel.h) takes
// E_R alone on the reflected ray's panels (reflectOnly: no panels at the refracted ray's horizon
// and its masking layer; 4,450 evaluations per point against 7,580, within 3.9e-7 of adaptive on
// the exit held-out grid, tests/integrate_dielectric_reflectance.cpp) and E_avg_T by reciprocity
// from the entering side's column (integrate/dielectric_albedo_avg.cpp).
// Eight lanes. Where the CPU has AVX-512F (dielectric_simd.h, checked at run time) the walks
// keep each ring's nodes and evaluate them at the ring's end: the column walk's reflected part
// and its moments eight nodes at a time (ReflectedRing, RingMoments8; the BTDF column's per-eta
// part eight etas at a time, or eight nodes at a time for fewer etas). Same operations lane by
// lane, no fused multiply-add, the lanes' sums in one order: the same bits as the portable path
// (tests/integrate_dielectric_simd.cpp; docs/design/glass-tables.md, "The rule's cost").
// The exit walk's own counts (eta < 1, kTuned's exit fields): 20 / 12 / 4 / 2 outer nodes, and the
// azimuth nodes of a ring by its outer panel's class too (ExitClassesOf); outer breaks where the
// cap c > c_crit passes the pole (CapPoleBreaks). The walk (FastWalk: the exit side, the entering
// side below eta 1.1 and E_R alone): its breaks by dielectric_exit_breaks.h (one division a ring,
// acos by a polynomial, the refracted horizon by false position; on the AVX-512F path an outer
// panel's rings eight at once, dielectric_exit_breaks_simd.cpp), a ring's nodes from precomputed
// smoothstep shares, the integrand with fused multiply-adds and its sums in eight lanes, by
// AVX-512F where the CPU has it (dielectric_simd_exit.cpp), else the same operations one node at
// a time with std::fma (dielectric_exit_ring.cpp): the same bits on either path, 0.66x the CPU
// time of FixedWalk's operations on the AVX-512F path (docs/design/glass-tables.md, "The exit
// walk by its own arithmetic").
// The exit pair by total internal reflection's complement (exitTirComplement, eta < 1, mu >=
// kTirComplementMinMu). Under total internal reflection (c < c_crit) F = 1 exactly and only the
// reflected term exists, so with r1 the reflected term at F = 1,
//     E_R = E_1 - integral_{c > c_crit} (1 - F) r1,   E_T = integral_{c > c_crit} (1 - F) t1,
// E_1 = integral r1 over every visible normal: GGX's directional albedo with F = 1 and the walk's
// height-correlated Smith G2, which fixed_rule_dfg.h's rule gives as A + B in ~550 evaluations
// (kE1Rule: within 4e-8 of adaptive quadrature). The walk then skips every ring whose largest
// cosine (phi = 0) and every azimuth panel whose first node lie below c_crit by kTirMargin (c
// falls with phi: the rest of the ring too), and its ring takes (Fd - Fn) / Fd instead of Fn / Fd
// on the reflected ray. The skipped nodes added +0 to E_T: its sums keep their bits. 0.49x the
// evaluations per texel of the exit pair (docs/design/glass-tables.md, "The exit pair by total
// internal reflection's complement").
#include "baker/integrate/dielectric_albedo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "baker/integrate/dielectric_adaptive_nodes.h"
#include "baker/integrate/dielectric_column_memo.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/integrate/dielectric_exit_breaks.h"
#include "baker/integrate/dielectric_fresnel_moments.h"
#include "baker/integrate/dielectric_lanes.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/dielectric_walk.h"
#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/math/quadrature.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"
#include "baker/models/roughness.h"

namespace kiln {
static_assert(dielectric_simd::kMaxColumnEtas == kMaxDielectricColumn,
              "dielectric_simd::AddColumnRing sizes its rings by kMaxColumnEtas");
namespace {

constexpr int kMaxBreaks = dielectric_walk::kMaxThetaBreaks;
static_assert(dielectric_simd::kMaxRingPhis == dielectric_walk::kMaxPhiBreaks,
              "PhiBreaks8's rings hold the walk's inner breaks");
static_assert(dielectric_simd::kMaxRingNodes >=
                  (dielectric_walk::kMaxPhiBreaks - 1) * kMaxCachedGaussNodes,
              "a ring's nodes must fit the AVX-512F paths' buffer");

/// The view and interface: what every evaluation needs.
struct View {
  double mu, st, thetaO, eta, eta2m1, cCrit, eps;
  double gDen;  ///< mu + mu Lambda(o)
  GGXDistribution dist;
  /// The constant threshold cosines of the Fresnel layer (eps, 4 eps, or a column's fixed set).
  int ncs = 0;
  double cs[2] = {0, 0};
  /// E_R alone (the exit averages' rule): no panels at the refracted ray's structures.
  bool reflectOnly = false;
  /// Ratios of the geometric panel sequences (DielectricRuleOptions): masking, grazing, tail.
  double maskingRatio = 4, grazingRatio = 4, tailRatio = 4;
  // The problem dielectric_walk.h walks (defined below).
  int ThetaBreaks(double* thetas) const;
  int PhiBreaks(PolarParam h, double* phis) const;
  Channels<2> Integrand(PolarParam h, double cp) const;
  using AdaptiveRing = dielectric_walk::LaneRing<View, dielectric_adaptive::AlbedoRing,
                                                 dielectric_adaptive::AlbedoNodes>;
  /// The adaptive walk's ring at h: its nodes at once (dielectric_walk::HasRingNodes), in
  /// AVX-512F lanes where dielectric_simd::Enabled() (the ring's constants once).
  AdaptiveRing RingOf(PolarParam h) const;
};

View MakeView(double mu, double alpha, double eta) {
  View v;
  v.mu = Clamp(mu, 0.0, 1.0);
  v.st = std::sqrt(std::max(0.0, (1 - v.mu) * (1 + v.mu)));
  v.thetaO = std::acos(v.mu);
  v.eta = eta;
  v.eta2m1 = (eta - 1) * (eta + 1);
  v.cCrit = eta < 1 ? std::sqrt(-v.eta2m1) : 0;
  v.eps = std::sqrt(std::abs(v.eta2m1));
  v.dist.alpha = std::max(alpha, MinAlpha);
  v.gDen = v.mu + v.dist.MuLambda(v.mu);
  if (eta != 1) {
    v.cs[v.ncs++] = v.eps;
    v.cs[v.ncs++] = 4 * v.eps;
  }
  return v;
}

/// mu of the refracted ray for c = o.m above the critical cosine, at microfacet cosine cosM (one
/// formula for both walks: dielectric_exit_breaks.h).
using dielectric_exit_breaks::MuRefracted;

/// The integrand {R, T} at microfacet polar angle h and azimuth cos(phi) = cp (without 1/pi).
inline Channels<2> Integrand(const View& v, PolarParam h, double cp) {
  Channels<2> out{0, 0};
  double c = v.mu * h.cosTheta + v.st * h.sinTheta * cp;
  if (!(c > 0) || !(h.cosTheta > 0)) return out;
  double base = c / h.cosTheta;
  double F = FrDielectric(std::min(c, 1.0), v.eta);
  double muR = 2 * c * h.cosTheta - v.mu;
  if (muR > 0 && F > 0) out[0] = base * F / (v.gDen + v.mu * (v.dist.MuLambda(muR) / muR));
  if (F < 1) {
    double muT = -MuRefracted(v, c, h.cosTheta);  // > 0: the ray goes down
    if (muT > 0) out[1] = base * (1 - F) / (v.gDen + v.mu * (v.dist.MuLambda(muT) / muT));
  }
  return out;
}

View::AdaptiveRing View::RingOf(PolarParam h) const {
  const double a2 = dist.alpha * dist.alpha, eta2 = eta * eta;
  return {*this,
          h,
          dielectric_simd::Enabled(),
          {mu * h.cosTheta, st * h.sinTheta, h.cosTheta, mu, gDen, a2, eta, eta2m1, eta2, eta2 + 1,
           -mu / eta}};
}

/// The bake rule's problem off the columns (eta < kDielectricTableEtaMin: the exit side, and
/// the entering side's first 10%), walked by FastWalk: Integrand's values in fewer operations,
/// which dielectric_simd's ring sums compute (FastRingSums, PortableRingSums). F from g^2 = c^2 +
/// eta^2 - 1 (total internal reflection where g^2 <= 0) by FrDielectric's cancellation-free forms
/// over one denominator (a = c + g, b = eta^2 c + g, X = (eta^2 + 1) c^2 - 1):
///     F = (eta^2 - 1)^2 (b^4 + X^2 a^4) / (2 a^4 b^4);
/// the refracted ray mu_t = (mu - (c - g) cos_m) / eta from the same g; each ray's masking
/// mu Lambda(i) = mu alpha^2 s_i^2 / P, P = 2 mu_i (sqrt(mu_i^2 + alpha^2 s_i^2) + mu_i), folded
/// with the weight into one division.
struct FastView : View {
  double a2 = 0, eta2 = 0;
  /// E_R as E_1 minus total internal reflection's complement (FastWalk; eta < 1 only).
  bool tirComplement = false;
};

/// The view of the fixed rule with options `opt` (its panel sequences' ratios).
View MakeRuleView(double mu, double alpha, double eta, const DielectricRuleOptions& opt) {
  View v = MakeView(mu, alpha, eta);
  v.maskingRatio = opt.maskingRatio;
  v.grazingRatio = opt.grazingRatio;
  v.tailRatio = opt.tailRatio;
  return v;
}

/// The same as a FastView (alpha^2 and eta^2 precomputed).
FastView MakeFastView(double mu, double alpha, double eta, const DielectricRuleOptions& opt) {
  FastView v;
  static_cast<View&>(v) = MakeRuleView(mu, alpha, eta, opt);
  v.a2 = Sqr(v.dist.alpha);
  v.eta2 = eta * eta;
  return v;
}

/// Threshold cosines c0 of the inner structures at microfacet polar angle h (see file comment).
int Thresholds(const View& v, PolarParam h, double* c0) {
  int n = 0;
  c0[n++] = v.mu / (2 * h.cosTheta);
  for (int i = 0; i < v.ncs; ++i) c0[n++] = v.cs[i];
  // The reflected ray's masking layer, mu_i ~ min(mu, alpha): geometric thresholds in mu_i.
  double scale = std::min(v.mu, v.dist.alpha);
  for (double m = scale / 4; m > 0 && m < 0.25 && n < 20; m *= v.maskingRatio)
    c0[n++] = (m + v.mu) / (2 * h.cosTheta);
  if (v.eta < 1) {
    c0[n++] = v.cCrit;
    // mu_t = -m for m = 0 (the horizon) and the masking layer's geometric m below mu.
    for (double m = 0; n < 30 && !v.reflectOnly; m = m == 0 ? scale / 4 : v.maskingRatio * m) {
      double k = (v.mu / v.eta - m) / h.cosTheta;
      if (!(k > 0)) break;
      double c = (k * k * v.eta * v.eta - v.eta * v.eta + 1) / (2 * k * v.eta);
      if (c >= k * v.eta && c > v.cCrit && c < 1) c0[n++] = c;
      if (!(scale > 0) || m > 0.25) break;
    }
  }
  return n;
}

/// Inner panel boundaries in phi over [0, phiMax] at polar angle h; returns their count (>= 2), or
/// 0 when nothing is visible.
int PhiBreaks(const View& v, PolarParam h, double* phis) {
  double den = v.st * h.sinTheta;
  auto cosPhiOf = [&](double c0) { return (c0 - v.mu * h.cosTheta) / den; };
  double phiMax = Pi;
  if (den > 0) {
    double cEnd = cosPhiOf(0);
    if (cEnd >= 1) return 0;
    if (cEnd > -1) phiMax = std::acos(cEnd);
  } else if (!(v.mu * h.cosTheta > 0)) {
    return 0;
  }
  int n = 0;
  phis[n++] = 0;
  if (den > 0) {
    double c0[32];
    int nc = Thresholds(v, h, c0);
    for (int i = 0; i < nc; ++i) {
      double cp = cosPhiOf(c0[i]);
      if (cp > -1 && cp < 1) {
        double p = std::acos(cp);
        if (p > 0 && p < phiMax) phis[n++] = p;
      }
    }
  }
  phis[n++] = phiMax;
  SortSmall(phis, n);
  return n;
}

/// The exit walk's outer breaks where the cap c > c_crit passes the pole theta_m = 0: its edge
/// there is at theta_m = d = |theta_o - acos c_crit| (the ring that touches it at phi = 0 or pi:
/// ThetaBreaks' critical-angle breaks), and the rings just beyond it cut the cap over an azimuth
/// range that changes on the scale d (at mu = mu_c, d = 0, their share of the cap grows like
/// sqrt(theta_m)). A single outer panel from d to the next break left 1.0e-6 at mu = mu_c + 6e-4,
/// roughness 0.55, eta' 1/3; geometric breaks d 8^k up to kCapPoleEnd (from kCapPoleFloor where d
/// is smaller) hold that structure to the panels' smoothstep.
constexpr double kCapPoleRatio = 8, kCapPoleFloor = 1e-3, kCapPoleEnd = 0.25;
template <class Add>
void CapPoleBreaks(const View& v, Add&& add) {
  double d = std::fabs(v.thetaO - std::acos(v.cCrit));
  if (d < kCapPoleFloor) {
    add(kCapPoleFloor);
    d = kCapPoleFloor;
  }
  for (double t = kCapPoleRatio * d; t < kCapPoleEnd; t *= kCapPoleRatio) add(t);
}

/// Outer panel boundaries in theta_m over [0, pi/2]. fast: the refracted horizon's by
/// dielectric_exit_breaks.h (the exit walk's, both paths), else by the scan and bisection below.
int ThetaBreaks(const View& v, double* thetas, bool fast = false) {
  int n = 0;
  const double to = v.thetaO, end = Pi / 2;
  auto add = [&](double t) {
    if (t > 0 && t < end && n < kMaxBreaks - 2) thetas[n++] = t;
  };
  thetas[n++] = 0;
  // Reflection horizon meets phi = pi and phi = 0; visibility meets phi = pi.
  add(Pi / 4 - to / 2);
  add(Pi / 4 + to / 2);
  add(Pi / 2 - to);
  // Constant thresholds meet phi = 0 (cos(theta - theta_o) = c0) and phi = pi.
  double cs[4];
  int nc = 0;
  for (int i = 0; i < v.ncs; ++i) cs[nc++] = v.cs[i];
  if (v.eta < 1) cs[nc++] = v.cCrit;
  for (int i = 0; i < nc; ++i) {
    if (!(cs[i] < 1)) continue;
    double a = std::acos(cs[i]);
    add(to + a);
    add(to - a);
    add(a - to);
    // ... and cross the reflected horizon c0 = mu / (2 cos_m) inside the circle.
    if (v.mu < 2 * cs[i]) add(std::acos(v.mu / (2 * cs[i])));
  }
  // The refracted horizon appears where it crosses c_crit: cos_m = mu / c_crit.
  if (v.eta < 1 && v.mu < v.cCrit && !v.reflectOnly) add(std::acos(v.mu / v.cCrit));
  // The refracted horizon meets phi = 0 or pi: sign changes of mu_t along theta_m, by a scan and
  // bisection (a fixed number of steps: deterministic).
  if (v.eta < 1 && !v.reflectOnly && fast) dielectric_exit_breaks::RefractedHorizonBreaks(v, add);
  if (v.eta < 1 && !v.reflectOnly && !fast) {
    for (int side = 0; side < 2; ++side) {
      auto muT = [&](double t, bool* ok) {
        double c = std::cos(side == 0 ? t - to : t + to);
        *ok = c > v.cCrit;
        return MuRefracted(v, c, std::cos(t));
      };
      const int steps = 64;
      double ta = 0;
      bool okA;
      double fa = muT(ta, &okA);
      for (int s = 1; s <= steps; ++s) {
        double tb = end * s / steps;
        bool okB;
        double fb = muT(tb, &okB);
        // One end under total internal reflection: move it to the critical point (bisection).
        double ua = ta, ub = tb, ga = fa, gb = fb;
        if (okA != okB) {
          double lo = ta, hi = tb;
          for (int it = 0; it < 60; ++it) {
            double mid = (lo + hi) / 2;
            bool okM;
            muT(mid, &okM);
            (okM == okA ? lo : hi) = mid;
          }
          bool dummy;
          if (okA) {
            ub = lo;
            gb = muT(ub, &dummy);
          } else {
            ua = hi;
            ga = muT(ua, &dummy);
          }
        }
        if ((okA || okB) && (ga > 0) != (gb > 0)) {
          double lo = ua, hi = ub;
          fa = ga;
          for (int it = 0; it < 60; ++it) {
            double mid = (lo + hi) / 2;
            bool okM;
            double fm = muT(mid, &okM);
            ((fm > 0) == (fa > 0) ? lo : hi) = mid;
          }
          add((lo + hi) / 2);
        }
        ta = tb;
        fa = fb;
        okA = okB;
      }
    }
  }
  // Grazing views: the cuts sweep over theta_m ~ mu / 2 at the start and pi/2 - theta_m ~ mu / 2
  // at the end (hemisphere.h): geometric panels there. Then the GGX tail, whose v ~ alpha^2 /
  // tan^2 theta_m compresses theta_m ~ 1 into v ~ alpha^2: geometric panels in tan theta_m from
  // alpha up, so that every panel spans a bounded ratio of v.
  double thetaCut = v.mu / 2;
  if (thetaCut > 0 && thetaCut < 0.125)
    for (double t = 4 * thetaCut; t < 0.5; t *= v.grazingRatio) {
      add(t);
      add(end - t);
    }
  for (double tn = 2 * v.dist.alpha; tn < 64; tn *= v.tailRatio) add(std::atan(tn));
  if (v.eta < 1 && fast) CapPoleBreaks(v, add);
  thetas[n++] = end;
  SortSmall(thetas, n);
  return n;
}

int View::ThetaBreaks(double* thetas) const { return kiln::ThetaBreaks(*this, thetas); }
int View::PhiBreaks(PolarParam h, double* phis) const { return kiln::PhiBreaks(*this, h, phis); }
Channels<2> View::Integrand(PolarParam h, double cp) const { return kiln::Integrand(*this, h, cp); }

/// The bake's node counts and ratios: found by a descent on the evaluations per point over a
/// grid of 1,716 (mu, r, eta) of the tables' domain, each step kept only while the worst
/// |fixed - adaptive at 1e-10| stayed below 3e-7 (half of kDielectricRuleBound), then the bulk's
/// 18 outer nodes raised to 24 when a third grid (tests/integrate_dielectric_rule.cpp) found
/// 6.9e-7 at (mu, r, eta) = (0.83, 0.7, 0.56): worst 2.7e-7, 2.8e-7, 3.2e-7 on the three grids.
/// The exit side's counts (eta < 1: the exit E pair's per-point walk): the bulk's outer panels
/// at 22 nodes (12, 4, 2 in the next classes), and the azimuth nodes of a ring by its outer class
/// too, 12 / 10 / 6 / 6 by width on the bulk's rings, 8 / 6 / 4 / 4, 4 / 4 / 2 / 2 and 2 on the
/// rings of weight below 1e-2, 1e-4, 1e-6: 15-18% fewer evaluations than the entering side's
/// counts over a 5,236-point exit grid (14 eta' 1/3 .. 0.999, 22 mu with mu_c -+ 1e-4, 0.01 and
/// mu = eta', 17 roughness 1/39^2 .. 1) and 9,000 random points of the tables' domain (a third
/// grazing, a fifth within 0.01 of mu_c, a seventh of mu = eta'), worst |fixed - adaptive at
/// 1e-10| 6.3e-7 and 5.5e-7 as before (6.3e-7, 5.2e-7). 20 outer nodes left 7.3e-7 next to mu_c
/// at roughness 0.44-0.61; 10 in the second class moved E_R's grazing slope at mu = 1e-6
/// (tests/runtime_stored_dielectric_exit.cpp); docs/design/glass-tables.md. Every texel of
/// albedo-r-exit against adaptive quadrature at 1e-10 then found 8 of 198,850 over 7e-7, at worst
/// 1.02e-6, all just off mu_c at roughness 0.5-0.6: the structure CapPoleBreaks resolves. With
/// those breaks the bulk's 20 outer nodes keep every texel within 6.2e-7 (16: 1.5e-6 at mu = 1,
/// where the azimuth is free and the outer rule alone sets the error; 18: 6.7e-7).
const DielectricRuleOptions kTuned = {{24, 12, 4, 2},
                                      {1e-2, 1e-4, 1e-6},
                                      {12, 10, 6, 6},
                                      {1, 0.1, 0.02},
                                      4,
                                      16,
                                      4,
                                      {20, 12, 4, 2},
                                      {{12, 10, 6, 6}, {8, 6, 4, 4}, {4, 4, 2, 2}, {2, 2, 2, 2}},
                                      true};

/// The least view cosine the exit walk takes E_R by total internal reflection's complement at
/// (exitTirComplement); below, the direct form. At grazing the complement walks the reflected term
/// on the cap (where F is small) less accurately than F times it: up to 1e-7 from adaptive at mu
/// = 1e-6 where mu = 0 is within 1e-9, which moved E_R's difference quotient at mu -> 0 by up to
/// 11% of its own change (tests/runtime_stored_dielectric_exit.cpp allows 2%); the direct form's
/// errors there follow mu = 0's. 3.1% of the exit tables' texels lie below.
constexpr double kTirComplementMinMu = 1e-4;

/// The node counts of E_1's rule (ReflectedAlbedoF1; FixedRuleOptions' fields).
constexpr FixedRuleOptions kE1Rule = {16, 12, 6, 2.0, 6, 6, SimdPath::Widest};

/// The node classes of the exit side's walk (eta < 1) for options opt: its exit counts, or the
/// entering side's where it has none.
dielectric_walk::NodeClasses ExitClassesOf(const DielectricRuleOptions& opt) {
  dielectric_walk::NodeClasses c = dielectric_walk::ClassesOf(opt);
  if (opt.exitOuterNodes[0] == 0) return c;
  for (int k = 0; k < 4; ++k) {
    c.outerNodes[k] = opt.exitOuterNodes[k];
    for (int q = 0; q < 4; ++q) c.innerNodes[k][q] = opt.exitInnerNodes[k][q];
  }
  return c;
}

/// The fixed rule's E_R moments for the entering side's columns (eta >= kDielectricTableEtaMin):
/// the panels of view v (made at eta = kDielectricTableEtaMin: on the entering side they depend
/// on eta only through the Fresnel layer's thresholds, fixed here at that eta's), and at every
/// node only the geometry (cos phi, c, the reflected ray's weight wR with its masking): into M[k]
/// the rule's sum of wR T_k(2 c - 1), k < dielectric_moments::kTerms, so that E_R(eta) =
/// sum_k a_k(eta) M[k] (file comment, "Columns"). The same panels, nodes and weights as
/// dielectric_walk::FixedWalk; a ring's nodes with wR > 0 are kept in order and their moments
/// taken at the ring's end (dielectric_moments::RingMoments), added with the ring's weight.
/// Returns the nodes walked.
long long ReflectedMoments(const View& v, const dielectric_walk::NodeClasses& rule, double* M) {
  struct Sums {
    const View& v;
    double* M;
    const dielectric_lanes::RingConsts k =
        dielectric_lanes::RingConstsOf(v.mu, v.gDen, v.dist.alpha);
    // The AVX-512F path (dielectric_simd.h) computes the shared part eight nodes at a time.
    const bool simd = dielectric_simd::Enabled();
    dielectric_simd::RingBuffer* buf = nullptr;
    PolarParam ring{};
    int kept = 0;  ///< the ring's nodes with wR > 0, in order
    double wR[dielectric_simd::kMaxRingNodes] = {}, cc[dielectric_simd::kMaxRingNodes] = {};
    void BeginRing(const PolarParam& h) {
      buf->J = 0;
      kept = 0;
      ring = h;
    }
    void Node(const PolarParam& h, double phi, double w) {
      if (simd) {
        buf->phi[buf->J] = phi;
        buf->w[buf->J++] = w;
        return;
      }
      const double c = v.mu * h.cosTheta + v.st * h.sinTheta * dielectric_walk::CosHalfTurn(phi);
      if (!(c > 0) || !(h.cosTheta > 0)) return;
      // The node's weight times c / cos_m over the view's and the reflected ray's masking.
      const double wbs = w * (c / h.cosTheta);
      const double muR = 2 * c * h.cosTheta - v.mu;
      const double r = muR > 0 ? wbs / (v.gDen + v.mu * (v.dist.MuLambda(muR) / muR)) : 0;
      if (r != 0) {
        wR[kept] = r;
        cc[kept++] = std::min(c, 1.0);
      }
    }
    void EndRing(double wo) {
      if (simd && ring.cosTheta > 0) {
        dielectric_simd::RingBuffer& b = *buf;
        const dielectric_simd::ColumnRing r =
            dielectric_simd::ColumnRingOf(v.mu, v.st, v.gDen, ring.cosTheta, ring.sinTheta, k);
        kept = dielectric_simd::ReflectedRing(r, b.phi, b.w, b.J, wR, cc);
      }
      if (kept == 0) return;
      double m[dielectric_moments::kTerms];
      if (simd)
        dielectric_simd::RingMoments8(wR, cc, kept, m);
      else
        dielectric_moments::RingMoments(wR, cc, kept, m);
      for (int q = 0; q < dielectric_moments::kTerms; ++q) M[q] = M[q] + wo * m[q];
    }
  } s{v, M};
  dielectric_simd::RingBuffer buffer;
  s.buf = &buffer;
  return dielectric_walk::WalkNodes(v, rule, s);
}

/// The smoothstep's share of a panel's Gauss nodes, per node count n: node j of the n-point rule
/// on panel [a, a + d] is at a + d s[j] with weight d ws[j] (s = t^2 (3 - 2 t), ws = gw 6 t
/// (1 - t): dielectric_walk::Smooth with the panel's width factored out).
struct SmoothNodes {
  double s[kMaxCachedGaussNodes], ws[kMaxCachedGaussNodes];
};

const SmoothNodes& SmoothNodesOf(int n) {
  static const std::vector<SmoothNodes> all = [] {
    std::vector<SmoothNodes> r(kMaxCachedGaussNodes + 1);
    for (int k = 1; k <= kMaxCachedGaussNodes; ++k) {
      const GaussRule01& g = CachedGaussLegendre01(k);
      for (int j = 0; j < k; ++j) {
        const double t = g.x[j];
        r[k].s[j] = t * t * (3 - 2 * t);
        r[k].ws[j] = g.w[j] * 6 * t * (1 - t);
      }
    }
    return r;
  }();
  return all[n];
}

/// Panel [a, b]'s n nodes by their smoothstep shares sn: node j at a + d s[j], weight d ws[j], d
/// = b - a (a product, then a sum: no fused step).
inline void PanelNodesOf(int n, const SmoothNodes& sn, double a, double b, double* __restrict phi,
                         double* __restrict w) {
  const double d = b - a;
  for (int j = 0; j < n; ++j) {
    phi[j] = a + d * sn.s[j];
    w[j] = d * sn.ws[j];
  }
}

/// PanelNodesOf for a count known when compiled (its loop unrolled).
template <int N>
inline void PanelNodes(const SmoothNodes& sn, double a, double b, double* __restrict phi,
                       double* __restrict w) {
  PanelNodesOf(N, sn, a, b, phi, w);
}

/// The exit walk's problem (both paths): a FastView with the breaks of dielectric_exit_breaks.h.
struct ExitView : FastView {
  dielectric_exit_breaks::ExitBreakConsts k;
  int ThetaBreaks(double* thetas) const { return kiln::ThetaBreaks(*this, thetas, true); }
  int PhiBreaks(PolarParam h, double* phis) const {
    return dielectric_exit_breaks::PhiBreaks(*this, k, h, phis);
  }
};

/// How far below c_crit a ring's largest cosine, or an azimuth panel's first node's, must lie for
/// the walk to skip it as wholly under total internal reflection: far more than the rounding of
/// c (a few ulps), so that every node skipped has g^2 = c^2 + eta^2 - 1 < 0 in the ring's own
/// arithmetic too and added +0 to E_T (and to the complement) before. A panel that starts at the
/// c_crit break has its first node a Gauss node's share of its width further.
constexpr double kTirMargin = 1e-13;

/// The rings (hs, cosM, sinM, wos; m of them) that reach total internal reflection's margin, c =
/// mu cos_m + sin_o sin_m cos phi >= c_crit - kTirMargin at phi = 0, kept in order; returns their
/// count. A dropped ring has only F = 1 nodes: no transmitted term, no term of the complement.
int DropTirRings(const FastView& p, int m, PolarParam* hs, double* cosM, double* sinM,
                 double* wos) {
  int kept = 0;
  for (int r = 0; r < m; ++r) {
    if (!(p.mu * cosM[r] + p.st * sinM[r] >= p.cCrit - kTirMargin)) continue;
    hs[kept] = hs[r];
    cosM[kept] = cosM[r];
    sinM[kept] = sinM[r];
    wos[kept++] = wos[r];
  }
  return kept;
}

/// The azimuth past which the ring (cos_m, sin_m) lies below c_crit - kTirMargin: acos((c_crit -
/// kTirMargin - mu cos_m) / (sin_o sin_m)) by dielectric_exit_breaks::Acos (0 where the whole ring
/// does, infinity where none of it or sin_o sin_m = 0).
inline double TirAzimuth(const FastView& p, double cosM, double sinM) {
  const double A = p.mu * cosM, B = p.st * sinM;
  if (!(B > 0)) return INFINITY;
  const double x = (p.cCrit - kTirMargin - A) / B;
  return x >= 1 ? 0.0 : x <= -1 ? INFINITY : dielectric_exit_breaks::Acos(x);
}

/// dielectric_walk::WalkPanels for the exit walk, the same panels, rings and order, with the
/// inner breaks of an outer panel's rings made first: eight rings at once by
/// dielectric_simd::PhiBreaks8 where simd (the same bits as ExitView::PhiBreaks, which the
/// portable path calls ring by ring). The visitor's calls are WalkPanels' but for Panel(a, b, n,
/// sn): an inner panel's node count n and its smoothstep shares sn (looked up once per outer
/// panel). Returns the azimuth nodes.
template <class Visitor>
long long ExitWalkPanels(const ExitView& p, const dielectric_walk::NodeClasses& rule, bool simd,
                         Visitor& visit) {
  using namespace dielectric_walk;
  double vs[kMaxThetaBreaks];
  const int nt = VBreaks(p, vs);
  const dielectric_simd::ExitPhiView pv{p.mu,      p.st,          p.cCrit,        p.eta2m1,
                                        p.eta < 1, p.ncs,         p.k.nReflected, p.k.nRefracted,
                                        p.cs,      p.k.reflected, p.k.refracted,  p.k.cDrop};
  constexpr int kMaxRings = kMaxCachedGaussNodes;
  PolarParam hs[kMaxRings];
  double cosM[kMaxRings], sinM[kMaxRings], wos[kMaxRings];
  double phis[kMaxRings][dielectric_simd::kMaxRingPhis];
  int nps[kMaxRings];
  long long count = 0;
  for (int i = 0; i + 1 < nt; ++i) {
    const int outerClass = OuterClass(p, rule, vs[i], vs[i + 1]);
    const int* innerNodes = rule.innerNodes[outerClass];
    const GaussRule01& go = CachedGaussLegendre01(rule.outerNodes[outerClass]);
    // The inner panels' node counts (CachedGaussLegendre01's clamp) and their smoothstep shares
    // by width class.
    int innerCount[4];
    const SmoothNodes* innerShares[4];
    for (int q = 0; q < 4; ++q) {
      innerCount[q] = static_cast<int>(CachedGaussLegendre01(innerNodes[q]).x.size());
      innerShares[q] = &SmoothNodesOf(innerCount[q]);
    }
    int m = 0;
    if (simd) {
      m = dielectric_simd::FastOuterRings(vs[i], vs[i + 1], Sqr(p.dist.alpha), go.x.data(),
                                          go.w.data(), static_cast<int>(go.x.size()), sinM, cosM,
                                          wos);
      for (int r = 0; r < m; ++r) hs[r] = {sinM[r], cosM[r]};
    } else {
      for (size_t ko = 0; ko < go.x.size(); ++ko) {
        if (!OuterRing(p, vs[i], vs[i + 1], go.x[ko], go.w[ko], &hs[m], &wos[m])) continue;
        cosM[m] = hs[m].cosTheta;
        sinM[m] = hs[m].sinTheta;
        ++m;
      }
    }
    if (p.tirComplement) m = DropTirRings(p, m, hs, cosM, sinM, wos);
    if (simd)
      for (int r = 0; r < m; r += 8)
        dielectric_simd::PhiBreaks8(pv, cosM + r, sinM + r, std::min(8, m - r), phis + r, nps + r);
    else
      for (int r = 0; r < m; ++r) nps[r] = p.PhiBreaks(hs[r], phis[r]);
    for (int r = 0; r < m; ++r) {
      visit.BeginRing(hs[r]);
      const double phiTir = p.tirComplement ? TirAzimuth(p, cosM[r], sinM[r]) : INFINITY;
      for (int k = 0; k + 1 < nps[r]; ++k) {
        const double width = phis[r][k + 1] - phis[r][k];
        if (!(width > 0)) continue;
        const int q = ClassOf(rule.innerWidth, width);
        // The rest of the ring is under total internal reflection where the panel's first node
        // is (c falls with phi).
        if (phis[r][k] + width * innerShares[q]->s[0] > phiTir) break;
        count += innerCount[q];
        visit.Panel(phis[r][k], phis[r][k + 1], innerCount[q], *innerShares[q]);
      }
      visit.EndRing(wos[r]);
    }
  }
  return count;
}

/// E_1, GGX's directional albedo with F = 1 (height-correlated Smith, the walk's reflected term's
/// conventions), by fixed_rule_dfg.h's rule with kE1Rule's node counts: A + B.
double ReflectedAlbedoF1(double mu, double alpha, long long* evals) {
  const std::array<double, 2> ab = FixedRuleGGXDFG(mu, alpha, kE1Rule, evals);
  return ab[0] + ab[1];
}

/// The exit side's per-point walk of a FastView (dielectric_walk::FixedWalk's panels and nodes,
/// FastView's terms): the panels of ExitView's breaks, a ring's panels
/// (dielectric_walk::WalkPanels) made its nodes (SmoothNodes: two operations a node), then the
/// ring's terms summed in eight lanes with fused multiply-adds, by dielectric_simd's FastRingSums
/// where the AVX-512F paths run, else by PortableRingSums (std::fma, the same lanes): the same
/// bits on either path; within 1e-14 of the FixedWalk it replaced, relative to E_R + E_T.
Channels<2> FastWalk(const FastView& v, const dielectric_walk::NodeClasses& rule,
                     long long* evals) {
  const bool simd = dielectric_simd::Enabled();
  ExitView ev;
  static_cast<FastView&>(ev) = v;
  ev.k = dielectric_exit_breaks::ConstsOf(ev);
  // The complement skips the ring past c_crit - kTirMargin: no boundaries of the reflected ray
  // there.
  if (v.tirComplement) ev.k.cDrop = v.cCrit - kTirMargin;
  struct Sum {
    const FastView& v;
    dielectric_simd::RingBuffer& b;
    bool simd;  ///< FastRingSums, else PortableRingSums
    double invEta = 1 / v.eta;
    PolarParam ring{};
    Channels<2> sum{0, 0};
    void BeginRing(const PolarParam& h) {
      b.J = 0;
      ring = h;
    }
    void Panel(double a, double bEnd, int n, const SmoothNodes& sn) {
      double* phi = b.phi + b.J;
      double* w = b.w + b.J;
      switch (n) {  // the exit rules' counts unrolled (two nodes an SSE2 operation)
        case 2:
          PanelNodes<2>(sn, a, bEnd, phi, w);
          break;
        case 4:
          PanelNodes<4>(sn, a, bEnd, phi, w);
          break;
        case 6:
          PanelNodes<6>(sn, a, bEnd, phi, w);
          break;
        case 8:
          PanelNodes<8>(sn, a, bEnd, phi, w);
          break;
        case 10:
          PanelNodes<10>(sn, a, bEnd, phi, w);
          break;
        case 12:
          PanelNodes<12>(sn, a, bEnd, phi, w);
          break;
        default:
          PanelNodesOf(n, sn, a, bEnd, phi, w);
      }
      b.J += n;
    }
    void EndRing(double wo) {
      if (!(ring.cosTheta > 0)) return;  // no node visible: the ring adds nothing
      const dielectric_simd::FastRing r{v.mu * ring.cosTheta,
                                        v.st * ring.sinTheta,
                                        ring.cosTheta,
                                        v.mu,
                                        v.eta,
                                        v.eta2,
                                        v.eta2m1,
                                        v.a2,
                                        v.gDen,
                                        invEta,
                                        v.reflectOnly,
                                        v.tirComplement};
      double c0, c1;
      (simd ? dielectric_simd::FastRingSums : dielectric_simd::PortableRingSums)(r, b.phi, b.w, b.J,
                                                                                 &c0, &c1);
      sum += wo * Channels<2>{c0, c1};
    }
  };
  dielectric_simd::RingBuffer buffer;
  Sum s{v, buffer, simd};
  const long long count = ExitWalkPanels(ev, rule, simd, s);
  if (evals) *evals += count;
  if (!v.tirComplement) return s.sum;
  return Channels<2>{ReflectedAlbedoF1(v.mu, v.dist.alpha, evals) - s.sum[0], s.sum[1]};
}

void CheckColumn(const double* etas, int n) {
  if (n < 1 || n > kMaxDielectricColumn)
    throw std::invalid_argument("dielectric column: " + std::to_string(n) + " etas (1 .. " +
                                std::to_string(kMaxDielectricColumn) + ")");
  for (int e = 0; e < n; ++e)
    if (!(etas[e] >= kDielectricTableEtaMin))
      throw std::invalid_argument("dielectric column: eta = " + std::to_string(etas[e]) +
                                  " below " + std::to_string(kDielectricTableEtaMin));
}

}  // namespace

void FixedRuleDielectricAlbedoColumn(double mu, double alpha, const double* etas, int n,
                                     const DielectricRuleOptions& opt, std::array<double, 2>* out,
                                     long long* evals, DielectricChannels channels) {
  CheckColumn(etas, n);
  for (int e = 0; e < n; ++e) out[e] = {NAN, NAN};
  long long count = 0;
  // E_R by the reflected ray's moments on this rule's panels.
  if (HasChannel(channels, 0)) {
    const View v = MakeRuleView(mu, alpha, kDielectricTableEtaMin, opt);
    double M[dielectric_moments::kTerms] = {};
    count += ReflectedMoments(v, dielectric_walk::ClassesOf(opt), M);
    for (int e = 0; e < n; ++e)
      out[e][0] = dielectric_moments::Contract(dielectric_moments::FresnelChebyshev(etas[e]), M);
  }
  // E_T = T_lobe - T_F by the BTDF pair's column (its bake's rule, remembered: the BTDF table
  // and these share its walk).
  if (HasChannel(channels, 1)) {
    std::array<double, 2> btdf[kMaxDielectricColumn];
    FixedRuleDielectricBtdfColumn(mu, alpha, etas, n, btdf, &count);
    for (int e = 0; e < n; ++e) out[e][1] = btdf[e][0] - btdf[e][1];
  }
  if (evals) *evals += count;
}

std::array<double, 2> SmoothDielectricAlbedo(double mu, double eta) {
  double F = FrDielectric(Clamp(mu, 0.0, 1.0), eta);
  return {F, 1 - F};
}

std::array<double, 2> DielectricAlbedo(double mu, double alpha, double eta,
                                       const IntegrationOptions& opt, IntegrationStats& stats) {
  const Channels<2> r = dielectric_walk::AdaptiveWalk(MakeView(mu, alpha, eta), opt, stats);
  return {r[0], r[1]};
}

void dielectric_adaptive::AlbedoRingNodes(double mu, double alpha, double eta, PolarParam h,
                                          const double* y, const double* phis, int np, int n,
                                          Channels<2>* out) {
  const View v = MakeView(mu, alpha, eta);
  v.RingOf(h).Nodes(y, phis, np, n, out);
}

DielectricRuleOptions TunedDielectricRuleOptions() { return kTuned; }

FixedRuleOptions DielectricExitE1RuleOptions() { return kE1Rule; }

std::array<double, 2> FixedRuleDielectricAlbedo(double mu, double alpha, double eta,
                                                const DielectricRuleOptions& opt,
                                                long long* evals) {
  if (eta >= kDielectricTableEtaMin) {  // the entering tables' rule: a column of one
    std::array<double, 2> e;
    FixedRuleDielectricAlbedoColumn(mu, alpha, &eta, 1, opt, &e, evals);
    return e;
  }
  FastView v = MakeFastView(mu, alpha, eta, opt);
  v.tirComplement = eta < 1 && opt.exitTirComplement && !(v.mu < kTirComplementMinMu);
  const Channels<2> r =
      FastWalk(v, eta < 1 ? ExitClassesOf(opt) : dielectric_walk::ClassesOf(opt), evals);
  return {r[0], r[1]};
}

double FixedRuleDielectricReflectance(double mu, double alpha, double eta,
                                      const DielectricRuleOptions& opt, long long* evals) {
  FastView v = MakeFastView(mu, alpha, eta, opt);
  v.reflectOnly = true;
  return FastWalk(v, dielectric_walk::ClassesOf(opt), evals)[0];
}

namespace {

/// The bake rule's recent results, {E_R, E_T} and the evaluations they took, by the bits of
/// (mu, alpha, eta): one integration gives both channels, and albedo-r and albedo-t (or their
/// -exit pair, or two averages) baked in one process read the same nodes, so the second table
/// finds its values here. A hit returns the bits the rule computes (it is deterministic) and
/// charges the evaluations the integration took, so files and manifests do not depend on what
/// else was baked. Sharded by the key's hash (one lock each); at most kMemoPerShard entries per
/// shard, then new points are not kept (the lookup-error search's scattered points would
/// otherwise fill it).
class RuleMemo {
 public:
  struct Value {
    std::array<double, 2> e;
    long long evals;
  };
  bool Find(double mu, double alpha, double eta, Value& out) {
    const Key k = KeyOf(mu, alpha, eta);
    const size_t h = KeyHash()(k);
    Shard& s = shards_[ShardOf(h)];
    std::lock_guard<std::mutex> lock(s.mutex);
    const Slot* slot = s.Probe(k, h);
    if (!slot || !slot->used) return false;
    out = slot->v;
    return true;
  }
  void Keep(double mu, double alpha, double eta, const Value& v) {
    const Key k = KeyOf(mu, alpha, eta);
    const size_t h = KeyHash()(k);
    Shard& s = shards_[ShardOf(h)];
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.count >= kMemoPerShard) return;
    if (s.slots.empty()) s.slots.resize(kSlotsPerShard);
    Slot* slot = s.Probe(k, h);
    if (slot->used) return;
    *slot = {k, v, true};
    ++s.count;
  }

 private:
  struct Key {
    std::uint64_t mu, alpha, eta;
    bool operator==(const Key& o) const { return mu == o.mu && alpha == o.alpha && eta == o.eta; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      std::uint64_t h = k.mu * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ k.alpha) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 31) ^ k.eta) * 0x94D049BB133111EBull;
      return static_cast<size_t>(h ^ (h >> 32));
    }
  };
  static constexpr int kShards = 16;
  static constexpr size_t kMemoPerShard = 16384;  // 262,144 points
  // An open-addressed table per shard, at most half full (a lookup reads one or two slots, where
  // a node-based map followed two pointers): about 29 MB once every shard holds a point.
  static constexpr size_t kSlotsPerShard = 2 * kMemoPerShard;
  struct Slot {
    Key k;
    Value v;
    bool used;
  };
  struct Shard {
    std::mutex mutex;
    std::vector<Slot> slots;  // kSlotsPerShard once the first point is kept
    size_t count = 0;
    /// The slot that holds k, or the free slot where it would go (linear probing from the
    /// hash's bits 16 and up: ShardOf took bits 7 .. 10); null while the table is empty.
    Slot* Probe(const Key& k, size_t h) {
      if (slots.empty()) return nullptr;
      for (size_t i = (h >> 16) & (kSlotsPerShard - 1);; i = (i + 1) & (kSlotsPerShard - 1))
        if (!slots[i].used || slots[i].k == k) return &slots[i];
    }
  };
  static std::uint64_t Bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  static Key KeyOf(double mu, double alpha, double eta) {
    return {Bits(mu), Bits(alpha), Bits(eta)};
  }
  static int ShardOf(size_t hash) { return static_cast<int>((hash >> 7) % kShards); }
  Shard shards_[kShards];
};

RuleMemo& Memo() {
  static RuleMemo memo;
  return memo;
}

}  // namespace

std::array<double, 2> FixedRuleDielectricAlbedo(double mu, double alpha, double eta,
                                                long long* evals) {
  RuleMemo::Value v;
  if (!Memo().Find(mu, alpha, eta, v)) {
    v.evals = 0;
    v.e = FixedRuleDielectricAlbedo(mu, alpha, eta, kTuned, &v.evals);
    Memo().Keep(mu, alpha, eta, v);
  }
  if (evals) *evals += v.evals;
  return v.e;
}

void FixedRuleDielectricAlbedoColumn(double mu, double alpha, const double* etas, int n,
                                     std::array<double, 2>* out, long long* evals) {
  static DielectricColumnMemo memo;
  memo.Column(mu, alpha, etas, n, out, evals, [&](std::array<double, 2>* e, long long* ev) {
    FixedRuleDielectricAlbedoColumn(mu, alpha, etas, n, kTuned, e, ev);
  });
}

}  // namespace kiln
