// The glass walks' AVX-512F paths (dielectric_simd.h). Each function mirrors, operation for
// operation and in the same order, the portable code it stands for in dielectric_albedo.cpp
// (FastView::Integrand, ColumnWalk's node): std::min(a, b) is (b < a ? b : a), which
// MINPD(b, a) computes ((b < a) ? b : a), likewise max; a branch becomes a mask and a
// select. Compiled for AVX-512F only (no FMA: no contraction of a * b + c), so every lane's
// result has the portable code's bits.
#include "baker/integrate/dielectric_simd.h"

#include <atomic>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define KILN_HAVE_AVX512_PATH 1
#define KILN_AVX512 __attribute__((target("avx512f")))
#endif

namespace kiln {
namespace dielectric_simd {
namespace {

bool CpuHasAvx512() {
#if defined(KILN_HAVE_AVX512_PATH)
  return __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

std::atomic<bool>& Switch() {
  static std::atomic<bool> on{CpuHasAvx512()};
  return on;
}

}  // namespace

bool Enabled() { return Switch().load(std::memory_order_relaxed); }
void SetEnabled(bool on) { Switch().store(on && CpuHasAvx512()); }

#if defined(KILN_HAVE_AVX512_PATH)
namespace {

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

/// FastView's weigh(mi, w): base w p / (gDen p + mu a2 s^2).
KILN_AVX512 inline V Weigh(V base, V mi, V w, V a2, V gDen, V mu) {
  const V one = Set(1), zero = _mm512_setzero_pd();
  const V a2s2 = Mul(a2, StdMax(zero, Mul(Sub(one, mi), Add(one, mi))));
  const V p = Mul(Mul(Set(2), mi), Add(Sqrt(Add(Mul(mi, mi), a2s2)), mi));
  return Div(Mul(Mul(base, w), p), Add(Mul(gDen, p), Mul(mu, a2s2)));
}

/// A FastRing's constants, broadcast.
struct FastConsts {
  V A, B, cosM, mu, eta, eta2, eta2m1, a2, gDen, e2m1sq;
  bool reflectOnly;
};

KILN_AVX512 inline FastConsts ConstsOf(const FastRing& r) {
  return {Set(r.A),     Set(r.B),      Set(r.cosM), Set(r.mu),   Set(r.eta),
          Set(r.eta2),  Set(r.eta2m1), Set(r.a2),   Set(r.gDen), Set(r.eta2m1 * r.eta2m1),
          r.reflectOnly};
}

/// FastView::Integrand {R, T} at the azimuths phi[u] of lanes k[u], U vectors at once (their
/// operations interleaved: the chain of one vector is long, of cos, square roots and divisions):
/// the terms into R[u], T[u] (0 in the other lanes). Each lane's operations are the portable
/// code's; a ray's term is computed only where some lane of the U vectors has it.
template <int U>
KILN_AVX512 inline __attribute__((always_inline)) void FastTerms(const FastConsts& q, const V* phi,
                                                                 const M* k, V* R, V* T) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  V c[U], base[U], cc[U], g[U], F[U], muR[U];
  M ok[U], rok[U], tok[U];
  M anyR = 0, anyT = 0;
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    c[u] = Add(q.A, Mul(q.B, CosHalfTurn8(phi[u])));
    ok[u] = Gt(c[u], zero) & k[u];
    base[u] = Div(c[u], q.cosM);
    cc[u] = StdMin(c[u], one);
    const V g2 = Add(Mul(cc[u], cc[u]), q.eta2m1);
    const M gok = Gt(g2, zero);
    g[u] = _mm512_mask_sqrt_pd(zero, gok, g2);
    const V a = Add(cc[u], g[u]), b = Add(Mul(q.eta2, cc[u]), g[u]);
    const V aa = Mul(a, a), bb = Mul(b, b);
    const V x = Sub(Mul(Mul(Add(q.eta2, one), cc[u]), cc[u]), one);
    const V a4 = Mul(aa, aa), b4 = Mul(bb, bb);
    const V Fv =
        StdMin(one, Div(Mul(q.e2m1sq, Add(b4, Mul(Mul(x, x), a4))), Mul(Mul(two, a4), b4)));
    F[u] = _mm512_mask_blend_pd(gok, one, Fv);
    muR[u] = Sub(Mul(Mul(two, c[u]), q.cosM), q.mu);
    // Each ray's term only where some lane has it (under total internal reflection none
    // transmits; past the reflected horizon none reflects).
    rok[u] = ok[u] & Gt(muR[u], zero) & Gt(F[u], zero);
    anyR |= rok[u];
  }
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u)
    R[u] =
        anyR ? _mm512_maskz_mov_pd(rok[u], Weigh(base[u], muR[u], F[u], q.a2, q.gDen, q.mu)) : zero;
  V muT[U];
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    tok[u] = 0;
    muT[u] = zero;
    if (!q.reflectOnly) {
      muT[u] = Div(Sub(q.mu, Mul(Sub(cc[u], g[u]), q.cosM)), q.eta);
      tok[u] = ok[u] & Lt(F[u], one) & Gt(muT[u], zero);
    }
    anyT |= tok[u];
  }
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u)
    T[u] = anyT ? _mm512_maskz_mov_pd(tok[u],
                                      Weigh(base[u], muT[u], Sub(one, F[u]), q.a2, q.gDen, q.mu))
                : zero;
}

}  // namespace

