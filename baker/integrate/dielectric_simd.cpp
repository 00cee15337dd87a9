// The glass walks' AVX-512F column paths (dielectric_simd.h; the exit walk's is
// dielectric_simd_exit.cpp). Each function mirrors, operation for operation and in the same
// order, the portable code it stands for in dielectric_albedo.cpp and dielectric_btdf.cpp
// (ReflectedMoments' ring and moments, dielectric_fresnel_moments.h's RingMoments; BtdfColumnWalk's
// node and its per-eta part dielectric_lanes::EtaTerms):
// std::min(a, b) is (b < a ? b : a), which MINPD(b, a) computes ((b < a) ? b : a), likewise max; a
// branch becomes a mask and a select. Compiled for AVX-512F only (no FMA: no contraction of a * b +
// c), so every lane's result has the portable code's bits.
#include "baker/integrate/dielectric_simd.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

#include "baker/integrate/dielectric_fresnel_moments.h"
#include "baker/integrate/dielectric_simd_ops.h"

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

/// The environment variable KILN_NO_AVX512 set to anything but "" or "0": the portable paths
/// from the start (to check that a bake on a CPU without AVX-512F gives the same bytes).
bool PortableRequested() {
  const char* text = std::getenv("KILN_NO_AVX512");
  return text && *text && std::strcmp(text, "0") != 0;
}

std::atomic<bool>& Switch() {
  static std::atomic<bool> on{CpuHasAvx512() && !PortableRequested()};
  return on;
}

}  // namespace

bool Enabled() { return Switch().load(std::memory_order_relaxed); }
void SetEnabled(bool on) { Switch().store(on && CpuHasAvx512()); }

#if defined(KILN_HAVE_AVX512_PATH)
using namespace ops;

KILN_AVX512 int ReflectedRing(const ColumnRing& r, const double* phi, const double* w, int J,
                              double* wR, double* cc) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V A = Set(r.A), B = Set(r.B), cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen),
          a2 = Set(r.a2);
  int kept = 0;
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
    // The portable walk keeps a node where c > 0, mu_R > 0 and its weight is not 0, in order.
    const M keep = ok & Gt(muR, zero) & _mm512_cmp_pd_mask(wr, zero, _CMP_NEQ_UQ);
    _mm512_mask_compressstoreu_pd(wR + kept, keep, wr);
    _mm512_mask_compressstoreu_pd(cc + kept, keep, StdMin(c, one));
    kept += __builtin_popcount(keep);
  }
  return kept;
}

/// The ring's and a group of eight etas' constants, as EtaTerms takes them.
struct RingV {
  V cosM, mu, a2, oma2, kh;
};
struct EtaV {
  V e2m1, e2, ie;
};
KILN_AVX512 inline RingV RingVOf(const ColumnRing& r) {
  return {Set(r.cosM), Set(r.mu), Set(r.a2), Set(r.oma2), Set(r.kh)};
}

/// ColumnWalk's and BtdfColumnWalk's per-eta quantities at cosine c (each lane its own eta), the
/// portable code's operations in its order: Fresnel's transmittance Tf = 1 - F into *tf, the
/// refracted ray's p into *p and its denominator p + kh s_t^2 into *den.
KILN_AVX512 inline void EtaTerms(V c, const EtaV& e, const RingV& rv, V* tf, V* p, V* den) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  const V g = Sqrt(Add(Mul(c, c), e.e2m1));
  const V a = Add(c, g), b = Add(Mul(e.e2, c), g), aa = Mul(a, a), bb = Mul(b, b), cg = Mul(c, g);
  *tf = Div(Mul(Add(cg, cg), Add(bb, Mul(e.e2, aa))), Mul(aa, bb));
  const V muT = Mul(Sub(rv.mu, Mul(Sub(c, g), rv.cosM)), e.ie), mt2 = Mul(muT, muT);
  // Max(zero, X) of dielectric_lanes.h is _mm_max_pd(zero, X): (0 > X) ? 0 : X.
  const V s2 = Max(zero, Sub(one, mt2));
  *p = Mul(muT, Add(Sqrt(Add(rv.a2, Mul(rv.oma2, mt2))), muT));
  *den = Add(*p, Mul(rv.kh, s2));
}

