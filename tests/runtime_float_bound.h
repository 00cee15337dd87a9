// The accuracy LutSampler's float path promises (kiln/lut.h, kiln/lut_float_path.h): how far
// a linear lookup on the float path may lie from the double-arithmetic reference lookup.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "kiln/lut.h"

namespace kiln::test {

/// The largest |difference| of two neighbouring texels of channel c along axis d.
inline double NeighbourStep(const LutView& v, int d, int c) {
  double g = 0.0;
  const int n[3] = {v.size(0), v.size(1), v.size(2)};
  for (int i2 = 0; i2 < n[2]; ++i2)
    for (int i1 = 0; i1 < n[1]; ++i1)
      for (int i0 = 0; i0 < n[0]; ++i0) {
        int j[3] = {i0, i1, i2};
        if (++j[d] >= n[d]) continue;
        const double a = v.at(i0, i1, i2, c), b = v.at(j[0], j[1], j[2], c);
        g = std::fmax(g, std::fabs(b - a));
      }
  return g;
}

/// The float path's bound for channel c of view v: sum over the axes of
/// 2 kFloatNodeSnap (N_d - 1) G_d, plus kFloatLerpUlps ulps of the largest |texel|.
inline double FloatPathBound(const LutView& v, int c) {
  double bound = 0.0, vmax = 0.0;
  for (int d = 0; d < v.dims; ++d)
    bound += 2.0 * detail::kFloatNodeSnap * (v.size(d) - 1) * NeighbourStep(v, d, c);
  const std::size_t count = v.valueCount() / static_cast<std::size_t>(v.channels);
  for (std::size_t k = 0; k < count; ++k)
    vmax = std::fmax(vmax, std::fabs(v.data[k * static_cast<std::size_t>(v.channels) + c]));
  const float top = static_cast<float>(vmax);
  const double ulp = std::nextafter(top, std::numeric_limits<float>::infinity()) - top;
  return bound + detail::kFloatLerpUlps * ulp;
}

}  // namespace kiln::test