KILN_AVX512 void FastRingIntegrand(const FastRing& r, const double* phi, int J, double* outR,
                                   double* outT) {
  const FastConsts q = ConstsOf(r);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    V R, T;
    const V p = _mm512_maskz_loadu_pd(k, phi + j);
    FastTerms<1>(q, &p, &k, &R, &T);
    _mm512_mask_storeu_pd(outR + j, k, R);
    _mm512_mask_storeu_pd(outT + j, k, T);
  }
}

KILN_AVX512 void FastRingWeighted(const FastRing& r, bool visible, RingBuffer& buf) {
  constexpr int U = 2;  // vectors per step
  const FastConsts q = ConstsOf(r);
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2), three = Set(3), six = Set(6);
  const int J = buf.J;
  for (int j = 0; j < J; j += 8 * U) {
    V phi[U], w[U], R[U], T[U];
    M k[U];
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u) {
      const int left = J - j - 8 * u, m = left < 0 ? 0 : left < 8 ? left : 8;
      k[u] = static_cast<M>((1u << m) - 1);
      const int o = j + 8 * u;
      // Smooth(a, b, t, &dj): dj = (b - a) * 6 * t * (1 - t), phi = a + (b - a) * t * t *
      // (3 - 2 t); the node's weight gw * dj.
      const V a = _mm512_maskz_loadu_pd(k[u], buf.a + o),
              b = _mm512_maskz_loadu_pd(k[u], buf.b + o),
              t = _mm512_maskz_loadu_pd(k[u], buf.t + o);
      const V d = Sub(b, a);
      const V dj = Mul(Mul(Mul(d, six), t), Sub(one, t));
      phi[u] = Add(a, Mul(Mul(Mul(d, t), t), Sub(three, Mul(two, t))));
      w[u] = Mul(_mm512_maskz_loadu_pd(k[u], buf.gw + o), dj);
      R[u] = T[u] = zero;
    }
    if (visible) FastTerms<U>(q, phi, k, R, T);
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u) {
      _mm512_mask_storeu_pd(buf.tR + j + 8 * u, k[u], Mul(w[u], R[u]));
      _mm512_mask_storeu_pd(buf.tT + j + 8 * u, k[u], Mul(w[u], T[u]));
    }
  }
}

