// Two doubles per lane pair for the glass rules' eta columns (dielectric_albedo.cpp,
// dielectric_btdf.cpp: two etas at once): SSE2 where the compiler has it (x86-64 always), plain
// doubles otherwise.
#pragma once
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

}  // namespace dielectric_lanes
}  // namespace kiln
