// Beckmann's Smith Lambda with one exp and no erfc (Walter et al. 2007 eq. 27, Heitz 2014):
//     Lambda(x) = (exp(-x^2) / (x sqrt(pi)) - erfc(x)) / 2,  x = mu / (alpha sin),
//     mu Lambda = (alpha sin / 2) exp(-x^2) psi(x),  psi(x) = 1/sqrt(pi) - x erfcx(x),
// erfcx(x) = exp(x^2) erfc(x). psi is smooth, positive and decreasing on [0, inf) (1/sqrt(pi) at
// 0, ~ 1 / (2 sqrt(pi) x^2) for large x): on [0, kBeckmannPsiMaxX] it is a piecewise polynomial
// (beckmann_lambda.cpp), so mu Lambda costs one exp where the erfc form costs up to three (erfc
// itself takes two beyond x = 1.25), without its cancellation between the two terms.
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/math/constants.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kiln {

/// The end of psi's polynomial pieces; beyond it, Lambda < 1.1e-17 (fixed_rule_microfacet.cpp).
constexpr double kBeckmannPsiMaxX = 6;
/// Pieces of width 1/4 on [0, kBeckmannPsiMaxX], each a polynomial of this many terms.
constexpr int kBeckmannPsiPieces = 24, kBeckmannPsiTerms = 12;
/// Coefficients of piece i in z = 8 x - (2 i + 1) in [-1, 1], constant term first
/// (scripts/beckmann_lambda_coeffs.py: Chebyshev interpolation in 50-digit arithmetic).
extern const double kBeckmannPsiCoeffs[kBeckmannPsiPieces][kBeckmannPsiTerms];

/// psi(x) = 1/sqrt(pi) - x erfcx(x) for x in [0, kBeckmannPsiMaxX] (clamped into it), within
/// 6e-16 relative (tests/models_beckmann_lambda.cpp). Deterministic: plain double arithmetic in a
/// fixed order.
inline double BeckmannPsi(double x) {
  x = std::min(std::max(x, 0.0), kBeckmannPsiMaxX);
  const int i = std::min(static_cast<int>(x * 4), kBeckmannPsiPieces - 1);
  const double z = 8 * x - (2 * i + 1);
  const double* c = kBeckmannPsiCoeffs[i];
  // Estrin's scheme (a short dependency chain): pairs, then quads, then the two halves.
  const double z2 = z * z, z4 = z2 * z2;
  const double p01 = c[0] + c[1] * z, p23 = c[2] + c[3] * z, p45 = c[4] + c[5] * z;
  const double p67 = c[6] + c[7] * z, p89 = c[8] + c[9] * z, pab = c[10] + c[11] * z;
  const double q0 = p01 + p23 * z2, q1 = p45 + p67 * z2, q2 = p89 + pab * z2;
  return q0 + (q1 + q2 * z4) * z4;
}

#if defined(__SSE2__)
/// BeckmannPsi in both lanes, x in [0, kBeckmannPsiMaxX] in each (the caller clamps): the same
/// operations, so each lane has BeckmannPsi's bits.
inline __m128d BeckmannPsi2(__m128d x) {
  const int i0 = std::min(static_cast<int>(_mm_cvtsd_f64(x) * 4), kBeckmannPsiPieces - 1);
  const int i1 =
      std::min(static_cast<int>(_mm_cvtsd_f64(_mm_unpackhi_pd(x, x)) * 4), kBeckmannPsiPieces - 1);
  const __m128d z = _mm_sub_pd(_mm_mul_pd(_mm_set1_pd(8), x), _mm_set_pd(2 * i1 + 1, 2 * i0 + 1));
  const double *a = kBeckmannPsiCoeffs[i0], *b = kBeckmannPsiCoeffs[i1];
  auto c = [&](int k) { return _mm_set_pd(b[k], a[k]); };
  auto pair = [&](int k) { return _mm_add_pd(c(k), _mm_mul_pd(c(k + 1), z)); };
  const __m128d z2 = _mm_mul_pd(z, z), z4 = _mm_mul_pd(z2, z2);
  const __m128d q0 = _mm_add_pd(pair(0), _mm_mul_pd(pair(2), z2));
  const __m128d q1 = _mm_add_pd(pair(4), _mm_mul_pd(pair(6), z2));
  const __m128d q2 = _mm_add_pd(pair(8), _mm_mul_pd(pair(10), z2));
  return _mm_add_pd(q0, _mm_mul_pd(_mm_add_pd(q1, _mm_mul_pd(q2, z4)), z4));
}
#endif

/// mu Lambda(mu) of Beckmann at roughness alpha > 0, view cosine mu in [0, 1] and sine
/// sin = sqrt(1 - mu^2) given: (alpha sin / 2) exp(-x^2) psi(x), x = mu / (alpha sin), for
/// x <= kBeckmannPsiMaxX (one exp); beyond, the erfc form (Lambda < 1.1e-17 there), and 0 where
/// exp(-x^2) underflows (x >= 27). alpha / (2 sqrt(pi)) at mu = 0; 0 at sin = 0.
/// Within 1e-15 + x^2 2^-52 relative of the exact value at the rounded x for x <=
/// kBeckmannPsiMaxX (exp(-x^2) takes x^2's rounding, as any double form does).
inline double BeckmannMuLambda(double mu, double sin, double alpha) {
  if (!(sin > 0)) return 0;
  const double as = alpha * sin, x = mu / as;
  if (!(x < 27)) return 0;
  if (x <= kBeckmannPsiMaxX) return as / 2 * std::exp(-x * x) * BeckmannPsi(x);
  return std::max(0.0, (as * std::exp(-x * x) * InvSqrtPi - mu * std::erfc(x)) / 2);
}

}  // namespace kiln
