// Sheen rows (fixed_rule_sheen_row.h). The scalar form is the definition; the AVX2 form takes
// four azimuth nodes at once with the same operations in the same order (LogFast4 and ExpFast4
// have LogFast's and ExpFast's bits in each lane, 0 below kExpUnderflow as ExpFast); a lane
// outside their tables (sin^2(theta_h) not a normal positive double, or an exp argument in
// [kExpUnderflow, -kExpFastMaxAbs)) takes SheenNdf itself. The AVX-512F form does the AVX2 form's
// operations eight nodes at a time (masks for its compares, MINPD / MAXPD with its operand order,
// no fused multiply-add: -ffp-contract=off), the terms added in node order: the same bits.
#include "baker/integrate/fixed_rule_sheen_row.h"

#include <algorithm>
#include <cmath>

#include "baker/math/constants.h"
#include "baker/math/fast_exp_log.h"
#if defined(__x86_64__)
#include "baker/integrate/dielectric_simd.h"
#include "baker/math/fast_exp_log_avx2.h"
#include "baker/math/fast_exp_log_avx512.h"
#endif

namespace kiln {
namespace {

/// The smallest normal double: LogFast's table path starts here.
constexpr double kMinNormal = 2.2250738585072014e-308;

/// Node j's term ws_j (D V) of the row (0 where h is undefined); sin^2(theta_h) as HalfSin2.
inline double NodeTerm(const SheenRowNdf& ndf, const SheenRow& r, size_t j) {
  const double sx = r.woX + r.sinT * r.cosPhi[j], sy = 0 + r.sinT * r.sinPhi[j];
  const double sz = r.woZ + r.muL;
  const double xy = sx * sx + sy * sy, len2 = xy + sz * sz;
  if (!(len2 > 0)) return r.ws[j] * 0;
  const double s2 = std::min(1.0, std::max(0.0, xy / len2));
  return r.ws[j] * (SheenNdf(ndf, s2) * r.v);
}

}  // namespace

double SheenNdf(const SheenRowNdf& ndf, double sin2h) {
  const double alpha = ndf.alpha;
  if (ndf.velvet) {
    const double a2 = alpha * alpha, norm = 1 / (Pi * (1 + 4 * a2));
    if (a2 <= 0 || sin2h <= 0) return norm;
    const double cos2h = 1 - sin2h;
    return norm * (1 + 4 * ExpFast(-cos2h / (a2 * sin2h)) / (sin2h * sin2h));
  }
  if (sin2h <= 0) return 0;
  return (2 + 1 / alpha) * ExpFast(LogFast(sin2h) * (0.5 / alpha)) / (2 * Pi);
}

double SheenRowSumScalar(const SheenRowNdf& ndf, const SheenRow& r) {
  double row = 0;
  for (size_t j = 0; j < r.n; ++j) row += NodeTerm(ndf, r, j);
  return row;
}

#if defined(__x86_64__)

namespace {

/// Whether this CPU runs the AVX2 lanes.
bool HasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

/// ExpFast in four lanes for any argument but those in [kExpUnderflow, -kExpFastMaxAbs), which the
/// caller redoes: 0 below kExpUnderflow (as ExpFast), the table above.
KILN_AVX2 inline __m256d ExpOrZero4(__m256d arg) {
  const __m256d e = ExpFast4(_mm256_max_pd(arg, _mm256_set1_pd(-kExpFastMaxAbs)));
  return _mm256_and_pd(_mm256_cmp_pd(arg, _mm256_set1_pd(kExpUnderflow), _CMP_GE_OQ), e);
}

/// The row's first nodes four at a time, their terms added to `row` in node order; returns how
/// many it took (a multiple of 4).
KILN_AVX2 size_t SheenRowSumAvx2(const SheenRowNdf& ndf, const SheenRow& r, double& rowOut) {
  double row = rowOut;  // (in a register: through the reference it would be stored each node)
  const double alpha = ndf.alpha, a2 = alpha * alpha;
  if (ndf.velvet && !(a2 > 0)) return 0;  // D = norm everywhere: the scalar form
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1);
  const __m256d sinT = _mm256_set1_pd(r.sinT), woX = _mm256_set1_pd(r.woX);
  const double szs = r.woZ + r.muL;
  const __m256d sz2 = _mm256_set1_pd(szs * szs), v = _mm256_set1_pd(r.v);
  const __m256d minArg = _mm256_set1_pd(-kExpFastMaxAbs), minNormal = _mm256_set1_pd(kMinNormal);
  const __m256d charlieK = _mm256_set1_pd(0.5 / alpha), charlieC = _mm256_set1_pd(2 + 1 / alpha);
  const __m256d twoPi = _mm256_set1_pd(2 * Pi), a2v = _mm256_set1_pd(a2), four = _mm256_set1_pd(4);
  const __m256d velvetNorm = _mm256_set1_pd(1 / (Pi * (1 + 4 * a2)));
  alignas(32) double dv[4], s2v[4], argv[4], tv[4];
  size_t j = 0;
  for (; j + 4 <= r.n; j += 4) {
    const __m256d sx = _mm256_add_pd(woX, _mm256_mul_pd(sinT, _mm256_loadu_pd(r.cosPhi + j)));
    const __m256d sy = _mm256_add_pd(zero, _mm256_mul_pd(sinT, _mm256_loadu_pd(r.sinPhi + j)));
    const __m256d xy = _mm256_add_pd(_mm256_mul_pd(sx, sx), _mm256_mul_pd(sy, sy));
    const __m256d len2 = _mm256_add_pd(xy, sz2);
    const __m256d ok = _mm256_cmp_pd(len2, zero, _CMP_GT_OQ);
    const __m256d s2 =
        _mm256_and_pd(ok, _mm256_min_pd(one, _mm256_max_pd(_mm256_div_pd(xy, len2), zero)));
    const __m256d s2c = _mm256_max_pd(s2, minNormal);
    __m256d arg, d;
    if (!ndf.velvet) {
      arg = _mm256_mul_pd(LogFast4(s2c), charlieK);
      d = _mm256_div_pd(_mm256_mul_pd(charlieC, ExpOrZero4(arg)), twoPi);
    } else {
      arg = _mm256_sub_pd(zero, _mm256_div_pd(_mm256_sub_pd(one, s2c), _mm256_mul_pd(a2v, s2c)));
      const __m256d e = ExpOrZero4(arg);
      d = _mm256_mul_pd(velvetNorm, _mm256_add_pd(one, _mm256_div_pd(_mm256_mul_pd(four, e),
                                                                     _mm256_mul_pd(s2c, s2c))));
    }
    // Lanes off the tables: SheenNdf itself (an exp argument in [kExpUnderflow, -kExpFastMaxAbs)).
    const __m256d off =
        _mm256_or_pd(_mm256_cmp_pd(s2, minNormal, _CMP_NGE_UQ),
                     _mm256_and_pd(_mm256_cmp_pd(arg, minArg, _CMP_LT_OQ),
                                   _mm256_cmp_pd(arg, _mm256_set1_pd(kExpUnderflow), _CMP_GE_OQ)));
    if (_mm256_movemask_pd(off) != 0) {
      _mm256_store_pd(dv, d);
      _mm256_store_pd(s2v, s2);
      _mm256_store_pd(argv, arg);
      for (int l = 0; l < 4; ++l)
        if (!(s2v[l] >= kMinNormal) || (argv[l] < -kExpFastMaxAbs && argv[l] >= kExpUnderflow))
          dv[l] = SheenNdf(ndf, s2v[l]);
      d = _mm256_load_pd(dv);
    }
    // ws_j (D V) where h is defined, ws_j 0 where not (as the scalar form).
    const __m256d term =
        _mm256_mul_pd(_mm256_loadu_pd(r.ws + j), _mm256_and_pd(ok, _mm256_mul_pd(d, v)));
    _mm256_store_pd(tv, term);
    for (double t : tv) row += t;
  }
  rowOut = row;
  return j;
}

/// ExpOrZero4 in eight lanes.
KILN_AVX512F inline __m512d ExpOrZero8(__m512d arg) {
  const __m512d e = ExpFast8(_mm512_maskz_max_pd(0xFF, arg, _mm512_set1_pd(-kExpFastMaxAbs)));
  return _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(arg, _mm512_set1_pd(kExpUnderflow), _CMP_GE_OQ), e);
}

