// ExpFast, LogFast and Log1pNonNegative (fast_exp_log.h) in the four lanes of an AVX2 register,
// for the fixed rules' AVX2 paths: functions with the avx2 target attribute, to be called only
// where the CPU has AVX2 (__builtin_cpu_supports("avx2")). Each lane does the scalar form's
// operations in its order, without fused multiply-adds, so it has the scalar form's bits
// (tests/math_fast_exp_log.cpp).
#pragma once
#if defined(__x86_64__)
#include <immintrin.h>

#include "baker/math/fast_exp_log.h"

#define KILN_AVX2 __attribute__((target("avx2")))

namespace kiln {

/// table[index] in four lanes (32- and 64-bit indices), by masked gathers into zero (GCC's
/// unmasked gather reads an undefined source register).
KILN_AVX2 inline __m256d Gather4(const double* table, __m128i index) {
  const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), table, index, all, 8);
}
KILN_AVX2 inline __m256d Gather4(const double* table, __m256i index) {
  const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  return _mm256_mask_i64gather_pd(_mm256_setzero_pd(), table, index, all, 8);
}

/// 0 <= n < 2^52 in each 64-bit lane, as a double (exact): n in the mantissa of 2^52, less 2^52.
KILN_AVX2 inline __m256d SmallToDouble4(__m256i n) {
  const __m256d two52 = _mm256_set1_pd(4503599627370496.0);
  return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(n, _mm256_castpd_si256(two52))), two52);
}

/// a - r b in four lanes.
KILN_AVX2 inline __m256d Lin4(__m256d r, double a, double b) {
  return _mm256_sub_pd(_mm256_set1_pd(a), _mm256_mul_pd(r, _mm256_set1_pd(b)));
}

/// ExpFast in four lanes, |x| <= kExpFastMaxAbs in each: ExpFast2's operations.
KILN_AVX2 inline __m256d ExpFast4(__m256d x) {
  const __m256d shift = _mm256_set1_pd(kExpShift);
  const __m256d kd =
      _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(x, _mm256_set1_pd(kExpInvLn2N)), shift), shift);
  const __m256d r = _mm256_sub_pd(_mm256_sub_pd(x, _mm256_mul_pd(kd, _mm256_set1_pd(kExpLn2NHi))),
                                  _mm256_mul_pd(kd, _mm256_set1_pd(kExpLn2NLo)));
  const __m128i k = _mm256_cvtpd_epi32(kd);  // kd is an integer: exact
  const __m128i j = _mm_and_si128(k, _mm_set1_epi32(63));
  const __m128i e = _mm_srai_epi32(_mm_sub_epi32(k, j), 6);
  const __m256d t = Gather4(kExp2Sixtyfourths, j);
  const __m256i biased = _mm256_cvtepi32_epi64(_mm_add_epi32(e, _mm_set1_epi32(1023)));
  const __m256d scale = _mm256_castsi256_pd(_mm256_slli_epi64(biased, 52));
  const __m256d r2 = _mm256_mul_pd(r, r);
  const __m256d inner =
      _mm256_add_pd(_mm256_add_pd(_mm256_set1_pd(0.5), _mm256_mul_pd(r, _mm256_set1_pd(1.0 / 6))),
                    _mm256_mul_pd(r2, _mm256_add_pd(_mm256_set1_pd(1.0 / 24),
                                                    _mm256_mul_pd(r, _mm256_set1_pd(1.0 / 120)))));
  const __m256d p = _mm256_add_pd(r, _mm256_mul_pd(r2, inner));
  return _mm256_mul_pd(_mm256_add_pd(t, _mm256_mul_pd(t, p)), scale);
}

/// LogFast in four lanes, x normal, positive and finite in each: LogFast2's operations.
KILN_AVX2 inline __m256d LogFast4(__m256d x) {
  const __m256i bits = _mm256_castpd_si256(x);
  const __m256d e =
      _mm256_sub_pd(SmallToDouble4(_mm256_srli_epi64(bits, 52)), _mm256_set1_pd(1023));
  const __m256i j = _mm256_srli_epi64(
      _mm256_add_epi64(_mm256_and_si256(_mm256_srli_epi64(bits, 45), _mm256_set1_epi64x(127)),
                       _mm256_set1_epi64x(1)),
      1);
  const __m256d m = _mm256_castsi256_pd(
      _mm256_or_si256(_mm256_and_si256(bits, _mm256_set1_epi64x(0x000FFFFFFFFFFFFFll)),
                      _mm256_set1_epi64x(0x3FF0000000000000ll)));
  const __m256d centre =
      _mm256_mul_pd(_mm256_add_pd(_mm256_set1_pd(64), SmallToDouble4(j)), _mm256_set1_pd(1.0 / 64));
  const __m256d r = _mm256_mul_pd(_mm256_sub_pd(m, centre), Gather4(kLogInvCentres, j));
  const __m256d r2 = _mm256_mul_pd(r, r), r4 = _mm256_mul_pd(r2, r2);
  const __m256d q01 = Lin4(r, 0.5, 1.0 / 3), q23 = Lin4(r, 0.25, 1.0 / 5);
  const __m256d q45 = Lin4(r, 1.0 / 6, 1.0 / 7), q67 = Lin4(r, 0.125, 1.0 / 9);
  const __m256d Q =
      _mm256_add_pd(_mm256_add_pd(q01, _mm256_mul_pd(q23, r2)),
                    _mm256_mul_pd(r4, _mm256_add_pd(_mm256_add_pd(q45, _mm256_mul_pd(q67, r2)),
                                                    _mm256_mul_pd(r4, _mm256_set1_pd(0.1)))));
  const __m256d hi =
      _mm256_add_pd(_mm256_mul_pd(e, _mm256_set1_pd(kLogLn2Hi)), Gather4(kLogCentresHi, j));
  const __m256d lo =
      _mm256_add_pd(_mm256_mul_pd(e, _mm256_set1_pd(kLogLn2Lo)), Gather4(kLogCentresLo, j));
  return _mm256_add_pd(hi, _mm256_add_pd(lo, _mm256_sub_pd(r, _mm256_mul_pd(r2, Q))));
}

/// Log1pNonNegative in four lanes, y >= 0 finite in each: Log1pNonNegative2's operations.
KILN_AVX2 inline __m256d Log1pNonNegative4(__m256d y) {
  const __m256d one = _mm256_set1_pd(1), u = _mm256_add_pd(one, y);
  const __m256d l = LogFast4(u);
  const __m256d small = _mm256_cmp_pd(y, _mm256_set1_pd(0.75), _CMP_LT_OQ);
  const __m256d scaled = _mm256_mul_pd(l, _mm256_div_pd(y, _mm256_sub_pd(u, one)));
  const __m256d v = _mm256_blendv_pd(l, scaled, small);
  return _mm256_blendv_pd(v, y, _mm256_cmp_pd(u, one, _CMP_EQ_OQ));
}

}  // namespace kiln

#endif