KILN_AVX512 void ColumnRingShared(const ColumnRing& r, const double* phi, const double* w, int J,
                                  unsigned char* valid, double* wR, double* wb, double* cc) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V A = Set(r.A), B = Set(r.B), cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen),
          a2 = Set(r.a2);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    const V c = Add(A, Mul(B, CosHalfTurn8(_mm512_maskz_loadu_pd(k, phi + j))));
    const M ok = Gt(c, zero) & k;
    const V wbs = Mul(_mm512_maskz_loadu_pd(k, w + j), Div(c, cosM));
    const V muR = Sub(Mul(Mul(two, c), cosM), mu);
    // GGXDistribution::MuLambda(muR).
    const V s2 = StdMax(zero, Sub(one, Mul(muR, muR)));
    const V den = Mul(two, Add(Sqrt(Add(Mul(muR, muR), Mul(a2, s2))), muR));
    const V ml = _mm512_maskz_mov_pd(Gt(den, zero), Div(Mul(a2, s2), den));
    const V wr = Div(wbs, Add(gDen, Mul(mu, Div(ml, muR))));
    // Nodes not visited: zero weights and a benign cc (their terms are then exactly 0).
    _mm512_mask_storeu_pd(wR + j, k, _mm512_maskz_mov_pd(ok & Gt(muR, zero), wr));
    _mm512_mask_storeu_pd(wb + j, k, _mm512_maskz_mov_pd(ok, wbs));
    _mm512_mask_storeu_pd(cc + j, k, _mm512_mask_blend_pd(ok, Set(0.5), StdMin(c, one)));
    for (int i = 0; i < m; ++i) valid[j + i] = (ok >> i) & 1;
  }
}

KILN_AVX512 void ColumnRingEtas(const ColumnRing& r, const unsigned char* valid, const double* wR,
                                const double* wb, const double* cc, int J, const double* eta2m1,
                                const double* eta2, const double* inv, int groups, double* ring0,
                                double* ring1) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen), a2 = Set(r.a2);
  for (int q = 0; q < groups; ++q) {
    const V e2m1 = _mm512_loadu_pd(eta2m1 + 8 * q), e2 = _mm512_loadu_pd(eta2 + 8 * q),
            ie = _mm512_loadu_pd(inv + 8 * q), e2p1 = Add(e2, one), e2m1sq = Mul(e2m1, e2m1);
    V r0 = _mm512_loadu_pd(ring0 + 8 * q), r1 = _mm512_loadu_pd(ring1 + 8 * q);
    for (int j = 0; j < J; ++j) {
      if (!valid[j]) continue;
      const V c = Set(cc[j]), c2 = Mul(c, c);
      const V g = Sqrt(Add(c2, e2m1));
      const V a = Add(c, g), b = Add(Mul(e2, c), g), x = Sub(Mul(Mul(e2p1, c), c), one);
      const V aa = Mul(a, a), bb = Mul(b, b), a4 = Mul(aa, aa), b4 = Mul(bb, bb);
      // Min(one, X) of dielectric_lanes.h is _mm_min_pd(one, X): (1 < X) ? 1 : X.
      const V F = Min(one, Div(Mul(e2m1sq, Add(b4, Mul(Mul(x, x), a4))), Mul(Mul(two, a4), b4)));
      r0 = Add(r0, Mul(Set(wR[j]), F));
      const V muT = Mul(Sub(mu, Mul(Sub(c, g), cosM)), ie);
      // Max(zero, X) is _mm_max_pd(zero, X): (0 > X) ? 0 : X.
      const V a2s2 = Mul(a2, Max(zero, Mul(Sub(one, muT), Add(one, muT))));
      const V p = Mul(Mul(two, muT), Add(Sqrt(Add(Mul(muT, muT), a2s2)), muT));
      r1 = Add(r1, Div(Mul(Mul(Set(wb[j]), Sub(one, F)), p), Add(Mul(gDen, p), Mul(mu, a2s2))));
    }
    _mm512_storeu_pd(ring0 + 8 * q, r0);
    _mm512_storeu_pd(ring1 + 8 * q, r1);
  }
}