KILN_AVX512 void RingMoments8(const double* wR, const double* cc, int J, double* ring) {
  constexpr int kTerms = dielectric_moments::kTerms;
  V acc[kTerms];
  for (int k = 0; k < kTerms; ++k) acc[k] = _mm512_setzero_pd();
  const V one = Set(1), two = Set(2);
  // Two groups of eight nodes at a time (two independent recurrences in flight), the first's
  // terms added before the second's: each lane's sums in the nodes' order.
  for (int j = 0; j < J; j += 16) {
    V x2[2], u0[2], u1[2];
    for (int h = 0; h < 2; ++h) {
      const int left = J - j - 8 * h, m = left < 0 ? 0 : left < 8 ? left : 8;
      const M in = static_cast<M>((1u << m) - 1);
      // Lanes past the ring's end: w = 0 and x = 0, as the portable form pads them.
      const V x =
          _mm512_maskz_mov_pd(in, Sub(Mul(two, _mm512_maskz_loadu_pd(in, cc + j + 8 * h)), one));
      x2[h] = Add(x, x);
      u0[h] = _mm512_maskz_loadu_pd(in, wR + j + 8 * h);
      u1[h] = Mul(u0[h], x);
    }
    const int groups = J - j > 8 ? 2 : 1;
    for (int h = 0; h < groups; ++h) {
      acc[0] = Add(acc[0], u0[h]);
      acc[1] = Add(acc[1], u1[h]);
    }
    for (int k = 2; k < kTerms; ++k) {
      const V a = Sub(Mul(x2[0], u1[0]), u0[0]), b = Sub(Mul(x2[1], u1[1]), u0[1]);
      acc[k] = Add(acc[k], a);
      if (groups == 2) acc[k] = Add(acc[k], b);
      u0[0] = u1[0];
      u1[0] = a;
      u0[1] = u1[1];
      u1[1] = b;
    }
  }
  for (int k = 0; k < kTerms; ++k) {
    double s[8];
    _mm512_storeu_pd(s, acc[k]);
    ring[k] = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
  }
}

KILN_AVX512 void BtdfRingShared(const ColumnRing& r, const double* phi, const double* w, int J,
                                unsigned char* valid, double* wb, double* cc) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  const V A = Set(r.A), B = Set(r.B), cosM = Set(r.cosM), gDen = Set(r.gDen);
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    const V c = Add(A, Mul(B, CosHalfTurn8(_mm512_maskz_loadu_pd(k, phi + j))));
    const M ok = Gt(c, zero) & k;
    const V wbs = Mul(_mm512_maskz_loadu_pd(k, w + j), Div(c, cosM));
    _mm512_mask_storeu_pd(wb + j, k, _mm512_maskz_mov_pd(ok, Div(wbs, gDen)));
    _mm512_mask_storeu_pd(cc + j, k, _mm512_mask_blend_pd(ok, Set(0.5), StdMin(c, one)));
    for (int i = 0; i < m; ++i) valid[j + i] = (ok >> i) & 1;
  }
}

KILN_AVX512 void BtdfRingEtas(const ColumnRing& r, const unsigned char* valid, const double* wb,
                              const double* cc, int J, const double* eta2m1, const double* eta2,
                              const double* inv, int groups, double* ring0, double* ring1) {
  const V one = Set(1);
  const RingV rv = RingVOf(r);
  for (int q = 0; q < groups; ++q) {
    const EtaV e{_mm512_loadu_pd(eta2m1 + 8 * q), _mm512_loadu_pd(eta2 + 8 * q),
                 _mm512_loadu_pd(inv + 8 * q)};
    V r0 = _mm512_loadu_pd(ring0 + 8 * q), r1 = _mm512_loadu_pd(ring1 + 8 * q);
    for (int j = 0; j < J; ++j) {
      if (!valid[j]) continue;
      V tf, p, den;
      EtaTerms(Set(cc[j]), e, rv, &tf, &p, &den);
      const V t = Div(Mul(Set(wb[j]), p), den);
      r0 = Add(r0, t);
      r1 = Add(r1, Mul(t, Sub(one, tf)));
    }
    _mm512_storeu_pd(ring0 + 8 * q, r0);
    _mm512_storeu_pd(ring1 + 8 * q, r1);
  }
}

KILN_AVX512 void BtdfRingOneEta(const ColumnRing& r, const double* wb, const double* cc, int J,
                                double eta2m1, double eta2, double inv, double* t0, double* t1) {
  const V one = Set(1);
  const RingV rv = RingVOf(r);
  const EtaV e{Set(eta2m1), Set(eta2), Set(inv)};
  for (int j = 0; j < J; j += 8) {
    const int m = J - j < 8 ? J - j : 8;
    const M k = static_cast<M>((1u << m) - 1);
    V tf, p, den;
    EtaTerms(_mm512_mask_loadu_pd(Set(0.5), k, cc + j), e, rv, &tf, &p, &den);
    const V t = Div(Mul(_mm512_maskz_loadu_pd(k, wb + j), p), den);
    _mm512_mask_storeu_pd(t0 + j, k, t);
    _mm512_mask_storeu_pd(t1 + j, k, Mul(t, Sub(one, tf)));
  }
}

#else  // no AVX-512F path on this target: Enabled() is false, these are never called

int ReflectedRing(const ColumnRing&, const double*, const double*, int, double*, double*) {
  return 0;
}
void RingMoments8(const double*, const double*, int, double*) {}
void BtdfRingShared(const ColumnRing&, const double*, const double*, int, unsigned char*, double*,
                    double*) {}
void BtdfRingEtas(const ColumnRing&, const unsigned char*, const double*, const double*, int,
                  const double*, const double*, const double*, int, double*, double*) {}
void BtdfRingOneEta(const ColumnRing&, const double*, const double*, int, double, double, double,
                    double*, double*) {}

#endif

}  // namespace dielectric_simd
}  // namespace kiln
