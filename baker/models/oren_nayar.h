// Oren & Nayar 1994 "Generalization of Lambert's Reflectance Model": the full approximation
// (with the interreflection term) and the qualitative model (seeds 000 §5.9-5.10, 002).
// sigma = r is the slope standard deviation in radians.
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// Full Oren-Nayar: f1 = rho/pi [C1 + cos(phi) C2 tan(beta) + (1 - |cos(phi)|) C3 tan((a+b)/2)],
/// f2 = 0.17 rho^2/pi s2/(s2 + 0.13) [1 - cos(phi) (2 beta/pi)^2]. alpha = max(theta_l, theta_o),
/// beta = min. f2 is quadratic in rho (RhoParts::quad). Seed 000 drops tan((a+b)/2) and a square.
struct OrenNayar {
  static constexpr const char* kId = "oren-nayar";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double sigma = 0.5, rho = 1;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double theta_o = g.ThetaO(), theta_l = g.ThetaL();
    double alpha = std::max(theta_o, theta_l), beta = std::min(theta_o, theta_l);
    double s2 = sigma * sigma, cosPhi = g.cosPhi;
    double C1 = 1 - 0.5 * s2 / (s2 + 0.33);
    double C2 = 0.45 * s2 / (s2 + 0.09) *
                (cosPhi >= 0 ? std::sin(alpha) : std::sin(alpha) - std::pow(2 * beta / Pi, 3));
    double C3 = 0.125 * s2 / (s2 + 0.09) * Sqr(4 * alpha * beta / (Pi * Pi));
    double f1 = InvPi * (C1 + cosPhi * C2 * std::tan(beta) +
                         (1 - std::abs(cosPhi)) * C3 * std::tan((alpha + beta) / 2));
    double f2 = 0.17 * InvPi * s2 / (s2 + 0.13) * (1 - cosPhi * Sqr(2 * beta / Pi));
    return {f1, f2};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// Qualitative Oren-Nayar: f = rho/pi (A + B max(0, cos(phi)) sin(alpha) tan(beta)),
/// A = 1 - 0.5 s2/(s2 + 0.33) (0.57 with interreflection compensation), B = 0.45 s2/(s2 + 0.09).
struct OrenNayarQualitative {
  static constexpr const char* kId = "oren-nayar-qualitative";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double sigma = 0.5, rho = 1;
  bool interreflection = false;  ///< the "-ir" variant: A uses 0.57

  double A() const {
    double s2 = sigma * sigma;
    return 1 - 0.5 * s2 / (s2 + (interreflection ? 0.57 : 0.33));
  }
  double B() const {
    double s2 = sigma * sigma;
    return 0.45 * s2 / (s2 + 0.09);
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double theta_o = g.ThetaO(), theta_l = g.ThetaL();
    double alpha = std::max(theta_o, theta_l), beta = std::min(theta_o, theta_l);
    return {InvPi * (A() + B() * std::max(0.0, g.cosPhi) * std::sin(alpha) * std::tan(beta)), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
