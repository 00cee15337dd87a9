// Gotanda 2014 "Designing Reflectance Models for New Consoles": normalised Oren-Nayar with
// Fresnel (eq. 33-34) and the fitted Oren-Nayar for a GGX + Smith microsurface (eq. 35),
// seed 000 §5.12.2-5.12.3. sigma = r (Oren-Nayar family convention).
#pragma once
#include "baker/models/brdf.h"

namespace kiln {

/// f mu_l = rho/pi (1 - f0) [F_diff mu_l (1 - 0.5 s2/(s2 + 0.65))
///                           + 0.45 s2/(s2 + 0.09) (o.l - mu_o mu_l) min(1, mu_l/mu_o)],
/// F_diff = 21/20 (1 - f0)(1 - (1 - mu_l)^5)(1 - (1 - mu_o)^5).
/// Transcribed as the seed writes it: (1 - f0) appears both inside F_diff and outside.
/// The second term is negative for back-scattering (cos(phi) < 0), so f can be negative there.
struct GotandaFresnelDiffuse {
  static constexpr const char* kId = "gotanda-fresnel";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double sigma = 0.5, rho = 1, f0 = 0;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    double s2 = sigma * sigma;
    double Fdiff = 21.0 / 20.0 * (1 - f0) * (1 - Pow5(1 - g.mu_l)) * (1 - Pow5(1 - g.mu_o));
    // min(1, mu_l/mu_o) / mu_l = 1 / max(mu_l, mu_o); both on the horizon is the limit 1e-12.
    double invMax = 1 / std::max({g.mu_l, g.mu_o, 1e-12});
    double value = InvPi * (1 - f0) *
                   (Fdiff * (1 - 0.5 * s2 / (s2 + 0.65)) +
                    0.45 * s2 / (s2 + 0.09) * (g.ol - g.mu_o * g.mu_l) * invMax);
    return {value, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

/// f mu_l = 21/(20 pi) (1 - f0) (F_r L_m + V_d B_p) with e = o (eq. 35 and the three terms after
/// it; see docs/models.md 8). A fitted model: neither reciprocal nor bound to conserve energy.
/// Valid for sigma in [0, 1] (the fit's range; above it (1 - mu_o)^(5 - 4 s2) blows up).
struct GotandaGGXDiffuse {
  static constexpr const char* kId = "gotanda-ggx";
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double sigma = 0.5, rho = 1, f0 = 0;

  /// The factors of Parts that depend on mu_o and mu_l alone (as OrenNayar::Polar): the
  /// prefactor, F_r L_m / mu_l and V_d / mu_l.
  struct Polar {
    double scale, FrLm, VdOverMu;
  };
  /// Polar of g's mu_o and mu_l.
  Polar PolarFactors(const PairGeometry& g) const {
    double s = sigma, s2 = s * s, mu_o = g.mu_o, mu_l = g.mu_l;
    double den = s2 + 1.36053;  // the fit's denominator, shared by its first two factors
    double Fr = (1 - (0.542026 * s2 + 0.303573 * s) / den) *
                (1 - std::pow(1 - mu_o, 5 - 4 * s2) / den) *
                ((-0.733996 * s * s2 + 1.50912 * s2 - 1.16402 * s) *
                     std::pow(1 - mu_o, 1 + 1 / (39 * s2 * s2 + 1)) +
                 1);
    // L_m / mu_l and V_d / mu_l, written so that mu_l = 0 gives the limit.
    double LmOverMu = (std::max(1 - 2 * s, 0.0) * (1 - Pow5(1 - mu_l)) + std::min(2 * s, 1.0)) *
                      ((1 - 0.5 * s) + 0.5 * s * mu_l);
    double p = (1 - 0.3726732 * mu_o * mu_o) / (0.188566 + 0.388410 * mu_o);
    double VdOverMu = s2 / ((s2 + 0.09) * (1.31072 + 0.995584 * mu_o)) * OneMinusPowOverX(mu_l, p);
    return {21.0 / (20.0 * Pi) * (1 - f0), Fr * LmOverMu, VdOverMu};
  }
  /// Parts at g (above the horizon) from its PolarFactors.
  RhoParts PartsAt(const Polar& p, const PairGeometry& g) const {
    double d = g.ol - g.mu_o * g.mu_l;
    double Bp = d < 0 ? 1.4 * g.mu_o * g.mu_l * d : d;
    return {p.scale * (p.FrLm + p.VdOverMu * Bp), 0};
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    PairGeometry g(wo, wi);
    if (g.Below()) return {};
    return PartsAt(PolarFactors(g), g);
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).At(rho); }
};

}  // namespace kiln
