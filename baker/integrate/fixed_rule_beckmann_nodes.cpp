// Beckmann-family nodes of the microfacet fixed rule (fixed_rule_beckmann_nodes.h).
// The scalar form below is the definition; the SSE2 form computes two nodes at once with the
// same operations in the same order (each lane's arithmetic is IEEE double, as the scalar's):
// ExpFast2, Log1pNonNegative2 and BeckmannPsi2 give their scalar forms' bits in each lane, and a
// branch becomes a mask where both sides are computed on clamped arguments and each lane keeps
// its own (Blinn-Phong's exp below ExpFast's table, r < 1e-304, is taken lane by lane). The AVX2
// and AVX-512F forms do the same four and eight nodes at a time (-ffp-contract=off: no fused
// multiply-add), each lane's terms added in node order.
#include "baker/integrate/fixed_rule_beckmann_nodes.h"

#include <cmath>

#include "baker/math/fast_exp_log.h"
#include "baker/models/beckmann_lambda.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include "baker/integrate/dielectric_simd.h"
#include "baker/math/fast_exp_log_avx2.h"
#include "baker/math/fast_exp_log_avx512.h"
#include "baker/integrate/microfacet_node_lanes.h"
#endif

namespace kiln {
namespace {

/// Beckmann's Lambda(x) = (e^(-x^2) / (x sqrt(pi)) - erfc(x)) / 2 < e^(-x^2) / (2 sqrt(pi) x),
/// x = mu / (alpha sin), is below 1.1e-17 from this x on: less than a fifth of half an ulp
/// (2^-54 relative) of what Add adds it to (mu_o + mu_o Lambda(o) >= mu_o after a factor mu_o,
/// or mu_l after a factor mu_l), so the sum rounds to that term alone and g is gNum / gDenO, the
/// same bits without the erfc and exp (tests/integrate_fixed_rule_lambda_skip.cpp).
constexpr double kBeckmannLambdaNegligibleX = kBeckmannPsiMaxX;
/// Beckmann's r = exp(-u) (1 + u)^2 is taken as 0 from this u = tan^2 t' on.
constexpr double kBeckmannMaxU = 700;

/// r, the NDF's ratio to GGX's at the node (0: the node adds nothing).
/// Beckmann: exp(-u) (1 + u)^2, u = S^2 / C^2 (given as sOverC2, used where C^2 > 0);
/// Blinn-Phong: (q^2 / M2)^2 (1 + aS^2 / C^2)^(-K), K = 1 / alpha^2 - 1.
inline double Ratio(const BeckmannNodeView& v, double C2, double sOverC2, double qm,
                    double aSOverC2) {
  if (!v.blinnPhong) {
    const double u = C2 > 0 ? sOverC2 : INFINITY;
    return u < kBeckmannMaxU ? ExpFast(-u) * (1 + u) * (1 + u) : 0;
  }
  if (v.blinnK == 0) return qm * qm;
  return C2 > 0 ? qm * qm * ExpFast(-v.blinnK * Log1pNonNegative(aSOverC2)) : 0;
}

/// g = gN / gD at x = mu_l / (alpha sin_l): gNum / gDenO (as gRatio / 1) where Lambda(l)
/// vanishes; else, with 2 x Lambda(l) = exp(-x^2) psi(x), gNum 2x / (gDenO 2x + mu e psi)
/// (height-correlated) or gRatio 2x / (2x + e psi) (separable).
inline void MaskingQuotient(const BeckmannNodeView& v, double x, double* gN, double* gD) {
  if (!(x < kBeckmannLambdaNegligibleX)) {
    *gN = v.gRatio;
    *gD = 1;
    return;
  }
  const double ePsi = ExpFast(-x * x) * BeckmannPsi(x), x2 = 2 * x;
  *gN = v.separable ? v.gRatio * x2 : v.gNum * x2;
  *gD = v.separable ? x2 + ePsi : v.gDenO * x2 + v.mu * ePsi;
}

/// One node: adds its value to sumV and its (1 - o.h)^5 part to sumB.
inline void ScalarNode(const BeckmannNodeView& v, double c, double t, double weight, double& sumV,
                       double& sumB) {
  const double a = v.a, mu = v.mu;
  const double t2 = t * t, C = 1 - t2, q = 1 + t2, S = 2 * t, aS = a * S;
  const double C2 = C * C, aS2 = aS * aS, M2 = aS2 + C2;
  const double N1 = 2 * v.st * aS * C * c + mu * (C2 - aS2);  // mu_l M2
  if (!(N1 > 0)) return;
  const double invM2 = 1 / M2, rootL = std::sqrt((M2 - N1) * (M2 + N1));  // sin_l M2
  const double r = Ratio(v, C2, S * S / C2, q * q * invM2, aS2 / C2);
  if (r == 0) return;
  double gN, gD;
  MaskingQuotient(v, N1 / (a * rootL), &gN, &gD);
  const double shape = weight * t * (2 * v.oxs * c * t + v.ozs * C);
  const double val = shape * r * gN / (q * q * q * gD);
  const double oh = (v.st * aS * c + mu * C) * std::sqrt(invM2);
  const double w = 1 - oh, w2 = w * w;
  sumV += val;
  sumB += val * (w2 * w2 * w);
}

}  // namespace

double BeckmannNodeRatio(const BeckmannNodeView& v, double C2, double sOverC2, double qm,
                         double aSOverC2) {
  return Ratio(v, C2, sOverC2, qm, aSOverC2);
}

void AddBeckmannNodesScalar(const BeckmannNodeView& v, double c, const double* t,
                            const double* weight, int n, double& sumV, double& sumB) {
  for (int i = 0; i < n; ++i) ScalarNode(v, c, t[i], weight[i], sumV, sumB);
}

#if defined(__x86_64__)

namespace {

/// Whether this CPU runs the AVX2 lanes (four nodes at a time; no FMA: the same bits).
bool HasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

/// c_k + c_(k+1) z of each lane's psi piece (row: the piece's first coefficient's index).
KILN_AVX2 inline __m256d PsiPair4(const double* base, __m128i row, __m256d z, int k) {
  return _mm256_add_pd(Gather4(base + k, row), _mm256_mul_pd(Gather4(base + k + 1, row), z));
}

/// BeckmannPsi in four lanes, x in [0, kBeckmannPsiMaxX] in each: BeckmannPsi2's operations.
KILN_AVX2 inline __m256d BeckmannPsi4(__m256d x) {
  const __m128i i = _mm_min_epi32(_mm256_cvttpd_epi32(_mm256_mul_pd(x, _mm256_set1_pd(4))),
                                  _mm_set1_epi32(kBeckmannPsiPieces - 1));
  const __m256d odd = _mm256_cvtepi32_pd(_mm_add_epi32(_mm_add_epi32(i, i), _mm_set1_epi32(1)));
  const __m256d z = _mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(8), x), odd);
  const __m128i row = _mm_mullo_epi32(i, _mm_set1_epi32(kBeckmannPsiTerms));
  const double* base = &kBeckmannPsiCoeffs[0][0];
  const __m256d z2 = _mm256_mul_pd(z, z), z4 = _mm256_mul_pd(z2, z2);
  const __m256d q0 =
      _mm256_add_pd(PsiPair4(base, row, z, 0), _mm256_mul_pd(PsiPair4(base, row, z, 2), z2));
  const __m256d q1 =
      _mm256_add_pd(PsiPair4(base, row, z, 4), _mm256_mul_pd(PsiPair4(base, row, z, 6), z2));
  const __m256d q2 =
      _mm256_add_pd(PsiPair4(base, row, z, 8), _mm256_mul_pd(PsiPair4(base, row, z, 10), z2));
  return _mm256_add_pd(q0, _mm256_mul_pd(_mm256_add_pd(q1, _mm256_mul_pd(q2, z4)), z4));
}

