// Kajiya & Kay 1989, "Rendering fur with three dimensional textures" (SIGGRAPH '89): the fibre
// (hair) lighting model. Its directions are measured from the fibre tangent t, not from a surface
// normal. Formulas, and why it has no albedo tables: docs/models.md "Kajiya-Kay".
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/models/brdf.h"

namespace kiln {

/// Kajiya-Kay with the fibre tangent t = +x lying in the surface (directions below the horizon
/// give 0, as for every kiln model). With o, l pointing away from the fibre,
///   diffuse:  K_d sin(t, l)
///   specular: K_s max(0, cos phi)^p,  cos phi = sin(t, l) sin(t, o) - (t.l)(t.o),
/// phi the angle between o and the cone of mirror directions of l about the fibre (the paper
/// writes + (t.l)(t.e) with its eye vector e pointing towards the fibre). The value returned is
/// the model's radiance per unit incident radiance and solid angle: it already carries the
/// fibre's own projection factor sin(t, l) in the diffuse term, so it is not a BRDF over the
/// surface hemisphere (not reciprocal, hemispherical integrals of it have no physical meaning).
/// p = 2 / alpha^2 - 2 with alpha = max(r^2, 0.01) (at most 19998).
struct KajiyaKay {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double kd = 1, ks = 1;
  double p = 10;

  static double ExponentFromPerceptual(double r) {
    double alpha = std::max(r * r, 0.01);
    return 2 / (alpha * alpha) - 2;
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (CosTheta(wo) < 0 || CosTheta(wi) < 0) return {};
    double tl = Clamp(wi.x, -1.0, 1.0), to = Clamp(wo.x, -1.0, 1.0);
    double sl = SafeSqrt(1 - tl * tl), so = SafeSqrt(1 - to * to);
    double c = sl * so - tl * to;
    double spec = c > 0 ? std::pow(std::min(c, 1.0), p) : (p == 0 ? 1.0 : 0.0);
    return {kd * sl + ks * spec, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }
};

}  // namespace kiln
