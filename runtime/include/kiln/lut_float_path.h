// kiln/lut_float_path.h: the float arithmetic of LutSampler's fast linear lookups (kiln/lut.h)
// on the axes whose warp is linear, sqrt, root4 or root4-layer: the warp, the cell and the
// interpolation in float, branch-free but for the choice of warp.
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

#include "kiln/lut_inline.h"

namespace kiln {
namespace detail {

/// The warps the float path computes (see kiln::Warp): t = y, sqrt(y), y^(1/4), and the
/// root4-layer warp (y^(1/4) + y (1 + c) / (y + c)) / 2 with its collapsed form at c = 0.
enum class FloatWarp { Linear, Sqrt, Root4, Root4Layer };

/// Half-width, in warped units t, of the band around a node inside which the float path
/// snaps onto the node: 16 float ulps of 1, four times the float warps' largest error.
constexpr float kFloatNodeSnap = 0x1p-20f;

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

/// The root4-layer scale of kiln::layerScale in float, branch-free: r clamped to [lo, hi]
/// (NaN maps to lo), c = max(r^2, 1e-12) for r != 0 and c = 0 at r = 0 exactly.
KILN_INLINE float floatLayerScale(double lo, double hi, double r) noexcept {
  const double low = r > lo ? r : lo;  // NaN fails the comparison: lo
  const double rc = low < hi ? low : hi;
  const float c = static_cast<float>(rc * rc);
  const float floor = c < 1e-12f ? 1e-12f : c;
  return rc == 0.0 ? 0.0f : floor;
}

/// (1 - f) a + f b: a exactly at f = 0 (b is then a itself, FloatCell::step = 0).
KILN_INLINE float floatLerp(float a, float b, float f) noexcept { return (1.0f - f) * a + f * b; }

}  // namespace detail
}  // namespace kiln
