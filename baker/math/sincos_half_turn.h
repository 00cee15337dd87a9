// sin and cos of an azimuth on the half turn [0, pi] (the adaptive references' inner variable),
// by Cody-Waite reduction to [-pi/4, pi/4] and Taylor polynomials: no libm call per node.
#pragma once
#include <cmath>

#include "baker/math/constants.h"
#include "baker/math/vec3.h"

namespace kiln {

/// sin and cos of one angle.
struct SinCos {
  double sin, cos;
};

namespace sincos_detail {
/// pi / 2 - HalfPi (the low part of pi / 2 for the Cody-Waite reduction).
constexpr double kHalfPiLo = 6.123233995736766e-17;
/// Taylor coefficients of sin(x) = x + x^3 sum_k kSin[k] x^(2k) (x^3 .. x^17; the first term
/// left out is below 1e-19 on |x| <= pi/4) and cos(x) = 1 + x^2 sum_k kCos[k] x^(2k) (x^2 ..
/// x^16; below 2.1e-18): each n! is exact in double, so each coefficient is 1 / n! rounded once.
constexpr double kSin[8] = {
    -1.0 / 6,        1.0 / 120,        -1.0 / 5040,          1.0 / 362880,
    -1.0 / 39916800, 1.0 / 6227020800, -1.0 / 1307674368000, 1.0 / 355687428096000};
constexpr double kCos[8] = {
    -1.0 / 2,       1.0 / 24,        -1.0 / 720,         1.0 / 40320,
    -1.0 / 3628800, 1.0 / 479001600, -1.0 / 87178291200, 1.0 / 20922789888000};
}  // namespace sincos_detail

/// sin(phi) and cos(phi) for phi in [0, pi] (every azimuth the adaptive references visit), within
/// 2 ulp of std::sin and std::cos there and on all of (-pi/4, 5pi/4), whose slack covers a
/// Gauss-Kronrod node rounded past an end (tests/math_sincos_half_turn.cpp); outside that range,
/// and for NaN, it is std::sin and std::cos. phi is reduced to x = phi - k pi/2 in [-pi/4, pi/4]
/// with pi/2 in two parts (phi - k HalfPi is exact there, Sterbenz), so a result near 0 (phi
/// near 0, pi/2 or pi) keeps its relative precision; then Horner in x^2 (two independent chains).
inline SinCos SinCosHalfTurn(double phi) {
  using namespace sincos_detail;
  if (!(phi > -Pi / 4 && phi < Pi + Pi / 4)) return {std::sin(phi), std::cos(phi)};
  const int k = (phi >= Pi / 4) + (phi >= 3 * Pi / 4);  // the quarter turn nearest phi
  const double x = (phi - k * HalfPi) - k * kHalfPiLo, x2 = x * x;
  // Horner written out: GCC keeps the loop form rolled, at twice the instructions.
  const double ps =
      kSin[0] +
      x2 *
          (kSin[1] +
           x2 * (kSin[2] +
                 x2 * (kSin[3] + x2 * (kSin[4] + x2 * (kSin[5] + x2 * (kSin[6] + x2 * kSin[7]))))));
  const double pc =
      kCos[0] +
      x2 *
          (kCos[1] +
           x2 * (kCos[2] +
                 x2 * (kCos[3] + x2 * (kCos[4] + x2 * (kCos[5] + x2 * (kCos[6] + x2 * kCos[7]))))));
  const double s = x + x * x2 * ps, c = 1 + x2 * pc;
  // Selects, not branches: a panel's nodes alternate about its centre, across pi/4 or 3pi/4.
  const double sign = k == 2 ? -1.0 : 1.0;
  const double sinPhi = k == 1 ? c : s, cosPhi = k == 1 ? -s : c;
  return {sign * sinPhi, sign * cosPhi};
}

/// The unit vector at polar angle theta (given by its sine and cosine) and azimuth phi in
/// [0, pi]: SphericalDirection (vec3.h) with SinCosHalfTurn's sine and cosine.
inline Vec3 SphericalDirectionHalfTurn(double sinTheta, double cosTheta, double phi) {
  const SinCos sc = SinCosHalfTurn(phi);
  return {sinTheta * sc.cos, sinTheta * sc.sin, cosTheta};
}

}  // namespace kiln