/// The SSE2 loop's body four nodes at a time; returns how many nodes it took (a multiple of 4).
KILN_AVX2 int AddBeckmannNodesAvx2(const BeckmannNodeView& v, double c, const double* t,
                                   const double* weight, int n, double& sumVOut, double& sumBOut) {
  // (the sums in registers: through the references they would be stored and reloaded each node)
  double sumV = sumVOut, sumB = sumBOut;
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1), two = _mm256_set1_pd(2);
  const __m256d a = _mm256_set1_pd(v.a), mu = _mm256_set1_pd(v.mu), cc = _mm256_set1_pd(c);
  const __m256d twoSt = _mm256_set1_pd(2 * v.st), st = _mm256_set1_pd(v.st);
  const __m256d twoOxs = _mm256_set1_pd(2 * v.oxs), ozs = _mm256_set1_pd(v.ozs);
  const __m256d maxU = _mm256_set1_pd(kBeckmannMaxU);
  const __m256d psiMax = _mm256_set1_pd(kBeckmannLambdaNegligibleX);
  const __m256d gNum = _mm256_set1_pd(v.gNum), gDenO = _mm256_set1_pd(v.gDenO);
  const __m256d gRatio = _mm256_set1_pd(v.gRatio);
  const __m256d maxY = _mm256_set1_pd(1e300), minArg = _mm256_set1_pd(-kExpFastMaxAbs);
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d tt = _mm256_loadu_pd(t + i);
    const __m256d t2 = _mm256_mul_pd(tt, tt), C = _mm256_sub_pd(one, t2);
    const __m256d q = _mm256_add_pd(one, t2);
    const __m256d S = _mm256_mul_pd(two, tt), aS = _mm256_mul_pd(a, S);
    const __m256d C2 = _mm256_mul_pd(C, C), aS2 = _mm256_mul_pd(aS, aS);
    const __m256d M2 = _mm256_add_pd(aS2, C2);
    const __m256d N1 = _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(twoSt, aS), C), cc),
                                     _mm256_mul_pd(mu, _mm256_sub_pd(C2, aS2)));
    const __m256d invM2 = _mm256_div_pd(one, M2);
    const __m256d rootL =
        _mm256_sqrt_pd(_mm256_mul_pd(_mm256_sub_pd(M2, N1), _mm256_add_pd(M2, N1)));
    const __m256d live = _mm256_cmp_pd(C2, zero, _CMP_GT_OQ);
    __m256d r;
    if (!v.blinnPhong) {
      const __m256d sOverC2 = _mm256_div_pd(_mm256_mul_pd(S, S), C2);
      const __m256d u = _mm256_min_pd(sOverC2, maxU), u1 = _mm256_add_pd(one, u);
      const __m256d keep = _mm256_and_pd(live, _mm256_cmp_pd(sOverC2, maxU, _CMP_LT_OQ));
      r = _mm256_and_pd(keep,
                        _mm256_mul_pd(_mm256_mul_pd(ExpFast4(_mm256_sub_pd(zero, u)), u1), u1));
    } else {
      const __m256d qm = _mm256_mul_pd(_mm256_mul_pd(q, q), invM2);
      const __m256d qm2 = _mm256_mul_pd(qm, qm);
      if (v.blinnK == 0) {
        r = qm2;
      } else {
        const __m256d y = _mm256_and_pd(live, _mm256_min_pd(_mm256_div_pd(aS2, C2), maxY));
        const __m256d arg = _mm256_mul_pd(_mm256_set1_pd(-v.blinnK), Log1pNonNegative4(y));
        const __m256d low = _mm256_and_pd(live, _mm256_cmp_pd(arg, minArg, _CMP_LT_OQ));
        r = _mm256_and_pd(live, _mm256_mul_pd(qm2, ExpFast4(_mm256_max_pd(arg, minArg))));
        if (_mm256_movemask_pd(low) != 0) {  // exp below ExpFast's table: lane by lane
          alignas(32) double c2[4], qmv[4], ao[4], rv[4];
          _mm256_store_pd(c2, C2);
          _mm256_store_pd(qmv, qm);
          _mm256_store_pd(ao, _mm256_div_pd(aS2, C2));
          for (int l = 0; l < 4; ++l) rv[l] = BeckmannNodeRatio(v, c2[l], 0, qmv[l], ao[l]);
          r = _mm256_load_pd(rv);
        }
      }
    }
    const int add = _mm256_movemask_pd(
        _mm256_and_pd(_mm256_cmp_pd(N1, zero, _CMP_GT_OQ), _mm256_cmp_pd(r, zero, _CMP_NEQ_UQ)));
    if (add == 0) continue;
    const __m256d x = _mm256_div_pd(N1, _mm256_mul_pd(a, rootL));
    const __m256d xc = _mm256_max_pd(_mm256_min_pd(x, psiMax), zero);
    const __m256d ePsi =
        _mm256_mul_pd(ExpFast4(_mm256_sub_pd(zero, _mm256_mul_pd(xc, xc))), BeckmannPsi4(xc));
    const __m256d x2 = _mm256_mul_pd(two, xc);
    const __m256d gNl = _mm256_mul_pd(v.separable ? gRatio : gNum, x2);
    const __m256d gDl = v.separable
                            ? _mm256_add_pd(x2, ePsi)
                            : _mm256_add_pd(_mm256_mul_pd(gDenO, x2), _mm256_mul_pd(mu, ePsi));
    const __m256d lam = _mm256_cmp_pd(x, psiMax, _CMP_LT_OQ);
    const __m256d gN = _mm256_blendv_pd(gRatio, gNl, lam);
    const __m256d gD = _mm256_blendv_pd(one, gDl, lam);
    const __m256d shape = _mm256_mul_pd(
        _mm256_mul_pd(_mm256_loadu_pd(weight + i), tt),
        _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(twoOxs, cc), tt), _mm256_mul_pd(ozs, C)));
    const __m256d q3 = _mm256_mul_pd(_mm256_mul_pd(q, q), q);
    const __m256d val =
        _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(shape, r), gN), _mm256_mul_pd(q3, gD));
    const __m256d oh =
        _mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(st, aS), cc), _mm256_mul_pd(mu, C)),
                      _mm256_sqrt_pd(invM2));
    const __m256d w = _mm256_sub_pd(one, oh), w2 = _mm256_mul_pd(w, w);
    const __m256d b = _mm256_mul_pd(val, _mm256_mul_pd(_mm256_mul_pd(w2, w2), w));
    alignas(32) double vv[4], bv[4];
    _mm256_store_pd(vv, val);
    _mm256_store_pd(bv, b);
    for (int l = 0; l < 4; ++l)
      if (add & (1 << l)) {
        sumV += vv[l];
        sumB += bv[l];
      }
  }
  sumVOut = sumV;
  sumBOut = sumB;
  return i;
}

