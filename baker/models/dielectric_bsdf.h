// Rough dielectric BSDF: Walter, Marschner, Li & Torrance 2007, "Microfacet Models for Refraction
// through Rough Surfaces" (EGSR), eq. 20 (reflection) and 21 (refraction), with the GGX NDF
// (their eq. 33), the height-correlated Smith G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014
// eq. 99) for the reflected and the transmitted pair alike (as pbrt-v4 and Cycles do), and the
// exact unpolarised dielectric Fresnel term (models/fresnel.h, FrDielectric).
//
// Conventions. Normal +z. The side z > 0 has index 1, the side z < 0 index eta: eta is
// inside / outside as seen from a view above the surface, so eta > 1 enters a denser medium and
// eta < 1 leaves one (total internal reflection beyond sin theta = eta). wo (the view, where
// radiance goes) and wi (the light, where it comes from) point away from the surface, either side.
// Values exclude the cosine. alpha is GGX's alpha (alpha = r^2 from perceptual r, > 0).
// The generalised half vector of a refracted pair is m ~ n_o wo + n_i wi (n_o, n_i the indices on
// wo's and wi's sides), turned to +z; pairs with a back-facing microfacet give 0.
//   Importance form (no 1/eta^2), the one whose integral is an energy fraction:
//     fhat_t(wo, wi) = D(m) G2 (1 - F(wo.m)) |wi.m| |wo.m| / (|cos_i| |cos_o| (wi.m + wo.m / e)^2),
//     e = n_i / n_o;   integral fhat_t |cos_i| dwi = E_T, which is 1 - F(mu) for a smooth
//     interface.
//   Radiance form: f_t = fhat_t / e^2 (radiance is n^2-scaled across the interface).
//   Reciprocity (Veach 1997 eq. 5.14; Walter eq. 21 / n_o^2 is symmetric):
//     f_t(wo, wi) / n_o^2 = f_t(wi, wo) / n_i^2.
//   Reflection: f_r(wo, wi) = D(m) G2 F(wo.m) / (4 |cos_o| |cos_i|), m ~ wo + wi (symmetric).
#pragma once
#include <cmath>

#include "baker/math/vec3.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"

namespace kiln {

struct GGXDielectricBSDF {
  static constexpr const char* kId = "ggx-dielectric";
  GGXDistribution dist;  ///< dist.alpha: GGX alpha
  double eta = 1.5;      ///< index below (z < 0) over index above (z > 0)

  /// Height-correlated Smith G2 of a pair on any sides (the cosines taken in absolute value).
  double G2(Vec3 wo, Vec3 wi) const {
    double lo = dist.Lambda(std::abs(wo.z)), li = dist.Lambda(std::abs(wi.z));
    return 1 / (1 + lo + li);
  }

  /// Reflection part f_r(wo, wi) (wo, wi on the same side; 0 otherwise). No cosine.
  double Fr(Vec3 wo, Vec3 wi) const {
    if (!(wo.z * wi.z > 0)) return 0;
    Vec3 m = wo + wi;
    if (Dot(m, m) == 0) return 0;
    m = Normalize(m);
    if (m.z < 0) m = -1.0 * m;
    double om = Dot(wo, m);
    if (om * wo.z <= 0 || Dot(wi, m) * wi.z <= 0) return 0;  // back-facing microfacet
    // FrDielectric takes the cosine's sign as the side: from below, eta is inverted.
    double F = FrDielectric(om, eta);
    return dist.D(m) * G2(wo, wi) * F / (4 * std::abs(wo.z) * std::abs(wi.z));
  }

  /// Transmission part in importance form, fhat_t(wo, wi) (wo, wi on opposite sides; see the file
  /// comment). No cosine, no 1/eta^2.
  double FtImportance(Vec3 wo, Vec3 wi) const {
    if (!(wo.z * wi.z < 0)) return 0;
    double e = wo.z > 0 ? eta : 1 / eta;  // n_i / n_o
    Vec3 m = wo + e * wi;
    if (Dot(m, m) == 0) return 0;
    m = Normalize(m);
    if (m.z < 0) m = -1.0 * m;
    double om = Dot(wo, m), im = Dot(wi, m);
    if (om * wo.z <= 0 || im * wi.z <= 0) return 0;  // back-facing microfacet
    double denom = Sqr(im + om / e);
    if (!(denom > 0)) return 0;
    double F = FrDielectric(om, eta);
    return dist.D(m) * G2(wo, wi) * (1 - F) * std::abs(im * om) /
           (std::abs(wo.z) * std::abs(wi.z) * denom);
  }

  /// Transmission part in radiance form, f_t = fhat_t / (n_i / n_o)^2. No cosine.
  double Ft(Vec3 wo, Vec3 wi) const {
    double e = wo.z > 0 ? eta : 1 / eta;
    return FtImportance(wo, wi) / (e * e);
  }

  /// The whole BSDF in radiance form, f_r + f_t. No cosine.
  double f(Vec3 wo, Vec3 wi) const { return Fr(wo, wi) + Ft(wo, wi); }
};

}  // namespace kiln
