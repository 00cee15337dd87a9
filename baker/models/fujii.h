// Fujii's "tiny improved Oren-Nayar" (ION) and its energy-normalised variant (seed 000 §5.12.1).
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// s = l.o - mu_l mu_o, t = 1 if s <= 0 else max(mu_l, mu_o), f = rho (A + B s / t).
/// Plain: A = (1/pi)(1 - 0.5 s2/(s2 + 0.33) + 0.17 rho s2/(s2 + 0.13)) (the rho term makes f
/// quadratic in rho), B = (1/pi) 0.45 s2/(s2 + 0.09), sigma = r.
/// Normalised: A = 1/(pi + (pi/2 - 2/3) sigma'), B = sigma' A with sigma' = r in [0, 1].
struct FujiiOrenNayar {
  static constexpr const char* kId = "fujii";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double sigma = 0.5, rho = 1;
  bool normalized = false;  ///< the "fujii-normalized" variant

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double s = g.ol - g.mu_l * g.mu_o;
    double t = s <= 0 ? 1 : std::max(g.mu_l, g.mu_o);
    double sOverT = t > 0 ? s / t : 0;
    if (normalized) {
      double A = 1 / (Pi + (Pi / 2 - 2.0 / 3.0) * sigma);
      return {A + sigma * A * sOverT, 0};
    }
    double s2 = sigma * sigma;
    double A1 = InvPi * (1 - 0.5 * s2 / (s2 + 0.33));
    double A2 = InvPi * 0.17 * s2 / (s2 + 0.13);
    double B = InvPi * 0.45 * s2 / (s2 + 0.09);
    return {A1 + B * sOverT, A2};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