KILN_AVX512 void ColumnRingOneEta(const ColumnRing& r, const unsigned char*, const double* wR,
                                  const double* wb, const double* cc, int J, double eta2m1,
                                  double eta2, double inv, double* tR, double* tT) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen), a2 = Set(r.a2);
  const V e2m1 = Set(eta2m1), e2 = Set(eta2), ie = Set(inv), e2p1 = Add(e2, one),
          e2m1sq = Mul(e2m1, e2m1);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    const V c = _mm512_mask_loadu_pd(Set(0.5), k, cc + j), c2 = Mul(c, c);
    const V g = Sqrt(Add(c2, e2m1));
    const V a = Add(c, g), b = Add(Mul(e2, c), g), x = Sub(Mul(Mul(e2p1, c), c), one);
    const V aa = Mul(a, a), bb = Mul(b, b), a4 = Mul(aa, aa), b4 = Mul(bb, bb);
    const V F = Min(one, Div(Mul(e2m1sq, Add(b4, Mul(Mul(x, x), a4))), Mul(Mul(two, a4), b4)));
    _mm512_mask_storeu_pd(tR + j, k, Mul(_mm512_maskz_loadu_pd(k, wR + j), F));
    const V muT = Mul(Sub(mu, Mul(Sub(c, g), cosM)), ie);
    const V a2s2 = Mul(a2, Max(zero, Mul(Sub(one, muT), Add(one, muT))));
    const V p = Mul(Mul(two, muT), Add(Sqrt(Add(Mul(muT, muT), a2s2)), muT));
    _mm512_mask_storeu_pd(tT + j, k,
                          Div(Mul(Mul(_mm512_maskz_loadu_pd(k, wb + j), Sub(one, F)), p),
                              Add(Mul(gDen, p), Mul(mu, a2s2))));
  }
}

KILN_AVX512 void BtdfRingShared(const ColumnRing& r, const double* phi, const double* w, int J,
                                unsigned char* valid, double* wb, double* cc) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  const V A = Set(r.A), B = Set(r.B), cosM = Set(r.cosM);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    const V c = Add(A, Mul(B, CosHalfTurn8(_mm512_maskz_loadu_pd(k, phi + j))));
    const M ok = Gt(c, zero) & k;
    const V wbs = Mul(_mm512_maskz_loadu_pd(k, w + j), Div(c, cosM));
    _mm512_mask_storeu_pd(wb + j, k, _mm512_maskz_mov_pd(ok, wbs));
    _mm512_mask_storeu_pd(cc + j, k, _mm512_mask_blend_pd(ok, Set(0.5), StdMin(c, one)));
    for (int i = 0; i < m; ++i) valid[j + i] = (ok >> i) & 1;
  }
}

/// BtdfColumnWalk's per-eta terms at cos cc (c2 = cc^2) and weight wb: t and F.
KILN_AVX512 inline V BtdfTerm(V c, V wbv, V e2m1, V e2, V ie, V e2p1, V e2m1sq, V cosM, V mu,
                              V gDen, V a2, V* F) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V c2 = Mul(c, c);
  const V g = Sqrt(Add(c2, e2m1));
  // BtdfColumnWalk: x = (eta^2 + 1) cc2 - 1 (the E walk's is ((eta^2 + 1) cc) cc - 1).
  const V a = Add(c, g), b = Add(Mul(e2, c), g), x = Sub(Mul(e2p1, c2), one);
  const V aa = Mul(a, a), bb = Mul(b, b), a4 = Mul(aa, aa), b4 = Mul(bb, bb);
  *F = Min(one, Div(Mul(e2m1sq, Add(b4, Mul(Mul(x, x), a4))), Mul(Mul(two, a4), b4)));
  const V muT = Mul(Sub(mu, Mul(Sub(c, g), cosM)), ie);
  const V a2s2 = Mul(a2, Max(zero, Mul(Sub(one, muT), Add(one, muT))));
  const V p = Mul(Mul(two, muT), Add(Sqrt(Add(Mul(muT, muT), a2s2)), muT));
  return Div(Mul(wbv, p), Add(Mul(gDen, p), Mul(mu, a2s2)));
}

