// The exit walk's AVX-512F path (dielectric_simd.h, FastRingSums): one ring of the glass E pair's
// per-point walk (dielectric_albedo.cpp, FastView and FastWalk), eight azimuth nodes per
// instruction, with fused multiply-add (AVX-512F has it) and the ring's sums kept in vector
// accumulators. PortableRingSums (dielectric_exit_ring.cpp) does these operations one node at a
// time with std::fma and the same lanes, for the same bits (tests/integrate_dielectric_simd.cpp):
// change one, change the other. FastView's formulas, rearranged for a short chain of dependent
// operations (the ring is bound by it, not by the divider: docs/design/glass-tables.md, "The exit
// ring's dependency chain"): cos phi by an economised series in Estrin's form (CosRing), c = A +
// B cos phi fused, F = Fn / Fd with its division folded into the weights' (Weigh), mu_t's
// division by eta as a product with 1 / eta, and the factor 1 / cos_m of every weight applied
// once to the ring's sums.
#include "baker/integrate/dielectric_simd.h"
#include "baker/math/constants.h"
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

/// cos phi = -x P(x^2), x = phi - pi/2, P by kRingSinSeries (dielectric_simd.h) in Estrin's
/// scheme, its steps fused: a chain seven operations deep (Horner's would be eleven).
KILN_AVX512 inline V CosRing(V phi) {
  const V x = Sub(phi, Set(1.5707963267948966)), y = Mul(x, x);
  const V y2 = Mul(y, y), y4 = Mul(y2, y2), y8 = Mul(y4, y4);
  const double* k = kRingSinSeries;
  const V e01 = Fma(Set(k[1]), y, Set(k[0])), e23 = Fma(Set(k[3]), y, Set(k[2]));
  const V e45 = Fma(Set(k[5]), y, Set(k[4])), e67 = Fma(Set(k[7]), y, Set(k[6]));
  const V f03 = Fma(e23, y2, e01), f47 = Fma(e67, y2, e45);
  return Mul(Neg(x), Fma(Set(k[8]), y8, Fma(f47, y4, f03)));
}

/// A FastRing's constants, broadcast.
struct Consts {
  V A, B, cosM, mu, muHalf, invEta, eta2, eta2p1, eta2m1, e2m1sq, a2, oneMinusA2, gDen;
};

KILN_AVX512 inline Consts ConstsOf(const FastRing& r) {
  return {Set(r.A),      Set(r.B),      Set(r.cosM),     Set(r.mu),     Set(0.5 * r.mu),
          Set(r.invEta), Set(r.eta2),   Set(r.eta2 + 1), Set(r.eta2m1), Set(r.eta2m1 * r.eta2m1),
          Set(r.a2),     Set(1 - r.a2), Set(r.gDen)};
}

/// One ray's weighted term, FastView's weigh with F = fn / fd, times cos_m: wb fn p / (fd (gDen p
/// + mu a2 s_i^2)), p = 2 mu_i (sqrt(X) + mu_i), X = mu_i^2 + a2 s_i^2 = a2 + (1 - a2) mu_i^2
/// (s_i^2 = 1 - mu_i^2; mu_i exceeds 1 by rounding only) in one fused step, and a2 s_i^2 as X -
/// mu_i^2 (within an ulp of X, which is below an ulp of the denominator); wb = w c, the node's
/// weight times c (the factor 1 / cos_m is the ring's). fd (gDen p + mu a2 s_i^2) as one fused step
/// (fd gDen) p + fd mu a2 s_i^2, whose factors wait on no root.
KILN_AVX512 inline V Weigh(V wb, V mi, V fn, V fd, const Consts& q) {
  const V mi2 = Mul(mi, mi);
  const V X = Fma(q.oneMinusA2, mi2, q.a2), a2s2 = Sub(X, mi2);
  const V h = Mul(mi, Add(Sqrt(X), mi));  // p / 2
  return Div(Mul(Mul(wb, fn), h), Mul(fd, Fma(q.gDen, h, Mul(q.muHalf, a2s2))));
}

