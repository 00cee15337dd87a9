// A normalised Phong lobe (Lewis 1994) as a kiln custom model (kiln/model_abi.h):
//   f = (n + 2) / (2 pi) max(0, r.wi)^n,  r = reflect(wo) about the normal,
//   n = 2 / alpha^2,  alpha = max(roughness^2, 1e-3)  (n >= 2: f is smooth where r.wi = 0),
// whose directional albedo is at most 1 (Lewis 1994: energy conserving). Bake its tables with
//   kiln bake --model-source normalized_phong.cpp --only phong-normalized-albedo
#include <kiln/model_abi.h>

#include <algorithm>
#include <cmath>

namespace {
constexpr double kPi = 3.14159265358979323846;
/// The Phong exponent of roughness r.
double Exponent(double r) {
  double alpha = std::max(r * r, 1e-3);
  return 2 / (alpha * alpha);
}
}  // namespace

extern "C" int kiln_model_abi_version() { return KILN_MODEL_ABI_VERSION; }
extern "C" const char* kiln_model_id() { return "phong-normalized"; }
extern "C" int kiln_model_is_specular() { return 1; }
extern "C" int kiln_model_energy_conserving() { return 1; }
extern "C" double kiln_model_importance_alpha(double r) { return std::max(r * r, 1e-3); }

extern "C" double kiln_model_eval(const double wo[3], const double wi[3], double r) {
  if (wo[2] <= 0 || wi[2] <= 0) return 0;
  // r = reflect(wo) = (-wo.x, -wo.y, wo.z); cos of the angle between r and wi.
  double c = -wo[0] * wi[0] - wo[1] * wi[1] + wo[2] * wi[2];
  if (c <= 0) return 0;
  double n = Exponent(r);
  return (n + 2) / (2 * kPi) * std::pow(c, n);
}
