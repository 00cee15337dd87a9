#include "baker/integrate/ltc_objective.h"

#include <algorithm>
#include <cmath>

#include "baker/integrate/ltc_fit.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>

#include "baker/integrate/dielectric_simd.h"
#define KILN_AVX2 __attribute__((target("avx2")))
#define KILN_LTC_AVX512 __attribute__((target("avx512f")))
#endif

namespace kiln {

namespace {

/// Point k's term of the cross sum, pc[k] D(l_k) (the sparse M^-1 in `inv`, scale = |det M^-1| /
/// pi).
inline double CrossTerm(const double* inv, double scale, const double* px, const double* py,
                        const double* pz, const double* pc, size_t k) {
  const double qx = inv[0] * px[k] + inv[2] * pz[k], qy = inv[4] * py[k];
  const double qz = inv[6] * px[k] + inv[8] * pz[k];
  const double len2 = qx * qx + qy * qy + qz * qz;
  return pc[k] * (std::max(qz, 0.0) * scale / (len2 * len2));
}

/// Point j's term of the own sum, d_j (p = 2) or d_j^2 (the sparse M in `m`, k = |det M^-1| /
/// pi).
inline double OwnTerm(const double* m, double k, const double* cx, const double* cy,
                      const double* cz, int p, size_t j) {
  const double ax = m[0] * cx[j] + m[2] * cz[j], ay = m[4] * cy[j];
  const double az = m[6] * cx[j] + m[8] * cz[j];
  const double len2 = ax * ax + ay * ay + az * az, d = cz[j] * k * len2 * std::sqrt(len2);
  return p == 2 ? d : d * d;
}

/// The four partial sums' total, in the one order every path uses.
inline double Total(const double* acc) { return (acc[0] + acc[1]) + (acc[2] + acc[3]); }

}  // namespace

double LtcCrossSumScalar(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                         const double* pc, size_t n) {
  const double scale = kLtcInvPi * ltc.detInv;
  double acc[kLtcSumLanes] = {0, 0, 0, 0};
  for (size_t k = 0; k < n; ++k)
    acc[k % kLtcSumLanes] += CrossTerm(ltc.inv, scale, px, py, pz, pc, k);
  return Total(acc);
}

double LtcOwnSumScalar(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                       size_t n, int p) {
  const double k = kLtcInvPi * ltc.detInv;
  double acc[kLtcSumLanes] = {0, 0, 0, 0};
  for (size_t j = 0; j < n; ++j) acc[j % kLtcSumLanes] += OwnTerm(ltc.m, k, cx, cy, cz, p, j);
  return Total(acc);
}

#if defined(__x86_64__)

namespace {

/// Whether this CPU runs the AVX2 lanes (four points at a time; no FMA: the same bits).
bool LtcHasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

/// LtcCrossSum's first points four at a time, point k's term added to acc[k % 4]; returns how
/// many it took (a multiple of 4).
KILN_AVX2 size_t LtcCrossSumAvx2(const LtcMatrix& ltc, const double* px, const double* py,
                                 const double* pz, const double* pc, size_t n, double* acc) {
  const __m256d i0 = _mm256_set1_pd(ltc.inv[0]), i2 = _mm256_set1_pd(ltc.inv[2]);
  const __m256d i4 = _mm256_set1_pd(ltc.inv[4]), i6 = _mm256_set1_pd(ltc.inv[6]);
  const __m256d i8 = _mm256_set1_pd(ltc.inv[8]);
  const __m256d scale = _mm256_set1_pd(kLtcInvPi * ltc.detInv), zero = _mm256_setzero_pd();
  __m256d sum = _mm256_loadu_pd(acc);
  size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m256d x = _mm256_loadu_pd(px + k), y = _mm256_loadu_pd(py + k);
    const __m256d z = _mm256_loadu_pd(pz + k);
    const __m256d qx = _mm256_add_pd(_mm256_mul_pd(i0, x), _mm256_mul_pd(i2, z));
    const __m256d qy = _mm256_mul_pd(i4, y);
    const __m256d qz = _mm256_add_pd(_mm256_mul_pd(i6, x), _mm256_mul_pd(i8, z));
    const __m256d len2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(qx, qx), _mm256_mul_pd(qy, qy)),
                                       _mm256_mul_pd(qz, qz));
    const __m256d d =
        _mm256_div_pd(_mm256_mul_pd(_mm256_max_pd(zero, qz), scale), _mm256_mul_pd(len2, len2));
    sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_loadu_pd(pc + k), d));
  }
  _mm256_storeu_pd(acc, sum);
  return k;
}