/// The weighted terms {R, T} of U vectors of nodes (phi[u], w[u]) in lanes k[u], added to
/// accR[u], accT[u]; a ray's terms computed only where some lane of the U vectors has them
/// (under total internal reflection none transmits; past the reflected horizon none reflects).
/// complement: the reflected term's (1 - F) share instead of its F share (FastRing).
template <int U>
KILN_AVX512 inline __attribute__((always_inline)) void AddTerms(const Consts& q, bool reflectOnly,
                                                                bool complement, const V* phi,
                                                                const V* w, const M* k, V* accR,
                                                                V* accT) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  V wb[U], cc[U], g[U], Fn[U], Fd[U], muR[U], g2[U];
  M ok[U], rok[U], part[U], gok[U];
  M anyR = 0, anyG = 0;
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    const V c = Fma(q.B, CosRing(phi[u]), q.A);
    ok[u] = Gt(c, zero) & k[u];
    wb[u] = Mul(w[u], c);
    cc[u] = StdMin(c, one);
    g2[u] = Fma(cc[u], cc[u], q.eta2m1);
    gok[u] = Gt(g2[u], zero);
    anyG |= gok[u];
    muR[u] = Fms(Add(c, c), q.cosM, q.mu);
    anyR |= ok[u] & Gt(muR[u], zero);  // rok's lanes and more, known before F
  }
  // F = Fn / Fd by FrDielectric's cancellation-free form over one denominator (FastView), its
  // division left to the weights; F = 1 (Fn = Fd = 1) under total internal reflection and
  // where Fn < Fd fails (also for a NaN): wholly so where no lane has g^2 > 0 (a panel past the
  // critical angle), its operations then skipped.
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    g[u] = zero;
    Fn[u] = Fd[u] = one;
    part[u] = 0;
  }
  if (anyG) {
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u) {
      g[u] = _mm512_mask_sqrt_pd(zero, gok[u], g2[u]);
      const V a = Add(cc[u], g[u]), b = Fma(q.eta2, cc[u], g[u]);
      const V aa = Mul(a, a), bb = Mul(b, b);
      const V x = Fms(Mul(q.eta2p1, cc[u]), cc[u], one);
      const V a4 = Mul(aa, aa), b4 = Mul(bb, bb);
      const V n = Mul(q.e2m1sq, Fma(Mul(x, x), a4, b4)), d = Mul(Add(a4, a4), b4);
      part[u] = gok[u] & Lt(n, d);
      Fn[u] = _mm512_mask_blend_pd(part[u], one, n);
      Fd[u] = _mm512_mask_blend_pd(part[u], one, d);
    }
  }
  if (complement) {
    // (1 - F) times the reflected term with F = 1, where 0 <= F < 1 (none where no lane has g^2
    // > 0).
    if (anyR && anyG) {
#pragma GCC unroll 4
      for (int u = 0; u < U; ++u) {
        rok[u] = ok[u] & Gt(muR[u], zero) & part[u];
        accR[u] = Add(accR[u], _mm512_maskz_mov_pd(
                                   rok[u], Weigh(wb[u], muR[u], Sub(Fd[u], Fn[u]), Fd[u], q)));
      }
    }
  } else if (anyR) {
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u) {
      rok[u] = ok[u] & Gt(muR[u], zero) & Gt(Fn[u], zero);
      accR[u] = Add(accR[u], _mm512_maskz_mov_pd(rok[u], Weigh(wb[u], muR[u], Fn[u], Fd[u], q)));
    }
  }
  if (reflectOnly) return;
  if (!anyG) return;  // no lane transmits
  V muT[U];
  M tok[U];
  M anyT = 0;
#pragma GCC unroll 4
  for (int u = 0; u < U; ++u) {
    muT[u] = Mul(Fnma(Sub(cc[u], g[u]), q.cosM, q.mu), q.invEta);
    const M up = ok[u] & Gt(muT[u], zero);
    tok[u] = up & part[u];
    anyT |= up & gok[u];  // tok's lanes and more, known before F
  }
  if (anyT) {
#pragma GCC unroll 4
    for (int u = 0; u < U; ++u)
      accT[u] = Add(accT[u],
                    _mm512_maskz_mov_pd(tok[u], Weigh(wb[u], muT[u], Sub(Fd[u], Fn[u]), Fd[u], q)));
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
    AddTerms<2>(q, r.reflectOnly, r.tirComplement, p, wv, k, accR, accT);
  }
  if (j < J) {
    V p, wv;
    M k;
    LoadNodes(phi, w, J, j, &p, &wv, &k);
    AddTerms<1>(q, r.reflectOnly, r.tirComplement, &p, &wv, &k, accR, accT);
  }
  // The weights' common factor 1 / cos_m, once a ring.
  const double invCosM = 1 / r.cosM;
  *sumR = LaneSum(Add(accR[0], accR[1])) * invCosM;
  *sumT = LaneSum(Add(accT[0], accT[1])) * invCosM;
}

KILN_AVX512 int FastOuterRings(double va, double vb, double a2, const double* t, const double* w,
                               int n, double* sinM, double* cosM, double* wo) {
  const V zero = _mm512_setzero_pd(), one = Set(1), a = Set(va), d = Set(vb - va);
  int m = 0;
  for (int o = 0; o < n; o += 8) {
    const int left = n - o;
    const M k = static_cast<M>((1u << (left < 8 ? left : 8)) - 1);
    const V tv = _mm512_maskz_loadu_pd(k, t + o), wv = _mm512_maskz_loadu_pd(k, w + o);
    // Smooth: jac = (b - a) 6 t (1 - t), v = a + (b - a) t t (3 - 2 t); the ring's -jac.
    const V jac = Neg(Mul(Mul(Mul(d, Set(6)), tv), Sub(one, tv)));
    const V v = Add(a, Mul(Mul(Mul(d, tv), tv), Sub(Set(3), Mul(Set(2), tv))));
    const M ok = k & Gt(v, zero) & Gt(jac, zero);
    // FromV: tan^2 = alpha^2 (1 - v) / v, cos = 1 / sqrt(1 + tan^2), sin = sqrt(tan^2) cos.
    const V tan2 = Div(Mul(Set(a2), Sub(one, v)), v);
    const V c = Div(one, Sqrt(Add(one, tan2)));
    alignas(64) double sv[8], cv[8], wov[8];
    _mm512_store_pd(sv, Mul(Sqrt(tan2), c));
    _mm512_store_pd(cv, c);
    _mm512_store_pd(wov, Div(Mul(wv, jac), Set(Pi)));
    for (int l = 0; l < 8; ++l)
      if ((ok >> l) & 1) {
        sinM[m] = sv[l];
        cosM[m] = cv[l];
        wo[m++] = wov[l];
      }
  }
  return m;
}

#else  // no AVX-512F path on this target: Enabled() is false, these are never called

void FastRingSums(const FastRing&, const double*, const double*, int, double*, double*) {}
int FastOuterRings(double, double, double, const double*, const double*, int, double*, double*,
                   double*) {
  return 0;
}

#endif

}  // namespace dielectric_simd
}  // namespace kiln
