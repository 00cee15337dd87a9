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

  /// The factors of Parts that depend on the polar angles alone (a row of constant theta_l of the
  /// diffuse fixed rule evaluates them once: PolarFactors, then PartsAt at each azimuth, the
  /// same operations as Parts, so the same bits).
  struct Polar {
    double C1, C2Front, C2Back, C3, tanBeta, tanMid, f2Scale, beta2;
  };
  /// Polar of g's theta_o and theta_l (g.mu_o and g.mu_l alone).
  Polar PolarFactors(const PairGeometry& g) const {
    double theta_o = g.ThetaO(), theta_l = g.ThetaL();
    double alpha = std::max(theta_o, theta_l), beta = std::min(theta_o, theta_l);
    double s2 = sigma * sigma;
    Polar p;
    p.C1 = 1 - 0.5 * s2 / (s2 + 0.33);
    p.C2Front = 0.45 * s2 / (s2 + 0.09) * std::sin(alpha);
    p.C2Back = 0.45 * s2 / (s2 + 0.09) * (std::sin(alpha) - std::pow(2 * beta / Pi, 3));
    p.C3 = 0.125 * s2 / (s2 + 0.09) * Sqr(4 * alpha * beta / (Pi * Pi));
    p.tanBeta = std::tan(beta);
    p.tanMid = std::tan((alpha + beta) / 2);
    p.f2Scale = 0.17 * InvPi * s2 / (s2 + 0.13);
    p.beta2 = Sqr(2 * beta / Pi);
    return p;
  }
  /// Parts at g (above the horizon) from its PolarFactors.
  RhoParts PartsAt(const Polar& p, const PairGeometry& g) const {
    double cosPhi = g.cosPhi, C2 = cosPhi >= 0 ? p.C2Front : p.C2Back;
    double f1 = InvPi * (p.C1 + cosPhi * C2 * p.tanBeta + (1 - std::abs(cosPhi)) * p.C3 * p.tanMid);
    double f2 = p.f2Scale * (1 - cosPhi * p.beta2);
    return {f1, f2};
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    return PartsAt(PolarFactors(g), g);
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
  /// The factors of Parts that depend on the polar angles alone (as OrenNayar::Polar).
  struct Polar {
    double A, B, sinAlpha, tanBeta;
  };
  /// Polar of g's theta_o and theta_l (g.mu_o and g.mu_l alone).
  Polar PolarFactors(const PairGeometry& g) const {
    double theta_o = g.ThetaO(), theta_l = g.ThetaL();
    double alpha = std::max(theta_o, theta_l), beta = std::min(theta_o, theta_l);
    return {A(), B(), std::sin(alpha), std::tan(beta)};
  }
  /// Parts at g (above the horizon) from its PolarFactors.
  RhoParts PartsAt(const Polar& p, const PairGeometry& g) const {
    return {InvPi * (p.A + p.B * std::max(0.0, g.cosPhi) * p.sinAlpha * p.tanBeta), 0};
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    return PartsAt(PolarFactors(g), g);
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
