// Hammon 2017 "PBR Diffuse Lighting for GGX+Smith Microsurfaces" (seed 000 §6).
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// facing = 0.5 + 0.5 l.o, rough = facing (0.9 - 0.4 facing)(0.5 + n.h)/(n.h),
/// smooth = 1.05 (1 - (1 - mu_l)^5)(1 - (1 - mu_o)^5), single = (1/pi) lerp(smooth, rough, alpha),
/// multi = 0.1159 alpha, f = rho (single + rho multi). alpha = GGX alpha (= r^2).
struct HammonDiffuse {
  static constexpr const char* kId = "hammon";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double alpha = 0.25, rho = 1;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double facing = 0.5 + 0.5 * g.ol;
    double len = Length(wo + wi);
    // n.h -> 0 only with both directions on the horizon; 1e-12 keeps that corner finite.
    double nh = len > 0 ? std::max((g.mu_o + g.mu_l) / len, 1e-12) : 1e-12;
    double rough = facing > 0 ? facing * (0.9 - 0.4 * facing) * (0.5 + nh) / nh : 0;
    double smooth = 1.05 * (1 - Pow5(1 - g.mu_l)) * (1 - Pow5(1 - g.mu_o));
    return {InvPi * Lerp(alpha, smooth, rough), 0.1159 * alpha};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