/// kBeckmannPsiCoeffs transposed, term k of the pieces 8 g .. 8 g + 7 at [k][g] (g = 0, 1, 2):
/// what BeckmannPsi8's permutes pick from.
struct PsiColumns {
  alignas(64) double c[kBeckmannPsiTerms][3][8];
};
const PsiColumns& PsiTransposed() {
  static const PsiColumns t = [] {
    PsiColumns o{};
    for (int k = 0; k < kBeckmannPsiTerms; ++k)
      for (int i = 0; i < kBeckmannPsiPieces; ++i) o.c[k][i / 8][i % 8] = kBeckmannPsiCoeffs[i][k];
    return o;
  }();
  return t;
}
static_assert(kBeckmannPsiPieces == 24, "BeckmannPsi8 picks a piece's terms from three registers");

/// Term k of each lane's psi piece i (0..23): the table's value, picked by permutes (a gather's
/// bits, without one): pieces 0..15 by a two-register permute, 16..23 by a one-register one.
KILN_AVX512F inline __m512d PsiTerm8(const PsiColumns& t, __m512i i, __mmask8 high, int k) {
  const __m512d lo =
      _mm512_permutex2var_pd(_mm512_load_pd(t.c[k][0]), i, _mm512_load_pd(t.c[k][1]));
  const __m512d hi = _mm512_maskz_permutexvar_pd(0xFF, i, _mm512_load_pd(t.c[k][2]));
  return _mm512_mask_blend_pd(high, lo, hi);
}

