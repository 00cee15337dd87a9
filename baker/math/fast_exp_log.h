// exp, log and log1p for the fixed rules' inner loops: inline, branch-light, plain double
// arithmetic in a fixed order (deterministic; no libm call but log1p's log), within 2 ulp of exp,
// 6 ulp of log1p and 2 ulp or 3e-16 absolute of log on their stated domains
// (tests/math_fast_exp_log.cpp measures them against long double).
// ExpFast: exp(x) = 2^e 2^(j/64) exp(r), k = 64 e + j = round(64 x / ln 2), |r| <= ln 2 / 128,
// exp(r) - 1 by its Taylor polynomial to r^5 (truncation below 4e-17 relative), 2^(j/64) from a
// table of the correctly rounded values (fast_exp_log.cpp).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kiln {

/// 2^(j / 64), j = 0..63, correctly rounded (fast_exp_log.cpp).
extern const double kExp2Sixtyfourths[64];

/// The domain of ExpFast's table path; outside it ExpFast returns std::exp(x).
constexpr double kExpFastMaxAbs = 700;

/// ExpFast's constants: 64 / ln 2; 1.5 * 2^52, which rounds a sum to an integer; ln 2 / 64 in two
/// parts, the first with 31 significant bits (k * kExpLn2NHi exact for |k| < 2^17).
constexpr double kExpInvLn2N = 92.332482616893658, kExpShift = 6755399441055744.0;
constexpr double kExpLn2NHi = 0.01083042468962958, kExpLn2NLo = 6.619564634077006e-12;

/// Below this exp(x) rounds to 0 (exp(-745.13...) is half the smallest subnormal).
constexpr double kExpUnderflow = -746;

/// exp(x) within 2 ulp for |x| <= kExpFastMaxAbs, 0 below kExpUnderflow (as std::exp), std::exp(x)
/// between and beyond (NaN to NaN).
inline double ExpFast(double x) {
  if (x < kExpUnderflow) return 0;
  if (!(std::abs(x) <= kExpFastMaxAbs)) return std::exp(x);
  const double kd = (x * kExpInvLn2N + kExpShift) - kExpShift;
  const double r = (x - kd * kExpLn2NHi) - kd * kExpLn2NLo;
  const long long k = static_cast<long long>(kd);
  const int j = static_cast<int>(k & 63);
  const long long e = (k - j) / 64;
  const double r2 = r * r;
  const double p = r + r2 * (0.5 + r * (1.0 / 6) + r2 * (1.0 / 24 + r * (1.0 / 120)));
  const double t = kExp2Sixtyfourths[j];
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return (t + t * p) * scale;
}

#if defined(__SSE2__)
/// ExpFast in both lanes, |x| <= kExpFastMaxAbs in each (the caller clamps): the same
/// operations, so each lane has ExpFast's bits.
inline __m128d ExpFast2(__m128d x) {
  const __m128d shift = _mm_set1_pd(kExpShift);
  const __m128d kd = _mm_sub_pd(_mm_add_pd(_mm_mul_pd(x, _mm_set1_pd(kExpInvLn2N)), shift), shift);
  const __m128d r = _mm_sub_pd(_mm_sub_pd(x, _mm_mul_pd(kd, _mm_set1_pd(kExpLn2NHi))),
                               _mm_mul_pd(kd, _mm_set1_pd(kExpLn2NLo)));
  const __m128i k = _mm_cvtpd_epi32(kd);  // kd is an integer: exact in any rounding mode
  const __m128i j = _mm_and_si128(k, _mm_set1_epi32(63));
  const __m128i e = _mm_srai_epi32(_mm_sub_epi32(k, j), 6);  // (k - j) / 64, exact
  const int j0 = _mm_cvtsi128_si32(j), j1 = _mm_cvtsi128_si32(_mm_srli_si128(j, 4));
  const __m128d t = _mm_set_pd(kExp2Sixtyfourths[j1], kExp2Sixtyfourths[j0]);
  const __m128i biased = _mm_add_epi32(e, _mm_set1_epi32(1023));  // >= 1: zero-extends
  const __m128d scale =
      _mm_castsi128_pd(_mm_slli_epi64(_mm_unpacklo_epi32(biased, _mm_setzero_si128()), 52));
  const __m128d r2 = _mm_mul_pd(r, r);
  const __m128d inner = _mm_add_pd(
      _mm_add_pd(_mm_set1_pd(0.5), _mm_mul_pd(r, _mm_set1_pd(1.0 / 6))),
      _mm_mul_pd(r2, _mm_add_pd(_mm_set1_pd(1.0 / 24), _mm_mul_pd(r, _mm_set1_pd(1.0 / 120)))));
  const __m128d p = _mm_add_pd(r, _mm_mul_pd(r2, inner));
  return _mm_mul_pd(_mm_add_pd(t, _mm_mul_pd(t, p)), scale);
}
#endif

/// 1 / (1 + (j + 1/2) / 64) rounded (1 for j = 0), and -log of it, j = 0..63 (fast_exp_log.cpp).
extern const double kLogCentres[64], kLogOfCentres[64];

/// log(x) for normal positive finite x (std::log(x) otherwise) within 2 ulp or 3e-16 absolute,
/// whichever is larger, and 2 ulp for x in [1, 1 + 1/64) (log(1) = 0): x = 2^e m, m in [1, 2),
/// log(m) = log(1 + r) - log(c_j), c_j the inverted centre of m's 64th of [1, 2) (1 on the first,
/// where r = m - 1 is exact), r = m c_j - 1 (|r| < 1/64; its rounding is the absolute error),
/// log(1 + r) = r - r^2 Q(r) by its Taylor polynomial to r^10 (truncation below 1e-19 relative).
inline double LogFast(double x) {
  if (!(x >= 2.2250738585072014e-308 && x <= 1.7976931348623157e308)) return std::log(x);
  constexpr double kLn2Hi = 0.6931471804855391, kLn2Lo = 7.440617110012397e-11;  // 33 + 53 bits
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int e = static_cast<int>(bits >> 52) - 1023;
  const int j = static_cast<int>((bits >> 46) & 63);
  const std::uint64_t mBits = (bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
  double m;
  std::memcpy(&m, &mBits, sizeof m);
  const double r = m * kLogCentres[j] - 1, r2 = r * r, r4 = r2 * r2;
  const double q01 = 0.5 - r * (1.0 / 3), q23 = 0.25 - r * (1.0 / 5);
  const double q45 = 1.0 / 6 - r * (1.0 / 7), q67 = 0.125 - r * (1.0 / 9);
  const double Q = (q01 + q23 * r2) + r4 * ((q45 + q67 * r2) + r4 * 0.1);
  return e * kLn2Hi + ((e * kLn2Lo + kLogOfCentres[j]) + (r - r2 * Q));
}

/// log(1 + y) for y >= 0 within 6 ulp: log(u) y / (u - 1), u = 1 + y, below y = 3/4 (Goldberg
/// 1991, Theorem 4: the rounding of u cancels), log(u) from there, y where u rounds to 1.
inline double Log1pNonNegative(double y) {
  const double u = 1 + y;
  if (u == 1) return y;
  const double l = std::log(u);
  return y < 0.75 ? l * (y / (u - 1)) : l;
}

}  // namespace kiln
