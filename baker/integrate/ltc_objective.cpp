#include "baker/integrate/ltc_objective.h"

#include <algorithm>
#include <cmath>

#include "baker/integrate/ltc_fit.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kiln {

double LtcCrossSumScalar(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                         const double* pc, size_t n) {
  const double i0 = ltc.inv[0], i2 = ltc.inv[2], i4 = ltc.inv[4], i6 = ltc.inv[6], i8 = ltc.inv[8];
  const double scale = kLtcInvPi * ltc.detInv;
  double cross = 0;
  for (size_t k = 0; k < n; ++k) {
    double qx = i0 * px[k] + i2 * pz[k], qy = i4 * py[k], qz = i6 * px[k] + i8 * pz[k];
    double len2 = qx * qx + qy * qy + qz * qz;
    cross += pc[k] * (std::max(qz, 0.0) * scale / (len2 * len2));
  }
  return cross;
}

double LtcOwnSumScalar(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                       size_t n, int p) {
  const double m0 = ltc.m[0], m2 = ltc.m[2], m4 = ltc.m[4], m6 = ltc.m[6], m8 = ltc.m[8];
  const double k = kLtcInvPi * ltc.detInv;
  double own = 0;
  for (size_t j = 0; j < n; ++j) {
    double ax = m0 * cx[j] + m2 * cz[j], ay = m4 * cy[j], az = m6 * cx[j] + m8 * cz[j];
    double len2 = ax * ax + ay * ay + az * az, d = cz[j] * k * len2 * std::sqrt(len2);
    own += p == 2 ? d : d * d;
  }
  return own;
}

#if defined(__SSE2__)

double LtcCrossSum(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                   const double* pc, size_t n) {
  const __m128d i0 = _mm_set1_pd(ltc.inv[0]), i2 = _mm_set1_pd(ltc.inv[2]),
                i4 = _mm_set1_pd(ltc.inv[4]), i6 = _mm_set1_pd(ltc.inv[6]),
                i8 = _mm_set1_pd(ltc.inv[8]);
  const __m128d scale = _mm_set1_pd(kLtcInvPi * ltc.detInv), zero = _mm_setzero_pd();
  double cross = 0, term[2];
  size_t k = 0;
  for (; k + 2 <= n; k += 2) {
    const __m128d x = _mm_loadu_pd(px + k), y = _mm_loadu_pd(py + k), z = _mm_loadu_pd(pz + k);
    const __m128d qx = _mm_add_pd(_mm_mul_pd(i0, x), _mm_mul_pd(i2, z)), qy = _mm_mul_pd(i4, y),
                  qz = _mm_add_pd(_mm_mul_pd(i6, x), _mm_mul_pd(i8, z));
    const __m128d len2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(qx, qx), _mm_mul_pd(qy, qy)), _mm_mul_pd(qz, qz));
    // max(zero, qz) is (0 > qz ? 0 : qz), std::max(qz, 0.0)'s choice (NaN and -0 kept).
    const __m128d d = _mm_div_pd(_mm_mul_pd(_mm_max_pd(zero, qz), scale), _mm_mul_pd(len2, len2));
    _mm_storeu_pd(term, _mm_mul_pd(_mm_loadu_pd(pc + k), d));
    cross += term[0];
    cross += term[1];
  }
  if (k < n) cross += LtcCrossSumScalar(ltc, px + k, py + k, pz + k, pc + k, n - k);
  return cross;
}

double LtcOwnSum(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                 size_t n, int p) {
  const __m128d m0 = _mm_set1_pd(ltc.m[0]), m2 = _mm_set1_pd(ltc.m[2]), m4 = _mm_set1_pd(ltc.m[4]),
                m6 = _mm_set1_pd(ltc.m[6]), m8 = _mm_set1_pd(ltc.m[8]);
  const __m128d kk = _mm_set1_pd(kLtcInvPi * ltc.detInv);
  double own = 0, term[2];
  size_t j = 0;
  for (; j + 2 <= n; j += 2) {
    const __m128d x = _mm_loadu_pd(cx + j), y = _mm_loadu_pd(cy + j), z = _mm_loadu_pd(cz + j);
    const __m128d ax = _mm_add_pd(_mm_mul_pd(m0, x), _mm_mul_pd(m2, z)), ay = _mm_mul_pd(m4, y),
                  az = _mm_add_pd(_mm_mul_pd(m6, x), _mm_mul_pd(m8, z));
    const __m128d len2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(ax, ax), _mm_mul_pd(ay, ay)), _mm_mul_pd(az, az));
    __m128d d = _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(z, kk), len2), _mm_sqrt_pd(len2));
    if (p != 2) d = _mm_mul_pd(d, d);
    _mm_storeu_pd(term, d);
    own += term[0];
    own += term[1];
  }
  if (j < n) own += LtcOwnSumScalar(ltc, cx + j, cy + j, cz + j, n - j, p);
  return own;
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
