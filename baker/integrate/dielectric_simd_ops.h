// The AVX-512F lane operations the glass walks' paths share (dielectric_simd.cpp, the columns;
// dielectric_simd_exit.cpp, the exit walk): thin names for the intrinsics, with the operand
// orders that give std::min / std::max's results. Included only by those two files, each compiled
// for AVX-512F by the function attribute KILN_AVX512 (the rest of the build stays x86-64
// baseline).
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define KILN_HAVE_AVX512_PATH 1
#define KILN_AVX512 __attribute__((target("avx512f")))

namespace kiln {
namespace dielectric_simd {
namespace ops {

using V = __m512d;
using M = __mmask8;

KILN_AVX512 inline V Set(double x) { return _mm512_set1_pd(x); }
KILN_AVX512 inline V Add(V a, V b) { return _mm512_add_pd(a, b); }
KILN_AVX512 inline V Sub(V a, V b) { return _mm512_sub_pd(a, b); }
KILN_AVX512 inline V Mul(V a, V b) { return _mm512_mul_pd(a, b); }
KILN_AVX512 inline V Div(V a, V b) { return _mm512_div_pd(a, b); }
// _mm512_sqrt_pd, _mm512_min_pd and _mm512_max_pd with every lane's mask bit set (GCC 12's
// unmasked forms start from _mm512_undefined_pd, which -Wmaybe-uninitialized flags).
KILN_AVX512 inline V Sqrt(V a) { return _mm512_maskz_sqrt_pd(0xFF, a); }
/// MINPD: (a < b) ? a : b; MAXPD: (a > b) ? a : b.
KILN_AVX512 inline V Min(V a, V b) { return _mm512_maskz_min_pd(0xFF, a, b); }
KILN_AVX512 inline V Max(V a, V b) { return _mm512_maskz_max_pd(0xFF, a, b); }
KILN_AVX512 inline M Gt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
KILN_AVX512 inline M Lt(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
/// std::min(a, b) = (b < a) ? b : a.
KILN_AVX512 inline V StdMin(V a, V b) { return Min(b, a); }
/// std::max(a, b) = (a < b) ? b : a, i.e. (b > a) ? b : a.
KILN_AVX512 inline V StdMax(V a, V b) { return Max(b, a); }
/// -x exactly (the sign bit flipped).
KILN_AVX512 inline V Neg(V x) {
  return _mm512_castsi512_pd(_mm512_xor_si512(
      _mm512_castpd_si512(x), _mm512_set1_epi64(static_cast<long long>(1ull << 63))));
}

/// dielectric_walk::CosHalfTurn, lane by lane.
KILN_AVX512 inline V CosHalfTurn8(V phi) {
  const V x = Sub(phi, Set(1.5707963267948966)), x2 = Mul(x, x);
  V p = Set(1.9572941063391263e-20);
  p = Sub(Mul(p, x2), Set(8.2206352466243295e-18));
  p = Add(Mul(p, x2), Set(2.8114572543455206e-15));
  p = Sub(Mul(p, x2), Set(7.6471637318198164e-13));
  p = Add(Mul(p, x2), Set(1.6059043836821613e-10));
  p = Sub(Mul(p, x2), Set(2.505210838544172e-08));
  p = Add(Mul(p, x2), Set(2.7557319223985893e-06));
  p = Sub(Mul(p, x2), Set(0.00019841269841269841));
  p = Add(Mul(p, x2), Set(0.0083333333333333332));
  p = Sub(Mul(p, x2), Set(0.16666666666666666));
  p = Add(Mul(p, x2), Set(1));
  return Mul(Neg(x), p);
}

}  // namespace ops
}  // namespace dielectric_simd
}  // namespace kiln
#endif