/// LtcOwnSum's first points four at a time (as LtcCrossSumAvx2).
KILN_AVX2 size_t LtcOwnSumAvx2(const LtcMatrix& ltc, const double* cx, const double* cy,
                               const double* cz, size_t n, int p, double* acc) {
  const __m256d m0 = _mm256_set1_pd(ltc.m[0]), m2 = _mm256_set1_pd(ltc.m[2]);
  const __m256d m4 = _mm256_set1_pd(ltc.m[4]), m6 = _mm256_set1_pd(ltc.m[6]);
  const __m256d m8 = _mm256_set1_pd(ltc.m[8]);
  const __m256d kk = _mm256_set1_pd(kLtcInvPi * ltc.detInv);
  __m256d sum = _mm256_loadu_pd(acc);
  size_t j = 0;
  for (; j + 4 <= n; j += 4) {
    const __m256d x = _mm256_loadu_pd(cx + j), y = _mm256_loadu_pd(cy + j);
    const __m256d z = _mm256_loadu_pd(cz + j);
    const __m256d ax = _mm256_add_pd(_mm256_mul_pd(m0, x), _mm256_mul_pd(m2, z));
    const __m256d ay = _mm256_mul_pd(m4, y);
    const __m256d az = _mm256_add_pd(_mm256_mul_pd(m6, x), _mm256_mul_pd(m8, z));
    const __m256d len2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ax, ax), _mm256_mul_pd(ay, ay)),
                                       _mm256_mul_pd(az, az));
    __m256d d = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(z, kk), len2), _mm256_sqrt_pd(len2));
    if (p != 2) d = _mm256_mul_pd(d, d);
    sum = _mm256_add_pd(sum, d);
  }
  _mm256_storeu_pd(acc, sum);
  return j;
}

/// The AVX-512F paths' sums (where dielectric_simd::Enabled()): eight points' terms at a time,
/// added to the four partial sums as the AVX2 paths add them (points k..k+3, then k+4..k+7).
KILN_LTC_AVX512 inline __m256d AddEight(__m256d sum, __m512d term) {
  // (the masked extracts with every element set: GCC 12's unmasked ones start from an undefined
  // register, which -Wmaybe-uninitialized flags)
  sum = _mm256_add_pd(sum, _mm512_maskz_extractf64x4_pd(0xF, term, 0));
  return _mm256_add_pd(sum, _mm512_maskz_extractf64x4_pd(0xF, term, 1));
}

/// LtcCrossSumAvx2's terms eight at a time, the last block masked; takes all n points.
KILN_LTC_AVX512 size_t LtcCrossSumAvx512(const LtcMatrix& ltc, const double* px, const double* py,
                                         const double* pz, const double* pc, size_t n,
                                         double* acc) {
  const __m512d i0 = _mm512_set1_pd(ltc.inv[0]), i2 = _mm512_set1_pd(ltc.inv[2]);
  const __m512d i4 = _mm512_set1_pd(ltc.inv[4]), i6 = _mm512_set1_pd(ltc.inv[6]);
  const __m512d i8 = _mm512_set1_pd(ltc.inv[8]);
  const __m512d scale = _mm512_set1_pd(kLtcInvPi * ltc.detInv), zero = _mm512_setzero_pd();
  __m256d sum = _mm256_loadu_pd(acc);
  size_t k = 0;
  for (; k < n; k += 8) {
    // The last block's lanes beyond n load 0 and add +0 (a partial sum is never -0: every term
    // is >= +0 or NaN).
    const __mmask8 in = n - k >= 8 ? 0xFF : static_cast<__mmask8>((1u << (n - k)) - 1);
    const __m512d x = _mm512_maskz_loadu_pd(in, px + k), y = _mm512_maskz_loadu_pd(in, py + k);
    const __m512d z = _mm512_maskz_loadu_pd(in, pz + k);
    const __m512d qx = _mm512_add_pd(_mm512_mul_pd(i0, x), _mm512_mul_pd(i2, z));
    const __m512d qy = _mm512_mul_pd(i4, y);
    const __m512d qz = _mm512_add_pd(_mm512_mul_pd(i6, x), _mm512_mul_pd(i8, z));
    const __m512d len2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(qx, qx), _mm512_mul_pd(qy, qy)),
                                       _mm512_mul_pd(qz, qz));
    const __m512d d = _mm512_maskz_div_pd(
        in, _mm512_mul_pd(_mm512_maskz_max_pd(0xFF, zero, qz), scale), _mm512_mul_pd(len2, len2));
    sum = AddEight(sum, _mm512_mul_pd(_mm512_maskz_loadu_pd(in, pc + k), d));
  }
  _mm256_storeu_pd(acc, sum);
  return n;
}

