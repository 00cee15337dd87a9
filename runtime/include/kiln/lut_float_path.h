// kiln/lut_float_path.h: the float arithmetic of LutSampler's fast linear lookups (kiln/lut.h)
// on the axes whose warp is linear, sqrt, root4 or root4-layer: the warp, the cell and the
// interpolation in float, branch-free but for the choice of warp (and, on the root4-layer and
// sqrt pair, the collapsed layer of roughness 0).
//
// Accuracy (the contract LutSampler states): the float warped coordinate t lies within a few
// float ulps of 1 of the exact one, and a texel coordinate s = t (N - 1) within
// kFloatNodeSnap (N - 1) of an integer is snapped onto it, so a lookup at a node reads that
// node alone and returns the stored float bit for bit. Elsewhere the result differs from the
// double lookup (Axis::texel, double weights) by at most
//     sum over the axes d of 2 kFloatNodeSnap (N_d - 1) G_d  +  kFloatLerpUlps ulp(V),
// G_d the largest difference of two neighbouring nodes along axis d, V the largest |texel|.
// Depends on the C++ standard library only; no allocation, no exception, no global state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "kiln/lut_inline.h"

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define KILN_FLOAT_PATH_SSE2 1
#endif

namespace kiln {
namespace detail {

/// The warps the float path computes (see kiln::Warp): t = y, sqrt(y), y^(1/4), and the
/// root4-layer warp (y^(1/4) + y (1 + c) / (y + c)) / 2 with its collapsed form at c = 0.
enum class FloatWarp { Linear, Sqrt, Root4, Root4Layer };

/// Half-width, in warped units t, of the band around a node inside which the float path
/// snaps onto the node: 16 float ulps of 1, four times the float warps' largest error.
constexpr float kFloatNodeSnap = 0x1p-20f;

/// The largest |texel| of a table the float path takes. Beyond it (the ltc fits' entries reach
/// 6e5) float rounding is no longer small against a table's declared lookup error, an absolute
/// error measured where the values are small.
constexpr float kFloatPathMaxValue = 1024.0f;

/// True when each of the `count` floats at data is finite and at most kFloatPathMaxValue in
/// magnitude (a NaN fails).
inline bool floatPathValues(const float* data, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i)
    if (!(std::fabs(data[i]) <= kFloatPathMaxValue)) return false;
  return true;
}

/// Float roundings, in ulps of the largest |texel|, the float interpolation may add (three
/// levels of two products and a sum, with margin).
constexpr float kFloatLerpUlps = 8.0f;

/// The constants of one axis for the float path: y = (x - lo) * invRange in double (then
/// rounded to float), N - 1, the snap band in node units and the node stride in floats.
struct FloatAxis {
  double lo = 0.0, invRange = 1.0;
  float last = 0.0f;  ///< N - 1
  float snap = 0.0f;  ///< kFloatNodeSnap * (N - 1)
  std::size_t stride = 0;
  FloatWarp warp = FloatWarp::Linear;
};

/// The normalized coordinate y = (x - lo) / (hi - lo) of x, clamped to [0, 1] (NaN maps to 0).
KILN_INLINE float floatNormalized(const FloatAxis& a, double x) noexcept {
  const float y = static_cast<float>((x - a.lo) * a.invRange);
  const float low = y > 0.0f ? y : 0.0f;  // NaN fails the comparison: 0
  return low < 1.0f ? low : 1.0f;
}

/// The warped coordinate t in [0, 1] of y in [0, 1] (c: the root4-layer scale, >= 0; 0 is
/// the collapsed layer, where y = 0 maps to t = 1/2 and every y > 0 to (y^(1/4) + 1) / 2).
KILN_INLINE float floatWarped(FloatWarp warp, float y, float c) noexcept {
  switch (warp) {
    case FloatWarp::Linear:
      return y;
    case FloatWarp::Sqrt:
      return std::sqrt(y);
    case FloatWarp::Root4:
      return std::sqrt(std::sqrt(y));
    case FloatWarp::Root4Layer: {
      const float q = y + c;
      const float layer = q > 0.0f ? y * (1.0f + c) / q : 1.0f;  // y = c = 0: collapsed
      return 0.5f * (std::sqrt(std::sqrt(y)) + layer);
    }
  }
  return y;
}

/// One axis' part of a lookup: the offset of the cell's first node, the step to its second
/// (0 when the fraction is 0, so a node reads itself alone) and the fraction f in [0, 1).
struct FloatCell {
  std::size_t offset = 0;
  std::size_t step = 0;
  float f = 0.0f;
};

/// The cell of warped coordinate t on axis a: s = t (N - 1), snapped onto an integer within
/// a.snap: node index i = floor(s + a.snap) (N - 1 at the last node) and fraction s - i, or 0
/// (and no second node) when that is at most a.snap.
KILN_INLINE FloatCell floatCell(const FloatAxis& a, float t) noexcept {
  const float s = t * a.last;  // t <= 1: s <= N - 1
  const int i = static_cast<int>(s + a.snap);
  const float f = s - static_cast<float>(i);  // exact, >= -a.snap
  const bool inside = f > a.snap;
  FloatCell cell;
  cell.offset = static_cast<std::size_t>(i) * a.stride;
  cell.step = inside ? a.stride : 0;
  cell.f = inside ? f : 0.0f;
  return cell;
}

/// The cell of x on axis a (c: axis 0's root4-layer scale, ignored by the other warps).
KILN_INLINE FloatCell floatCellAt(const FloatAxis& a, double x, float c) noexcept {
  return floatCell(a, floatWarped(a.warp, floatNormalized(a, x), c));
}

/// The least root4-layer scale c of a layer that has not collapsed (kiln::layerScale's floor).
constexpr float kFloatLayerScaleFloor = 1e-12f;

/// The root4-layer scale of kiln::layerScale in float, branch-free: r clamped to [lo, hi]
/// (NaN maps to lo) and rounded to float, c = max(r^2, 1e-12) in float for r != 0 and c = 0
/// at r = 0 exactly (tested on the clamped double: a positive r below the least float is
/// not 0).
KILN_INLINE float floatLayerScale(double lo, double hi, double r) noexcept {
  const double low = r > lo ? r : lo;  // NaN fails the comparison: lo
  const double rc = low < hi ? low : hi;
  const float rf = static_cast<float>(rc);
  const float c = rf * rf;
  const float floor = c < kFloatLayerScaleFloor ? kFloatLayerScaleFloor : c;
  return rc == 0.0 ? 0.0f : floor;
}

/// The cells of 4 points on axis a: x[0], x[stride], x[2 stride], x[3 stride], layer scales
/// c[0..3] (read by the root4-layer warp only). The same floats as floatCellAt, 4 at once
/// (SSE2 where the compiler targets it: the same IEEE operations on 4 lanes).
KILN_INLINE void floatCells4(const FloatAxis& a, const double* x, std::size_t stride,
                             const float* c, FloatCell* cells) noexcept {
#ifdef KILN_FLOAT_PATH_SSE2
  const __m128d lo = _mm_set1_pd(a.lo), inv = _mm_set1_pd(a.invRange);
  const __m128 y01 = _mm_cvtpd_ps(_mm_mul_pd(_mm_sub_pd(_mm_set_pd(x[stride], x[0]), lo), inv));
  const __m128 y23 =
      _mm_cvtpd_ps(_mm_mul_pd(_mm_sub_pd(_mm_set_pd(x[3 * stride], x[2 * stride]), lo), inv));
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  // maxps gives its second operand when the first is NaN: NaN maps to 0, as floatClamp01.
  const __m128 y = _mm_min_ps(_mm_max_ps(_mm_movelh_ps(y01, y23), zero), one);
  __m128 t = y;
  if (a.warp == FloatWarp::Sqrt) {
    t = _mm_sqrt_ps(y);
  } else if (a.warp == FloatWarp::Root4) {
    t = _mm_sqrt_ps(_mm_sqrt_ps(y));
  } else if (a.warp == FloatWarp::Root4Layer) {
    const __m128 cv = _mm_loadu_ps(c), q = _mm_add_ps(y, cv);
    const __m128 positive = _mm_cmpgt_ps(q, zero);
    const __m128 divisor = _mm_or_ps(_mm_and_ps(positive, q), _mm_andnot_ps(positive, one));
    const __m128 ratio = _mm_div_ps(_mm_mul_ps(y, _mm_add_ps(one, cv)), divisor);
    const __m128 layer = _mm_or_ps(_mm_and_ps(positive, ratio), _mm_andnot_ps(positive, one));
    t = _mm_mul_ps(_mm_set1_ps(0.5f), _mm_add_ps(_mm_sqrt_ps(_mm_sqrt_ps(y)), layer));
  }
  const __m128 s = _mm_mul_ps(t, _mm_set1_ps(a.last)), snap = _mm_set1_ps(a.snap);
  const __m128i i = _mm_cvttps_epi32(_mm_add_ps(s, snap));
  const __m128 frac = _mm_sub_ps(s, _mm_cvtepi32_ps(i));
  const __m128 inside = _mm_cmpgt_ps(frac, snap);
  alignas(16) int index[4];
  alignas(16) float f[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(index), i);
  _mm_store_ps(f, _mm_and_ps(inside, frac));
  const int mask = _mm_movemask_ps(inside);
  for (int k = 0; k < 4; ++k) {
    cells[k].offset = static_cast<std::size_t>(index[k]) * a.stride;
    cells[k].step = (mask >> k) & 1 ? a.stride : 0;
    cells[k].f = f[k];
  }
#else
  for (int k = 0; k < 4; ++k) cells[k] = floatCellAt(a, x[k * stride], c[k]);
#endif
}

/// Axes 0 and 1 of a table for floatCellsLayerSqrt: their FloatAxis and their constants
/// packed in lanes (lane d: axis d), so that a lookup loads each pair at once.
struct FloatAxisPair {
  alignas(16) double lo[2] = {0.0, 0.0};
  alignas(16) double invRange[2] = {1.0, 1.0};
  alignas(16) float scale[4] = {};  ///< (N_0 - 1) / 2 (the warp's halving folded in), N_1 - 1
  alignas(16) float snap[4] = {};
  double rLo = 0.0, rHi = 1.0;  ///< axis 1's range, for the layer scale
  std::size_t stride[2] = {};   ///< node strides in floats
  bool unit = false;            ///< both axes span [0, 1]: y = x, r = y1, no normalization
  FloatAxis axis[2] = {};
};

/// The FloatAxisPair of axes a0 and a1, a1 spanning [rLo, rHi] (the range of the layer
/// scale's r).
inline FloatAxisPair floatAxisPair(const FloatAxis& a0, const FloatAxis& a1, double rLo,
                                   double rHi) noexcept {
  FloatAxisPair p;
  p.axis[0] = a0;
  p.axis[1] = a1;
  for (int d = 0; d < 2; ++d) {
    p.lo[d] = p.axis[d].lo;
    p.invRange[d] = p.axis[d].invRange;
    p.snap[d] = p.axis[d].snap;
    p.stride[d] = p.axis[d].stride;
  }
  p.scale[0] = 0.5f * a0.last;  // exact: a power-of-two scaling
  p.scale[1] = a1.last;
  p.rLo = rLo;
  p.rHi = rHi;
  p.unit = a0.lo == 0.0 && a0.invRange == 1.0 && a1.lo == 0.0 && a1.invRange == 1.0 && rLo == 0.0 &&
           rHi == 1.0;
  return p;
}

/// The cells of one point on axes 0 and 1 when axis 0 has the root4-layer warp and axis 1 the
/// sqrt warp (the catalogue's common form: mu, sqrt roughness), the layer scale taken from
/// x[1]: the same floats as floatLayerScale and floatCellAt on each axis. With SSE2 both
/// normalizations (none on [0, 1] axes: (x - 0) * 1 is x), the square roots of y0 and y1
/// and both cells share 2 lanes (3 square roots in 2 ops); on [0, 1] axes the layer scale's
/// r is y1; the warp's halving is folded into axis 0's N - 1 (a power-of-two scaling, exact,
/// so the same floats). One branch, on the collapsed layer (r = 0), kept off the arithmetic's
/// path to the division; none on the cells.
KILN_INLINE void floatCellsLayerSqrt(const FloatAxisPair& a, const double* x, FloatCell& k0,
                                     FloatCell& k1) noexcept {
#ifdef KILN_FLOAT_PATH_SSE2
  const __m128d xd = _mm_loadu_pd(x);
  const __m128d yd =
      a.unit ? xd : _mm_mul_pd(_mm_sub_pd(xd, _mm_load_pd(a.lo)), _mm_load_pd(a.invRange));
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  // maxps gives its second operand when the first is NaN: NaN maps to 0, as floatNormalized.
  const __m128 y = _mm_min_ps(_mm_max_ps(_mm_cvtpd_ps(yd), zero), one);
  // The layer scale c of floatLayerScale (lane 0): r clamped and rounded to float, squared,
  // at least kFloatLayerScaleFloor; c = 0 (where the layer is 1) when the clamped r is 0.
  __m128 r;
  bool layered;
  if (a.unit) {
    r = _mm_shuffle_ps(y, y, _MM_SHUFFLE(1, 1, 1, 1));  // r clamped to [0, 1] and rounded: y1
    layered = x[1] > 0.0;  // a positive r below the least float is not 0; NaN fails
  } else {
    // maxsd gives its second operand for a NaN: lo.
    const __m128d rc =
        _mm_min_sd(_mm_max_sd(_mm_unpackhi_pd(xd, xd), _mm_load_sd(&a.rLo)), _mm_load_sd(&a.rHi));
    r = _mm_cvtsd_ss(zero, rc);
    layered = _mm_cvtsd_f64(rc) != 0.0;
  }
  const __m128 root = _mm_sqrt_ps(y);  // lane 0: sqrt(y0), lane 1: t1 = sqrt(y1)
  // Lane 0 of each: the layer y0 (1 + c) / (y0 + c) as floatWarped (c > 0: y0 + c > 0), 1
  // at c = 0.
  __m128 layer = one;
  if (layered) {
    const __m128 c = _mm_max_ss(_mm_mul_ss(r, r), _mm_set_ss(kFloatLayerScaleFloor));
    layer = _mm_div_ss(_mm_mul_ss(y, _mm_add_ss(one, c)), _mm_add_ss(y, c));
  }
  // lane 0: 2 t0 = y0^(1/4) + layer, lane 1: t1.
  const __m128 t = _mm_add_ss(_mm_sqrt_ss(root), layer);
  const __m128 s = _mm_mul_ps(t, _mm_load_ps(a.scale)), snap = _mm_load_ps(a.snap);
  const __m128i i = _mm_cvttps_epi32(_mm_add_ps(s, snap));
  const __m128 frac = _mm_sub_ps(s, _mm_cvtepi32_ps(i));
  const __m128 inside = _mm_cmpgt_ps(frac, snap);
  const __m128 f = _mm_and_ps(inside, frac);
  const unsigned mask = static_cast<unsigned>(_mm_movemask_ps(inside));
  // The node indices (>= 0: t >= 0), unsigned, so no sign extension.
#if defined(__x86_64__) || defined(_M_X64)
  const std::uint64_t both = static_cast<std::uint64_t>(_mm_cvtsi128_si64(i));  // lanes 0, 1
  const std::uint32_t i0 = static_cast<std::uint32_t>(both),
                      i1 = static_cast<std::uint32_t>(both >> 32);
#else
  const std::uint32_t i0 = static_cast<std::uint32_t>(_mm_cvtsi128_si32(i));
  const std::uint32_t i1 = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_srli_si128(i, 4)));
