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
// the same panels with a fixed Gauss rule per panel, summed in one order (deterministic).
#include "baker/integrate/dielectric_btdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "baker/math/quadrature.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"
#include "baker/models/roughness.h"

namespace kiln {
namespace {

constexpr int kMaxBreaks = 48;

/// The view and interface: what every evaluation needs.
struct BtdfView {
  double mu, st, thetaO, eta, eta2m1, eps;
  double gDen;  ///< mu + mu Lambda(o)
  GGXDistribution dist;
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

/// The smoothstep map of panel [a, b] at t in [0, 1]: the point and its Jacobian.
inline double SmoothMap(double a, double b, double t, double* jac) {
  *jac = (b - a) * 6 * t * (1 - t);
  return a + (b - a) * t * t * (3 - 2 * t);
}

/// Both rules: `inner(h, phis, n, weight)` integrates one azimuth circle over its panels,
/// `outer(f, panels)` the circles over v.
template <class Inner, class Outer>
Channels<2> IntegrateBtdf(const BtdfView& v, Inner&& inner, Outer&& outer) {
  double thetas[kMaxBreaks];
  int nt = BtdfThetaBreaks(v, thetas);
  double vs[kMaxBreaks];
  for (int i = 0; i < nt; ++i) vs[i] = i == 0 ? 1.0 : v.dist.VFromTheta(thetas[i]);
  int panels = nt - 1;
  auto circle = [&](double x) -> Channels<2> {
    int i = std::min(static_cast<int>(x), panels - 1);
    double t = x - i, jac;
    double vv = SmoothMap(vs[i], vs[i + 1], t, &jac);
    jac = -jac;
    if (!(vv > 0) || !(jac > 0)) return Channels<2>{};
    PolarParam h = v.dist.FromV(vv);
    double phis[4];
    int np = BtdfPhiBreaks(v, h, phis);
    if (np < 2) return Channels<2>{};
    return (jac / Pi) * inner(h, phis, np, jac);
  };
  return outer(circle, panels);
}

/// The bake's node counts.
const DielectricBtdfRuleOptions kTuned = {12, 12};

}  // namespace

std::array<double, 2> SmoothDielectricBtdfPair(double mu, double eta) {
  return {1.0, FrDielectric(Clamp(mu, 0.0, 1.0), eta)};
}

std::array<double, 2> DielectricBtdfPair(double mu, double alpha, double eta,
                                         const IntegrationOptions& opt, IntegrationStats& stats) {
  BtdfView v = MakeBtdfView(mu, alpha, eta);
  double innerTol = opt.tol / 10;
  int panelsSeen = 1;
  auto inner = [&](PolarParam h, const double* phis, int np, double jac) {
    auto f = [&](double x) -> Channels<2> {
      int i = std::min(static_cast<int>(x), np - 2);
      double t = x - i, dj;
      double phi = SmoothMap(phis[i], phis[i + 1], t, &dj);
      ++stats.evals;
      return dj * BtdfIntegrand(v, h, std::cos(phi));
    };
    double xs[4];
    for (int i = 0; i < np; ++i) xs[i] = i;
    double tolHere = innerTol * Pi / (jac * panelsSeen);
    return IntegrateAdaptive<2>(f, xs, np, tolHere, opt.maxPanels);
  };
  double err = 0;
  auto outer = [&](auto& circle, int panels) {
    panelsSeen = panels;
    double xs[kMaxBreaks];
    for (int i = 0; i <= panels; ++i) xs[i] = i;
    return IntegrateAdaptive<2>(circle, xs, panels + 1, opt.tol / 2, opt.maxPanels, &err);
  };
  Channels<2> r = IntegrateBtdf(v, inner, outer);
  stats.errorEstimate = err;
  return r;
}

DielectricBtdfRuleOptions TunedDielectricBtdfRuleOptions() { return kTuned; }

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  const DielectricBtdfRuleOptions& opt,
                                                  long long* evals) {
  BtdfView v = MakeBtdfView(mu, alpha, eta);
  const GaussRule01& gi = CachedGaussLegendre01(opt.innerNodes);
  const GaussRule01& go = CachedGaussLegendre01(opt.outerNodes);
  long long count = 0;
  auto inner = [&](PolarParam h, const double* phis, int np, double) {
    Channels<2> sum{0, 0};
    for (int p = 0; p + 1 < np; ++p) {
      if (!(phis[p + 1] > phis[p])) continue;
      for (size_t k = 0; k < gi.x.size(); ++k) {
        double dj;
        double phi = SmoothMap(phis[p], phis[p + 1], gi.x[k], &dj);
        ++count;
        sum += (gi.w[k] * dj) * BtdfIntegrand(v, h, std::cos(phi));
      }
    }
    return sum;
  };
  auto outer = [&](auto& circle, int panels) {
    Channels<2> sum{0, 0};
    for (int i = 0; i < panels; ++i)
      for (size_t k = 0; k < go.x.size(); ++k) sum += go.w[k] * circle(i + go.x[k]);
    return sum;
  };
  Channels<2> r = IntegrateBtdf(v, inner, outer);
  if (evals) *evals += count;
  return r;
}

std::array<double, 2> FixedRuleDielectricBtdfPair(double mu, double alpha, double eta,
                                                  long long* evals) {
  return FixedRuleDielectricBtdfPair(mu, alpha, eta, kTuned, evals);
}

}  // namespace kiln
