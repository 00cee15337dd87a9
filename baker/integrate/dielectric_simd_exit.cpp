// The exit walk's AVX-512F path (dielectric_simd.h, FastRingSums): one ring of the glass E pair's
// per-point walk (dielectric_albedo.cpp, FastView and FastWalk), eight azimuth nodes per
// instruction, with fused multiply-add (AVX-512F has it) and the ring's sums kept in vector
// accumulators. PortableRingSums (dielectric_exit_ring.cpp) does these operations one node at a
// time with std::fma and the same lanes, for the same bits (tests/integrate_dielectric_simd.cpp):
// change one, change the other. FastView's formulas, rearranged where a fused form is shorter:
// c = A + B cos phi and the x^2 Horner steps of CosHalfTurn as fused steps, 1 - mu_i^2 by one
// fused step, c / cos_m as c (1 / cos_m) and mu_t's division by eta as a product with 1 / eta.
#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/dielectric_simd_ops.h"

namespace kiln {
namespace dielectric_simd {

#if defined(KILN_HAVE_AVX512_PATH)
namespace {

using namespace ops;

/// a b + c, rounded once.
KILN_AVX512 inline V Fma(V a, V b, V c) { return _mm512_fmadd_pd(a, b, c); }
/// a b - c, rounded once.
KILN_AVX512 inline V Fms(V a, V b, V c) { return _mm512_fmsub_pd(a, b, c); }
/// c - a b, rounded once.
KILN_AVX512 inline V Fnma(V a, V b, V c) { return _mm512_fnmadd_pd(a, b, c); }

/// dielectric_walk::CosHalfTurn's series (cos phi = -sin(phi - pi/2) to x^21), its Horner steps
/// fused.
KILN_AVX512 inline V CosHalfTurnFused(V phi) {
  const V x = Sub(phi, Set(1.5707963267948966)), x2 = Mul(x, x);
  const double* k = kCosHalfTurnSeries;
  V p = Set(k[0]);
  p = Fma(p, x2, Set(k[1]));
  p = Fma(p, x2, Set(k[2]));
  p = Fma(p, x2, Set(k[3]));
  p = Fma(p, x2, Set(k[4]));
  p = Fma(p, x2, Set(k[5]));
  p = Fma(p, x2, Set(k[6]));
  p = Fma(p, x2, Set(k[7]));
  p = Fma(p, x2, Set(k[8]));
  p = Fma(p, x2, Set(k[9]));
  p = Fma(p, x2, Set(k[10]));
  return Mul(Neg(x), p);
}

/// A FastRing's constants, broadcast.
struct Consts {
  V A, B, cosM, invCosM, mu, invEta, eta2, eta2p1, eta2m1, e2m1sq, a2, gDen;
};

KILN_AVX512 inline Consts ConstsOf(const FastRing& r) {
  return {Set(r.A),      Set(r.B),    Set(r.cosM),     Set(1 / r.cosM), Set(r.mu),
          Set(r.invEta), Set(r.eta2), Set(r.eta2 + 1), Set(r.eta2m1),   Set(r.eta2m1 * r.eta2m1),
          Set(r.a2),     Set(r.gDen)};
}

/// One ray's weighted term, FastView's weigh: wb f p / (gDen p + mu a2 s_i^2), p = 2 mu_i
/// (sqrt(mu_i^2 + a2 s_i^2) + mu_i), s_i^2 = max(0, 1 - mu_i^2); wb the node's weight times c /
/// cos_m.
KILN_AVX512 inline V Weigh(V wb, V mi, V f, const Consts& q) {
  const V a2s2 = Mul(q.a2, StdMax(_mm512_setzero_pd(), Fnma(mi, mi, Set(1))));
  const V p = Mul(Add(mi, mi), Add(Sqrt(Fma(mi, mi, a2s2)), mi));
  return Div(Mul(Mul(wb, f), p), Fma(q.gDen, p, Mul(q.mu, a2s2)));
}

/// The weighted terms {R, T} of U vectors of nodes (phi[u], w[u]) in lanes k[u], added to
/// accR[u], accT[u]; a ray's terms computed only where some lane of the U vectors has them
/// (under total internal reflection none transmits; past the reflected horizon none reflects).
template <int U>
KILN_AVX512 inline __attribute__((always_inline)) void AddTerms(const Consts& q, bool reflectOnly,
                                                                const V* phi, const V* w,
                                                                const M* k, V* accR, V* accT) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  V wb[U], cc[U], g[U], F[U], muR[U];
  M ok[U], rok[U];
  M anyR = 0;
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    const V c = Fma(q.B, CosHalfTurnFused(phi[u]), q.A);
    ok[u] = Gt(c, zero) & k[u];
    wb[u] = Mul(w[u], Mul(c, q.invCosM));
    cc[u] = StdMin(c, one);
    const V g2 = Fma(cc[u], cc[u], q.eta2m1);
    const M gok = Gt(g2, zero);
    g[u] = _mm512_mask_sqrt_pd(zero, gok, g2);
    // F by FrDielectric's cancellation-free form over one denominator (FastView).
    const V a = Add(cc[u], g[u]), b = Fma(q.eta2, cc[u], g[u]);
    const V aa = Mul(a, a), bb = Mul(b, b);
    const V x = Fms(Mul(q.eta2p1, cc[u]), cc[u], one);
    const V a4 = Mul(aa, aa), b4 = Mul(bb, bb);
    const V Fv = StdMin(one, Div(Mul(q.e2m1sq, Fma(Mul(x, x), a4, b4)), Mul(Add(a4, a4), b4)));
    F[u] = _mm512_mask_blend_pd(gok, one, Fv);
    muR[u] = Fms(Add(c, c), q.cosM, q.mu);
    rok[u] = ok[u] & Gt(muR[u], zero) & Gt(F[u], zero);
    anyR |= rok[u];
  }
  if (anyR) {
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u)
      accR[u] = Add(accR[u], _mm512_maskz_mov_pd(rok[u], Weigh(wb[u], muR[u], F[u], q)));
  }
  if (reflectOnly) return;
  V muT[U];
  M tok[U];
  M anyT = 0;
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    muT[u] = Mul(Fnma(Sub(cc[u], g[u]), q.cosM, q.mu), q.invEta);
    tok[u] = ok[u] & Lt(F[u], one) & Gt(muT[u], zero);
    anyT |= tok[u];
  }
  if (anyT) {
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u)
      accT[u] = Add(accT[u], _mm512_maskz_mov_pd(tok[u], Weigh(wb[u], muT[u], Sub(one, F[u]), q)));
  }
}

