// The albedo of a cosine lobe about the mirror direction as one integral over the lobe's angle.
//
// Derivation. Put l in polar coordinates about the mirror direction m = (-o_x, -o_y, mu):
// v = m.l, phi the azimuth about m. With s = sqrt(1 - mu^2), mu_l = mu v + s sqrt(1 - v^2) cos phi
// and, for a lobe that depends on v alone,
//     E = (n + 2) / (2 pi) int_0^1 v^n Phi(v) dv,  Phi(v) = int_0^2pi max(0, a + b cos phi) dphi,
// a = mu v >= 0, b = s sqrt(1 - v^2). Phi = 2 pi a where a >= b (v >= s: the whole circle is
// above the horizon) and 2 (a acos(-a / b) + sqrt(b^2 - a^2)) below. So
//     E = mu (1 - s^(n+2)) + (n + 2) / (2 pi) int_0^s v^n Phi(v) dv.
// On [0, s] put v = s sin(psi): b^2 - a^2 = s^2 cos^2(psi), acos(-a / b) = pi - atan2(cos psi,
// mu sin psi), and the integrand (s sin psi)^n 2 s (mu sin psi (pi - atan2(cos psi, mu sin psi))
// + cos psi) s cos psi is analytic in psi on [0, pi/2] but for psi^n at 0 (n not an integer)
// and the lobe's peak at psi = pi/2, of width 1 / sqrt(n + 1). Quadrature: for large n
// (12 widths < pi/4) only the last 12 widths, 4 Gauss panels of 12 nodes; otherwise [0, pi/4]
// by one panel graded towards 0 (psi = L expm1(h u) / expm1(h), h = log(1 + L / 1e-10), in which
// psi^n is smooth for every n > 0) and [pi/4, pi/2] by 4 Gauss panels of 12 nodes. The last
// panel of either is graded towards pi/2 at scale mu: atan2(cos psi, mu sin psi) turns from
// pi/2 to 0 within cos psi ~ mu there (the azimuths that reach below the horizon).
#include "baker/integrate/fixed_rule_lobe.h"

#include <algorithm>
#include <cmath>

#include "baker/math/quadrature.h"

