// Two doubles per lane pair for the glass rules' columns (dielectric_btdf.cpp: two etas at once;
// dielectric_fresnel_moments.h: two nodes at once): SSE2 where the compiler has it (x86-64
// always), plain doubles otherwise.
#pragma once
#include <array>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kiln {
namespace dielectric_lanes {

// The per-eta arithmetic on two etas at once: SSE2 where the compiler has it (x86-64 always),
// plain doubles otherwise. Each lane is IEEE arithmetic (add, mul, div, sqrt correctly
// rounded, min and max exact) in one fixed order, so an eta's value does not depend on its lane
// or on the other etas of its column.
#if defined(__SSE2__)
struct Pair {
  __m128d v;
};
inline Pair Load(const double* p) { return {_mm_loadu_pd(p)}; }
inline Pair Splat(double x) { return {_mm_set1_pd(x)}; }
inline Pair operator+(Pair a, Pair b) { return {_mm_add_pd(a.v, b.v)}; }
inline Pair operator-(Pair a, Pair b) { return {_mm_sub_pd(a.v, b.v)}; }
inline Pair operator*(Pair a, Pair b) { return {_mm_mul_pd(a.v, b.v)}; }
inline Pair operator/(Pair a, Pair b) { return {_mm_div_pd(a.v, b.v)}; }
inline Pair Sqrt(Pair a) { return {_mm_sqrt_pd(a.v)}; }
inline Pair Min(Pair a, Pair b) { return {_mm_min_pd(a.v, b.v)}; }
inline Pair Max(Pair a, Pair b) { return {_mm_max_pd(a.v, b.v)}; }
inline void Store(double* p, Pair a) { _mm_storeu_pd(p, a.v); }
#else
struct Pair {
  double v[2];
};
inline Pair Load(const double* p) { return {{p[0], p[1]}}; }
inline Pair Splat(double x) { return {{x, x}}; }
inline Pair operator+(Pair a, Pair b) { return {{a.v[0] + b.v[0], a.v[1] + b.v[1]}}; }
inline Pair operator-(Pair a, Pair b) { return {{a.v[0] - b.v[0], a.v[1] - b.v[1]}}; }
inline Pair operator*(Pair a, Pair b) { return {{a.v[0] * b.v[0], a.v[1] * b.v[1]}}; }
inline Pair operator/(Pair a, Pair b) { return {{a.v[0] / b.v[0], a.v[1] / b.v[1]}}; }
inline Pair Sqrt(Pair a) { return {{std::sqrt(a.v[0]), std::sqrt(a.v[1])}}; }
inline Pair Min(Pair a, Pair b) {
  return {{a.v[0] < b.v[0] ? a.v[0] : b.v[0], a.v[1] < b.v[1] ? a.v[1] : b.v[1]}};
}
inline Pair Max(Pair a, Pair b) {
  return {{a.v[0] > b.v[0] ? a.v[0] : b.v[0], a.v[1] > b.v[1] ? a.v[1] : b.v[1]}};
}
inline void Store(double* p, Pair a) {
  p[0] = a.v[0];
  p[1] = a.v[1];
}
#endif

/// A column walk's per-view constants of the refracted ray's masking (EtaTerms): a2 = alpha^2,
/// oma2 = 1 - a2, kh = mu a2 / (2 gDen) (gDen = mu + mu Lambda(o)).
struct RingConsts {
  double a2, oma2, kh;
};
inline RingConsts RingConstsOf(double mu, double gDen, double alpha) {
  const double a2 = alpha * alpha;
  return {a2, 1 - a2, mu * a2 / (2 * gDen)};
}

/// The BTDF column walk's per-eta quantities at cosine c = min(o.m, 1) for two etas (eta2m1 = eta^2
/// - 1, eta2 = eta^2, inv = 1 / eta), as derived in dielectric_albedo.cpp ("Columns"): Fresnel's
/// transmittance Tf = 1 - F into *tf, the refracted ray's p into *p and den = p + kh s_t^2 into
/// *den (kh, oma2, a2: RingConstsOf), so that wb p / den is the refracted term's weight for wb =
/// w (c / cos_m) / gDen. dielectric_simd.cpp's EtaTerms does the same operations in the same order.
inline void EtaTerms(Pair c, Pair eta2m1, Pair eta2, Pair inv, Pair cosM, Pair mu, Pair a2,
                     Pair oma2, Pair kh, Pair* tf, Pair* p, Pair* den) {
  const Pair zero = Splat(0), one = Splat(1);
  const Pair g = Sqrt(c * c + eta2m1);
  const Pair a = c + g, b = eta2 * c + g, aa = a * a, bb = b * b, cg = c * g;
  *tf = (cg + cg) * (bb + eta2 * aa) / (aa * bb);
  const Pair muT = (mu - (c - g) * cosM) * inv, mt2 = muT * muT;
  const Pair s2 = Max(zero, one - mt2);
  *p = muT * (Sqrt(a2 + oma2 * mt2) + muT);
  *den = *p + kh * s2;
}

/// Two channels of a column walk (dielectric_walk::WalkNodes' visitor state), per lane pair of
/// etas: a ring's sums (ring0, ring1) cleared by ClearRing, added to the totals with the ring's
/// weight by EndRing, in the walk's order; Write stores eta 2e's and 2e + 1's {sum0, sum1}.
template <int kPairs>
struct ColumnSums {
  int pairs = 0;
  Pair sum0[kPairs] = {}, sum1[kPairs] = {}, ring0[kPairs] = {}, ring1[kPairs] = {};
  void ClearRing() {
    for (int e = 0; e < pairs; ++e) ring0[e] = ring1[e] = Splat(0);
  }
  void EndRing(double wo) {
    const Pair w = Splat(wo);
    for (int e = 0; e < pairs; ++e) {
      sum0[e] = sum0[e] + w * ring0[e];
      sum1[e] = sum1[e] + w * ring1[e];
    }
  }
  void Write(std::array<double, 2>* out) const {
    for (int e = 0; e < pairs; ++e) {
      double a[2], b[2];
      Store(a, sum0[e]);
      Store(b, sum1[e]);
      out[2 * e] = {a[0], b[0]};
      out[2 * e + 1] = {a[1], b[1]};
    }
  }
};

}  // namespace dielectric_lanes
}  // namespace kiln