/// c_k + c_(k+1) z of each lane's psi piece in eight lanes (as PsiPair4).
KILN_AVX512F inline __m512d PsiPair8(const PsiColumns& t, __m512i i, __mmask8 high, __m512d z,
                                     int k) {
  return _mm512_add_pd(PsiTerm8(t, i, high, k), _mm512_mul_pd(PsiTerm8(t, i, high, k + 1), z));
}

/// BeckmannPsi in eight lanes, x in [0, kBeckmannPsiMaxX] in each: BeckmannPsi4's operations.
KILN_AVX512F inline __m512d BeckmannPsi8(__m512d x) {
  const __m256i i =
      _mm256_min_epi32(_mm512_maskz_cvttpd_epi32(0xFF, _mm512_mul_pd(x, _mm512_set1_pd(4))),
                       _mm256_set1_epi32(kBeckmannPsiPieces - 1));
  const __m512d odd = _mm512_maskz_cvtepi32_pd(
      0xFF, _mm256_add_epi32(_mm256_add_epi32(i, i), _mm256_set1_epi32(1)));
  const __m512d z = _mm512_sub_pd(_mm512_mul_pd(_mm512_set1_pd(8), x), odd);
  const __m512i i64 = _mm512_maskz_cvtepi32_epi64(0xFF, i);
  const __mmask8 high = _mm512_cmp_epi64_mask(i64, _mm512_set1_epi64(16), _MM_CMPINT_NLT);
  const PsiColumns& t = PsiTransposed();
  const __m512d z2 = _mm512_mul_pd(z, z), z4 = _mm512_mul_pd(z2, z2);
  const __m512d q0 =
      _mm512_add_pd(PsiPair8(t, i64, high, z, 0), _mm512_mul_pd(PsiPair8(t, i64, high, z, 2), z2));
  const __m512d q1 =
      _mm512_add_pd(PsiPair8(t, i64, high, z, 4), _mm512_mul_pd(PsiPair8(t, i64, high, z, 6), z2));
  const __m512d q2 =
      _mm512_add_pd(PsiPair8(t, i64, high, z, 8), _mm512_mul_pd(PsiPair8(t, i64, high, z, 10), z2));
  return _mm512_add_pd(q0, _mm512_mul_pd(_mm512_add_pd(q1, _mm512_mul_pd(q2, z4)), z4));
}

