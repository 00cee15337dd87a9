// Burley 2012 "Physically-Based Shading at Disney" diffuse, and Lagarde & de Rousiers 2014
// "Moving Frostbite to PBR" renormalised variant (seed 000 §4, §4.1).
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// Schlick-shaped retro-reflection factor 1 + (F_D90 - 1)(1 - mu)^5.
inline double DisneyDiffuseFresnel(double fd90, double mu) { return 1 + (fd90 - 1) * Pow5(1 - mu); }

/// Disney diffuse: f = rho/pi (1 + (F_D90 - 1)(1 - mu_l)^5)(1 + (F_D90 - 1)(1 - mu_o)^5),
/// F_D90 = 0.5 + 2 r cos^2(theta_d), r = roughness as is. Reciprocal, not energy conserving.
/// (The seed's GLSL passes SchlickFresnel's arguments out of order; this is the model.)
struct BurleyDiffuse {
  static constexpr const char* kId = "burley";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double roughness = 0.5, rho = 1;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double cos2Theta_d = (1 + g.ol) / 2;  // l.h = cos(theta_d), h the half vector
    double fd90 = 0.5 + 2 * roughness * cos2Theta_d;
    return {InvPi * DisneyDiffuseFresnel(fd90, g.mu_l) * DisneyDiffuseFresnel(fd90, g.mu_o), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// Frostbite: energyBias = lerp(0, 0.5, r), energyFactor = lerp(1, 1/1.51, r),
/// F_D90 = energyBias + 2 r cos^2(theta_d), f = rho/pi energyFactor F_L F_V.
struct FrostbiteDiffuse {
  static constexpr const char* kId = "frostbite";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double roughness = 0.5, rho = 1;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double energyBias = Lerp(roughness, 0.0, 0.5);
    double energyFactor = Lerp(roughness, 1.0, 1 / 1.51);
    double fd90 = energyBias + 2 * roughness * (1 + g.ol) / 2;
    return {InvPi * energyFactor * DisneyDiffuseFresnel(fd90, g.mu_l) *
                DisneyDiffuseFresnel(fd90, g.mu_o),
            0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
