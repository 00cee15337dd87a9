// A user's BRDF loaded through the C ABI of kiln/model_abi.h, as a model value type (brdf.h's
// interface) that the model variant (models/registry.h AnyModel) holds: CustomSpecularModel is
// integrated over half vectors (the lobe peaks around the mirror direction), CustomDiffuseModel
// over light directions. Every value f the lobe returns is checked: a NaN, infinite or negative f
// throws CustomModelError naming the model, the value and the directions.
#pragma once
#include <array>
#include <stdexcept>
#include <string>

#include "baker/models/brdf.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"
#include "baker/models/specular.h"

namespace kiln {

/// The most parameters a custom model declares beyond the roughness (model_abi.h).
constexpr int kMaxCustomParams = 4;
/// The smallest importance alpha of a specular lobe without kiln_model_importance_alpha: the
/// default hint is max(r^2, this).
constexpr double kDefaultImportanceAlphaMin = 1e-3;
/// The view cosine at which a custom lobe is evaluated for a view on the horizon (mu_o = 0).
constexpr double kHorizonMu = 1e-12;
/// A specular lobe's horizon view cosine is at most this times its importance alpha: a lobe of
/// width alpha sees mu_o << alpha as the horizon (kHorizonMu itself for alpha >= 1e-3).
constexpr double kHorizonMuPerAlpha = 1e-9;

/// A lobe that returned a NaN, infinite or negative f (the message names where).
struct CustomModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The functions of one loaded lobe (a shared library kept open for the process's lifetime).
struct CustomLobe {
  std::string id;
  std::string hash;    ///< FNV-1a 64 of the source (--model-source) or the library's bytes
  std::string origin;  ///< the file it came from, for messages
  bool specular = false;
  bool energyConserving = false;
  int paramCount = 0;
  double (*eval)(const double*, const double*, double) = nullptr;
  double (*evalParams)(const double*, const double*, double, const double*) = nullptr;
  double (*importanceAlpha)(double) = nullptr;
  /// kiln_model_eval_half (specular lobes): f given the walk's half vector too, or nullptr.
  double (*evalHalf)(const double*, const double*, const double*, double, const double*) = nullptr;
};

/// Throws CustomModelError for an f that is NaN, infinite or negative at (wo, wi).
void ThrowBadCustomValue(const CustomLobe& lobe, double f, Vec3 wo, Vec3 wi, double roughness);

/// The shared state of both custom model types: the lobe, its roughness and parameters.
struct CustomModelBase {
  const CustomLobe* lobe = nullptr;
  double roughness = 0.5;
  std::array<double, kMaxCustomParams> params{};
  /// The view cosine a view on the horizon is evaluated at (kHorizonMu, or less for a sharp
  /// specular lobe: kHorizonMuPerAlpha).
  double horizonMu = kHorizonMu;

  /// The lobe's f at (wo, wi), checked (finite, >= 0); 0 below the horizon. A view on the
  /// horizon (mu_o = 0, the first node of every mu axis) is evaluated at mu_o = horizonMu: the
  /// limit from above, which a lobe with a 1 / mu_o factor has where mu_o = 0 itself is 0 / 0.
  /// With `wh` (the unit half vector of (wo, wi) as an integrator generated it) and a lobe that
  /// defines kiln_model_eval_half, f comes from that function.
  double Checked(Vec3 wo, Vec3 wi, const Vec3* wh = nullptr) const;
};

/// A custom lobe integrated over light directions (kiln_model_is_specular() == 0).
struct CustomDiffuseModel : CustomModelBase {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  RhoParts Parts(Vec3 wo, Vec3 wi) const { return {Checked(wo, wi), 0}; }
  double f(Vec3 wo, Vec3 wi) const { return Checked(wo, wi); }
};

/// A custom lobe integrated over half vectors walked by a GGX lobe of the lobe's importance
/// alpha (integrate/hemisphere.h); `fresnel` multiplies f (F = 1 unless set, as for the
/// built-in microfacet models: the dfg tables split F out of a lobe that holds none). The walk's
/// half vector reaches the lobe through kiln_model_eval_half when it defines that function.
struct CustomSpecularModel : CustomModelBase {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  GGXDistribution importance;
  Fresnel fresnel;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double f = Checked(wo, wi);
    if (f == 0) return {};
    Vec3 wm = Normalize(wo + wi);
    return {f * fresnel(Dot(wo, wm)), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // Half-vector integration with q = D_ggx(h) cos(theta_h): f mu_l 4 (o.h) / (2 pi q), 1 / q
  // computed directly (no 0 / 0 where D underflows).
  PolarParam FromV(double v) const { return importance.FromV(v); }
  double VFromTheta(double theta) const { return importance.VFromTheta(theta); }
  double HalfWeight(const HalfSample& s) const;
  double MaskingScale() const { return importance.alpha; }
  /// Breaks in phi_h where mu_l = alpha / 4, alpha, 4 alpha, 16 alpha (alpha: the importance
  /// lobe's). The integrator grades mu_l geometrically up from min(mu_o, alpha) / 4 with a
  /// bounded number of breaks; for a view near the horizon (mu_o = kHorizonMu) those stop near
  /// 1e-4, short of a lobe that is cut by the horizon over a width ~alpha.
  int PhiKinks(double mu_o, double sinTheta_o, PolarParam h, double* cosPhi) const;
  int ThetaKinks(double, double*) const { return 0; }
};

}  // namespace kiln