/// r of eight nodes (the AVX2 loop's r, MINPD / MAXPD with its operand order): Beckmann's
/// exp(-u) (1 + u)^2, Blinn-Phong's qm^2 exp(-K log1p(aS^2 / C^2)), lane by lane
/// (BeckmannNodeRatio) where an exp falls below ExpFast's table.
KILN_AVX512F inline __m512d Ratio8(const BeckmannNodeView& v, __m512d S, __m512d q, __m512d C2,
                                   __m512d aS2, __m512d invM2) {
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
  const __mmask8 live = _mm512_cmp_pd_mask(C2, zero, _CMP_GT_OQ);
  if (!v.blinnPhong) {
    const __m512d maxU = _mm512_set1_pd(kBeckmannMaxU);
    const __m512d sOverC2 = _mm512_div_pd(_mm512_mul_pd(S, S), C2);
    const __m512d u = _mm512_maskz_min_pd(0xFF, sOverC2, maxU), u1 = _mm512_add_pd(one, u);
    const __mmask8 keep = live & _mm512_cmp_pd_mask(sOverC2, maxU, _CMP_LT_OQ);
    return _mm512_maskz_mov_pd(
        keep, _mm512_mul_pd(_mm512_mul_pd(ExpFast8(_mm512_sub_pd(zero, u)), u1), u1));
  }
  const __m512d qm = _mm512_mul_pd(_mm512_mul_pd(q, q), invM2), qm2 = _mm512_mul_pd(qm, qm);
  if (v.blinnK == 0) return qm2;
  const __m512d minArg = _mm512_set1_pd(-kExpFastMaxAbs);
  const __m512d y = _mm512_maskz_mov_pd(
      live, _mm512_maskz_min_pd(0xFF, _mm512_div_pd(aS2, C2), _mm512_set1_pd(1e300)));
  const __m512d arg = _mm512_mul_pd(_mm512_set1_pd(-v.blinnK), Log1pNonNegative8(y));
  const __mmask8 low = live & _mm512_cmp_pd_mask(arg, minArg, _CMP_LT_OQ);
  const __m512d r = _mm512_maskz_mov_pd(
      live, _mm512_mul_pd(qm2, ExpFast8(_mm512_maskz_max_pd(0xFF, arg, minArg))));
  if (low == 0) return r;
  alignas(64) double c2[8], qmv[8], ao[8], rv[8];  // exp below ExpFast's table: lane by lane
  _mm512_store_pd(c2, C2);
  _mm512_store_pd(qmv, qm);
  _mm512_store_pd(ao, _mm512_div_pd(aS2, C2));
  for (int l = 0; l < 8; ++l) rv[l] = BeckmannNodeRatio(v, c2[l], 0, qmv[l], ao[l]);
  return _mm512_load_pd(rv);
}

