// Fresnel reflectance: exact dielectric and conductor (Born & Wolf; pbrt-v4 util/scattering.h),
// Schlick's approximation (Schlick 1994) and F0 from the index of refraction.
#pragma once
#include <algorithm>
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
  // cos^2(theta_t) = 1 - sin^2(theta_i) / eta^2 = (cos^2(theta_i) + eta^2 - 1) / eta^2, and the
  // numerators of r_perp and r_parl multiplied by their conjugates, so that nothing cancels at
  // grazing incidence with eta near 1 (where the textbook 1 - (1 - mu^2) / eta^2 loses mu^2
  // below the rounding of 1 and reports total internal reflection at eta = 1):
  //   r_perp = (1 - eta^2) / (cos_i + eta cos_t)^2,
  //   r_parl = (eta^2 - 1) ((eta^2 + 1) cos_i^2 - 1) / (eta^2 (eta cos_i + cos_t)^2).
  double eta2m1 = (eta - 1) * (eta + 1);
  double cos2Theta_t = (Sqr(cosTheta_i) + eta2m1) / Sqr(eta);
  if (cos2Theta_t <= 0) return 1.0;  // total internal reflection (and grazing incidence)
  double cosTheta_t = std::sqrt(cos2Theta_t);
  double r_perp = -eta2m1 / Sqr(cosTheta_i + eta * cosTheta_t);
  double r_parl = eta2m1 * ((Sqr(eta) + 1) * Sqr(cosTheta_i) - 1) /
                  (Sqr(eta) * Sqr(eta * cosTheta_i + cosTheta_t));
  return std::min(1.0, (Sqr(r_parl) + Sqr(r_perp)) / 2);  // |r| = 1 may round to 1 + 2^-52
}

/// Unpolarized Fresnel reflectance of a conductor with complex index eta = n + i k (k >= 0;
/// the sign of k does not change the result). R = (|r_s|^2 + |r_p|^2) / 2, seed 004.
/// cosTheta_i is clamped to [0, 1]. k = 0 reduces to FrDielectric (TIR included).
inline double FrComplex(double cosTheta_i, double n, double k) {
  using C = std::complex<double>;
  cosTheta_i = Clamp(cosTheta_i, 0.0, 1.0);
  C eta(n, k);
  // The cancellation-free forms of FrDielectric, which hold for a complex eta as well.
  C eta2 = eta * eta, eta2m1 = (eta - 1.0) * (eta + 1.0);
  C cosTheta_t = std::sqrt((Sqr(cosTheta_i) + eta2m1) / eta2);
  C r_perp = -eta2m1 / ((cosTheta_i + eta * cosTheta_t) * (cosTheta_i + eta * cosTheta_t));
  C r_parl = eta2m1 * ((eta2 + 1.0) * Sqr(cosTheta_i) - 1.0) /
             (eta2 * (eta * cosTheta_i + cosTheta_t) * (eta * cosTheta_i + cosTheta_t));
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
      case Kind::One:
        return 1.0;
      case Kind::Schlick:
        return FrSchlick(f0, cosTheta_d);
      case Kind::Dielectric:
        return FrDielectric(cosTheta_d, eta);
      case Kind::Conductor:
        return FrComplex(cosTheta_d, eta, k);
    }
    return 1.0;
  }
};

}  // namespace kiln
