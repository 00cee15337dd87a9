// Fresnel reflectance: exact dielectric and conductor (Born & Wolf; pbrt-v4 util/scattering.h),
// Schlick's approximation (Schlick 1994) and F0 from the index of refraction.
#pragma once
#include <complex>

#include "baker/math/vec3.h"

namespace kiln {

/// Unpolarized Fresnel reflectance of a dielectric interface.
/// cosTheta_i: cosine of the incident angle (negative means from the other side, eta is then
/// inverted); eta: relative index n_t / n_i. Total internal reflection returns 1.
inline double FrDielectric(double cosTheta_i, double eta) {
  cosTheta_i = Clamp(cosTheta_i, -1.0, 1.0);
  if (cosTheta_i < 0) {
    eta = 1 / eta;
    cosTheta_i = -cosTheta_i;
  }
  double sin2Theta_i = 1 - Sqr(cosTheta_i);
  double sin2Theta_t = sin2Theta_i / Sqr(eta);
  if (sin2Theta_t >= 1) return 1.0;
  double cosTheta_t = SafeSqrt(1 - sin2Theta_t);
  double r_parl = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
  double r_perp = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
  return (Sqr(r_parl) + Sqr(r_perp)) / 2;
}

/// Unpolarized Fresnel reflectance of a conductor with complex index eta = n + i k (k >= 0;
/// the sign of k does not change the result). R = (|r_s|^2 + |r_p|^2) / 2, seed 004.
/// cosTheta_i is clamped to [0, 1]. k = 0 reduces to FrDielectric (TIR included).
inline double FrComplex(double cosTheta_i, double n, double k) {
  using C = std::complex<double>;
  cosTheta_i = Clamp(cosTheta_i, 0.0, 1.0);
  C eta(n, k);
  double sin2Theta_i = 1 - Sqr(cosTheta_i);
  C sin2Theta_t = sin2Theta_i / (eta * eta);
  C cosTheta_t = std::sqrt(1.0 - sin2Theta_t);
  C r_parl = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
  C r_perp = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
  double R = (std::norm(r_parl) + std::norm(r_perp)) / 2;
  return std::isfinite(R) ? Clamp(R, 0.0, 1.0) : 1.0;
}

/// Schlick's approximation F0 + (1 - F0)(1 - cos)^5; cos clamped to [0, 1].
inline double FrSchlick(double f0, double cosTheta) {
  return f0 + (1 - f0) * Pow5(1 - Clamp(cosTheta, 0.0, 1.0));
}

/// Normal-incidence reflectance |(1 - eta) / (1 + eta)|^2 of a complex index n + i k.
inline double F0FromEta(double n, double k = 0) {
  return (Sqr(1 - n) + Sqr(k)) / (Sqr(1 + n) + Sqr(k));
}

/// Which Fresnel term a specular lobe uses. One: F = 1 (the albedo tables' convention).
struct Fresnel {
  enum class Kind { One, Schlick, Dielectric, Conductor };
  Kind kind = Kind::One;
  double f0 = 1;   ///< Schlick's F0
  double eta = 1;  ///< real part of the relative index (Dielectric, Conductor)
  double k = 0;    ///< imaginary part (Conductor)

  /// F at cos(theta_d) = o.h.
  double operator()(double cosTheta_d) const {
    switch (kind) {
      case Kind::One: return 1.0;
      case Kind::Schlick: return FrSchlick(f0, cosTheta_d);
      case Kind::Dielectric: return FrDielectric(cosTheta_d, eta);
      case Kind::Conductor: return FrComplex(cosTheta_d, eta, k);
    }
    return 1.0;
  }
};

}  // namespace kiln
