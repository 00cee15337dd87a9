// exp, log and log1p for the fixed rules' inner loops: inline, branch-light, plain double
// arithmetic in a fixed order (deterministic, no libm call), within 2 ulp of exp and log and 6 ulp
// of log1p on their stated domains, and the same in both lanes of an SSE2 register
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

/// The centres c_j = 1 + j / 64 of LogFast's intervals, j = 0..64: 1 / c_j rounded, and
/// log(c_j) = hi + lo (fast_exp_log.cpp).
extern const double kLogInvCentres[65], kLogCentresHi[65], kLogCentresLo[65];

/// LogFast's ln 2 in two parts, the first with 33 significant bits (e * hi exact for |e| < 2^20).
constexpr double kLogLn2Hi = 0.6931471804855391, kLogLn2Lo = 7.440617110012397e-11;

/// LogFast's interval of m in [1, 2) from x's bits: j = 0..64, the nearest c_j = 1 + j / 64
/// (halves of the 128ths of [1, 2): |m - c_j| <= 1/128).
inline int LogInterval(std::uint64_t bits) {
  return static_cast<int>(((bits >> 45) & 127) + 1) >> 1;
}

/// log(x) for normal positive finite x (std::log(x) otherwise) within 2 ulp: x = 2^e m,
/// m in [1, 2), log(x) = e ln 2 + log(c_j) + log(1 + r), r = (m - c_j) / c_j with m - c_j exact
/// and |r| <= 1/128 (r = m - 1 exact at c_0 = 1, r = (m - 2) / 2 exact at c_64 = 2, where e ln 2
/// and log 2 cancel exactly: x near 1 from either side keeps its relative accuracy),
/// log(1 + r) = r - r^2 Q(r) by its Taylor polynomial to r^10 (truncation below 1e-21 relative),
/// e ln 2 and log(c_j) each in two parts.
inline double LogFast(double x) {
  if (!(x >= 2.2250738585072014e-308 && x <= 1.7976931348623157e308)) return std::log(x);
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int e = static_cast<int>(bits >> 52) - 1023, j = LogInterval(bits);
  const std::uint64_t mBits = (bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
  double m;
  std::memcpy(&m, &mBits, sizeof m);
  const double r = (m - (64 + j) * (1.0 / 64)) * kLogInvCentres[j], r2 = r * r, r4 = r2 * r2;
  const double q01 = 0.5 - r * (1.0 / 3), q23 = 0.25 - r * (1.0 / 5);
  const double q45 = 1.0 / 6 - r * (1.0 / 7), q67 = 0.125 - r * (1.0 / 9);
  const double Q = (q01 + q23 * r2) + r4 * ((q45 + q67 * r2) + r4 * 0.1);
  return (e * kLogLn2Hi + kLogCentresHi[j]) + ((e * kLogLn2Lo + kLogCentresLo[j]) + (r - r2 * Q));
}

/// log(1 + y) for y >= 0 within 6 ulp: log(u) y / (u - 1), u = 1 + y, below y = 3/4 (Goldberg
/// 1991, Theorem 4: the rounding of u cancels), log(u) from there, y where u rounds to 1; log is
/// LogFast (2 ulp just above 1).
inline double Log1pNonNegative(double y) {
  const double u = 1 + y;
  if (u == 1) return y;
  const double l = LogFast(u);
  return y < 0.75 ? l * (y / (u - 1)) : l;
}

#if defined(__SSE2__)
/// LogFast in both lanes, x normal, positive and finite in each (the caller clamps): the same
/// operations, so each lane has LogFast's bits.
inline __m128d LogFast2(__m128d x) {
  const __m128i bits = _mm_castpd_si128(x);
  // e + 1023 as a double: the biased exponent in the mantissa of 2^52, less 2^52 + 1023.
  const __m128i biased = _mm_srli_epi64(bits, 52);
  const __m128d e = _mm_sub_pd(
      _mm_castsi128_pd(_mm_or_si128(biased, _mm_castpd_si128(_mm_set1_pd(4503599627370496.0)))),
      _mm_set1_pd(4503599627370496.0 + 1023));
  alignas(16) std::uint64_t lanes[2];
  _mm_store_si128(reinterpret_cast<__m128i*>(lanes), bits);
  const int j0 = LogInterval(lanes[0]), j1 = LogInterval(lanes[1]);
  const __m128d m =
      _mm_castsi128_pd(_mm_or_si128(_mm_and_si128(bits, _mm_set1_epi64x(0x000FFFFFFFFFFFFFll)),
                                    _mm_set1_epi64x(0x3FF0000000000000ll)));
  const __m128d inv = _mm_set_pd(kLogInvCentres[j1], kLogInvCentres[j0]);
  const __m128d centre = _mm_set_pd((64 + j1) * (1.0 / 64), (64 + j0) * (1.0 / 64));
  const __m128d r = _mm_mul_pd(_mm_sub_pd(m, centre), inv);
  const __m128d r2 = _mm_mul_pd(r, r), r4 = _mm_mul_pd(r2, r2);
  auto lin = [&](double a, double b) {
    return _mm_sub_pd(_mm_set1_pd(a), _mm_mul_pd(r, _mm_set1_pd(b)));
  };
  const __m128d q01 = lin(0.5, 1.0 / 3), q23 = lin(0.25, 1.0 / 5);
  const __m128d q45 = lin(1.0 / 6, 1.0 / 7), q67 = lin(0.125, 1.0 / 9);
  const __m128d Q = _mm_add_pd(_mm_add_pd(q01, _mm_mul_pd(q23, r2)),
                               _mm_mul_pd(r4, _mm_add_pd(_mm_add_pd(q45, _mm_mul_pd(q67, r2)),
                                                         _mm_mul_pd(r4, _mm_set1_pd(0.1)))));
  const __m128d hi = _mm_add_pd(_mm_mul_pd(e, _mm_set1_pd(kLogLn2Hi)),
                                _mm_set_pd(kLogCentresHi[j1], kLogCentresHi[j0]));
  const __m128d lo = _mm_add_pd(_mm_mul_pd(e, _mm_set1_pd(kLogLn2Lo)),
                                _mm_set_pd(kLogCentresLo[j1], kLogCentresLo[j0]));
  return _mm_add_pd(hi, _mm_add_pd(lo, _mm_sub_pd(r, _mm_mul_pd(r2, Q))));
}

/// Log1pNonNegative in both lanes, y >= 0 finite in each: each lane has its bits.
inline __m128d Log1pNonNegative2(__m128d y) {
  const __m128d one = _mm_set1_pd(1), u = _mm_add_pd(one, y);
  const __m128d l = LogFast2(u);
  const __m128d small = _mm_cmplt_pd(y, _mm_set1_pd(0.75));
  const __m128d scaled = _mm_mul_pd(l, _mm_div_pd(y, _mm_sub_pd(u, one)));
  const __m128d v = _mm_or_pd(_mm_and_pd(small, scaled), _mm_andnot_pd(small, l));
  const __m128d unit = _mm_cmpeq_pd(u, one);
  return _mm_or_pd(_mm_and_pd(unit, y), _mm_andnot_pd(unit, v));
}
#endif

}  // namespace kiln
