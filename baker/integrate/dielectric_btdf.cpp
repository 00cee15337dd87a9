// The split-sum BTDF pair {T_lobe, T_F} of the GGX dielectric over the visible microfacet normals,
// for a view entering the denser medium (eta >= 1).
//
// Derivation. As in dielectric_albedo.cpp: a view o = (sin_o, 0, mu) meets the microfacet normal m
// with c = o.m > 0 and refracts to i_t = -o / eta + (c / eta - cos_t) m, cos_t =
// sqrt(c^2 + eta^2 - 1) / eta (always, for eta >= 1: no total internal reflection, and the ray
// always goes down: mu_t = -i_t.z > 0). With the Jacobian of the refraction map (Walter 2007
// eq. 17) the importance-form BTDF fhat_t = (1 - F(c)) W_t integrates over i to
//     integral W_t w |cos_i| di = integral D(m) c G2(o, i_t) w / mu dm
// for any weight w(c) of the microfacet; w = 1 gives T_lobe, w = F(c) gives T_F, and
// T_lobe - T_F = E_T of dielectric_albedo.h. With v = a^2 / (a^2 + tan^2 theta_m) (GGX's
// complementary CDF of D cos: D cos dm = dv dphi / (2 pi)) and the mirror symmetry phi -> -phi,
//     T = (1 / pi) int_0^1 dv int_0^pi dphi (c / cos_m) w / (mu + mu Lambda(o) + mu Lambda(i_t)).
// Along an azimuth circle c = mu cos_m + sin_o sin_m cos(phi) is monotone in phi; the structures
// are thresholds in c: c = 0 (visibility: the end of the circle) and, for T_F, c = eps =
// sqrt(eta^2 - 1) (the Fresnel term's layer at grazing: branch points at c = +-i eps; eps >= 0.46
// over the tables' eta >= 1.1, so one panel boundary suffices). The outer panels (in theta_m) are
// where those thresholds meet phi = 0 or pi, geometric panels at grazing views, and GGX's tail
// (geometric in tan theta_m from alpha up). Every panel maps t in [0, 1] through the smoothstep
// 3t^2 - 2t^3 (the square-root ends at c = 0 and the cos_m^-1 ~ v^-1/2 of the tail become analytic
// in t). The reflected ray is not followed (no reflection horizon, no critical angle), so the
// panels are fewer than the E tables' and a small Gauss rule per panel reaches the bound.
// The adaptive rule bisects the panels (Gauss-Kronrod 15, to the tolerance); the fixed rule takes
// the same panels with Gauss nodes per panel by its weight class, summed in one order
// (deterministic). Both walk the panels with dielectric_walk.h, the walk the E tables' rules
// take with their own integrand and thresholds (dielectric_albedo.cpp).
// Columns (eta >= kDielectricTableEtaMin = 1.1, the table's whole eta axis). The panels depend on
// eta only through the Fresnel threshold c = eps (the outer breaks where it meets phi = 0 and pi,
// the inner break on each circle); the weight c / cos_m not at all. So the fixed rule there fixes
// eps at eta = 1.1's (0.458), whatever eta (for eta >= sqrt(2), eps >= 1, which had no panel,
// the walk now keeps the one at 0.458), as the E tables' columns do: one walk of (v, phi_m) per
// (mu, alpha) serves every eta of a column (BtdfColumnWalk), per node the geometry once and per
// eta only F and the refracted ray by the E columns' forms (dielectric_albedo.cpp, "Columns";
// dielectric_lanes::EtaTerms): T_f = 1 - F = 2 c g (b^2 + eta^2 a^2) / (a^2 b^2) from g =
// sqrt(c^2 + eta^2 - 1) = eta cos_t, the weight c / cos_m / (gDen + mu Lambda(t)) as wb p / (p +
// kh s_t^2): 2 square roots and 2 divisions per eta, two etas per lane pair. Each eta's sums are
// its own, in the walk's order: a column of one (a single point: the lookup-error search, kiln
// verify) gives the bits the column gives. Below 1.1 (eta in [1, 1.1): the reference's and tests'
// points, off the table) the per-point walk with eta's own panels as before. Measured: the worst
// |fixed - adaptive at 1e-10| on the test's grid (tests/integrate_dielectric_btdf.cpp) 6.8e-8
// (1.0e-7 before), on a grid between its nodes 5.4e-8; evaluations per texel 2,083 counted per eta
// (1,607 before: the Fresnel panels kept above sqrt(2)), of which a 40-eta column walks ~52 per
// texel; cost in docs/models.md section 16 and the README.
#include "baker/integrate/dielectric_btdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "baker/integrate/dielectric_adaptive_nodes.h"
#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_column_memo.h"
#include "baker/integrate/dielectric_lanes.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/dielectric_walk.h"
#include "baker/math/quadrature.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"
#include "baker/models/roughness.h"

