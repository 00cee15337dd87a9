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
#include "baker/integrate/dielectric_btdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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

/// The bake's node counts: the E tables' weight classes (dielectric_walk.h) with 12, 8, 4, 2
/// outer and 12, 10, 6, 6 inner nodes, against 12 x 12 on every panel before: a quarter to a
/// third fewer evaluations, the worst |fixed - adaptive at 1e-10| unchanged on two grids (the
/// test's, 1.6e-7, and one between its nodes, 1.0e-7: mu 1e-6 .. 0.99, alpha 1e-5 .. 0.95, eta
/// 1.0001 .. 2.95); 10 inner nodes on the 0.1 .. 1 class left 4.6e-7 on the second.
const DielectricBtdfRuleOptions kTuned = {
    {12, 8, 4, 2}, {1e-2, 1e-4, 1e-6}, {12, 10, 6, 6}, {1, 0.1, 0.02}};

}  // namespace

std::array<double, 2> SmoothDielectricBtdfPair(double mu, double eta) {
  return {1.0, FrDielectric(Clamp(mu, 0.0, 1.0), eta)};
}

std::array<double, 2> DielectricBtdfPair(double mu, double alpha, double eta,
                                         const IntegrationOptions& opt, IntegrationStats& stats) {
  const Channels<2> r = dielectric_walk::AdaptiveWalk(MakeBtdfView(mu, alpha, eta), opt, stats);
  return {r[0], r[1]};
}

DielectricBtdfRuleOptions TunedDielectricBtdfRuleOptions() { return kTuned; }

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  const DielectricBtdfRuleOptions& opt,
                                                  long long* evals) {
  const Channels<2> r = dielectric_walk::FixedWalk(MakeBtdfView(mu, alpha, eta),
                                                   dielectric_walk::ClassesOf(opt), evals);
  return {r[0], r[1]};
}

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  long long* evals) {
  return FixedRuleDielectricBtdfPair(mu, alpha, eta, kTuned, evals);
}

}  // namespace kiln
