// Deterministic directional integrals over the hemisphere of light directions,
//     E(o) = integral_{H^2} g(o, l) mu_l dl,
// for a channel-valued g, to a tolerance that is absolute where the integral is at most 1 and
// relative above (WithRelativeTolerance below), in double precision.
//
// Light space (smooth lobes): E = 2 int_0^{pi/2} dtheta_l sin cos int_0^pi dphi g, the factor 2
// from the mirror symmetry phi -> -phi of isotropic models. The diffuse models bend where
// theta_l = theta_o (max/min of the angles) and at phi = pi/2 (the sign of cos(phi)): those are
// the first panel boundaries, so every panel is smooth and Gauss-Kronrod converges fast. A model
// names the other cosines where it bends (LightMuKinks: charlie-smith's Lambda switch at
// mu_l = 1/2 and its clamp V <= 1), which become boundaries too (a quarter of the evaluations).
//
// Half-vector space (sharp lobes): with l = reflect(o, h), dl = 4 (o.h) dh, and h walked by
// (v, phi_h) where v is the complementary CDF of the lobe's own polar density (see
// models/specular.h), so a lobe of alpha = 1e-4 is as easy as alpha = 1. The horizon cut is exact:
// mu_l = 2 (o.h) cos(theta_h) - mu_o > 0  <=>  cos(phi_h) > c = -mu_o cos(2 theta_h)
// / (sin(theta_o) sin(2 theta_h)), so the inner integral runs over [0, acos(c)]. The whole circle
// survives for theta_h < pi/4 - theta_o/2 and nothing for theta_h > pi/4 + theta_o/2: those are the
// outer panel boundaries. Near them the inner integral behaves like (distance)^(3/2); each outer
// panel therefore maps t in [0,1] through the smoothstep 3t^2 - 2t^3, which turns that into an
// analytic t^3 and restores the fast convergence of the Gauss rule.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "baker/math/quadrature.h"
#include "baker/math/sincos_half_turn.h"
#include "baker/models/brdf.h"
#include "baker/models/specular.h"