KILN_AVX512 void BtdfRingEtas(const ColumnRing& r, const unsigned char* valid, const double* wb,
                              const double* cc, int J, const double* eta2m1, const double* eta2,
                              const double* inv, int groups, double* ring0, double* ring1) {
  const V one = Set(1);
  const V cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen), a2 = Set(r.a2);
  for (int q = 0; q < groups; ++q) {
    const V e2m1 = _mm512_loadu_pd(eta2m1 + 8 * q), e2 = _mm512_loadu_pd(eta2 + 8 * q),
            ie = _mm512_loadu_pd(inv + 8 * q), e2p1 = Add(e2, one), e2m1sq = Mul(e2m1, e2m1);
    V r0 = _mm512_loadu_pd(ring0 + 8 * q), r1 = _mm512_loadu_pd(ring1 + 8 * q);
    for (int j = 0; j < J; ++j) {
      if (!valid[j]) continue;
      V F;
      const V t =
          BtdfTerm(Set(cc[j]), Set(wb[j]), e2m1, e2, ie, e2p1, e2m1sq, cosM, mu, gDen, a2, &F);
      r0 = Add(r0, t);
      r1 = Add(r1, Mul(t, F));
    }
    _mm512_storeu_pd(ring0 + 8 * q, r0);
    _mm512_storeu_pd(ring1 + 8 * q, r1);
  }
}

KILN_AVX512 void BtdfRingOneEta(const ColumnRing& r, const double* wb, const double* cc, int J,
                                double eta2m1, double eta2, double inv, double* t0, double* t1) {
  const V one = Set(1);
  const V cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen), a2 = Set(r.a2);
  const V e2m1 = Set(eta2m1), e2 = Set(eta2), ie = Set(inv), e2p1 = Add(e2, one),
          e2m1sq = Mul(e2m1, e2m1);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    V F;
    const V t =
        BtdfTerm(_mm512_mask_loadu_pd(Set(0.5), k, cc + j), _mm512_maskz_loadu_pd(k, wb + j), e2m1,
                 e2, ie, e2p1, e2m1sq, cosM, mu, gDen, a2, &F);
    _mm512_mask_storeu_pd(t0 + j, k, t);
    _mm512_mask_storeu_pd(t1 + j, k, Mul(t, F));
  }
}

#else  // no AVX-512F path on this target: Enabled() is false, these are never called

void FastRingIntegrand(const FastRing&, const double*, int, double*, double*) {}
void FastRingWeighted(const FastRing&, bool, RingBuffer&) {}
void ColumnRingShared(const ColumnRing&, const double*, const double*, int, unsigned char*, double*,
                      double*, double*) {}
void ColumnRingEtas(const ColumnRing&, const unsigned char*, const double*, const double*,
                    const double*, int, const double*, const double*, const double*, int, double*,
                    double*) {}
void ColumnRingOneEta(const ColumnRing&, const unsigned char*, const double*, const double*,
                      const double*, int, double, double, double, double*, double*) {}
void BtdfRingShared(const ColumnRing&, const double*, const double*, int, unsigned char*, double*,
                    double*) {}
void BtdfRingEtas(const ColumnRing&, const unsigned char*, const double*, const double*, int,
                  const double*, const double*, const double*, int, double*, double*) {}
void BtdfRingOneEta(const ColumnRing&, const double*, const double*, int, double, double, double,
                    double*, double*) {}

#endif

}  // namespace dielectric_simd
}  // namespace kiln
