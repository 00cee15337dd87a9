// Fresnel's reflectance on the entering side as a Chebyshev series in the cosine, and the
// moments that turn a column walk's E_R into a few multiply-adds per eta
// (dielectric_albedo.cpp, "Columns"): for eta >= kDielectricTableEtaMin = 1.1,
//     F(c, eta) ~ F_N(c, eta) = sum_{k <= kDegree} a_k(eta) T_k(2 c - 1),   c in [0, 1],
// so a walk's sum over nodes of w R F(c, eta) is sum_k a_k(eta) M_k, M_k = sum over nodes of
// w R T_k(2 c - 1): exactly the rule applied to F_N. F(., eta) is analytic on [0, 1] there (its
// nearest singularities are the branch points c = +-i sqrt(eta^2 - 1), 0.458 at eta 1.1), so the
// coefficients decay geometrically (Trefethen, Approximation Theory and Approximation Practice,
// ch. 8): kDegree 26 leaves max |F - F_N| = 1.1e-11 over the domain (worst at eta 3, c ~ 0;
// degree 24: 8.4e-11, 22: 6.6e-10), held under kFitBound by tests/integrate_dielectric_moments.cpp.
#pragma once

#include "baker/integrate/dielectric_lanes.h"

namespace kiln {
namespace dielectric_moments {

/// Degree of the Chebyshev series of F; the series has kTerms coefficients.
constexpr int kDegree = 26;
constexpr int kTerms = kDegree + 1;
/// The declared max |F(c, eta) - F_N(c, eta)| over c in [0, 1], eta in [1.1, 3] (measured 1.1e-11).
constexpr double kFitBound = 1e-10;

/// The coefficients a_0 .. a_kDegree of F_N(., eta) for eta >= 1.1 (eta as inside / outside):
/// interpolation at kSamples = 64 Chebyshev points (a discrete cosine transform of FrDielectric),
/// truncated. Deterministic; remembered per eta (by its bits, at most 65,536 etas).
struct Coefficients {
  double a[kTerms];
};
const Coefficients& FresnelChebyshev(double eta);

/// F_N(c, eta) from its coefficients, by the three-term recurrence (the tests' check of the fit).
double EvaluateSeries(const Coefficients& co, double c);

/// A ring's moments: ring[k] = sum over its J nodes of wR[j] T_k(2 cc[j] - 1), k < kTerms (cc in
/// [0, 1]), each term u_k = wR T_k by the recurrence u_0 = wR, u_1 = wR x, u_k = 2 x u_(k-1) -
/// u_(k-2) (x = 2 cc - 1: the weight rides along, three operations a term). The nodes are taken
/// eight at a time, node j into lane j mod 8 (past the end: wR = 0, x = 0), each lane's sums in
/// the nodes' order, the eight lanes then added as ((0 + 1) + (2 + 3)) + ((4 + 5) + (6 + 7)): one
/// fixed order of IEEE operations (no fused multiply-add), the same bits whichever path gave wR
/// and cc (dielectric_simd::RingMoments8 is the same in eight-lane instructions).
inline void RingMoments(const double* wR, const double* cc, int J, double* ring) {
  using dielectric_lanes::Pair;
  using dielectric_lanes::Splat;
  Pair acc[kTerms][4];
  for (int k = 0; k < kTerms; ++k)
    for (int l = 0; l < 4; ++l) acc[k][l] = Splat(0);
  for (int j0 = 0; j0 < J; j0 += 8) {
    double wl[8], xl[8];
    for (int l = 0; l < 8; ++l) {
      const bool in = j0 + l < J;
      wl[l] = in ? wR[j0 + l] : 0;
      xl[l] = in ? 2 * cc[j0 + l] - 1 : 0;
    }
    Pair x2[4], u0[4], u1[4];
    for (int l = 0; l < 4; ++l) {
      const Pair x = dielectric_lanes::Load(xl + 2 * l);
      x2[l] = x + x;
      u0[l] = dielectric_lanes::Load(wl + 2 * l);
      u1[l] = u0[l] * x;
      acc[0][l] = acc[0][l] + u0[l];
      acc[1][l] = acc[1][l] + u1[l];
    }
    for (int k = 2; k < kTerms; ++k)
      for (int l = 0; l < 4; ++l) {
        const Pair u2 = x2[l] * u1[l] - u0[l];
        acc[k][l] = acc[k][l] + u2;
        u0[l] = u1[l];
        u1[l] = u2;
      }
  }
  for (int k = 0; k < kTerms; ++k) {
    double s[8];
    for (int l = 0; l < 4; ++l) dielectric_lanes::Store(s + 2 * l, acc[k][l]);
    ring[k] = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
  }
}

/// sum_k co.a[k] M[k] in the order of k: E_R of one eta from a column's moments.
inline double Contract(const Coefficients& co, const double* M) {
  double s = 0;
  for (int k = 0; k < kTerms; ++k) s = s + co.a[k] * M[k];
  return s;
}

}  // namespace dielectric_moments
}  // namespace kiln