namespace kiln {

/// Tolerance and panel budget of an integral; stats collect what it cost.
struct IntegrationOptions {
  double tol = 1e-9;    ///< tolerance on every channel: absolute, relative where |E| > 1
  int maxPanels = 400;  ///< per adaptive level
};
struct IntegrationStats {
  long long evals = 0;  ///< integrand evaluations
  double errorEstimate = 0;
  bool capped = false;  ///< some adaptive level stopped above its tolerance (IntegrateAdaptive)
};

/// Runs integral(options, stats) -> Channels<N> to opt.tol absolute where the result is at most
/// 1 in magnitude and opt.tol relative above. An absolute tolerance on a large integral asks for
/// more digits than double has (Ward's albedo grows like mu^(-1/2), Duer's like 1 / mu: 7.7e10 at
/// mu = 1e-12, where 1e-9 absolute is 1e-20 relative and every adaptive level ran to its panel
/// cap, 20 s per albedo). A first pass takes the initial panels of every level only (maxPanels
/// 0). Where no level is above its tolerance there, it is the absolute result itself (the full
/// run would compute the same panels and stop: the same bits), and it is returned. Otherwise its
/// magnitude m sets the tolerance, opt.tol max(1, m). An estimate far above the final value (a
/// lobe the first panels overweigh) is redone at the tolerance the value calls for, so the
/// result never gets a looser tolerance than max(1, |E|) opt.tol.
template <int N, class Integral>
Channels<N> WithRelativeTolerance(Integral&& integral, const IntegrationOptions& opt,
                                  IntegrationStats& stats) {
  auto magnitude = [](const Channels<N>& v) {
    double m = 0;
    for (int c = 0; c < N; ++c) m = std::max(m, std::abs(v[c]));
    return m;
  };
  IntegrationOptions first = opt;
  first.maxPanels = 0;
  IntegrationStats firstStats;
  Channels<N> estimate = integral(first, firstStats);
  stats.evals += firstStats.evals;
  if (!firstStats.capped) {
    stats.errorEstimate = firstStats.errorEstimate;
    return estimate;
  }
  double scale = magnitude(estimate);
  if (!(scale > 1) || !std::isfinite(scale)) return integral(opt, stats);
  IntegrationOptions scaled = opt;
  scaled.tol = opt.tol * scale;
  Channels<N> r = integral(scaled, stats);
  double needed = std::max(1.0, magnitude(r));
  if (!(scale <= 2 * needed)) {
    scaled.tol = opt.tol * needed;
    r = integral(scaled, stats);
  }
  return r;
}

inline void SortSmall(double* x, int n);  // below: the panel boundaries' insertion sort

/// Where g bends along one circle theta_l of light space (a model's LightPhiKinks): writes the
/// cos(phi_l) of its bends (at most 4) for the circle's sin and cos, returns their count.
using LightPhiKinkFn = std::function<int(double sinTheta_l, double cosTheta_l, double* cosPhi)>;

/// E(o) over light space for g(wo, wi) -> Channels<N> (g excludes the cosine), to the absolute
/// tolerance opt.tol.
/// muKinks (optional): light cosines where g bends (a model's LightMuKinks), extra outer panel
/// boundaries at theta_l = acos(mu_l). phiKinks (optional): bends in phi_l on each circle, extra
/// inner panel boundaries.
template <int N, class G>
Channels<N> IntegrateLightSpaceAbsolute(double mu_o, G&& g, const IntegrationOptions& opt,
                                        IntegrationStats& stats,
                                        const std::vector<double>& muKinks = {},
                                        const LightPhiKinkFn& phiKinks = {}) {
  Vec3 wo = ViewDirection(mu_o);
  double theta_o = std::acos(Clamp(mu_o, 0.0, 1.0));
  std::vector<double> thetaBreaks = {0, Pi / 2};
  if (theta_o > 0 && theta_o < Pi / 2) thetaBreaks.push_back(theta_o);
  for (double mu_l : muKinks)
    if (mu_l > 0 && mu_l < 1) thetaBreaks.push_back(std::acos(mu_l));
  std::sort(thetaBreaks.begin(), thetaBreaks.end());
  thetaBreaks.erase(std::unique(thetaBreaks.begin(), thetaBreaks.end()), thetaBreaks.end());
  double innerTol = opt.tol / (10 * Pi);
  double errSum = 0;
  auto outer = [&](double theta_l) -> Channels<N> {
    double sinT = std::sin(theta_l), cosT = std::cos(theta_l);
    double phiBreaks[7] = {0, Pi / 2, Pi};
    int np = 3;
    if (phiKinks) {
      double cosPhi[4];
      const int nk = std::min(phiKinks(sinT, cosT, cosPhi), 4);
      for (int k = 0; k < nk; ++k)
        if (cosPhi[k] > -1 && cosPhi[k] < 1) phiBreaks[np++] = std::acos(cosPhi[k]);
      SortSmall(phiBreaks, np);
    }
    auto inner = [&](double phi) -> Channels<N> {
      ++stats.evals;
      return g(wo, SphericalDirectionHalfTurn(sinT, cosT, phi));
    };
    double e = 0;
    Channels<N> r =
        IntegrateAdaptive<N>(inner, phiBreaks, np, innerTol, opt.maxPanels, &e, &stats.capped);
    errSum += e;
    return (2 * sinT * cosT) * r;
  };
  double err = 0;
  Channels<N> r =
      IntegrateAdaptive<N>(outer, thetaBreaks.data(), static_cast<int>(thetaBreaks.size()),
                           opt.tol / 2, opt.maxPanels, &err, &stats.capped);
  stats.errorEstimate = err;
  return r;
}

/// E(o) over light space for g(wo, wi) -> Channels<N> (g excludes the cosine), to opt.tol
/// absolute, relative where |E| > 1 (WithRelativeTolerance).
template <int N, class G>
Channels<N> IntegrateLightSpace(double mu_o, G&& g, const IntegrationOptions& opt,
                                IntegrationStats& stats, const std::vector<double>& muKinks = {},
                                const LightPhiKinkFn& phiKinks = {}) {
  return WithRelativeTolerance<N>(
      [&](const IntegrationOptions& o, IntegrationStats& st) {
        return IntegrateLightSpaceAbsolute<N>(mu_o, g, o, st, muKinks, phiKinks);
      },
      opt, stats);
}

/// Insertion sort for the handful of panel boundaries (std::sort trips GCC 12's -Warray-bounds).
/// The element moves by shifts, not swaps: GCC 12 turned the swaps into overlapping two-double
/// stores, whose store-to-load forwarding stalls made the sort a tenth of the glass exit walk's
/// time (perf); the order is the same (the same comparisons).
inline void SortSmall(double* x, int n) {
  for (int i = 1; i < n; ++i) {
    const double key = x[i];
    int j = i;
    for (; j > 0 && x[j - 1] > key; --j) x[j] = x[j - 1];
    x[j] = key;
  }
}

/// cos(phi_h) of the horizon cut at microfacet polar angle h for view mu_o (see the file comment);
/// -inf: the whole circle is above the horizon, >= 1: none of it.
inline double HorizonCutCosPhi(double mu_o, double sinTheta_o, PolarParam h) {
  double cos2 = Sqr(h.cosTheta) - Sqr(h.sinTheta), sin2 = 2 * h.sinTheta * h.cosTheta;
  if (mu_o <= 0) return 0;
  double den = sinTheta_o * sin2;
  if (den <= 0) return cos2 > 0 ? -INFINITY : INFINITY;
  return -mu_o * cos2 / den;
}

namespace hemisphere_detail {
/// A model's HalfWeight at one view mu_o: its HalfWeightAtView(mu_o) where it has one (the
/// view's constants computed once, the same bits), else a call of HalfWeight. m must outlive it.
template <class M>
auto ViewHalfWeightOf(const M& m, double mu_o, int) -> decltype(m.HalfWeightAtView(mu_o)) {
  return m.HalfWeightAtView(mu_o);
}
template <class M>
auto ViewHalfWeightOf(const M& m, double, long) {
  return [&m](const HalfSample& s) { return m.HalfWeight(s); };
}
}  // namespace hemisphere_detail

/// E(o) over half-vector space for a specular model M (kDomain == HalfVector): weights(const
/// HalfSample&, double rho) -> Channels<N>, rho = model.HalfWeight(sample) (the same bits from
/// model.HalfWeightAtView(mu_o) where M has it); to the absolute tolerance opt.tol.
template <int N, class M, class W>
Channels<N> IntegrateHalfVectorAbsolute(const M& model, double mu_o, W&& weights,
                                        const IntegrationOptions& opt, IntegrationStats& stats) {
  mu_o = Clamp(mu_o, 0.0, 1.0);
  Vec3 wo = ViewDirection(mu_o);
  double sinTheta_o = wo.x, theta_o = std::acos(mu_o);
  double thetaEnd = std::min(Pi / 2, Pi / 4 + theta_o / 2);
  // Outer panel boundaries in theta_h: 0, the start of the horizon cut, model kinks, the end.
  double thetas[32];
  int nt = 0;
  thetas[nt++] = 0;
  double thetaCut = Pi / 4 - theta_o / 2;
  if (thetaCut > 0) thetas[nt++] = thetaCut;
  // Grazing views: the cut sweeps from phi = pi to pi/2 over theta_h in [thetaCut, ~30 thetaCut];
  // geometric panels resolve that scale at once instead of by bisection.
  // The same happens mirrored at the end, where the cut closes over pi/2 - theta_h in
  // [thetaCut, ~30 thetaCut] (pi/2 - thetaEnd = thetaCut); there the weight also grows like
  // 1 / cos(theta_h) ~ v^(-1/2), so the panels must reach out to O(1): a panel edge left at
  // pi/2 - t with t << 1 would leave a near-singularity of scale t just outside it that the rule
  // of the panel next to it cannot see (it cost 4e4 mu alpha at mu_o = 1e-10). 12 panels a side,
  // with the ratio grown beyond 4 when thetaCut is tiny.
  double ratio = thetaCut > 0 ? std::max(4.0, std::pow(0.5 / thetaCut, 1.0 / 12)) : 4;
  for (double t = ratio * thetaCut; thetaCut > 0 && t < std::min(0.5, thetaEnd) && nt < 14;
       t *= ratio)
    thetas[nt++] = t;
  for (double t = ratio * thetaCut; thetaCut > 0 && Pi / 2 - t > 0.5 && nt < 26; t *= ratio)
    thetas[nt++] = Pi / 2 - t;
  double kinks[4];
  int nk = model.ThetaKinks(theta_o, kinks);
  for (int i = 0; i < nk; ++i)
    if (kinks[i] > 0 && kinks[i] < thetaEnd) thetas[nt++] = kinks[i];
  thetas[nt++] = thetaEnd;
  SortSmall(thetas, nt);
  // Panel i spans v in [vs[i+1], vs[i]] (v decreases as theta grows); the outer variable x runs
  // over [0, panels] with panel i at [i, i+1].
  double vs[32];
  for (int i = 0; i < nt; ++i) vs[i] = i == 0 ? 1.0 : model.VFromTheta(thetas[i]);
  int panels = nt - 1;
  double innerTol = opt.tol / 10;
  const auto rho = hemisphere_detail::ViewHalfWeightOf(model, mu_o, 0);
  auto outer = [&](double x) -> Channels<N> {
    int i = std::min(static_cast<int>(x), panels - 1);
    double t = x - i, va = vs[i], vb = vs[i + 1];
    double v = va + (vb - va) * t * t * (3 - 2 * t);
    double jac = (va - vb) * 6 * t * (1 - t);
    if (!(v > 0) || !(jac > 0)) return Channels<N>{};
    PolarParam h = model.FromV(v);
    double c = HorizonCutCosPhi(mu_o, sinTheta_o, h);
    if (c >= 1) return Channels<N>{};
    double phiMax = std::acos(std::max(c, -1.0));
    double phis[24];
    int np = 0;
    phis[np++] = 0;
    // Masking bends where mu_l ~ min(mu_o, scale) (Lambda(l) against 1 + Lambda(o)): geometric
    // panels in mu_l resolve that scale. mu_l = 2 cos_h (sin_o sin_h cos(phi) + mu_o cos_h) - mu_o.
    double den = 2 * h.cosTheta * sinTheta_o * h.sinTheta;
    double scale = std::min(mu_o, model.MaskingScale());
    // m > 0: at the smallest subnormals scale / 4 rounds to 0, and 0 * 4 would loop forever.
    if (den > 0 && scale > 0)
      for (double m = scale / 4; m > 0 && m < 0.25 && np < 16; m *= 4) {
        double cphi = (m + mu_o - 2 * mu_o * Sqr(h.cosTheta)) / den;
        if (cphi > std::max(c, -1.0) && cphi < 1) phis[np++] = std::acos(cphi);
      }
    double cosKinks[4];
    int nck = model.PhiKinks(mu_o, sinTheta_o, h, cosKinks);
    for (int k = 0; k < nck; ++k)
      if (cosKinks[k] > std::max(c, -1.0) && cosKinks[k] < 1) phis[np++] = std::acos(cosKinks[k]);
    phis[np++] = phiMax;
    SortSmall(phis, np);
    auto inner = [&](double phi) -> Channels<N> {
      ++stats.evals;
      HalfSample s;
      s.wo = wo;
      s.wm = SphericalDirectionHalfTurn(h.sinTheta, h.cosTheta, phi);
      s.oh = Dot(wo, s.wm);
      s.cosTheta_h = h.cosTheta;
      s.mu_o = mu_o;
      s.mu_l = 2 * s.oh * h.cosTheta - mu_o;
      if (!(s.mu_l > 0) || !(s.oh > 0)) return Channels<N>{};
      s.wi = Reflect(wo, s.wm);
      return weights(s, rho(s));
    };
    // The outer rule weighs this inner integral by 2 jac: its tolerance scales inversely, so
    // a panel of tiny measure is not integrated to a precision nobody can see.
    double tolHere = innerTol / (2 * jac * panels);
    return (2 * jac) *
           IntegrateAdaptive<N>(inner, phis, np, tolHere, opt.maxPanels, nullptr, &stats.capped);
  };
  double xs[32];
  for (int i = 0; i <= panels; ++i) xs[i] = i;
  double err = 0;
  Channels<N> r =
      IntegrateAdaptive<N>(outer, xs, panels + 1, opt.tol / 2, opt.maxPanels, &err, &stats.capped);
  stats.errorEstimate = err;
  return r;
}

/// E(o) over half-vector space for a specular model M (IntegrateHalfVectorAbsolute), to opt.tol
/// absolute, relative where |E| > 1 (WithRelativeTolerance).
template <int N, class M, class W>
Channels<N> IntegrateHalfVector(const M& model, double mu_o, W&& weights,
                                const IntegrationOptions& opt, IntegrationStats& stats) {
  return WithRelativeTolerance<N>(
      [&](const IntegrationOptions& o, IntegrationStats& st) {
        return IntegrateHalfVectorAbsolute<N>(model, mu_o, weights, o, st);
      },
      opt, stats);
}

}  // namespace kiln