/// The AVX2 loop's body eight nodes at a time (AVX-512F, where dielectric_simd::Enabled()): the
/// same operations, masks for its compares, the last block masked; takes all n nodes.
KILN_AVX512F int AddBeckmannNodesAvx512(const BeckmannNodeView& v, double c, const double* t,
                                        const double* weight, int n, double& sumVOut,
                                        double& sumBOut) {
  // (the sums in registers: through the references they would be stored and reloaded each node)
  double sumV = sumVOut, sumB = sumBOut;
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1), two = _mm512_set1_pd(2);
  const __m512d a = _mm512_set1_pd(v.a), mu = _mm512_set1_pd(v.mu), cc = _mm512_set1_pd(c);
  const __m512d twoSt = _mm512_set1_pd(2 * v.st), st = _mm512_set1_pd(v.st);
  const __m512d twoOxs = _mm512_set1_pd(2 * v.oxs), ozs = _mm512_set1_pd(v.ozs);
  const __m512d psiMax = _mm512_set1_pd(kBeckmannLambdaNegligibleX);
  const __m512d gNum = _mm512_set1_pd(v.gNum), gDenO = _mm512_set1_pd(v.gDenO);
  const __m512d gRatio = _mm512_set1_pd(v.gRatio);
  int i = 0;
  for (; i < n; i += 8) {
    // The last block's lanes beyond n load 0 and add nothing (`in`).
    const __mmask8 in = n - i >= 8 ? 0xFF : static_cast<__mmask8>((1u << (n - i)) - 1);
    const microfacet_lanes::NodeBlock8 nb =
        microfacet_lanes::LoadNodeBlock8(t + i, in, a, mu, twoSt, cc);
    const __m512d tt = nb.tt, C = nb.C, q = nb.q, S = nb.S, aS = nb.aS;
    const __m512d C2 = nb.C2, aS2 = nb.aS2, M2 = nb.M2, N1 = nb.N1;
    const __m512d invM2 = _mm512_div_pd(one, M2);
    const __m512d rootL =
        _mm512_maskz_sqrt_pd(0xFF, _mm512_mul_pd(_mm512_sub_pd(M2, N1), _mm512_add_pd(M2, N1)));
    const __m512d r = Ratio8(v, S, q, C2, aS2, invM2);
    const int add =
        in & _mm512_cmp_pd_mask(N1, zero, _CMP_GT_OQ) & _mm512_cmp_pd_mask(r, zero, _CMP_NEQ_UQ);
    if (add == 0) continue;
    const __m512d x = _mm512_div_pd(N1, _mm512_mul_pd(a, rootL));
    // g = gN / gD: gRatio / 1 where Lambda(l) vanishes (x >= 6), else MaskingQuotient's form; a
    // block none of whose added lanes has Lambda(l) takes no exp and no psi.
    const __mmask8 lam = _mm512_cmp_pd_mask(x, psiMax, _CMP_LT_OQ);
    __m512d gN = gRatio, gD = one;
    if ((lam & add) != 0) {
      const __m512d xc = _mm512_maskz_max_pd(0xFF, _mm512_maskz_min_pd(0xFF, x, psiMax), zero);
      const __m512d ePsi =
          _mm512_mul_pd(ExpFast8(_mm512_sub_pd(zero, _mm512_mul_pd(xc, xc))), BeckmannPsi8(xc));
      const __m512d x2 = _mm512_mul_pd(two, xc);
      const __m512d gNl = _mm512_mul_pd(v.separable ? gRatio : gNum, x2);
      const __m512d gDl = v.separable
                              ? _mm512_add_pd(x2, ePsi)
                              : _mm512_add_pd(_mm512_mul_pd(gDenO, x2), _mm512_mul_pd(mu, ePsi));
      gN = _mm512_mask_blend_pd(lam, gRatio, gNl);
      gD = _mm512_mask_blend_pd(lam, one, gDl);
    }
    const __m512d shape = _mm512_mul_pd(
        _mm512_mul_pd(_mm512_maskz_loadu_pd(in, weight + i), tt),
        _mm512_add_pd(_mm512_mul_pd(_mm512_mul_pd(twoOxs, cc), tt), _mm512_mul_pd(ozs, C)));
    const __m512d q3 = _mm512_mul_pd(_mm512_mul_pd(q, q), q);
    const __m512d val =
        _mm512_div_pd(_mm512_mul_pd(_mm512_mul_pd(shape, r), gN), _mm512_mul_pd(q3, gD));
    const __m512d oh =
        _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_mul_pd(st, aS), cc), _mm512_mul_pd(mu, C)),
                      _mm512_maskz_sqrt_pd(0xFF, invM2));
    const __m512d w = _mm512_sub_pd(one, oh), w2 = _mm512_mul_pd(w, w);
    const __m512d b = _mm512_mul_pd(val, _mm512_mul_pd(_mm512_mul_pd(w2, w2), w));
    alignas(64) double vv[8], bv[8];
    _mm512_store_pd(vv, val);
    _mm512_store_pd(bv, b);
    for (int l = 0; l < 8; ++l)
      if (add & (1 << l)) {
        sumV += vv[l];
        sumB += bv[l];
      }
  }
  sumVOut = sumV;
  sumBOut = sumB;
  return n;
}

}  // namespace

