// The interface every kiln BRDF value type keeps (pbrt-v4 bxdfs.h style), and the geometry
// of a pair of directions that the diffuse models share.
//
// Every model is a small value type with:
//   static constexpr const char* kId;              the CLI/table id
//   static constexpr IntegrationDomain kDomain;    how its integrals are taken (see integrate/)
//   RhoParts Parts(Vec3 wo, Vec3 wi) const;        f at rho = 1, split into the rho^1 and rho^2
//                                                  parts: f(rho) = rho lin + rho^2 quad
//   double f(Vec3 wo, Vec3 wi) const;              the BRDF at the model's rho
// BRDF values exclude the cosine. wo (view) and wi (light) point away from the surface, the
// normal is +z; a direction below the horizon gives 0.
#pragma once
#include <cmath>

#include "baker/math/vec3.h"

namespace kiln {

/// f = rho * lin + rho^2 * quad (quad = 0 for models linear in rho).
struct RhoParts {
  double lin = 0, quad = 0;
  double At(double rho) const { return rho * lin + rho * rho * quad; }
};

/// Light space: integrate over (theta_l, phi) — smooth lobes (the diffuse models).
/// Half-vector space: integrate over microfacet normals through the lobe's polar CDF — sharp lobes.
enum class IntegrationDomain { Light, HalfVector };

/// The angular quantities of a direction pair that the diffuse models use.
struct PairGeometry {
  double mu_o, mu_l;  ///< cos(theta_o), cos(theta_l)
  double sinTheta_o, sinTheta_l;
  double cosPhi;  ///< cos of the azimuth difference (1 when either is normal)
  double ol;      ///< o . l

  PairGeometry(Vec3 wo, Vec3 wi)
      : mu_o(CosTheta(wo)),
        mu_l(CosTheta(wi)),
        sinTheta_o(SinTheta(wo)),
        sinTheta_l(SinTheta(wi)),
        cosPhi(1),
        ol(Dot(wo, wi)) {
    double s = sinTheta_o * sinTheta_l;
    if (s > 0) cosPhi = Clamp((wo.x * wi.x + wo.y * wi.y) / s, -1.0, 1.0);
  }
  bool Below() const { return mu_o < 0 || mu_l < 0; }
  double ThetaO() const { return std::acos(Clamp(mu_o, -1.0, 1.0)); }
  double ThetaL() const { return std::acos(Clamp(mu_l, -1.0, 1.0)); }
};

/// (1 - (1 - x)^p) / x for x in [0, 1], p > 0, with its limit p at x = 0 (no cancellation).
inline double OneMinusPowOverX(double x, double p) {
  if (x <= 0) return p;
  return -std::expm1(p * std::log1p(-std::min(x, 1.0))) / x;
}

}  // namespace kiln
