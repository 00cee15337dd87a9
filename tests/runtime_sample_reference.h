// The generic-stencil lookup of LutView::sample as it was before the prepared sampler
// (LutSampler): a stencil of nodes and double weights per axis from Axis::texel, summed over
// the product grid. Kept, unchanged in arithmetic, as the reference the fast paths are
// compared against (tests/runtime_sampler_fast_path.cpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "kiln/lut.h"

namespace kiln::test {

/// Nodes and weights one axis contributes to a reference lookup (at most 4).
struct ReferenceStencil {
  int index[4] = {0, 0, 0, 0};
  double weight[4] = {1.0, 0.0, 0.0, 0.0};
  int count = 1;
};

/// The stencil of axis `a` at x (layer scale c, split as LutView::layerScaleAt/splitAt).
inline ReferenceStencil MakeReferenceStencil(const Axis& a, double x, Filter filter, double c,
                                             double split) {
  ReferenceStencil st;
  const int n = a.size;
  if (n <= 1) return st;
  const double s = a.texel(x, c, split);
  int i = static_cast<int>(std::floor(s));
  if (i > n - 2) i = n - 2;
  if (i < 0) i = 0;
  const double f = s - static_cast<double>(i);
  if (filter == Filter::Linear || n < 3) {
    st.count = 2;
    st.index[0] = i;
    st.index[1] = i + 1;
    st.weight[0] = 1.0 - f;
    st.weight[1] = f;
    return st;
  }
  double wm1 = 0.5 * (((-f + 2.0) * f - 1.0) * f);
  double w0 = 0.5 * ((3.0 * f - 5.0) * f * f + 2.0);
  double w1 = 0.5 * (((-3.0 * f + 4.0) * f + 1.0) * f);
  double w2 = 0.5 * ((f - 1.0) * f * f);
  if (i == 0) {
    w0 += 3.0 * wm1;
    w1 -= 3.0 * wm1;
    w2 += wm1;
    wm1 = 0.0;
  }
  if (i == n - 2) {
    w1 += 3.0 * w2;
    w0 -= 3.0 * w2;
    wm1 += w2;
    w2 = 0.0;
  }
  st.count = 0;
  const int idx[4] = {i - 1, i, i + 1, i + 2};
  const double wts[4] = {wm1, w0, w1, w2};
  for (int k = 0; k < 4; ++k) {
    if (idx[k] < 0 || idx[k] > n - 1) continue;
    st.index[st.count] = idx[k];
    st.weight[st.count] = wts[k];
    ++st.count;
  }
  return st;
}

/// The reference lookup: every channel of view v at x, written to out (zeros when invalid).
inline void ReferenceSample(const LutView& v, const double* x, float* out, Filter filter) {
  if (!v.valid()) {
    for (int c = 0; c < v.channels; ++c) out[c] = 0.0f;
    return;
  }
  ReferenceStencil stencil[3];
  const double scale = v.layerScaleAt(x), split = v.splitAt(x);
  for (int d = 0; d < v.dims; ++d)
    stencil[d] = MakeReferenceStencil(v.axis[d], x[d], filter, scale, split);
  const std::size_t n0 = static_cast<std::size_t>(v.size(0));
  const std::size_t n1 = static_cast<std::size_t>(v.size(1));
  const std::size_t nc = static_cast<std::size_t>(v.channels);
  for (int c = 0; c < v.channels; ++c) {
    double sum = 0.0;
    bool started = false;
    for (int k2 = 0; k2 < stencil[2].count; ++k2) {
      for (int k1 = 0; k1 < stencil[1].count; ++k1) {
        const double w21 = stencil[2].weight[k2] * stencil[1].weight[k1];
        if (w21 == 0.0) continue;
        const std::size_t row = (static_cast<std::size_t>(stencil[2].index[k2]) * n1 +
                                 static_cast<std::size_t>(stencil[1].index[k1])) *
                                n0 * nc;
        for (int k0 = 0; k0 < stencil[0].count; ++k0) {
          const double w = w21 * stencil[0].weight[k0];
          if (w == 0.0) continue;
          const double val =
              static_cast<double>(v.data[row + static_cast<std::size_t>(stencil[0].index[k0]) * nc +
                                         static_cast<std::size_t>(c)]);
          sum = started ? sum + w * val : w * val;
          started = true;
        }
      }
    }
    const double fmax = static_cast<double>(std::numeric_limits<float>::max());
    if (sum > fmax) sum = fmax;
    if (sum < -fmax) sum = -fmax;
    out[c] = static_cast<float>(sum);
  }
}

}  // namespace kiln::test
