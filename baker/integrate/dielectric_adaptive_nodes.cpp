// The glass adaptive references' inner integrand in eight AVX-512F lanes
// (dielectric_adaptive_nodes.h): the scalar code's operations (dielectric_albedo.cpp's Integrand,
// dielectric_btdf.cpp's BtdfIntegrand, fresnel.h's FrDielectric, microfacet.h's GGX MuLambda,
// sincos_half_turn.h's SinCosHalfTurn) lane by lane in their order, std::min / std::max by their
// operand orders, the branches as selects: the same bits. Change one, change the other.
#include "baker/integrate/dielectric_adaptive_nodes.h"

#include "baker/integrate/dielectric_simd_ops.h"
#include "baker/math/constants.h"
#include "baker/math/sincos_half_turn.h"

namespace kiln {
namespace dielectric_adaptive {

#if defined(KILN_HAVE_AVX512_PATH)
namespace {

using namespace dielectric_simd::ops;

KILN_AVX512 inline M Ge(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ); }
KILN_AVX512 inline M Le(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
/// mask ? b : a, lane by lane.
KILN_AVX512 inline V Select(M mask, V a, V b) { return _mm512_mask_blend_pd(mask, a, b); }
/// mask ? x : +0.
KILN_AVX512 inline V Keep(M mask, V x) { return _mm512_maskz_mov_pd(mask, x); }

/// SinCosHalfTurn(phi).cos lane by lane on (-pi/4, 5pi/4) (its reduction and Horner chains);
/// *inRange gets the lanes there (the others are std::cos's: the caller's).
KILN_AVX512 inline V CosHalfTurnLanes(V phi, M* inRange) {
  using namespace sincos_detail;
  *inRange = Gt(phi, Set(-Pi / 4)) & Lt(phi, Set(Pi + Pi / 4));
  const M ge1 = Ge(phi, Set(Pi / 4)), ge3 = Ge(phi, Set(3 * Pi / 4));
  const V zero = _mm512_setzero_pd(), one = Set(1);
  const V k = Add(Select(ge1, zero, one), Select(ge3, zero, one));
  const V x = Sub(Sub(phi, Mul(k, Set(HalfPi))), Mul(k, Set(kHalfPiLo))), x2 = Mul(x, x);
  V ps = Set(kSin[7]), pc = Set(kCos[7]);
  for (int j = 6; j >= 0; --j) {
    ps = Add(Set(kSin[j]), Mul(x2, ps));
    pc = Add(Set(kCos[j]), Mul(x2, pc));
  }
  const V s = Add(x, Mul(Mul(x, x2), ps)), c = Add(one, Mul(x2, pc));
  const M k1 = ge1 & static_cast<M>(~ge3), k2 = ge1 & ge3;
  const V cosPhi = Select(k1, c, Neg(s));
  return Mul(Select(k2, one, Set(-1.0)), cosPhi);
}

/// The lanes of phi not in inRange (never on the walks' azimuths [0, pi]) by the scalar
/// SinCosHalfTurn (std::cos there).
[[gnu::noinline, gnu::cold]] KILN_AVX512 V CosOutOfRange(V phi, V cp, M inRange) {
  alignas(64) double p[8], c[8];
  _mm512_store_pd(p, phi);
  _mm512_store_pd(c, cp);
  for (int i = 0; i < 8; ++i)
    if (!((inRange >> i) & 1)) c[i] = SinCosHalfTurn(p[i]).cos;
  return _mm512_load_pd(c);
}

/// The azimuth phi of n <= 8 lanes of AdaptiveWalk's inner variable y[0 ..] on a ring with
/// boundaries phis[0 .. np - 1] (dielectric_walk::RingAzimuth lane by lane: the panel k =
/// min(int(y), np - 2) and Smooth's operations), *dj its Jacobian; returns cos phi
/// (SinCosHalfTurn's bits). Lanes from n up have y = 0.
KILN_AVX512 inline V CosAzimuth(const double* y, const double* phis, int np, int n, V* dj) {
  const M live = static_cast<M>((1u << n) - 1);
  const V yv = _mm512_maskz_loadu_pd(live, y);
  const __m256i k =
      _mm256_min_epi32(_mm512_maskz_cvttpd_epi32(0xFF, yv), _mm256_set1_epi32(np - 2));
  const V a = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF, k, phis, 8);
  const V b = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF,
                                       _mm256_add_epi32(k, _mm256_set1_epi32(1)), phis, 8);
  const V t = Sub(yv, _mm512_maskz_cvtepi32_pd(0xFF, k)), ba = Sub(b, a), one = Set(1);
  *dj = Mul(Mul(Mul(ba, Set(6)), t), Sub(one, t));
  const V phi = Add(a, Mul(Mul(Mul(ba, t), t), Sub(Set(3), Mul(Set(2), t))));
  M inRange;
  const V cp = CosHalfTurnLanes(phi, &inRange);
  return (inRange & live) == live ? cp : CosOutOfRange(phi, cp, inRange | static_cast<M>(~live));
}

/// GGXDistribution::MuLambda(m) lane by lane (alpha^2 = a2).
KILN_AVX512 inline V MuLambdaLanes(V m, V a2) {
  const V zero = _mm512_setzero_pd();
  const V s2 = StdMax(zero, Sub(Set(1), Mul(m, m))), as2 = Mul(a2, s2);
  const V den = Mul(Set(2), Add(Sqrt(Add(Mul(m, m), as2)), m));
  return Keep(Gt(den, zero), Div(as2, den));
}

/// The ring constants FrDielectric takes (eta, (eta - 1)(eta + 1), eta^2, eta^2 + 1).
struct FresnelLanes {
  V eta, eta2m1, eta2, eta2p1;
};

/// FrDielectric(x, eta) lane by lane for x > 0 (no flip to the other side).
KILN_AVX512 inline V FresnelLanesOf(const FresnelLanes& f, V x) {
  const V one = Set(1);
  x = StdMin(one, StdMax(Set(-1), x));  // Clamp(x, -1, 1)
  const V xx = Mul(x, x);
  const V cos2 = Div(Add(xx, f.eta2m1), f.eta2);
  const V ct = Sqrt(cos2);
  const V q1 = Add(x, Mul(f.eta, ct)), q2 = Add(Mul(f.eta, x), ct);
  const V rPerp = Div(Neg(f.eta2m1), Mul(q1, q1));
  const V rParl = Div(Mul(f.eta2m1, Sub(Mul(f.eta2p1, xx), one)), Mul(f.eta2, Mul(q2, q2)));
  const V F = StdMin(one, Div(Add(Mul(rParl, rParl), Mul(rPerp, rPerp)), Set(2)));
  return Select(Le(cos2, _mm512_setzero_pd()), F, one);  // total internal reflection: 1
}

/// Writes out[i] = {r[lane i] dj[lane i], t[lane i] dj[lane i]} for i < n.
KILN_AVX512 inline void Store(V r, V t, V w, int n, Channels<2>* out) {
  alignas(64) double rs[8], ts[8];
  _mm512_store_pd(rs, Mul(r, w));
  _mm512_store_pd(ts, Mul(t, w));
  for (int i = 0; i < n; ++i) out[i] = Channels<2>{rs[i], ts[i]};
}

/// AlbedoNodes of n <= 8 nodes.
KILN_AVX512 void AlbedoLanes(const AlbedoRing& r, const FresnelLanes& f, const double* y,
                             const double* phis, int np, int n, Channels<2>* out) {
  const V zero = _mm512_setzero_pd(), one = Set(1), two = Set(2);
  const V cosM = Set(r.cosM), mu = Set(r.mu), gDen = Set(r.gDen), a2 = Set(r.a2);
  V dj;
  const V c = Add(Set(r.A), Mul(Set(r.B), CosAzimuth(y, phis, np, n, &dj)));
  const M visible = Gt(c, zero) & (r.cosM > 0 ? static_cast<M>(0xFF) : static_cast<M>(0));
  const V base = Div(c, cosM);
  const V F = FresnelLanesOf(f, StdMin(c, one));
  const V muR = Sub(Mul(Mul(two, c), cosM), mu);
  const M reflected = visible & Gt(muR, zero) & Gt(F, zero);
  const V R = Div(Mul(base, F), Add(gDen, Mul(mu, Div(MuLambdaLanes(muR, a2), muR))));
  // MuRefracted: (-mu) / eta + (c / eta - cos_t) cos_m, cos_t = sqrt(max(0, c^2 + eta^2 - 1)) /
  // eta.
  const V cosT = Div(Sqrt(StdMax(zero, Add(Mul(c, c), f.eta2m1))), f.eta);
  const V muT = Neg(Add(Set(r.negMuOverEta), Mul(Sub(Div(c, f.eta), cosT), cosM)));
  const M refracted = visible & Lt(F, one) & Gt(muT, zero);
  const V T = Div(Mul(base, Sub(one, F)), Add(gDen, Mul(mu, Div(MuLambdaLanes(muT, a2), muT))));
  Store(Keep(reflected, R), Keep(refracted, T), dj, n, out);
}

/// BtdfNodes of n <= 8 nodes.
KILN_AVX512 void BtdfLanes(const BtdfRing& r, const FresnelLanes& f, const double* y,
                           const double* phis, int np, int n, Channels<2>* out) {
  const V zero = _mm512_setzero_pd(), one = Set(1);
  const V cosM = Set(r.cosM), mu = Set(r.mu);
  V dj;
  V c = Add(Set(r.A), Mul(Set(r.B), CosAzimuth(y, phis, np, n, &dj)));
  const M visible = Gt(c, zero) & (r.cosM > 0 ? static_cast<M>(0xFF) : static_cast<M>(0));
  c = StdMin(c, one);
  const V cosT = Div(Sqrt(Add(Mul(c, c), f.eta2m1)), f.eta);
  const V muT = Sub(Set(r.muOverEta), Mul(Sub(Div(c, f.eta), cosT), cosM));
  const M down = visible & Gt(muT, zero);
  const V g = Div(Div(c, cosM), Add(Set(r.gDen), Mul(mu, Div(MuLambdaLanes(muT, Set(r.a2)), muT))));
  Store(Keep(down, g), Keep(down, Mul(g, FresnelLanesOf(f, c))), dj, n, out);
}

}  // namespace

KILN_AVX512 void AlbedoNodes(const AlbedoRing& r, const double* y, const double* phis, int np,
                             int n, Channels<2>* out) {
  const FresnelLanes f{Set(r.eta), Set(r.eta2m1), Set(r.eta2), Set(r.eta2p1)};
  for (int i = 0; i < n; i += 8) AlbedoLanes(r, f, y + i, phis, np, n - i < 8 ? n - i : 8, out + i);
}

KILN_AVX512 void BtdfNodes(const BtdfRing& r, const double* y, const double* phis, int np, int n,
                           Channels<2>* out) {
  const FresnelLanes f{Set(r.eta), Set(r.eta2m1), Set(r.eta2), Set(r.eta2p1)};
  for (int i = 0; i < n; i += 8) BtdfLanes(r, f, y + i, phis, np, n - i < 8 ? n - i : 8, out + i);
}

#else  // no AVX-512F path on this target: dielectric_simd::Enabled() is false, never called

void AlbedoNodes(const AlbedoRing&, const double*, const double*, int, int, Channels<2>*) {}
void BtdfNodes(const BtdfRing&, const double*, const double*, int, int, Channels<2>*) {}

#endif

}  // namespace dielectric_adaptive
}  // namespace kiln
