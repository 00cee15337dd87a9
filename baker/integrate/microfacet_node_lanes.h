// The microfacet fixed rule's node geometry eight azimuth nodes at a time (AVX-512F), shared by
// the GGX lanes (fixed_rule_microfacet.cpp) and the Beckmann-family lanes
// (fixed_rule_beckmann_nodes.cpp): the scalar rule's operations on t = tan(phi_m / 2), lane by
// lane, in its order (the files that include this are compiled with -ffp-contract=off), so each
// lane has the scalar form's bits. Call only where dielectric_simd::Enabled().
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "baker/math/fast_exp_log_avx512.h"

namespace kiln::microfacet_lanes {

/// One block of eight nodes: t, C = 1 - t^2, q = 1 + t^2, S = 2 t, aS = a S, their squares C2 and
/// aS2, M2 = aS2 + C2, and N1 = 2 sin_o aS C c + mu (C2 - aS2) (the light's cosine times M2;
/// N1 > 0: the light is above the surface). Lanes outside `in` load t = 0.
struct NodeBlock8 {
  __m512d tt, C, q, S, aS, C2, aS2, M2, N1;
};

/// The block of the nodes t[0 .. 7] (lanes `in`), for alpha `a`, view cosine `mu`, `twoSt` = 2
/// sin_o and `cc` = cos of the node's other angle, each broadcast to the eight lanes.
KILN_AVX512F_INLINE inline NodeBlock8 LoadNodeBlock8(const double* t, __mmask8 in, __m512d a,
                                                     __m512d mu, __m512d twoSt, __m512d cc) {
  const __m512d one = _mm512_set1_pd(1), two = _mm512_set1_pd(2);
  NodeBlock8 b;
  b.tt = _mm512_maskz_loadu_pd(in, t);
  const __m512d t2 = _mm512_mul_pd(b.tt, b.tt);
  b.C = _mm512_sub_pd(one, t2);
  b.q = _mm512_add_pd(one, t2);
  b.S = _mm512_mul_pd(two, b.tt);
  b.aS = _mm512_mul_pd(a, b.S);
  b.C2 = _mm512_mul_pd(b.C, b.C);
  b.aS2 = _mm512_mul_pd(b.aS, b.aS);
  b.M2 = _mm512_add_pd(b.aS2, b.C2);
  b.N1 = _mm512_add_pd(_mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(twoSt, b.aS), b.C), cc),
                       _mm512_mul_pd(mu, _mm512_sub_pd(b.C2, b.aS2)));
  return b;
}

}  // namespace kiln::microfacet_lanes
#endif