/// The AVX-512F lanes' constants of an NDF, and of one row.
struct NdfLanes {
  bool velvet;
  __m512d charlieK, charlieC, twoPi, a2v, velvetNorm;
};
struct RowLanes {
  __m512d sinT, woX, sz2, v;
};

KILN_AVX512F inline NdfLanes NdfLanesOf(const SheenRowNdf& ndf) {
  const double alpha = ndf.alpha, a2 = alpha * alpha;
  return {ndf.velvet,
          _mm512_set1_pd(0.5 / alpha),
          _mm512_set1_pd(2 + 1 / alpha),
          _mm512_set1_pd(2 * Pi),
          _mm512_set1_pd(a2),
          _mm512_set1_pd(1 / (Pi * (1 + 4 * a2)))};
}

KILN_AVX512F inline RowLanes RowLanesOf(const SheenRow& r) {
  const double szs = r.woZ + r.muL;
  return {_mm512_set1_pd(r.sinT), _mm512_set1_pd(r.woX), _mm512_set1_pd(szs * szs),
          _mm512_set1_pd(r.v)};
}

/// The terms ws_j (D V) of the row's nodes j0 .. j0 + count - 1 (count <= 8; the lanes beyond
/// load 0 and are not to be added): SheenRowSumAvx2's operations eight at a time.
KILN_AVX512F inline __m512d Block8(const SheenRowNdf& ndf, const NdfLanes& k, const RowLanes& w,
                                   const SheenRow& r, size_t j0, size_t count) {
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
  const __m512d minArg = _mm512_set1_pd(-kExpFastMaxAbs), minNormal = _mm512_set1_pd(kMinNormal);
  const __mmask8 in = static_cast<__mmask8>((1u << count) - 1);
  const __m512d sx =
      _mm512_add_pd(w.woX, _mm512_mul_pd(w.sinT, _mm512_maskz_loadu_pd(in, r.cosPhi + j0)));
  const __m512d sy =
      _mm512_add_pd(zero, _mm512_mul_pd(w.sinT, _mm512_maskz_loadu_pd(in, r.sinPhi + j0)));
  const __m512d xy = _mm512_add_pd(_mm512_mul_pd(sx, sx), _mm512_mul_pd(sy, sy));
  const __m512d len2 = _mm512_add_pd(xy, w.sz2);
  const __mmask8 ok = _mm512_cmp_pd_mask(len2, zero, _CMP_GT_OQ);
  // min(one, max(q, zero)) as MINPD / MAXPD with the AVX2 form's operand order.
  const __m512d q = _mm512_div_pd(xy, len2);
  const __m512d s2 =
      _mm512_maskz_mov_pd(ok, _mm512_maskz_min_pd(0xFF, one, _mm512_maskz_max_pd(0xFF, q, zero)));
  const __m512d s2c = _mm512_maskz_max_pd(0xFF, s2, minNormal);
  __m512d arg, d;
  if (!k.velvet) {
    arg = _mm512_mul_pd(LogFast8(s2c), k.charlieK);
    d = _mm512_div_pd(_mm512_mul_pd(k.charlieC, ExpOrZero8(arg)), k.twoPi);
  } else {
    arg = _mm512_sub_pd(zero, _mm512_div_pd(_mm512_sub_pd(one, s2c), _mm512_mul_pd(k.a2v, s2c)));
    const __m512d e = ExpOrZero8(arg);
    d = _mm512_mul_pd(k.velvetNorm,
                      _mm512_add_pd(one, _mm512_div_pd(_mm512_mul_pd(_mm512_set1_pd(4), e),
                                                       _mm512_mul_pd(s2c, s2c))));
  }
  // Lanes off the tables: SheenNdf itself (as the AVX2 form).
  const __mmask8 off = in & (_mm512_cmp_pd_mask(s2, minNormal, _CMP_NGE_UQ) |
                             (_mm512_cmp_pd_mask(arg, minArg, _CMP_LT_OQ) &
                              _mm512_cmp_pd_mask(arg, _mm512_set1_pd(kExpUnderflow), _CMP_GE_OQ)));
  if (off != 0) {
    alignas(64) double dv[8], s2v[8], argv[8];
    _mm512_store_pd(dv, d);
    _mm512_store_pd(s2v, s2);
    _mm512_store_pd(argv, arg);
    for (size_t l = 0; l < count; ++l)
      if (!(s2v[l] >= kMinNormal) || (argv[l] < -kExpFastMaxAbs && argv[l] >= kExpUnderflow))
        dv[l] = SheenNdf(ndf, s2v[l]);
    d = _mm512_load_pd(dv);
  }
  return _mm512_mul_pd(_mm512_maskz_loadu_pd(in, r.ws + j0),
                       _mm512_maskz_mov_pd(ok, _mm512_mul_pd(d, w.v)));
}

