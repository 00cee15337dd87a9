// Lafortune et al. 1997, "Non-linear approximation of reflectance functions" (SIGGRAPH '97):
// generalised cosine lobes f = sum_i (C_x,i o_x l_x + C_y,i o_y l_y + C_z,i o_z l_z)^n_i in the
// local frame. Formulas and kiln's default lobe set: docs/models.md "Lafortune".
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "baker/models/brdf.h"

namespace kiln {

/// One generalised cosine lobe: weight (C_x o_x l_x + C_y o_y l_y + C_z o_z l_z)^n, where the
/// bracket is clamped at 0 (a lobe is zero where its bracket is negative).
struct LafortuneLobe {
  double cx = -1, cy = -1, cz = 1;  ///< direction coefficients (-1, -1, 1: the mirror, Phong)
  double n = 1;                     ///< exponent
  double weight = 1;                ///< the scale Lafortune folds into |C|^n, kept apart here
};

/// kiln's `lafortune`: one lobe, C = (-1, -1, 1) (the classic Phong special case: the bracket is
/// cos of the angle between l and the mirror direction of o), exponent
/// n = (2 / alpha^2 - 2) / 4 with alpha = max(r^2, 0.01) (the Blinn-Phong exponent of alpha over 4,
/// the Phong lobe about the mirror being ~4x narrower in exponent than the Blinn-Phong lobe about
/// the normal; at most 4999.5), and weight rs (n + 2) / (2 pi), the normalised Phong factor, so
/// E(1) = rs at normal incidence. Reciprocal: the bracket is symmetric in o and l.
struct LafortuneBRDF {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  LafortuneLobe lobe;

  static double ExponentFromPerceptual(double r) {
    double alpha = std::max(r * r, 0.01);
    return (2 / (alpha * alpha) - 2) / 4;
  }
  static LafortuneBRDF Phong(double r, double rs) {
    LafortuneBRDF m;
    m.lobe.n = ExponentFromPerceptual(r);
    m.lobe.weight = rs * (m.lobe.n + 2) / (2 * Pi);
    return m;
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (CosTheta(wo) < 0 || CosTheta(wi) < 0) return {};
    double b = lobe.cx * wo.x * wi.x + lobe.cy * wo.y * wi.y + lobe.cz * wo.z * wi.z;
    if (b <= 0) return {lobe.n == 0 ? lobe.weight : 0, 0};
    return {lobe.weight * std::pow(std::min(b, 1.0), lobe.n), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  /// The light cosine where the lobe's edge, the great circle b = 0, touches a circle theta_l
  /// (o in the xz plane, ViewDirection): b = C_x s_o sin_l cos(phi_l) + C_z mu_o cos_l, so
  /// tan(theta_l) = |C_z| mu_o / (|C_x| s_o). An outer panel boundary of the adaptive integrator
  /// (integrate/hemisphere.h): below n = 1 the lobe is a near-step across that circle.
  std::vector<double> LightMuKinks(double mu_o) const {
    const double s = std::sqrt(std::max(0.0, (1 - mu_o) * (1 + mu_o)));
    const double a = std::abs(lobe.cz) * mu_o, b = std::abs(lobe.cx) * s;
    if (!(a > 0 && b > 0)) return {};
    return {b / std::hypot(a, b)};  // cos(theta_l) = 1 / sqrt(1 + (a / b)^2)
  }
  /// cos(phi_l) of the lobe's edge b = 0 on the circle theta_l (sin_l, cos_l): an inner panel
  /// boundary of the adaptive integrator. Returns 1 (or 0 where the circle misses it).
  int LightPhiKinks(double mu_o, double sinTheta_l, double cosTheta_l, double* cosPhi) const {
    const double s = std::sqrt(std::max(0.0, (1 - mu_o) * (1 + mu_o)));
    const double den = lobe.cx * s * sinTheta_l;
    if (den == 0) return 0;
    cosPhi[0] = -lobe.cz * mu_o * cosTheta_l / den;
    return cosPhi[0] > -1 && cosPhi[0] < 1 ? 1 : 0;
  }
};

}  // namespace kiln
