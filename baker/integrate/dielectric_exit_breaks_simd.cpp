// The exit walk's inner breaks eight rings at once (dielectric_simd.h, PhiBreaks8): the AVX-512F
// path's form of dielectric_exit_breaks::PhiBreaks, one ring a lane. Each threshold is the same
// IEEE operations as there (products and sums rounded one by one: no fused multiply-add, this
// file is compiled with -ffp-contract=off), acos by the same polynomial in the same order, its
// branches as selects; a ring's boundaries are then gathered and sorted as there. So both paths
// of the exit walk get the same breaks, bit for bit (tests/integrate_dielectric_simd.cpp).
#include "baker/integrate/dielectric_exit_breaks.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/dielectric_simd_ops.h"

namespace kiln {
namespace dielectric_simd {

#if defined(KILN_HAVE_AVX512_PATH)
namespace {

using namespace ops;

/// Most candidate thresholds of a ring: the first two, cs, c_crit, both masking layers.
constexpr int kMaxSlots = 3 + 2 + 2 * dielectric_exit_breaks::kMaxLayer;

/// dielectric_exit_breaks::Acos lane by lane (its operations and order; lanes outside (-1, 1)
/// give NaN or a value the caller drops).
KILN_AVX512 inline V Acos8(V x) {
  const V ax = _mm512_abs_pd(x), half = Set(0.5);
  const M big = Gt(ax, half);
  const V z = _mm512_mask_blend_pd(big, Mul(x, x), Mul(Sub(Set(1), ax), half));
  const V s = _mm512_mask_blend_pd(big, ax, Sqrt(z));
  const double* c = dielectric_exit_breaks::kAsinSeries;
  const V z2 = Mul(z, z), z4 = Mul(z2, z2), z8 = Mul(z4, z4);
  V pr[6];  // c[2 i] + c[2 i + 1] z
  for (int i = 0; i < 6; ++i) pr[i] = Add(Set(c[2 * i]), Mul(Set(c[2 * i + 1]), z));
  const V p01 = pr[0], p23 = pr[1], p45 = pr[2], p67 = pr[3], p89 = pr[4], p1011 = pr[5];
  const V p = Add(Add(Add(p01, Mul(z2, p23)), Mul(z4, Add(p45, Mul(z2, p67)))),
                  Mul(z8, Add(Add(p89, Mul(z2, p1011)), Mul(z4, Set(c[12])))));
  const V r = Add(s, Mul(Mul(s, z), p));
  const M neg = Lt(x, _mm512_setzero_pd());
  const V small = Sub(Set(Pi / 2), _mm512_mask_blend_pd(neg, r, Neg(r)));
  const V r2 = Mul(Set(2), r);
  const V large = _mm512_mask_blend_pd(neg, r2, Sub(Set(Pi), r2));
  return _mm512_mask_blend_pd(big, small, large);
}

/// The boundaries of eight rings between 0 and phiMax: the candidates in the thresholds' order
/// (their acos, the lanes that keep each), then sorted lane by lane (Sort): slot k holds each
/// lane's k-th smallest (+inf past a lane's count); count the lanes' counts.
struct Slots {
  int nCand = 0, n = 0;
  V cand[kMaxSlots];
  M candKeep[kMaxSlots];
  V phi[kMaxSlots];
  V count;
};

/// Adds threshold c0 (lanes `where`) to s's candidates: cp = (c0 - A) / (sin_o sin_m), kept
/// where it is in (-1, 1) and its acos in (0, phiMax). No branch waits on an acos here: the
/// thresholds' acos overlap.
KILN_AVX512 inline void AddSlot(Slots* s, V c0, M where, V A, V inv, V phiMax) {
  const V cp = Mul(Sub(c0, A), inv);
  const M in = where & Gt(cp, Set(-1)) & Lt(cp, Set(1));
  if (!in) return;  // no lane's boundary: its acos is not needed
  const V q = Acos8(cp);
  s->cand[s->nCand] = q;
  s->candKeep[s->nCand++] = in & Gt(q, _mm512_setzero_pd()) & Lt(q, phiMax);
}

/// Inserts s's kept candidates in their order into each lane's sorted column by min and max (the
/// values are neither NaN nor signed zeros: the same order as SortSmall's).
KILN_AVX512 inline void Sort(Slots* s) {
  for (int c = 0; c < s->nCand; ++c) {
    const M keep = s->candKeep[c];
    if (!keep) continue;
    V x = _mm512_mask_blend_pd(keep, Set(INFINITY), s->cand[c]);
    for (int k = 0; k < s->n; ++k) {
      const V lo = Min(s->phi[k], x);
      x = Max(s->phi[k], x);
      s->phi[k] = lo;
    }
    s->phi[s->n++] = x;
    s->count = _mm512_mask_add_pd(s->count, keep, s->count, Set(1));
  }
}

}  // namespace

KILN_AVX512 void PhiBreaks8(const ExitPhiView& v, const double* cosM, const double* sinM, int m,
                            double (*phis)[kMaxRingPhis], int* np) {
  const M lanes = static_cast<M>((1u << m) - 1);
  const V cosT = _mm512_maskz_loadu_pd(lanes, cosM), sinT = _mm512_maskz_loadu_pd(lanes, sinM);
  const V zero = _mm512_setzero_pd(), one = Set(1), minusOne = Set(-1);
  const V den = Mul(Set(v.st), sinT), A = Mul(Set(v.mu), cosT);
  const M edge = static_cast<M>(~Gt(den, zero) & lanes);  // sin_o sin_m = 0: the whole circle
  const V inv = Div(one, den), invCos = Div(one, cosT), half = Mul(Set(0.5), invCos);
  const V cp0 = Mul(Neg(A), inv);
  const M seen = static_cast<M>(lanes & ~edge & ~_mm512_cmp_pd_mask(cp0, one, _CMP_GE_OQ));
  const V phiMax = _mm512_mask_blend_pd(Gt(cp0, minusOne), Set(Pi), Acos8(cp0));
  Slots s;
  s.count = zero;
  // The reflected ray's thresholds where not below cDrop (PhiBreaks' addReflected).
  const V cDrop = Set(v.cDrop), horizon = Mul(Set(v.mu), half);
  AddSlot(&s, horizon, seen & ~Lt(horizon, cDrop), A, inv, phiMax);
  for (int i = 0; i < v.ncs; ++i) AddSlot(&s, Set(v.cs[i]), seen, A, inv, phiMax);
  for (int i = 0; i < v.nReflected; ++i) {
    const V c0 = Mul(Add(Set(v.reflected[i]), Set(v.mu)), half);
    AddSlot(&s, c0, seen & ~Lt(c0, cDrop), A, inv, phiMax);
  }
  if (v.exitSide) {
    AddSlot(&s, Set(v.cCrit), seen, A, inv, phiMax);
    // The refracted layer: a lane stops at its first q <= 0 or at kMaxThresholds thresholds.
    int count = 1 + 1 + v.ncs + v.nReflected;  // thresholds so far, the same in every lane
    V counts = Set(count);
    M going = seen;
    const V c2 = Set(-v.eta2m1), cCrit = Set(v.cCrit);
    for (int i = 0; i < v.nRefracted && going; ++i) {
      going &= Lt(counts, Set(dielectric_exit_breaks::kMaxThresholds));
      const V q = Mul(Set(v.refracted[i]), invCos);
      going &= Gt(q, zero);
      const V c = Div(Add(Mul(q, q), c2), Mul(Set(2), q));
      const M in = going & _mm512_cmp_pd_mask(c, q, _CMP_GE_OQ) & Gt(c, cCrit) & Lt(c, one);
      AddSlot(&s, c, in, A, inv, phiMax);
      counts = _mm512_mask_add_pd(counts, in, counts, one);
    }
  }
  Sort(&s);
  alignas(64) double maxes[8], as[8], counts[8], sorted[kMaxSlots][8];
  _mm512_store_pd(maxes, phiMax);
  _mm512_store_pd(as, A);
  _mm512_store_pd(counts, s.count);
  for (int k = 0; k < s.n; ++k) _mm512_store_pd(sorted[k], s.phi[k]);
  for (int l = 0; l < m; ++l) {
    double* p = phis[l];
    if ((edge >> l) & 1) {  // PhiBreaks' den <= 0 case
      np[l] = as[l] > 0 ? 2 : 0;
      p[0] = 0;
      p[1] = Pi;
      continue;
    }
    if (!((seen >> l) & 1)) {
      np[l] = 0;
      continue;
    }
    // 0, the lane's boundaries in order (each below phiMax), phiMax: PhiBreaks' sorted list.
    const int kept = static_cast<int>(counts[l]);
    p[0] = 0;
    for (int k = 0; k < kept; ++k) p[k + 1] = sorted[k][l];
    p[kept + 1] = maxes[l];
    np[l] = kept + 2;
  }
}

#else  // no AVX-512F path on this target: Enabled() is false, this is never called

void PhiBreaks8(const ExitPhiView&, const double*, const double*, int, double (*)[kMaxRingPhis],
                int*) {}

#endif

}  // namespace dielectric_simd
}  // namespace kiln