#endif
  k0.offset = static_cast<std::size_t>(i0) * a.stride[0];
  k1.offset = static_cast<std::size_t>(i1) * a.stride[1];
  k0.step = a.stride[0] & (std::size_t{0} - (mask & 1u));
  k1.step = a.stride[1] & (std::size_t{0} - ((mask >> 1) & 1u));
  k0.f = _mm_cvtss_f32(f);
  k1.f = _mm_cvtss_f32(_mm_shuffle_ps(f, f, 1));
#else
  const float c = floatLayerScale(a.rLo, a.rHi, x[1]);
  k0 = floatCellAt(a.axis[0], x[0], c);
  k1 = floatCellAt(a.axis[1], x[1], c);
#endif
}

/// a - f (a - b) = (1 - f) a + f b: a exactly where a == b (a constant stretch of a table,
/// and every node: FloatCell::step = 0 there, so b is a itself), -0 included.
KILN_INLINE float floatLerp(float a, float b, float f) noexcept { return a - f * (a - b); }

#ifdef KILN_FLOAT_PATH_SSE2
/// The 2 floats at p (channels 0 and 1 of a texel) in lanes 0 and 1.
KILN_INLINE __m128 floatLoad2(const float* p) noexcept {
  return _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(p)));
}

/// floatLerp on each lane: a - f (a - b), the same IEEE operations.
KILN_INLINE __m128 floatLerp4(__m128 a, __m128 b, __m128 f) noexcept {
  return _mm_sub_ps(a, _mm_mul_ps(f, _mm_sub_ps(a, b)));
}
#endif

