// ExpFast, LogFast and Log1pNonNegative (fast_exp_log.h) in the eight lanes of an AVX-512F
// register, for the fixed rules' AVX-512F paths: functions with the avx512f target attribute, to
// be called only where those paths run (dielectric_simd::Enabled(): the CPU has AVX-512F and
// KILN_NO_AVX512 is not set). Each lane does the scalar form's operations in its order, without
// fused multiply-adds, as the AVX2 forms (fast_exp_log_avx2.h), so it has the scalar form's bits
// (tests/math_fast_exp_log.cpp). Their tables are read by permutes (Lookup64x8), not gathers.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "baker/math/fast_exp_log.h"

#define KILN_AVX512F __attribute__((target("avx512f")))
/// (The lane functions below are always inlined into the AVX-512F loops that call them.)
#define KILN_AVX512F_INLINE __attribute__((target("avx512f"), always_inline))

namespace kiln {

// (Masked forms with every lane set throughout, here and in the paths that include this: GCC
// 12's unmasked ones start from an undefined register, which -Wmaybe-uninitialized flags.)

/// table[index] in eight lanes for a table of 64 entries, index in [0, 63] in each 64-bit lane:
/// the table's values (a gather's bits) by four two-register permutes (16 entries each, the
/// index's low four bits) and a select on its bits 4 and 5 (cheaper than a gather here).
/// Entries 16 g .. 16 g + 15 of a table at the index's low four bits (Lookup64x8's permutes).
KILN_AVX512F inline __m512d Lookup16x8(const double* table, int g, __m512i index) {
  return _mm512_permutex2var_pd(_mm512_loadu_pd(table + 16 * g), index,
                                _mm512_loadu_pd(table + 16 * g + 8));
}
KILN_AVX512F inline __m512d Lookup64x8(const double* table, __m512i index) {
  const __mmask8 bit4 = _mm512_test_epi64_mask(index, _mm512_set1_epi64(16));
  const __mmask8 bit5 = _mm512_test_epi64_mask(index, _mm512_set1_epi64(32));
  const __m512d low =
      _mm512_mask_blend_pd(bit4, Lookup16x8(table, 0, index), Lookup16x8(table, 1, index));
  const __m512d high =
      _mm512_mask_blend_pd(bit4, Lookup16x8(table, 2, index), Lookup16x8(table, 3, index));
  return _mm512_mask_blend_pd(bit5, low, high);
}

/// The same for a table of 65 entries, index in [0, 64]: entry 64 by one more select.
KILN_AVX512F inline __m512d Lookup65x8(const double* table, __m512i index) {
  const __mmask8 last = _mm512_cmp_epi64_mask(index, _mm512_set1_epi64(64), _MM_CMPINT_EQ);
  return _mm512_mask_blend_pd(last, Lookup64x8(table, index), _mm512_set1_pd(table[64]));
}

/// 0 <= n < 2^52 in each 64-bit lane, as a double (exact): n in the mantissa of 2^52, less 2^52.
KILN_AVX512F inline __m512d SmallToDouble8(__m512i n) {
  const __m512d two52 = _mm512_set1_pd(4503599627370496.0);
  return _mm512_sub_pd(_mm512_castsi512_pd(_mm512_or_si512(n, _mm512_castpd_si512(two52))), two52);
}

/// a - r b in eight lanes.
KILN_AVX512F inline __m512d Lin8(__m512d r, double a, double b) {
  return _mm512_sub_pd(_mm512_set1_pd(a), _mm512_mul_pd(r, _mm512_set1_pd(b)));
}

/// ExpFast in eight lanes, |x| <= kExpFastMaxAbs in each: ExpFast4's operations.
KILN_AVX512F_INLINE inline __m512d ExpFast8(__m512d x) {
  const __m512d shift = _mm512_set1_pd(kExpShift);
  const __m512d kd =
      _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(x, _mm512_set1_pd(kExpInvLn2N)), shift), shift);
  const __m512d r = _mm512_sub_pd(_mm512_sub_pd(x, _mm512_mul_pd(kd, _mm512_set1_pd(kExpLn2NHi))),
                                  _mm512_mul_pd(kd, _mm512_set1_pd(kExpLn2NLo)));
  const __m256i k = _mm512_maskz_cvtpd_epi32(0xFF, kd);  // kd is an integer: exact
  const __m256i j = _mm256_and_si256(k, _mm256_set1_epi32(63));
  const __m256i e = _mm256_srai_epi32(_mm256_sub_epi32(k, j), 6);
  const __m512d t = Lookup64x8(kExp2Sixtyfourths, _mm512_maskz_cvtepi32_epi64(0xFF, j));
  const __m512i biased =
      _mm512_maskz_cvtepi32_epi64(0xFF, _mm256_add_epi32(e, _mm256_set1_epi32(1023)));
  const __m512d scale = _mm512_castsi512_pd(_mm512_maskz_slli_epi64(0xFF, biased, 52));
  const __m512d r2 = _mm512_mul_pd(r, r);
  const __m512d inner =
      _mm512_add_pd(_mm512_add_pd(_mm512_set1_pd(0.5), _mm512_mul_pd(r, _mm512_set1_pd(1.0 / 6))),
                    _mm512_mul_pd(r2, _mm512_add_pd(_mm512_set1_pd(1.0 / 24),
                                                    _mm512_mul_pd(r, _mm512_set1_pd(1.0 / 120)))));
  const __m512d p = _mm512_add_pd(r, _mm512_mul_pd(r2, inner));
  return _mm512_mul_pd(_mm512_add_pd(t, _mm512_mul_pd(t, p)), scale);
}