/// LtcOwnSumAvx2's terms eight at a time (as LtcCrossSumAvx512).
KILN_LTC_AVX512 size_t LtcOwnSumAvx512(const LtcMatrix& ltc, const double* cx, const double* cy,
                                       const double* cz, size_t n, int p, double* acc) {
  const __m512d m0 = _mm512_set1_pd(ltc.m[0]), m2 = _mm512_set1_pd(ltc.m[2]);
  const __m512d m4 = _mm512_set1_pd(ltc.m[4]), m6 = _mm512_set1_pd(ltc.m[6]);
  const __m512d m8 = _mm512_set1_pd(ltc.m[8]);
  const __m512d kk = _mm512_set1_pd(kLtcInvPi * ltc.detInv);
  __m256d sum = _mm256_loadu_pd(acc);
  size_t j = 0;
  for (; j < n; j += 8) {
    // (the last block as LtcCrossSumAvx512's: its missing terms are +0)
    const __mmask8 in = n - j >= 8 ? 0xFF : static_cast<__mmask8>((1u << (n - j)) - 1);
    const __m512d x = _mm512_maskz_loadu_pd(in, cx + j), y = _mm512_maskz_loadu_pd(in, cy + j);
    const __m512d z = _mm512_maskz_loadu_pd(in, cz + j);
    const __m512d ax = _mm512_add_pd(_mm512_mul_pd(m0, x), _mm512_mul_pd(m2, z));
    const __m512d ay = _mm512_mul_pd(m4, y);
    const __m512d az = _mm512_add_pd(_mm512_mul_pd(m6, x), _mm512_mul_pd(m8, z));
    const __m512d len2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ax, ax), _mm512_mul_pd(ay, ay)),
                                       _mm512_mul_pd(az, az));
    __m512d d =
        _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(z, kk), len2), _mm512_maskz_sqrt_pd(0xFF, len2));
    if (p != 2) d = _mm512_mul_pd(d, d);
    sum = AddEight(sum, d);
  }
  _mm256_storeu_pd(acc, sum);
  return n;
}

}  // namespace

#endif

#if defined(__SSE2__)

namespace {

/// A 3x3 matrix with the LTC's zero pattern (entries 0, 2, 4, 6, 8), in both lanes.
struct SparseLanes {
  __m128d a0, a2, a4, a6, a8;
  explicit SparseLanes(const double* a)
      : a0(_mm_set1_pd(a[0])),
        a2(_mm_set1_pd(a[2])),
        a4(_mm_set1_pd(a[4])),
        a6(_mm_set1_pd(a[6])),
        a8(_mm_set1_pd(a[8])) {}
};

/// Two points (x, y, z) times the matrix a, and their squared lengths: the scalar loops'
/// operations in their order, so each lane has their bits.
struct TransformedLanes {
  __m128d x, y, z, len2;
};
inline TransformedLanes Transform(const SparseLanes& a, __m128d x, __m128d y, __m128d z) {
  TransformedLanes q;
  q.x = _mm_add_pd(_mm_mul_pd(a.a0, x), _mm_mul_pd(a.a2, z));
  q.y = _mm_mul_pd(a.a4, y);
  q.z = _mm_add_pd(_mm_mul_pd(a.a6, x), _mm_mul_pd(a.a8, z));
  q.len2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(q.x, q.x), _mm_mul_pd(q.y, q.y)), _mm_mul_pd(q.z, q.z));
  return q;
}

}  // namespace

