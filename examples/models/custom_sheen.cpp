// A custom sheen lobe as a kiln custom model (kiln/model_abi.h): an inverted Gaussian of the
// half vector's polar angle with a Neubelt-style visibility, a tuned cloth lobe
//   f = rho D(h) / (4 (mu_o + mu_l - mu_o mu_l)),
//   D = (1 + 4 exp(-cot^2(theta_h) / s^2) / sin^4(theta_h)) / (pi (1 + 4 s^2)),  s = max(r, 0.02)^2
// (Ashikhmin & Premoze 2007's velvet distribution under Neubelt & Pettineo 2013's visibility),
// a lobe that grows towards grazing, integrated over light directions. Its one extra
// parameter, rho (the sheen colour's strength), is given as --rho. Bake its tables with
//   kiln bake --model-source custom_sheen.cpp --only soft-sheen-albedo,soft-sheen-albedo-avg
#include <kiln/model_abi.h>

#include <algorithm>
#include <cmath>

namespace {
constexpr double kPi = 3.14159265358979323846;
double Sheen(const double wo[3], const double wi[3], double r, double rho) {
  double mu_o = wo[2], mu_l = wi[2];
  if (mu_o <= 0 || mu_l <= 0) return 0;
  double h[3] = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
  double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (len == 0) return 0;
  double c = h[2] / len, s2 = std::max(1 - c * c, 1e-12);
  double s = std::max(r, 0.02);
  s *= s;
  double d = (1 + 4 * std::exp(-c * c / (s2 * s * s)) / (s2 * s2)) / (kPi * (1 + 4 * s * s));
  return rho * d / (4 * (mu_o + mu_l - mu_o * mu_l));
}
}  // namespace

extern "C" int kiln_model_abi_version() { return KILN_MODEL_ABI_VERSION; }
extern "C" const char* kiln_model_id() { return "soft-sheen"; }
extern "C" int kiln_model_is_specular() { return 0; }

extern "C" int kiln_model_param_count() { return 1; }
extern "C" const char* kiln_model_param_name(int) { return "rho"; }
extern "C" void kiln_model_param_range(int, double* lo, double* hi, double* def) {
  *lo = 0;
  *hi = 1;
  *def = 1;
}
extern "C" double kiln_model_eval_params(const double wo[3], const double wi[3], double r,
                                         const double* params) {
  return Sheen(wo, wi, r, params[0]);
}
extern "C" double kiln_model_eval(const double wo[3], const double wi[3], double r) {
  return Sheen(wo, wi, r, 1);
}
