// GGX written by a user (height-correlated Smith masking, F = 1), as a kiln custom model
// (kiln/model_abi.h): the same lobe as kiln's built-in "ggx", alpha = max(r^2, 1e-12). The lobe
// is written in terms of the half vector: kiln_model_eval_half takes the one kiln's walk
// generated, whose components hold full relative precision, so the tables equal ggx's down to
// r = 0. kiln_model_eval forms the half vector from the two directions (for single evaluations:
// there its slope is known to ~1e-16 absolute, coarse where alpha < ~1e-7).
//   kiln bake --model-source user_ggx.cpp --only user-ggx-albedo
#include <kiln/model_abi.h>

#include <algorithm>
#include <cmath>

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMinAlpha = 1e-12;  // the built-in ggx's floor
double Alpha(double r) { return std::max(r * r, kMinAlpha); }
/// mu Lambda(mu), without cancellation.
double MuLambda(double mu, double a2) {
  double s2 = std::max(0.0, 1 - mu * mu);
  return a2 * s2 / (2 * (std::sqrt(mu * mu + a2 * s2) + mu));
}
/// f from the view and light cosines and the unit half vector h.
double Ggx(double mu_o, const double h[3], double mu_l, double r) {
  if (mu_o <= 0 || mu_l <= 0 || h[2] <= 0) return 0;
  // D = 1 / (pi a^2 cos^4 (1 + tan^2 / a^2)^2), tan^2 from the components (1 - cos^2 cancels
  // where alpha is tiny).
  double c = h[2], a2 = Alpha(r) * Alpha(r);
  double tan2 = (h[0] * h[0] + h[1] * h[1]) / (c * c);
  double d = 1 / (kPi * a2 * c * c * c * c * (1 + tan2 / a2) * (1 + tan2 / a2));
  double g = 1 / (1 + MuLambda(mu_o, a2) / mu_o + MuLambda(mu_l, a2) / mu_l);
  double f = d * g / (4 * mu_o * mu_l);
  return std::isfinite(f) ? f : 0;
}
}  // namespace

extern "C" int kiln_model_abi_version() { return KILN_MODEL_ABI_VERSION; }
extern "C" const char* kiln_model_id() { return "user-ggx"; }
extern "C" int kiln_model_is_specular() { return 1; }
extern "C" int kiln_model_energy_conserving() { return 1; }
extern "C" double kiln_model_importance_alpha(double r) { return Alpha(r); }

extern "C" double kiln_model_eval(const double wo[3], const double wi[3], double r) {
  double h[3] = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
  double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (!(len > 0)) return 0;
  for (double& x : h) x /= len;
  return Ggx(wo[2], h, wi[2], r);
}

extern "C" double kiln_model_eval_half(const double wo[3], const double wh[3], const double wi[3],
                                       double r, const double*) {
  return Ggx(wo[2], wh, wi[2], r);
}