namespace kiln {
namespace {

constexpr int kMaxBreaks = dielectric_walk::kMaxThetaBreaks;

/// The view and interface: what every evaluation needs.
struct BtdfView {
  double mu, st, thetaO, eta, eta2m1, eps;
  double gDen;  ///< mu + mu Lambda(o)
  GGXDistribution dist;
  // The problem dielectric_walk.h walks (defined below).
  int ThetaBreaks(double* thetas) const;
  int PhiBreaks(PolarParam h, double* phis) const;
  Channels<2> Integrand(PolarParam h, double cp) const;
  using AdaptiveRing = dielectric_walk::LaneRing<BtdfView, dielectric_adaptive::BtdfRing,
                                                 dielectric_adaptive::BtdfNodes>;
  /// The adaptive walk's ring at h: its nodes at once (dielectric_walk::HasRingNodes), in
  /// AVX-512F lanes where dielectric_simd::Enabled() (the ring's constants once).
  AdaptiveRing RingOf(PolarParam h) const;
};

BtdfView MakeBtdfView(double mu, double alpha, double eta) {
  if (!(eta >= 1))
    throw std::invalid_argument("the split-sum BTDF pair takes eta >= 1 (entering), not " +
                                std::to_string(eta));
  BtdfView v;
  v.mu = Clamp(mu, 0.0, 1.0);
  v.st = std::sqrt(std::max(0.0, (1 - v.mu) * (1 + v.mu)));
  v.thetaO = std::acos(v.mu);
  v.eta = eta;
  v.eta2m1 = (eta - 1) * (eta + 1);
  v.eps = std::sqrt(v.eta2m1);
  v.dist.alpha = std::max(alpha, MinAlpha);
  v.gDen = v.mu + v.dist.MuLambda(v.mu);
  return v;
}

/// The integrand {T_lobe, T_F} at microfacet polar angle h and azimuth cos(phi) = cp (without
/// 1/pi).
inline Channels<2> BtdfIntegrand(const BtdfView& v, PolarParam h, double cp) {
  Channels<2> out{0, 0};
  double c = v.mu * h.cosTheta + v.st * h.sinTheta * cp;
  if (!(c > 0) || !(h.cosTheta > 0)) return out;
  c = std::min(c, 1.0);
  double cosT = std::sqrt(c * c + v.eta2m1) / v.eta;
  double muT = v.mu / v.eta - (c / v.eta - cosT) * h.cosTheta;  // > 0: the ray goes down
  if (!(muT > 0)) return out;
  double g = (c / h.cosTheta) / (v.gDen + v.mu * (v.dist.MuLambda(muT) / muT));
  out[0] = g;
  out[1] = g * FrDielectric(c, v.eta);
  return out;
}

/// Inner panel boundaries in phi over [0, phiMax] at polar angle h; returns their count (>= 2),
/// or 0 when nothing is visible.
int BtdfPhiBreaks(const BtdfView& v, PolarParam h, double* phis) {
  double den = v.st * h.sinTheta;
  double phiMax = Pi;
  if (den > 0) {
    double cEnd = -v.mu * h.cosTheta / den;
    if (cEnd >= 1) return 0;
    if (cEnd > -1) phiMax = std::acos(cEnd);
  } else if (!(v.mu * h.cosTheta > 0)) {
    return 0;
  }
  int n = 0;
  phis[n++] = 0;
  if (den > 0 && v.eps > 0 && v.eps < 1) {
    double cp = (v.eps - v.mu * h.cosTheta) / den;
    if (cp > -1 && cp < 1) {
      double p = std::acos(cp);
      if (p > 0 && p < phiMax) phis[n++] = p;
    }
  }
  phis[n++] = phiMax;
  return n;
}

/// Outer panel boundaries in theta_m over [0, pi/2].
int BtdfThetaBreaks(const BtdfView& v, double* thetas) {
  int n = 0;
  const double to = v.thetaO, end = Pi / 2;
  auto add = [&](double t) {
    if (t > 0 && t < end && n < kMaxBreaks - 2) thetas[n++] = t;
  };
  thetas[n++] = 0;
  add(Pi / 2 - to);              // visibility meets phi = pi
  if (v.eps > 0 && v.eps < 1) {  // the Fresnel threshold meets phi = 0 and pi
    double a = std::acos(v.eps);
    add(to + a);
    add(to - a);
    add(a - to);
  }
  // Grazing views: the cuts sweep over theta_m ~ mu / 2 (hemisphere.h): geometric panels. Then
  // GGX's tail: geometric panels in tan theta_m from alpha up.
  double thetaCut = v.mu / 2;
  if (thetaCut > 0 && thetaCut < 0.125)
    for (double t = 4 * thetaCut; t < 0.5; t *= 4) {
      add(t);
      add(end - t);
    }
  for (double tn = 2 * v.dist.alpha; tn < 64; tn *= 4) add(std::atan(tn));
  thetas[n++] = end;
  SortSmall(thetas, n);
  return n;
}

int BtdfView::ThetaBreaks(double* thetas) const { return BtdfThetaBreaks(*this, thetas); }
int BtdfView::PhiBreaks(PolarParam h, double* phis) const { return BtdfPhiBreaks(*this, h, phis); }
Channels<2> BtdfView::Integrand(PolarParam h, double cp) const {
  return BtdfIntegrand(*this, h, cp);
}

BtdfView::AdaptiveRing BtdfView::RingOf(PolarParam h) const {
  const double a2 = dist.alpha * dist.alpha, eta2 = eta * eta;
  return {*this,
          h,
          dielectric_simd::Enabled(),
          {mu * h.cosTheta, st * h.sinTheta, h.cosTheta, mu, gDen, a2, eta, eta2m1, eta2, eta2 + 1,
           mu / eta}};
}

/// The bake's node counts: the E tables' weight classes (dielectric_walk.h) with 12, 8, 4, 2
/// outer and 12, 10, 6, 6 inner nodes, against 12 x 12 on every panel before: a quarter to a
/// third fewer evaluations, the worst |fixed - adaptive at 1e-10| unchanged on two grids (the
/// test's, 1.6e-7, and one between its nodes, 1.0e-7: mu 1e-6 .. 0.99, alpha 1e-5 .. 0.95, eta
/// 1.0001 .. 2.95); 10 inner nodes on the 0.1 .. 1 class left 4.6e-7 on the second.
const DielectricBtdfRuleOptions kTuned = {
    {12, 8, 4, 2}, {1e-2, 1e-4, 1e-6}, {12, 10, 6, 6}, {1, 0.1, 0.02}};

using namespace dielectric_lanes;  // Pair: two etas per lane pair

/// The per-eta constants of a column (eta >= kDielectricTableEtaMin), two etas per lane pair, the
/// last pair padded with a copy of the last eta.
struct BtdfEtaConsts {
  double eta2m1[kMaxDielectricColumn], eta2[kMaxDielectricColumn], inv[kMaxDielectricColumn];
  int pairs;
  int n;  ///< the column's etas (the AVX-512F path pads to a multiple of 8 with the last)
};

/// The fixed rule's walk for a column of etas >= kDielectricTableEtaMin at once: the panels of
/// view v (made at eta = kDielectricTableEtaMin: they depend on eta only through the Fresnel
/// threshold c = eps, fixed at that eta's), at every node the geometry once (cos phi, c, the
/// weight c / cos_m) and per eta only F, the refracted ray and its masking. The same panels,
/// nodes and summation order as dielectric_walk::FixedWalk; each eta's sums are independent of
/// the others' (a column of one gives the same bits). out: 2 * ks.pairs entries. evals
/// (optional): the nodes walked (each eta's evaluations).
void BtdfColumnWalk(const BtdfView& v, const BtdfEtaConsts& ks,
                    const dielectric_walk::NodeClasses& rule, std::array<double, 2>* out,
                    long long* evals) {
  struct Sums {
    const BtdfView& v;
    const BtdfEtaConsts& ks;
    const int np2;
    const dielectric_lanes::RingConsts k =
        dielectric_lanes::RingConstsOf(v.mu, v.gDen, v.dist.alpha);
    const Pair one = Splat(1), mu = Splat(v.mu), a2 = Splat(k.a2), oma2 = Splat(k.oma2),
               kh = Splat(k.kh);
    dielectric_lanes::ColumnSums<kMaxDielectricColumn / 2> sums{np2};
    Pair cosM = Splat(0);
    // The AVX-512F path (dielectric_simd.h): the ring's nodes kept, their terms at EndRing.
    const bool simd = dielectric_simd::Enabled();
    dielectric_simd::RingBuffer* buf = nullptr;
    PolarParam ring{};
    double total0[kMaxDielectricColumn] = {}, total1[kMaxDielectricColumn] = {};
    void BeginRing(const PolarParam& h) {
      if (simd) {
        buf->J = 0;
        ring = h;
        return;
      }
      sums.ClearRing();
      cosM = Splat(h.cosTheta);
    }
    void Node(const PolarParam& h, double phi, double w) {
      if (simd) {
        buf->phi[buf->J] = phi;
        buf->w[buf->J++] = w;
        return;
      }
      const double c = v.mu * h.cosTheta + v.st * h.sinTheta * dielectric_walk::CosHalfTurn(phi);
      if (!(c > 0) || !(h.cosTheta > 0)) return;
      const Pair wb = Splat(w * (c / h.cosTheta) / v.gDen), cc = Splat(std::min(c, 1.0));
      // Per eta (dielectric_lanes::EtaTerms): Tf = 1 - F, the refracted ray's p and denominator;
      // T_lobe's term t = wb p / den (wb over gDen), T_F's t (1 - Tf).
      for (int e = 0; e < np2; ++e) {
        Pair tf, p, den;
        dielectric_lanes::EtaTerms(cc, Load(ks.eta2m1 + 2 * e), Load(ks.eta2 + 2 * e),
                                   Load(ks.inv + 2 * e), cosM, mu, a2, oma2, kh, &tf, &p, &den);
        const Pair t = wb * p / den;
        sums.ring0[e] = sums.ring0[e] + t;
        sums.ring1[e] = sums.ring1[e] + t * (one - tf);
      }
    }
    void EndRing(double wo) {
      if (simd) {
        SimdRing(wo);
        return;
      }
      sums.EndRing(wo);
    }
    // The same sums by dielectric_simd: the shared part eight nodes at a time, then eight etas
    // at a time (a column of eight or more) or one eta and eight nodes at a time (fewer), each
    // eta's terms added in the nodes' order.
    void SimdRing(double wo) {
      dielectric_simd::RingBuffer& b = *buf;
      const int J = b.J, n = ks.n;
      if (!(ring.cosTheta > 0)) return;  // no node visited: the ring adds nothing
      const dielectric_simd::ColumnRing r =
          dielectric_simd::ColumnRingOf(v.mu, v.st, v.gDen, ring.cosTheta, ring.sinTheta, k);
      dielectric_simd::BtdfRingShared(r, b.phi, b.w, J, b.valid, b.wb, b.cc);
      dielectric_simd::AddColumnRing(
          n, b, wo,
          [&](double* ring0, double* ring1) {
            dielectric_simd::BtdfRingEtas(r, b.valid, b.wb, b.cc, J, ks.eta2m1, ks.eta2, ks.inv,
                                          (n + 7) / 8, ring0, ring1);
          },
          [&](int e) {
            dielectric_simd::BtdfRingOneEta(r, b.wb, b.cc, J, ks.eta2m1[e], ks.eta2[e], ks.inv[e],
                                            b.tR, b.tT);
          },
          total0, total1);
    }
  } s{v, ks, ks.pairs};
  dielectric_simd::RingBuffer buffer;
  s.buf = &buffer;
  const long long count = dielectric_walk::WalkNodes(v, rule, s);
  if (s.simd)
    for (int e = 0; e < ks.n; ++e) out[e] = {s.total0[e], s.total1[e]};
  else
    s.sums.Write(out);
  if (evals) *evals += count;
}

}  // namespace

std::array<double, 2> SmoothDielectricBtdfPair(double mu, double eta) {
  return {1.0, FrDielectric(Clamp(mu, 0.0, 1.0), eta)};
}

std::array<double, 2> DielectricBtdfPair(double mu, double alpha, double eta,
                                         const IntegrationOptions& opt, IntegrationStats& stats) {
  const Channels<2> r = dielectric_walk::AdaptiveWalk(MakeBtdfView(mu, alpha, eta), opt, stats);
  return {r[0], r[1]};
}

void dielectric_adaptive::BtdfRingNodes(double mu, double alpha, double eta, PolarParam h,
                                        const double* y, const double* phis, int np, int n,
                                        Channels<2>* out) {
  const BtdfView v = MakeBtdfView(mu, alpha, eta);
  v.RingOf(h).Nodes(y, phis, np, n, out);
}

DielectricBtdfRuleOptions TunedDielectricBtdfRuleOptions() { return kTuned; }

void FixedRuleDielectricBtdfColumn(double mu, double alpha, const double* etas, int n,
                                   const DielectricBtdfRuleOptions& opt, std::array<double, 2>* out,
                                   long long* evals) {
  if (n < 1 || n > kMaxDielectricColumn)
    throw std::invalid_argument("BTDF column: " + std::to_string(n) + " etas (1 .. " +
                                std::to_string(kMaxDielectricColumn) + ")");
  for (int e = 0; e < n; ++e)
    if (!(etas[e] >= kDielectricTableEtaMin))
      throw std::invalid_argument("BTDF column: eta = " + std::to_string(etas[e]) + " below " +
                                  std::to_string(kDielectricTableEtaMin));
  const BtdfView v = MakeBtdfView(mu, alpha, kDielectricTableEtaMin);
  BtdfEtaConsts ks;
  ks.pairs = (n + 1) / 2;
  ks.n = n;
  for (int e = 0; e < kMaxDielectricColumn; ++e) {
    const double eta = etas[std::min(e, n - 1)];
    ks.eta2m1[e] = (eta - 1) * (eta + 1);
    ks.eta2[e] = eta * eta;
    ks.inv[e] = 1 / eta;
  }
  std::array<double, 2> all[kMaxDielectricColumn];
  BtdfColumnWalk(v, ks, dielectric_walk::ClassesOf(opt), all, evals);
  std::copy(all, all + n, out);
}

void FixedRuleDielectricBtdfColumn(double mu, double alpha, const double* etas, int n,
                                   std::array<double, 2>* out, long long* evals) {
  static DielectricColumnMemo memo;
  memo.Column(mu, alpha, etas, n, out, evals, [&](std::array<double, 2>* e, long long* ev) {
    FixedRuleDielectricBtdfColumn(mu, alpha, etas, n, kTuned, e, ev);
  });
}

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  const DielectricBtdfRuleOptions& opt,
                                                  long long* evals) {
  if (eta >= kDielectricTableEtaMin) {  // the tables' side: a column of one
    std::array<double, 2> p;
    FixedRuleDielectricBtdfColumn(mu, alpha, &eta, 1, opt, &p, evals);
    return p;
  }
  const Channels<2> r = dielectric_walk::FixedWalk(MakeBtdfView(mu, alpha, eta),
                                                   dielectric_walk::ClassesOf(opt), evals);
  return {r[0], r[1]};
}

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  long long* evals) {
  return FixedRuleDielectricBtdfPair(mu, alpha, eta, kTuned, evals);
}

}  // namespace kiln