/// The interpolation of 2 channels (the texels at p, nodes s0 apart on axis 0, s1 on axis 1,
/// s2 on axis 2; D axes) with fractions f0, f1, f2 to out[0..1]: floatLerp along axis 0, then
/// 1, then 2, both channels at once on SSE2 lanes (the same floats as one channel after the
/// other).
template <int D>
KILN_INLINE void floatTaps2(const float* p, std::size_t s0, std::size_t s1, std::size_t s2,
                            float f0, float f1, float f2, float* out) noexcept {
#ifdef KILN_FLOAT_PATH_SSE2
  const __m128 g0 = _mm_set1_ps(f0), g1 = _mm_set1_ps(f1);
  __m128 v = floatLerp4(floatLoad2(p), floatLoad2(p + s0), g0);
  if (D >= 2) v = floatLerp4(v, floatLerp4(floatLoad2(p + s1), floatLoad2(p + s1 + s0), g0), g1);
  if (D >= 3) {
    const float* q = p + s2;
    const __m128 w = floatLerp4(floatLerp4(floatLoad2(q), floatLoad2(q + s0), g0),
                                floatLerp4(floatLoad2(q + s1), floatLoad2(q + s1 + s0), g0), g1);
    v = floatLerp4(v, w, _mm_set1_ps(f2));
  }
  _mm_store_sd(reinterpret_cast<double*>(out), _mm_castps_pd(v));
#else
  for (int ch = 0; ch < 2; ++ch) {
    float v = floatLerp(p[ch], p[s0 + ch], f0);
    if (D >= 2) v = floatLerp(v, floatLerp(p[s1 + ch], p[s1 + s0 + ch], f0), f1);
    if (D >= 3) {
      const float* q = p + s2;
      const float w = floatLerp(floatLerp(q[ch], q[s0 + ch], f0),
                                floatLerp(q[s1 + ch], q[s1 + s0 + ch], f0), f1);
      v = floatLerp(v, w, f2);
    }
    out[ch] = v;
  }
#endif
}

}  // namespace detail
}  // namespace kiln
