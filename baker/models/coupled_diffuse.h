// Diffuse lobes coupled to a specular layer (seed 004): Shirley et al. 1997, Ashikhmin & Shirley
// 2000, and tri-Ace's energy-conserving Lambert (Gotanda 2010).
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// Shirley 1997: f = 21/(20 pi) rho (1 - F0)(1 - (1 - mu_l)^5)(1 - (1 - mu_o)^5).
struct ShirleyDiffuse {
  static constexpr const char* kId = "shirley";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double rho = 1, f0 = 0;
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (wo.z < 0 || wi.z < 0) return {};
    return {21.0 / (20.0 * Pi) * (1 - f0) * (1 - Pow5(1 - wi.z)) * (1 - Pow5(1 - wo.z)), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// Ashikhmin-Shirley 2000: f = 28 rho/(23 pi) (1 - R_s)(1 - (1 - mu_l/2)^5)(1 - (1 - mu_o/2)^5).
/// Exact: E(mu) = rho (1 - R_s)(1 - (1 - mu/2)^5).
struct AshikhminShirleyDiffuse {
  static constexpr const char* kId = "ashikhmin-shirley-diffuse";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double rho = 1, rs = 0;
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (wo.z < 0 || wi.z < 0) return {};
    return {28.0 / (23.0 * Pi) * (1 - rs) * (1 - Pow5(1 - wi.z / 2)) * (1 - Pow5(1 - wo.z / 2)), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// tri-Ace: f = rho/pi (1 - R_s (F0 + (1 - F0)(1 - mu_l)^5)). Depends on mu_l only: not
/// reciprocal. Exact: E = rho (1 - R_s (F0 + (1 - F0)/21)).
struct TriAceLambert {
  static constexpr const char* kId = "triace-lambert";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double rho = 1, rs = 0, f0 = 0;
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (wo.z < 0 || wi.z < 0) return {};
    return {InvPi * (1 - rs * (f0 + (1 - f0) * Pow5(1 - wi.z))), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// Lambert: f = rho / pi. Exact: E = rho.
struct Lambert {
  static constexpr const char* kId = "lambert";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double rho = 1;
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (wo.z < 0 || wi.z < 0) return {};
    return {InvPi, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
