// The exit walk's panel breaks in fewer operations (dielectric_albedo.cpp, FastWalk, both
// paths): the same outer (theta_m) and inner (phi_m) boundaries as ThetaBreaks and PhiBreaks of
// dielectric_albedo.cpp (derivations there), to within rounding, from
//  - per view: the masking layers' sequences m = scale / 4 by the ratio (ExitBreakConsts), and
//    for the refracted ray's thresholds mu - m eta;
//  - per ring: one division (1 / (sin_o sin_m)) and 1 / cos_m, each threshold's cos(phi) by a
//    product, and acos by a polynomial (Acos below);
//  - the refracted horizon's outer breaks: the scan's cosines from a table of the scan's angles
//    (cos(t -+ theta_o) by the angle-sum formula), its critical points in closed form, and its
//    roots by the Illinois variant of false position (to 1e-15 rad) instead of 60 bisections.
// Scalar code, the same on the AVX-512F and the portable path of the exit walk.
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/integrate/dielectric_walk.h"
#include "baker/integrate/hemisphere.h"

namespace kiln {
namespace dielectric_exit_breaks {

/// Most terms of a masking layer's sequence (the portable rule stops at 20 thresholds).
constexpr int kMaxLayer = 24;
/// The portable rule's limits on a ring's thresholds: all of them, and before the reflected
/// masking layer's last.
constexpr int kMaxThresholds = 30, kMaxReflectedThresholds = 20;

/// A view's thresholds that do not depend on the ring: the reflected ray's masking layer m (the
/// thresholds (m + mu) / (2 cos_m)) and the refracted ray's mu - m eta for m = 0 and its layer
/// (the thresholds at q = (mu - m eta) / cos_m, c = (q^2 + 1 - eta^2) / (2 q)).
struct ExitBreakConsts {
  int nReflected = 0, nRefracted = 0;
  double reflected[kMaxLayer], refracted[kMaxLayer];
  /// The reflected ray's thresholds (its horizon and masking layer) below this are no boundaries
  /// (the exit walk's complement form: past them the ring is under total internal reflection and
  /// skipped); they still count towards kMaxThresholds.
  double cDrop = -INFINITY;
};

/// (asin(x) - x) / (x z), z = x^2 in [0, 1/4], as a polynomial in z: asin's Taylor series
/// ((2n)! / (4^n (n!)^2 (2n + 1)), n = 1 .. 45) economised by shifted Chebyshev polynomials on
/// [0, 1/4] to degree 12 in exact rationals (economisation error below 1.5e-17), then rounded.
constexpr double kAsinSeries[13] = {
    0.16666666666666669,  0.0749999999999834,   0.04464285714653523, 0.03038194412500875,
    0.022372173467043486, 0.017352380709839098, 0.01397138708310213, 0.011477517005507167,
    0.01033337215296726,  0.005413184483715509, 0.01751883397953867, -0.015032162599250313,
    0.02887836274645239};

/// acos x for x in (-1, 1): for |x| <= 1/2, pi/2 - asin x; above, 2 asin sqrt((1 - |x|) / 2)
/// (an exact argument), or pi minus it for x < 0; asin(s) = s + s z P(z), z = s^2, P by
/// kAsinSeries. Within 5e-16 of libm's acos (4.4e-16 over 300,000 points, a scratch check).
inline double Acos(double x) {
  const double ax = std::abs(x);
  const bool big = ax > 0.5;
  const double z = big ? (1 - ax) * 0.5 : x * x;
  const double s = big ? std::sqrt(z) : ax;
  // P(z) by Estrin's scheme (a short dependency chain: a ring's few acos overlap).
  const double* c = kAsinSeries;
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double p01 = c[0] + c[1] * z, p23 = c[2] + c[3] * z, p45 = c[4] + c[5] * z,
               p67 = c[6] + c[7] * z, p89 = c[8] + c[9] * z, p1011 = c[10] + c[11] * z;
  const double p =
      (p01 + z2 * p23) + z4 * (p45 + z2 * p67) + z8 * ((p89 + z2 * p1011) + z4 * c[12]);
  const double r = s + s * z * p;
  if (!big) return Pi / 2 - (x < 0 ? -r : r);
  return x < 0 ? Pi - 2 * r : 2 * r;
}

/// The view's constants (the portable Thresholds' loops, their terms kept).
template <class View>
ExitBreakConsts ConstsOf(const View& v) {
  ExitBreakConsts k;
  const double scale = std::min(v.mu, v.dist.alpha);
  for (double m = scale / 4;
       m > 0 && m < 0.25 && 1 + v.ncs + k.nReflected < kMaxReflectedThresholds; m *= v.maskingRatio)
    k.reflected[k.nReflected++] = m;
  if (v.eta < 1 && !v.reflectOnly)
    for (double m = 0; k.nRefracted < kMaxLayer; m = m == 0 ? scale / 4 : v.maskingRatio * m) {
      k.refracted[k.nRefracted++] = v.mu - m * v.eta;
      if (!(scale > 0) || m > 0.25) break;
    }
  return k;
}

/// PhiBreaks of dielectric_albedo.cpp: the inner boundaries in phi over [0, phiMax] at polar
/// angle h, sorted; returns their count (>= 2), or 0 when nothing is visible.
template <class View>
int PhiBreaks(const View& v, const ExitBreakConsts& k, PolarParam h, double* phis) {
  const double den = v.st * h.sinTheta, A = v.mu * h.cosTheta;
  if (!(den > 0)) {
    if (!(A > 0)) return 0;
    phis[0] = 0;
    phis[1] = Pi;
    return 2;
  }
  // 0.5 / cos_m as 0.5 (1 / cos_m): the same bits (a power of two scales exactly).
  const double inv = 1 / den, invCos = 1 / h.cosTheta, half = 0.5 * invCos;
  double cp[2 + kMaxThresholds];
  int n = 0;
  cp[n++] = -A * inv;  // the end of visibility, c0 = 0
  if (cp[0] >= 1) return 0;
  auto add = [&](double c0) { cp[n++] = (c0 - A) * inv; };
  // A reflected threshold below cDrop: a slot outside (-1, 1), no boundary.
  auto addReflected = [&](double c0) {
    if (c0 < k.cDrop)
      cp[n++] = 2;
    else
      add(c0);
  };
  addReflected(v.mu * half);
  for (int i = 0; i < v.ncs; ++i) add(v.cs[i]);
  for (int i = 0; i < k.nReflected; ++i) addReflected((k.reflected[i] + v.mu) * half);
  if (v.eta < 1) {
    add(v.cCrit);
    const double c2 = -v.eta2m1;
    for (int i = 0; i < k.nRefracted && n - 1 < kMaxThresholds; ++i) {
      const double q = k.refracted[i] * invCos;
      if (!(q > 0)) break;
      const double c = (q * q + c2) / (2 * q);
      if (c >= q && c > v.cCrit && c < 1) add(c);
    }
  }
  const double phiMax = cp[0] > -1 ? Acos(cp[0]) : Pi;  // cp[0] < 1 (above)
  int np = 0;
  phis[np++] = 0;
  for (int i = 1; i < n; ++i)
    if (cp[i] > -1 && cp[i] < 1) {
      const double q = Acos(cp[i]);
      if (q > 0 && q < phiMax) phis[np++] = q;
    }
  phis[np++] = phiMax;
  SortSmall(phis, np);
  return np;
}

/// The refracted ray's mu at c = o.m, microfacet cosine cosM (continuous at the critical cosine,
/// where cos_t = 0); the rule of dielectric_albedo.cpp and the exit walk's breaks alike.
template <class View>
double MuRefracted(const View& v, double c, double cosM) {
  const double cosT = std::sqrt(std::max(0.0, c * c + v.eta2m1)) / v.eta;
  return -v.mu / v.eta + (c / v.eta - cosT) * cosM;
}

/// cos x for x in [-pi, pi] by dielectric_walk::CosHalfTurn (cos is even).
inline double CosAny(double x) { return dielectric_walk::CosHalfTurn(std::abs(x)); }

/// The root in [lo, hi] of f, whose signs (f > 0) differ at the ends (fLo = f(lo), fHi =
/// f(hi)): false position with the Illinois halving, until the bracket is narrower than 1e-15
/// or the point stops moving (at most 100 steps; deterministic).
template <class F>
double Root(F&& f, double lo, double hi, double fLo, double fHi) {
  constexpr double kWidth = 1e-15;
  int side = 0;
  double x = (lo + hi) / 2;
  for (int it = 0; it < 100 && hi - lo > kWidth; ++it) {
    const double xNew = fHi != fLo ? (lo * fHi - hi * fLo) / (fHi - fLo) : (lo + hi) / 2;
    const double xn = xNew > lo && xNew < hi ? xNew : (lo + hi) / 2;
    if (it > 0 && xn == x) break;
    x = xn;
    const double fx = f(x);
    if ((fx > 0) == (fHi > 0)) {
      hi = x;
      fHi = fx;
      if (side == -1) fLo /= 2;
      side = -1;
    } else {
      lo = x;
      fLo = fx;
      if (side == 1) fHi /= 2;
      side = 1;
    }
  }
  return x;
}

/// The angles of the portable scan for the refracted horizon, t = (pi / 2) s / 64, s = 0 .. 64,
/// their cos and sin.
constexpr int kScanSteps = 64;
struct ScanTable {
  double cosT[kScanSteps + 1], sinT[kScanSteps + 1], t[kScanSteps + 1];
};
inline const ScanTable& Scan() {
  static const ScanTable table = [] {
    ScanTable s;
    for (int i = 0; i <= kScanSteps; ++i) {
      s.t[i] = (Pi / 2) * i / kScanSteps;
      s.cosT[i] = std::cos(s.t[i]);
      s.sinT[i] = std::sin(s.t[i]);
    }
    return s;
  }();
  return table;
}

/// The refracted horizon's outer breaks (ThetaBreaks of dielectric_albedo.cpp, its scan and
/// bisections): where mu_t changes sign along phi = 0 (side 0, c = cos(t - theta_o)) and phi =
/// pi (side 1, c = cos(t + theta_o)), c above the critical cosine; add(t) for each.
template <class View, class Add>
void RefractedHorizonBreaks(const View& v, Add&& add) {
  const ScanTable& s = Scan();
  const double to = v.thetaO, co = std::cos(to), so = std::sin(to);
  const double a = std::acos(v.cCrit);  // c > c_crit  <=>  |angle| < a
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1 : 1;
    auto muT = [&](double t) { return MuRefracted(v, CosAny(t + sign * to), CosAny(t)); };
    // At the scan's angles: cos(t -+ theta_o) by the angle-sum formula.
    auto cAt = [&](int i) { return s.cosT[i] * co - sign * s.sinT[i] * so; };
    double fa = MuRefracted(v, cAt(0), s.cosT[0]);
    bool okA = cAt(0) > v.cCrit;
    for (int i = 1; i <= kScanSteps; ++i) {
      const double ta = s.t[i - 1], tb = s.t[i], cb = cAt(i);
      const bool okB = cb > v.cCrit;
      const double fb = MuRefracted(v, cb, s.cosT[i]);
      double ua = ta, ub = tb, ga = fa, gb = fb;
      if (okA != okB) {
        // The critical point between them: t -+ theta_o = -+a.
        double tc = side == 0 ? (okA ? to + a : to - a) : a - to;
        tc = std::min(std::max(tc, ta), tb);
        (okA ? ub : ua) = tc;
        (okA ? gb : ga) = muT(tc);
      }
      if ((okA || okB) && (ga > 0) != (gb > 0)) add(Root(muT, ua, ub, ga, gb));
      fa = fb;
      okA = okB;
    }
  }
}

}  // namespace dielectric_exit_breaks
}  // namespace kiln
