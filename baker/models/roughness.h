// Roughness conventions: Disney 2012 (alpha = r^2), Unity smoothness, pbrt-v3 RoughnessToAlpha,
// and the Blinn-Phong exponent matched to a microfacet alpha (Walter et al. 2007).
#pragma once
#include <algorithm>
#include <cmath>

namespace kiln {

/// Smallest alpha the integrators use: alpha = 0 is the mirror limit, taken as this.
constexpr double MinAlpha = 1e-12;

/// Microfacet alpha from perceptual roughness r in [0, 1] (Burley 2012): alpha = r^2.
inline double AlphaFromPerceptual(double r) { return r * r; }
/// Perceptual roughness from Unity's smoothness: r = 1 - smoothness.
inline double PerceptualFromUnitySmoothness(double smoothness) { return 1 - smoothness; }
/// pbrt-v3 RoughnessToAlpha: x = ln(max(r, 1e-3)), a quartic polynomial in x.
inline double PbrtV3RoughnessToAlpha(double r) {
  double x = std::log(std::max(r, 1e-3));
  return 1.62142 + 0.819955 * x + 0.1734 * x * x + 0.0171201 * x * x * x +
         0.000640711 * x * x * x * x;
}
/// Blinn-Phong exponent for a Beckmann-equivalent alpha: s = 2 / alpha^2 - 2 (docs/models.md 13).
inline double BlinnPhongExponentFromAlpha(double alpha) {
  alpha = std::max(alpha, MinAlpha);
  return std::max(0.0, 2 / (alpha * alpha) - 2);
}

}  // namespace kiln
