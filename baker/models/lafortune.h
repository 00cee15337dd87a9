// Lafortune et al. 1997, "Non-linear approximation of reflectance functions" (SIGGRAPH '97):
// generalised cosine lobes f = sum_i (C_x,i o_x l_x + C_y,i o_y l_y + C_z,i o_z l_z)^n_i in the
// local frame. Formulas and kiln's default lobe set: docs/models.md "Lafortune".
#pragma once
#include <algorithm>
#include <cmath>

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
};

}  // namespace kiln
