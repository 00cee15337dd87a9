// Minimal 3-vector and shading-frame helpers (pbrt-v4 conventions: normal n = +z).
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/math/constants.h"

namespace kiln {

/// A direction or point in the shading frame; the surface normal is (0, 0, 1).
struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double Dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double Length(Vec3 a) { return std::sqrt(Dot(a, a)); }
/// Unit vector along a; returns (0,0,0) for a zero vector (never NaN).
inline Vec3 Normalize(Vec3 a) {
  double len = Length(a);
  return len > 0 ? (1.0 / len) * a : Vec3{};
}

/// sqrt that returns 0 for the tiny negative arguments rounding produces.
inline double SafeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }
inline double Sqr(double x) { return x * x; }
inline double Pow5(double x) {
  double x2 = x * x;
  return x2 * x2 * x;
}
inline double Clamp(double x, double lo, double hi) { return std::min(hi, std::max(lo, x)); }
inline double Lerp(double t, double a, double b) { return a + t * (b - a); }

inline double CosTheta(Vec3 w) { return w.z; }
inline double Sin2Theta(Vec3 w) { return std::max(0.0, w.x * w.x + w.y * w.y); }
inline double SinTheta(Vec3 w) { return std::sqrt(Sin2Theta(w)); }
/// tan^2(theta) of w; +inf on the horizon.
inline double Tan2Theta(Vec3 w) { return Sin2Theta(w) / Sqr(w.z); }

/// The direction with polar angle theta (given by its sine and cosine) and azimuth phi.
inline Vec3 SphericalDirection(double sinTheta, double cosTheta, double phi) {
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

/// The view direction wo at cos(theta_o) = mu, azimuth 0 (in the xz plane).
inline Vec3 ViewDirection(double mu) {
  mu = Clamp(mu, -1.0, 1.0);
  return {SafeSqrt(1 - mu * mu), 0, mu};
}

/// Direction from the BRDF's angular arguments: cos(theta) and the azimuth phi.
inline Vec3 DirectionFromMuPhi(double mu, double phi) {
  mu = Clamp(mu, -1.0, 1.0);
  return SphericalDirection(SafeSqrt(1 - mu * mu), mu, phi);
}

/// Mirror reflection of wo about the microfacet normal wm: 2 (wo.wm) wm - wo.
inline Vec3 Reflect(Vec3 wo, Vec3 wm) { return 2 * Dot(wo, wm) * wm - wo; }

}  // namespace kiln
