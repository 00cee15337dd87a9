// Specification: hardware bilinear filtering fed with Axis::gpuCoord equals the
// CPU linear path. The emulation below is what a GPU does with a clamp-to-edge,
// linear-filtered texture (texel centres at (i + 0.5) / N), computed in double
// (real hardware quantizes the weights, see runtime/FORMAT.md), and the 3D path
// mirrors runtime/shaders/kiln_lut.glsl.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kiln/lut.h"

namespace {

using kiln::Axis;
using kiln::LutView;
using kiln::Warp;

/// A 2D texture of width x height texels, `channels` floats each, row 0 first.
struct Texture {
  const float* texels;
  int width;
  int height;
  int channels;

  float fetch(int x, int y, int c) const {
    x = x < 0 ? 0 : (x >= width ? width - 1 : x);  // clamp to edge
    y = y < 0 ? 0 : (y >= height ? height - 1 : y);
    return texels[(std::size_t(y) * width + x) * channels + c];
  }

  /// Bilinear filtering at normalized coordinates (u, v).
  double bilinear(double u, double v, int c) const {
    const double x = u * width - 0.5, y = v * height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    const int ix = int(fx), iy = int(fy);
    return (1 - ay) * ((1 - ax) * fetch(ix, iy, c) + ax * fetch(ix + 1, iy, c)) +
           ay * ((1 - ax) * fetch(ix, iy + 1, c) + ax * fetch(ix + 1, iy + 1, c));
  }
};

/// The shader's lookup: one bilinear fetch for 1D/2D, two blended fetches
/// from the stacked image for 3D (as kilnSample3D in kiln_lut.glsl).
double gpuSample(const LutView& lut, const double* x, int c) {
  const Texture tex{lut.data, lut.size(0), lut.size(1) * lut.size(2), lut.channels};
  // A root4-layer axis 0 follows axis 1's value (kilnLayerScale in the shader).
  const double u = lut.axis[0].gpuCoord(x[0], lut.layerScaleAt(x));
  if (lut.dims == 1) return tex.bilinear(u, 0.5, c);
  if (lut.dims == 2) return tex.bilinear(u, lut.axis[1].gpuCoord(x[1]), c);
  const int n1 = lut.size(1), n2 = lut.size(2);
  const double s1 = lut.axis[1].texel(x[1]);
  const double s2 = lut.axis[2].texel(x[2]);
  const double k0 = std::min(std::floor(s2), double(std::max(n2 - 2, 0)));
  const double f = s2 - k0;
  const double k1 = std::min(k0 + 1.0, double(n2 - 1));
  const double v0 = (k0 * n1 + 0.5 + s1) / (double(n1) * n2);
  const double v1 = (k1 * n1 + 0.5 + s1) / (double(n1) * n2);
  return (1 - f) * tex.bilinear(u, v0, c) + f * tex.bilinear(u, v1, c);
}

}  // namespace

TEST_CASE("hardware bilinear filtering at gpuCoord equals the CPU linear lookup",
          "[runtime][gpu]") {
  const Warp warps[] = {Warp::Linear, Warp::Sqrt,  Warp::Square,     Warp::Log,
                        Warp::Root4,  Warp::Angle, Warp::Root4Layer, Warp::LayerEta};
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (Warp warp : warps) {
    const double lo = warp == Warp::Log ? 0.05 : -0.5;
    const double hi = 2.0;
    std::vector<std::vector<Axis>> shapes = {
        {{lo, hi, 13, warp}},
        {{lo, hi, 9, warp}, {lo, hi, 6, warp}},
        {{lo, hi, 2, warp}, {lo, hi, 5, Warp::Linear}},
        {{lo, hi, 7, warp}, {lo, hi, 4, warp}, {lo, hi, 5, warp}},
        {{lo, hi, 3, Warp::Linear}, {lo, hi, 5, warp}, {lo, hi, 2, warp}},
    };
    if (warp == Warp::Root4Layer)  // only on axis 0, before a roughness-like axis 1
      shapes = {
          {{lo, hi, 9, warp}, {0.0, 1.0, 6, Warp::Sqrt}},
          {{lo, hi, 7, warp}, {0.0, 0.3, 4, Warp::Linear}, {lo, hi, 5, Warp::Linear}},
      };
    if (warp == Warp::LayerEta)  // only on axis 0, before an index axis 1 (eta = 1 inside)
      shapes = {
          {{lo, hi, 9, warp}, {1.0, 3.0, 6, Warp::Sqrt}},
          {{lo, hi, 7, warp}, {0.5, 2.0, 4, Warp::Linear}, {lo, hi, 5, Warp::Linear}},
      };
    for (const auto& axes : shapes) {
      LutView lut;
      lut.channels = 2;
      lut.dims = int(axes.size());
      for (std::size_t d = 0; d < axes.size(); ++d) lut.axis[d] = axes[d];
      std::vector<float> data(lut.valueCount());
      for (float& v : data) v = value(rng);
      lut.data = data.data();
      INFO("warp " << kiln::warpName(warp) << ", dims " << lut.dims);
      std::uniform_real_distribution<double> inside(lo - 0.3, hi + 0.3);  // some outside
      for (int k = 0; k < 400; ++k) {
        double x[3];
        for (int d = 0; d < lut.dims; ++d) x[d] = inside(rng);
        if (k < 8)  // the corners exactly
          for (int d = 0; d < lut.dims; ++d) x[d] = (k >> d) & 1 ? hi : lo;
        float cpu[2];
        lut.sample(x, cpu, kiln::Filter::Linear);
        for (int c = 0; c < 2; ++c) CHECK(gpuSample(lut, x, c) == Approx(cpu[c]).margin(1e-6));
      }
    }
  }
}

TEST_CASE("the emulated GPU lookup is not trivially equal: a half-texel shift is caught",
          "[runtime][gpu]") {
  // Guards the test above: sampling at t (N - 1) / N without the half-texel
  // offset, a classic mistake, must disagree with the CPU path.
  const Axis axis{0.0, 1.0, 8, Warp::Sqrt};
  std::vector<float> data = {0, 1, 4, 9, 16, 25, 36, 49};
  LutView lut;
  lut.data = data.data();
  lut.channels = 1;
  lut.dims = 1;
  lut.axis[0] = axis;
  const Texture tex{data.data(), 8, 1, 1};
  const double x = 0.3;
  float cpu;
  lut.sample(&x, &cpu);
  const double wrong = tex.bilinear(axis.warped(x) * 7.0 / 8.0, 0.5, 0);
  const double right = tex.bilinear(axis.gpuCoord(x), 0.5, 0);
  CHECK(right == Approx(cpu).margin(1e-6));
  CHECK(std::fabs(wrong - cpu) > 0.1);
}