#endif

#if defined(__SSE2__)

void AddBeckmannNodes(const BeckmannNodeView& v, double c, const double* t, const double* weight,
                      int n, double& sumV, double& sumB) {
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1), two = _mm_set1_pd(2);
  const __m128d a = _mm_set1_pd(v.a), mu = _mm_set1_pd(v.mu), cc = _mm_set1_pd(c);
  const __m128d twoSt = _mm_set1_pd(2 * v.st), st = _mm_set1_pd(v.st);
  const __m128d twoOxs = _mm_set1_pd(2 * v.oxs), ozs = _mm_set1_pd(v.ozs);
  const __m128d maxU = _mm_set1_pd(kBeckmannMaxU), psiMax = _mm_set1_pd(kBeckmannLambdaNegligibleX);
  const __m128d gNum = _mm_set1_pd(v.gNum), gDenO = _mm_set1_pd(v.gDenO);
  const __m128d gRatio = _mm_set1_pd(v.gRatio);
  const __m128d maxY = _mm_set1_pd(1e300), minArg = _mm_set1_pd(-kExpFastMaxAbs);
  int i = 0;
#if defined(__x86_64__)
  if (dielectric_simd::Enabled()) {  // (takes every node)
    AddBeckmannNodesAvx512(v, c, t, weight, n, sumV, sumB);
    return;
  }
  if (HasAvx2()) i = AddBeckmannNodesAvx2(v, c, t, weight, n, sumV, sumB);