double LtcCrossSum(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                   const double* pc, size_t n) {
  const SparseLanes inv(ltc.inv);
  const double s = kLtcInvPi * ltc.detInv;
  const __m128d scale = _mm_set1_pd(s), zero = _mm_setzero_pd();
  alignas(16) double acc[kLtcSumLanes] = {0, 0, 0, 0};
  size_t k = 0;
#if defined(__x86_64__)
  if (dielectric_simd::Enabled()) k = LtcCrossSumAvx512(ltc, px, py, pz, pc, n, acc);
  if (LtcHasAvx2()) k += LtcCrossSumAvx2(ltc, px + k, py + k, pz + k, pc + k, n - k, acc);
#endif
  // Two points at a time into acc[0..1] or acc[2..3] (k even: k % 4 is 0 or 2).
  __m128d sum[2] = {_mm_load_pd(acc), _mm_load_pd(acc + 2)};
  for (; k + 2 <= n; k += 2) {
    const __m128d x = _mm_loadu_pd(px + k), y = _mm_loadu_pd(py + k), z = _mm_loadu_pd(pz + k);
    const TransformedLanes q = Transform(inv, x, y, z);
    // max(zero, q.z) is (0 > q.z ? 0 : q.z), std::max(q.z, 0.0)'s choice (NaN and -0 kept).
    const __m128d d =
        _mm_div_pd(_mm_mul_pd(_mm_max_pd(zero, q.z), scale), _mm_mul_pd(q.len2, q.len2));
    __m128d& acc2 = sum[(k % kLtcSumLanes) / 2];
    acc2 = _mm_add_pd(acc2, _mm_mul_pd(_mm_loadu_pd(pc + k), d));
  }
  _mm_store_pd(acc, sum[0]);
  _mm_store_pd(acc + 2, sum[1]);
  for (; k < n; ++k) acc[k % kLtcSumLanes] += CrossTerm(ltc.inv, s, px, py, pz, pc, k);
  return Total(acc);
}

double LtcOwnSum(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                 size_t n, int p) {
  const SparseLanes m(ltc.m);
  const double k1 = kLtcInvPi * ltc.detInv;
  const __m128d kk = _mm_set1_pd(k1);
  alignas(16) double acc[kLtcSumLanes] = {0, 0, 0, 0};
  size_t j = 0;
#if defined(__x86_64__)
  if (dielectric_simd::Enabled()) j = LtcOwnSumAvx512(ltc, cx, cy, cz, n, p, acc);
  if (LtcHasAvx2()) j += LtcOwnSumAvx2(ltc, cx + j, cy + j, cz + j, n - j, p, acc);
#endif
  __m128d sum[2] = {_mm_load_pd(acc), _mm_load_pd(acc + 2)};
  for (; j + 2 <= n; j += 2) {
    const __m128d x = _mm_loadu_pd(cx + j), y = _mm_loadu_pd(cy + j), z = _mm_loadu_pd(cz + j);
    const __m128d len2 = Transform(m, x, y, z).len2;
    __m128d d = _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(z, kk), len2), _mm_sqrt_pd(len2));
    if (p != 2) d = _mm_mul_pd(d, d);
    __m128d& acc2 = sum[(j % kLtcSumLanes) / 2];
    acc2 = _mm_add_pd(acc2, d);
  }
  _mm_store_pd(acc, sum[0]);
  _mm_store_pd(acc + 2, sum[1]);
  for (; j < n; ++j) acc[j % kLtcSumLanes] += OwnTerm(ltc.m, k1, cx, cy, cz, p, j);
  return Total(acc);
}

#else

double LtcCrossSum(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                   const double* pc, size_t n) {
  return LtcCrossSumScalar(ltc, px, py, pz, pc, n);
}

double LtcOwnSum(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                 size_t n, int p) {
  return LtcOwnSumScalar(ltc, cx, cy, cz, n, p);
}

#endif

}  // namespace kiln