/// The sum of a vector's eight lanes, pairwise in one fixed order (GCC 12's
/// _mm512_reduce_add_pd starts from an undefined vector, which -Wuninitialized flags).
KILN_AVX512 inline double LaneSum(V x) {
  alignas(64) double l[8];
  _mm512_store_pd(l, x);
  return ((l[0] + l[4]) + (l[2] + l[6])) + ((l[1] + l[5]) + (l[3] + l[7]));
}

/// The nodes o .. o + 7 of J (phi, w) into *p, *wv, the lanes that hold one in *k (zeros in the
/// others).
KILN_AVX512 inline void LoadNodes(const double* phi, const double* w, int J, int o, V* p, V* wv,
                                  M* k) {
  const int left = J - o, m = left < 0 ? 0 : left < 8 ? left : 8;
  *k = static_cast<M>((1u << m) - 1);
  *p = _mm512_maskz_loadu_pd(*k, phi + o);
  *wv = _mm512_maskz_loadu_pd(*k, w + o);
}

}  // namespace

KILN_AVX512 void FastRingSums(const FastRing& r, const double* phi, const double* w, int J,
                              double* sumR, double* sumT) {
  const Consts q = ConstsOf(r);
  // Two vectors per step (one vector's chain of cos, 3 roots and 3 divisions is long), one for
  // the last eight nodes or fewer.
  V accR[2], accT[2];
  for (int u = 0; u < 2; ++u) accR[u] = accT[u] = _mm512_setzero_pd();
  int j = 0;
  for (; J - j > 8; j += 16) {
    V p[2], wv[2];
    M k[2];
    LoadNodes(phi, w, J, j, &p[0], &wv[0], &k[0]);
    LoadNodes(phi, w, J, j + 8, &p[1], &wv[1], &k[1]);
    AddTerms<2>(q, r.reflectOnly, p, wv, k, accR, accT);
  }
  if (j < J) {
    V p, wv;
    M k;
    LoadNodes(phi, w, J, j, &p, &wv, &k);
    AddTerms<1>(q, r.reflectOnly, &p, &wv, &k, accR, accT);
  }
  *sumR = LaneSum(Add(accR[0], accR[1]));
  *sumT = LaneSum(Add(accT[0], accT[1]));
}

#else  // no AVX-512F path on this target: Enabled() is false, this is never called

void FastRingSums(const FastRing&, const double*, const double*, int, double*, double*) {}

#endif

}  // namespace dielectric_simd
}  // namespace kiln
