#include "baker/models/custom_lobe.h"

#include <cmath>
#include <cstdio>

namespace kiln {
namespace {

/// How far up from mu_o / 4 the half-vector integrator's geometric masking breaks in mu_l reach
/// (integrate/hemisphere.h: ratio 4, at most 15 breaks): 4^13 mu_o.
constexpr double kMaskingBreakReach = 67108864.0;

}  // namespace

void ThrowBadCustomValue(const CustomLobe& lobe, double f, Vec3 wo, Vec3 wi, double roughness) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "model '%s' (%s): f = %g at wo = (%.17g, %.17g, %.17g), wi = (%.17g, %.17g, "
                "%.17g), roughness %.17g: f must be finite and >= 0",
                lobe.id.c_str(), lobe.origin.c_str(), f, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z,
                roughness);
  throw CustomModelError(buf);
}

double CustomModelBase::Checked(Vec3 wo, Vec3 wi, const Vec3* wh) const {
  if (CosTheta(wo) < 0 || CosTheta(wi) < 0) return 0;
  if (CosTheta(wo) == 0) wo = Normalize(Vec3{wo.x, wo.y, horizonMu});
  const double o[3] = {wo.x, wo.y, wo.z}, i[3] = {wi.x, wi.y, wi.z};
  double f;
  if (wh && lobe->evalHalf) {
    const double h[3] = {wh->x, wh->y, wh->z};
    f = lobe->evalHalf(o, h, i, roughness, params.data());
  } else {
    f = lobe->paramCount > 0 ? lobe->evalParams(o, i, roughness, params.data())
                             : lobe->eval(o, i, roughness);
  }
  if (!(f >= 0) || !std::isfinite(f)) ThrowBadCustomValue(*lobe, f, wo, wi, roughness);
  return f;
}

int CustomSpecularModel::PhiKinks(double mu_o, double sinTheta_o, PolarParam h,
                                  double* cosPhi) const {
  // mu_l = 2 (o.h) cos_h - mu_o with o.h = sin_o sin_h cos(phi) + mu_o cos_h.
  const double den = 2 * h.cosTheta * sinTheta_o * h.sinTheta;
  // The integrator's own breaks, geometric from min(mu_o, alpha) / 4, reach alpha / 4 unless
  // mu_o is far below alpha (kMaskingBreakReach): only then are these needed (else they repeat
  // its breaks, or add panels a smooth lobe does not need).
  if (!(den > 0) || mu_o * kMaskingBreakReach >= importance.alpha) return 0;
  int count = 0;
  for (double m = importance.alpha / 4; count < 4; m *= 4)
    cosPhi[count++] = (m + mu_o - 2 * mu_o * Sqr(h.cosTheta)) / den;
  return count;
}

double CustomSpecularModel::HalfWeight(const HalfSample& s) const {
  double f = Checked(s.wo, s.wi, &s.wm);
  if (f == 0) return 0;
  // tan^2 from the normal's components: 1 - c^2 cancels where alpha is tiny.
  double a2 = Sqr(importance.alpha), c = s.cosTheta_h;
  double tan2 = (Sqr(s.wm.x) + Sqr(s.wm.y)) / (c * c);
  double invQ = Pi * a2 * c * c * c * Sqr(1 + tan2 / a2);
  return f * fresnel(s.oh) * s.mu_l * 4 * s.oh * invQ / (2 * Pi);
}

}  // namespace kiln