#endif
  for (; i + 2 <= n; i += 2) {
    const __m128d tt = _mm_loadu_pd(t + i);
    const __m128d t2 = _mm_mul_pd(tt, tt), C = _mm_sub_pd(one, t2), q = _mm_add_pd(one, t2);
    const __m128d S = _mm_mul_pd(two, tt), aS = _mm_mul_pd(a, S);
    const __m128d C2 = _mm_mul_pd(C, C), aS2 = _mm_mul_pd(aS, aS), M2 = _mm_add_pd(aS2, C2);
    const __m128d N1 = _mm_add_pd(_mm_mul_pd(_mm_mul_pd(_mm_mul_pd(twoSt, aS), C), cc),
                                  _mm_mul_pd(mu, _mm_sub_pd(C2, aS2)));
    const __m128d invM2 = _mm_div_pd(one, M2);
    const __m128d rootL = _mm_sqrt_pd(_mm_mul_pd(_mm_sub_pd(M2, N1), _mm_add_pd(M2, N1)));
    // r: Beckmann's in the lanes (u clamped to kBeckmannMaxU, where r is 0 anyway; C2 = 0 gives
    // +inf, clamped too), Blinn-Phong's (a log1p and an exp of the lane's own range) lane by lane.
    __m128d r;
    if (!v.blinnPhong) {
      const __m128d sOverC2 = _mm_div_pd(_mm_mul_pd(S, S), C2);
      const __m128d u = _mm_min_pd(sOverC2, maxU), u1 = _mm_add_pd(one, u);
      const __m128d live = _mm_and_pd(_mm_cmpgt_pd(C2, zero), _mm_cmplt_pd(sOverC2, maxU));
      r = _mm_and_pd(live, _mm_mul_pd(_mm_mul_pd(ExpFast2(_mm_sub_pd(zero, u)), u1), u1));
    } else {
      const __m128d qm = _mm_mul_pd(_mm_mul_pd(q, q), invM2), qm2 = _mm_mul_pd(qm, qm);
      if (v.blinnK == 0) {
        r = qm2;
      } else {
        // (C2 > 0 lanes; the others' y clamped to a finite value and masked.)
        const __m128d live = _mm_cmpgt_pd(C2, zero);
        const __m128d y = _mm_and_pd(live, _mm_min_pd(_mm_div_pd(aS2, C2), maxY));
        const __m128d arg = _mm_mul_pd(_mm_set1_pd(-v.blinnK), Log1pNonNegative2(y));
        if (_mm_movemask_pd(_mm_and_pd(live, _mm_cmplt_pd(arg, minArg))) == 0) {
          r = _mm_and_pd(live, _mm_mul_pd(qm2, ExpFast2(_mm_max_pd(arg, minArg))));
        } else {  // exp below ExpFast's table (r < 1e-304): lane by lane, as the scalar form
          alignas(16) double c2[2], qmv[2], ao[2], rv[2];
          _mm_store_pd(c2, C2);
          _mm_store_pd(qmv, qm);
          _mm_store_pd(ao, _mm_div_pd(aS2, C2));
          for (int l = 0; l < 2; ++l) rv[l] = Ratio(v, c2[l], 0, qmv[l], ao[l]);
          r = _mm_load_pd(rv);
        }
      }
    }
    // Bit l: lane l adds (mu_l > 0 and r != 0).
    const int add = _mm_movemask_pd(_mm_and_pd(_mm_cmpgt_pd(N1, zero), _mm_cmpneq_pd(r, zero)));
    if (add == 0) continue;
    // g = gN / gD (MaskingQuotient): psi at x clamped to [0, 6] (NaN: 6), gRatio / 1 where
    // !(x < 6).
    const __m128d x = _mm_div_pd(N1, _mm_mul_pd(a, rootL));
    const __m128d xc = _mm_max_pd(_mm_min_pd(x, psiMax), zero);
    const __m128d ePsi =
        _mm_mul_pd(ExpFast2(_mm_sub_pd(zero, _mm_mul_pd(xc, xc))), BeckmannPsi2(xc));
    const __m128d x2 = _mm_mul_pd(two, xc);
    const __m128d gNl = _mm_mul_pd(v.separable ? gRatio : gNum, x2);
    const __m128d gDl = v.separable ? _mm_add_pd(x2, ePsi)
                                    : _mm_add_pd(_mm_mul_pd(gDenO, x2), _mm_mul_pd(mu, ePsi));
    const __m128d lam = _mm_cmplt_pd(x, psiMax);
    const __m128d gN = _mm_or_pd(_mm_and_pd(lam, gNl), _mm_andnot_pd(lam, gRatio));
    const __m128d gD = _mm_or_pd(_mm_and_pd(lam, gDl), _mm_andnot_pd(lam, one));
    const __m128d shape =
        _mm_mul_pd(_mm_mul_pd(_mm_loadu_pd(weight + i), tt),
                   _mm_add_pd(_mm_mul_pd(_mm_mul_pd(twoOxs, cc), tt), _mm_mul_pd(ozs, C)));
    const __m128d q3 = _mm_mul_pd(_mm_mul_pd(q, q), q);
    const __m128d val = _mm_div_pd(_mm_mul_pd(_mm_mul_pd(shape, r), gN), _mm_mul_pd(q3, gD));
    const __m128d oh = _mm_mul_pd(_mm_add_pd(_mm_mul_pd(_mm_mul_pd(st, aS), cc), _mm_mul_pd(mu, C)),
                                  _mm_sqrt_pd(invM2));
    const __m128d w = _mm_sub_pd(one, oh), w2 = _mm_mul_pd(w, w);
    const __m128d b = _mm_mul_pd(val, _mm_mul_pd(_mm_mul_pd(w2, w2), w));
    alignas(16) double vv[2], bv[2];
    _mm_store_pd(vv, val);
    _mm_store_pd(bv, b);
    for (int l = 0; l < 2; ++l)
      if (add & (1 << l)) {
        sumV += vv[l];
        sumB += bv[l];
      }
  }
  if (i < n) AddBeckmannNodesScalar(v, c, t + i, weight + i, n - i, sumV, sumB);
}

#else

void AddBeckmannNodes(const BeckmannNodeView& v, double c, const double* t, const double* weight,
                      int n, double& sumV, double& sumB) {
  AddBeckmannNodesScalar(v, c, t, weight, n, sumV, sumB);
}

#endif

}  // namespace kiln