/// SheenRowSumAvx2's lanes eight at a time (AVX-512F, where dielectric_simd::Enabled()): the
/// same operations (Block8), each lane's term added in node order, the last block masked; the
/// rows a, b (b optional: nullptr) share their azimuth nodes, their two chains of additions
/// interleaved. Not for the velvet at alpha = 0 (the scalar form).
KILN_AVX512F void SheenRowsSumAvx512(const SheenRowNdf& ndf, const SheenRow& a, const SheenRow* b,
                                     double* outA, double* outB) {
  const NdfLanes k = NdfLanesOf(ndf);
  const RowLanes wa = RowLanesOf(a), wb = RowLanesOf(b ? *b : a);
  double rowA = 0, rowB = 0;
  alignas(64) double ta[8], tb[8];
  for (size_t j = 0; j < a.n; j += 8) {
    const size_t count = std::min<size_t>(8, a.n - j);
    _mm512_store_pd(ta, Block8(ndf, k, wa, a, j, count));
    if (!b) {
      for (size_t l = 0; l < count; ++l) rowA += ta[l];
      continue;
    }
    _mm512_store_pd(tb, Block8(ndf, k, wb, *b, j, count));
    for (size_t l = 0; l < count; ++l) {
      rowA += ta[l];
      rowB += tb[l];
    }
  }
  *outA = rowA;
  if (b) *outB = rowB;
}