namespace kiln {
namespace {

struct Lobe {
  double mu, s, n;
  long long count = 0;
  /// The integrand at psi (without the (n + 2) / (2 pi)).
  double At(double psi) {
    ++count;
    const double sp = std::sin(psi), cp = std::cos(psi), v = s * sp;
    if (!(v > 0)) return 0;
    const double phi = 2 * s * (mu * sp * (Pi - std::atan2(cp, mu * sp)) + cp);
    return std::exp(n * std::log(v)) * phi * s * cp;
  }
};

template <typename K>
double Plain(K& k, double a, double b, int nodes) {
  const GaussRule01& g = CachedGaussLegendre01(nodes);
  double sum = 0;
  for (size_t i = 0; i < g.x.size(); ++i) sum += g.w[i] * k.At(a + (b - a) * g.x[i]);
  return sum * (b - a);
}

/// [0, L] graded towards 0 at scale e.
template <typename K>
double GradedToZero(K& k, double L, double e, int nodes) {
  const double h = std::log1p(L / e), em = std::expm1(h);
  const GaussRule01& g = CachedGaussLegendre01(nodes);
  double sum = 0;
  for (size_t i = 0; i < g.x.size(); ++i) {
    const double psi = L * std::expm1(h * g.x[i]) / em;
    sum += g.w[i] * k.At(psi) * L * h * std::exp(h * g.x[i]) / em;
  }
  return sum;
}

/// [end - L, end] graded towards end at scale e (or plain when e is not below L / 4).
template <typename K>
double GradedToEnd(K& k, double end, double L, double e, int nodes) {
  if (!(e > 0 && e < L / 4)) return Plain(k, end - L, end, nodes);
  const double h = std::log1p(L / e), em = std::expm1(h);
  const GaussRule01& g = CachedGaussLegendre01(nodes + static_cast<int>(std::ceil(2 * h)));
  double sum = 0;
  for (size_t i = 0; i < g.x.size(); ++i) {
    const double x = L * std::expm1(h * g.x[i]) / em;
    sum += g.w[i] * k.At(end - x) * L * h * std::exp(h * g.x[i]) / em;
  }
  return sum;
}

/// unity-brdf3's lobe g(v) = min(16, c v^n) over both signs of v = m.l (the (R.L)^4 of the
/// texture is even in R.L), c = (n + 2) / (2 pi^2): the integrand at psi of the twin-summed form
/// (without the 1 / pi), v = s sin(psi). The lobe about m contributes Phi(+v), its twin about -m
/// Phi(-v): Phi(v) + Phi(-v) = 2 s (mu sin psi (pi - 2 atan2(cos psi, mu sin psi)) + 2 cos psi).
struct TwinLobe {
  double mu, s, n, c;
  long long count = 0;
  double At(double psi) {
    ++count;
    const double sp = std::sin(psi), cp = std::cos(psi), v = s * sp;
    if (!(v > 0)) return 0;
    const double phi = 2 * s * (mu * sp * (Pi - 2 * std::atan2(cp, mu * sp)) + 2 * cp);
    return std::min(16.0, c * std::exp(n * std::log(v))) * phi * s * cp;
  }
};

}  // namespace

double FixedRuleUnityBRDF3Albedo(double mu, double n, long long* evals) {
  TwinLobe k;
  k.mu = std::min(1.0, std::max(0.0, mu));
  k.s = std::sqrt((1 - k.mu) * (1 + k.mu));
  k.n = std::max(n, 0.0);
  k.c = (k.n + 2) / (2 * Pi * Pi);
  // The clamp: c v^n = 16 at v_c = e^t, t = ln(16 / c) / n (v_c >= 1: no clamp, c <= 16).
  const double t = k.c > 16 ? std::log(16 / k.c) / k.n : 0;
  const bool clamps = k.c > 16;
  // v >= s (the whole azimuth circle above the horizon, the twin wholly below):
  // 2 pi mu int_s^1 min(16, c v^n) v dv, split at mid = clamp(v_c, s, 1).
  double closed;
  if (!clamps) {
    closed =
        2 * k.mu * k.c * (1 - std::exp((k.n + 2) * std::log(std::max(k.s, 1e-300)))) / (k.n + 2);
  } else {
    const double vc = std::exp(t);
    if (vc <= k.s) {
      closed = 16 * k.mu * k.mu * k.mu;  // 2 mu 16 (1 - s^2) / 2
    } else {
      const double lobe =
          k.c * (std::exp((k.n + 2) * t) - std::exp((k.n + 2) * std::log(std::max(k.s, 1e-300)))) /
          (k.n + 2);
      closed = 2 * k.mu * (lobe - 8 * std::expm1(2 * t));
    }
  }
  double integral = 0;
  if (k.s > 0) {
    const double w = 1 / std::sqrt(k.n + 1), half = Pi / 2;
    if (12 * w < Pi / 4) {
      // The clamp's kink at psi_c = asin(v_c / s) (cos psi_c = sqrt((s - v_c)(s + v_c)) / s,
      // s - v_c = -mu^2 / (1 + s) - expm1(t) without cancellation): a panel boundary.
      double psiC = half;
      if (clamps) {
        const double vc = std::exp(t), gap = -k.mu * k.mu / (1 + k.s) - std::expm1(t);
        if (gap > 0) psiC = std::atan2(vc, std::sqrt(gap * (k.s + vc)));
      }
      const double lo = std::min(half - 12 * w, psiC);
      if (psiC < half) {
        const int panels = std::max(1, static_cast<int>(std::ceil((psiC - lo) / (3 * w))));
        for (int p = 0; p < panels; ++p)
          integral +=
              Plain(k, lo + (psiC - lo) * p / panels, lo + (psiC - lo) * (p + 1) / panels, 12);
        integral += GradedToEnd(k, half, half - psiC, k.mu, 12);
      } else {
        for (int p = 0; p < 3; ++p) integral += Plain(k, lo + 3 * w * p, lo + 3 * w * (p + 1), 12);
        integral += GradedToEnd(k, half, 3 * w, k.mu, 12);
      }
    } else {
      integral += GradedToZero(k, Pi / 4, 1e-10, 48);
      for (int p = 0; p < 3; ++p)
        integral += Plain(k, Pi / 4 + Pi / 16 * p, Pi / 4 + Pi / 16 * (p + 1), 12);
      integral += GradedToEnd(k, half, Pi / 16, k.mu, 12);
    }
  }
  if (evals) *evals += k.count;
  return closed + integral / Pi;
}

double FixedRuleMirrorLobeAlbedo(double mu, double n, long long* evals) {
  Lobe k;
  k.mu = std::min(1.0, std::max(0.0, mu));
  k.s = std::sqrt((1 - k.mu) * (1 + k.mu));
  k.n = std::max(n, 0.0);
  const double closed = k.mu * (1 - std::exp((k.n + 2) * std::log(std::max(k.s, 1e-300))));
  double integral = 0;
  if (k.s > 0) {
    const double w = 1 / std::sqrt(k.n + 1), half = Pi / 2;
    if (12 * w < Pi / 4) {
      const double lo = half - 12 * w;
      for (int p = 0; p < 4; ++p) integral += Plain(k, lo + 3 * w * p, lo + 3 * w * (p + 1), 12);
    } else {
      integral += GradedToZero(k, Pi / 4, 1e-10, 48);
      for (int p = 0; p < 3; ++p)
        integral += Plain(k, Pi / 4 + Pi / 16 * p, Pi / 4 + Pi / 16 * (p + 1), 12);
      integral += GradedToEnd(k, half, Pi / 16, k.mu, 12);
    }
  }
  if (evals) *evals += k.count;
  return closed + (k.n + 2) / (2 * Pi) * integral;
}

}  // namespace kiln