/// LogFast in eight lanes, x normal, positive and finite in each: LogFast4's operations.
KILN_AVX512F_INLINE inline __m512d LogFast8(__m512d x) {
  const __m512i bits = _mm512_castpd_si512(x);
  const __m512d e =
      _mm512_sub_pd(SmallToDouble8(_mm512_maskz_srli_epi64(0xFF, bits, 52)), _mm512_set1_pd(1023));
  const __m512i j = _mm512_maskz_srli_epi64(
      0xFF,
      _mm512_add_epi64(
          _mm512_and_si512(_mm512_maskz_srli_epi64(0xFF, bits, 45), _mm512_set1_epi64(127)),
          _mm512_set1_epi64(1)),
      1);
  const __m512d m = _mm512_castsi512_pd(
      _mm512_or_si512(_mm512_and_si512(bits, _mm512_set1_epi64(0x000FFFFFFFFFFFFFll)),
                      _mm512_set1_epi64(0x3FF0000000000000ll)));
  const __m512d centre =
      _mm512_mul_pd(_mm512_add_pd(_mm512_set1_pd(64), SmallToDouble8(j)), _mm512_set1_pd(1.0 / 64));
  const __m512d r = _mm512_mul_pd(_mm512_sub_pd(m, centre), Lookup65x8(kLogInvCentres, j));
  const __m512d r2 = _mm512_mul_pd(r, r), r4 = _mm512_mul_pd(r2, r2);
  const __m512d q01 = Lin8(r, 0.5, 1.0 / 3), q23 = Lin8(r, 0.25, 1.0 / 5);
  const __m512d q45 = Lin8(r, 1.0 / 6, 1.0 / 7), q67 = Lin8(r, 0.125, 1.0 / 9);
  const __m512d Q =
      _mm512_add_pd(_mm512_add_pd(q01, _mm512_mul_pd(q23, r2)),
                    _mm512_mul_pd(r4, _mm512_add_pd(_mm512_add_pd(q45, _mm512_mul_pd(q67, r2)),
                                                    _mm512_mul_pd(r4, _mm512_set1_pd(0.1)))));
  const __m512d hi =
      _mm512_add_pd(_mm512_mul_pd(e, _mm512_set1_pd(kLogLn2Hi)), Lookup65x8(kLogCentresHi, j));
  const __m512d lo =
      _mm512_add_pd(_mm512_mul_pd(e, _mm512_set1_pd(kLogLn2Lo)), Lookup65x8(kLogCentresLo, j));
  return _mm512_add_pd(hi, _mm512_add_pd(lo, _mm512_sub_pd(r, _mm512_mul_pd(r2, Q))));
}

/// Log1pNonNegative in eight lanes, y >= 0 finite in each: Log1pNonNegative4's operations.
KILN_AVX512F_INLINE inline __m512d Log1pNonNegative8(__m512d y) {
  const __m512d one = _mm512_set1_pd(1), u = _mm512_add_pd(one, y);
  const __m512d l = LogFast8(u);
  const __mmask8 small = _mm512_cmp_pd_mask(y, _mm512_set1_pd(0.75), _CMP_LT_OQ);
  const __m512d scaled = _mm512_mul_pd(l, _mm512_div_pd(y, _mm512_sub_pd(u, one)));
  const __m512d v = _mm512_mask_blend_pd(small, l, scaled);
  return _mm512_mask_blend_pd(_mm512_cmp_pd_mask(u, one, _CMP_EQ_OQ), v, y);
}

}  // namespace kiln

#endif