/// Whether the AVX-512F rows take this NDF (not the velvet at alpha = 0: D = norm, the scalar
/// form).
bool RowsAvx512(const SheenRowNdf& ndf) {
  return dielectric_simd::Enabled() && !(ndf.velvet && !(ndf.alpha * ndf.alpha > 0));
}

}  // namespace

double SheenRowSum(const SheenRowNdf& ndf, const SheenRow& r) {
  double row = 0;
  if (RowsAvx512(ndf)) {
    SheenRowsSumAvx512(ndf, r, nullptr, &row, nullptr);
    return row;
  }
  size_t j = 0;
  if (HasAvx2()) j = SheenRowSumAvx2(ndf, r, row);
  for (; j < r.n; ++j) row += NodeTerm(ndf, r, j);
  return row;
}

void SheenRowSum2(const SheenRowNdf& ndf, const SheenRow& a, const SheenRow& b, double* sumA,
                  double* sumB) {
  if (RowsAvx512(ndf) && a.n == b.n && a.cosPhi == b.cosPhi && a.sinPhi == b.sinPhi &&
      a.ws == b.ws) {
    SheenRowsSumAvx512(ndf, a, &b, sumA, sumB);
    return;
  }
  *sumA = SheenRowSum(ndf, a);
  *sumB = SheenRowSum(ndf, b);
}

#else

double SheenRowSum(const SheenRowNdf& ndf, const SheenRow& r) { return SheenRowSumScalar(ndf, r); }

void SheenRowSum2(const SheenRowNdf& ndf, const SheenRow& a, const SheenRow& b, double* sumA,
                  double* sumB) {
  *sumA = SheenRowSumScalar(ndf, a);
  *sumB = SheenRowSumScalar(ndf, b);
}

#endif

}  // namespace kiln
