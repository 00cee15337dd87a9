// Unity's built-in Standard shader BRDFs (UnityStandardBRDF.cginc, Unity Technologies, MIT; seed
// 001): the specular lobes of BRDF1_Unity_PBS (GGX, approximate Smith-joint visibility),
// BRDF2_Unity_PBS (modified GGX with the combined visibility-Fresnel term of "Optimizing PBR for
// Mobile", Siggraph 2015) and BRDF3_Unity_PBS (normalised Phong in "RDF" form, read from the
// unity_NHxRoughness texture). Formulas, constants and clamps: docs/models.md "Unity's BRDFs".
//
// Unity's light convention: a shader multiplies its specular term by light.color * nl while a
// Lambertian surface is diffColor * light.color * nl (no 1/pi), so the physical BRDF is the
// shader's term divided by pi. The values below are physical BRDFs (no cosine), in double
// precision (Unity's float/half rounding is not modelled), at the default compile switches
// (UNITY_BRDF_GGX = 1, linear colour space, not SHADER_API_MOBILE). Specular only: the diffuse
// term (Disney for BRDF1, Lambert for BRDF2/3) is not part of these models.
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/models/brdf.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"
#include "baker/models/specular.h"

namespace kiln {

/// Unity's PerceptualRoughnessToSpecPower: m = r^2, n = max(2 / max(1e-4, m^2) - 2, 1e-4). The
/// Blinn-Phong exponent (at most 19998) of perceptual roughness r.
inline double UnitySpecPower(double r) {
  double m = r * r;
  return std::max(2 / std::max(1e-4, m * m) - 2, 1e-4);
}

/// Unity_SafeNormalize(l + v): (l + v) / sqrt(max(0.001, |l + v|^2)).
inline Vec3 UnitySafeHalf(Vec3 wo, Vec3 wi) {
  Vec3 h = wo + wi;
  return (1 / std::sqrt(std::max(0.001, Dot(h, h)))) * h;
}

/// The range the shader scales unity_NHxRoughness's texels by (LUT_RANGE in BRDF3_Direct).
constexpr double kUnityNHxRoughnessRange = 16;

/// The "1" of UnityBRDF2's GGX denominator d = n.h^2 (a^2 - 1) + 1.00001 (BRDF2_Unity_PBS): it
/// keeps d >= 1e-5 at a = 0.
constexpr double kUnityBRDF2GgxOne = 1.00001;

/// sqrt(0.1): the l.h where UnityBRDF2's max(0.1, l.h^2) turns (at the mirror l.h = mu, so the
/// kink of its albedo E(mu)).
constexpr double kUnityBRDF2LhKink = 0.31622776601683794;

/// The alpha of the GGX polar CDF that samples UnityBRDF1's half vectors: 1e-7^(1/4), the width
/// of its capped lobe.
constexpr double kUnityBRDF1SamplerAlpha = 0.01778279410038923;

/// The alpha of the GGX polar CDF that samples UnityBRDF2's half vectors: sqrt(1e-5), the width
/// the 1.00001 of its denominator leaves.
constexpr double kUnityBRDF2SamplerAlpha = 0.0031622776601683794;

/// The texel unity_NHxRoughness holds at x = (R.L)^4 in [0, 1] and perceptual roughness r in
/// [0, 1], as the shader reads it before its * 16 (docs/models.md "unity-brdf3"):
///   T = min(1, (n + 2) / (2 pi^2) x^(n / 4) / 16),  n = UnitySpecPower(r) / 4
/// (the Phong exponent of the Blinn-Phong one; x^(n/4) = |R.L|^n). Unity's own generator
/// (GeneratedTextures.cpp) is not public: this is the formula of the shader's in-source fallback
/// next to the lookup, in the texture's [0, 1] range.
inline double UnityNHxRoughnessTexel(double x, double r) {
  double n = UnitySpecPower(r) / 4;
  x = Clamp(x, 0.0, 1.0);
  double lobe = x > 0 ? std::exp(n / 4 * std::log(x)) : 0.0;
  return std::min(1.0, (n + 2) / (2 * Pi * Pi) * lobe / kUnityNHxRoughnessRange);
}

/// The half-vector weight f mu_l 4 (o.h) / (2 pi q) of a lobe sampled through GGX's polar CDF
/// at `sampler` (q = D(wm) cos(theta_h)); `f()` is evaluated only where q > 0 (else 0).
template <typename F>
double WeightThroughGgx(const GGXDistribution& sampler, const HalfSample& s, F f) {
  double q = sampler.D(s.wm) * s.cosTheta_h;
  if (!(q > 0)) return 0;
  return f() * s.mu_l * 4 * s.oh / (2 * Pi * q);
}

/// BRDF1_Unity_PBS's specular lobe (UNITY_BRDF_GGX branch), perceptual roughness r:
///   a = max(r^2, 0.002)
///   D = a^2 / (pi ((n.h^2 (a^2 - 1) + 1)^2 + 1e-7))            GGXTerm
///   V = 0.5 / (nl (nv (1 - a) + a) + nv (nl (1 - a) + a) + 1e-5)  SmithJointGGXVisibilityTerm
///   f = D V F(l.h),  h = Unity_SafeNormalize(l + v), F Schlick with F0 = specColor (f0).
/// V is Unity's approximation of the height-correlated Smith term (the sqrt dropped); the
/// epsilons cap D at a^2 / (pi 1e-7), which dominates below r ~ 0.13.
struct UnityBRDF1 {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  double a = 0.002;  ///< Unity's roughness: max(r^2, 0.002)
  Fresnel fresnel;

  static double AFromPerceptual(double r) { return std::max(r * r, 0.002); }
  double D(double nh) const {
    double a2 = a * a, d = (nh * a2 - nh) * nh + 1;
    return a2 / (Pi * (d * d + 1e-7));
  }
  double V(double nl, double nv) const {
    double lambdaV = nl * (nv * (1 - a) + a), lambdaL = nv * (nl * (1 - a) + a);
    return 0.5 / (lambdaV + lambdaL + 1e-5);
  }
  /// The formula without kiln's horizon convention: finite at mu = 0 (the epsilons), so the
  /// integrators take its limit there.
  double Value(Vec3 wo, Vec3 wi) const {
    double nv = std::abs(CosTheta(wo)), nl = Clamp(CosTheta(wi), 0.0, 1.0);
    Vec3 h = UnitySafeHalf(wo, wi);
    double nh = Clamp(CosTheta(h), 0.0, 1.0), lh = Clamp(Dot(wi, h), 0.0, 1.0);
    return D(nh) * V(nl, nv) * fresnel(lh);
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (CosTheta(wo) <= 0 || CosTheta(wi) <= 0) return {};
    return {Value(wo, wi), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // Half-vector integration through GGX's polar CDF at alpha_q = max(a, 1e-7^(1/4)), the width
  // of the capped lobe: q = D_GGX(alpha_q) cos(theta_h), and the weight f mu_l 4 (o.h)/(2 pi q).
  GGXDistribution Sampler() const { return GGXDistribution{std::max(a, kUnityBRDF1SamplerAlpha)}; }
  PolarParam FromV(double v) const { return Sampler().FromV(v); }
  double VFromTheta(double theta) const { return Sampler().VFromTheta(theta); }
  double HalfWeight(const HalfSample& s) const {
    return WeightThroughGgx(Sampler(), s, [&] { return Value(s.wo, s.wi); });
  }
  double MaskingScale() const { return a; }
  int PhiKinks(double, double, PolarParam, double*) const { return 0; }
  int ThetaKinks(double, double*) const { return 0; }
};

/// Where unity-brdf2's albedo E(mu) has its kink, sqrt(0.1) (Unity's max(0.1, LdotH^2) at the
/// mirror, LdotH = mu): the constant split point of that table's mu axis.
constexpr double kUnityBRDF2MuKink = kUnityBRDF2LhKink;

/// BRDF2_Unity_PBS's specular lobe (UNITY_BRDF_GGX branch, linear colour space), perceptual
/// roughness r, a = r^2 (no minimum):
///   d = n.h^2 (a^2 - 1) + 1.00001
///   f = rs a^2 / (4 pi max(0.1, l.h^2) (a + 0.5) d^2)
/// (GGX's D times the combined visibility-Fresnel approximation 1 / (4 l.h^2 (a + 0.5)), the
/// "Fresnel approximated with 1/LdotH"); rs = specColor. `fresnel` stays F = 1 (Unity's BRDF2 has
/// no other Fresnel factor); r = 0 gives f = 0.
struct UnityBRDF2 {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  double a = 0.25;  ///< r^2
  double rs = 1;    ///< specColor
  Fresnel fresnel;

  /// The formula without kiln's horizon convention (it does not depend on n.v).
  double Value(Vec3 wo, Vec3 wi) const {
    Vec3 h = UnitySafeHalf(wo, wi);
    double nh = Clamp(CosTheta(h), 0.0, 1.0), lh = Clamp(Dot(wi, h), 0.0, 1.0);
    double a2 = a * a, d = nh * nh * (a2 - 1) + kUnityBRDF2GgxOne;
    double term = a2 / (std::max(0.1, lh * lh) * (a + 0.5) * (d * d) * 4);
    return rs * term / Pi * fresnel(lh);
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (CosTheta(wo) <= 0 || CosTheta(wi) <= 0) return {};
    return {Value(wo, wi), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // GGX's polar CDF at alpha_q = max(a, sqrt(1e-5)), the width the 1.00001 leaves.
  GGXDistribution Sampler() const { return GGXDistribution{std::max(a, kUnityBRDF2SamplerAlpha)}; }
  PolarParam FromV(double v) const { return Sampler().FromV(v); }
  double VFromTheta(double theta) const { return Sampler().VFromTheta(theta); }
  double HalfWeight(const HalfSample& s) const {
    return WeightThroughGgx(Sampler(), s, [&] { return Value(s.wo, s.wi); });
  }
  double MaskingScale() const { return 0; }
  int PhiKinks(double, double, PolarParam, double*) const { return 0; }
  int ThetaKinks(double, double*) const { return 0; }
};

/// BRDF3_Unity_PBS's specular lobe, perceptual roughness r: the shader reads
/// 16 T((R.L)^4, r) (UnityNHxRoughnessTexel) with R = reflect(viewDir, n) = v - 2 (n.v) n, so
///   f = rs 16 T((R.L)^4, r) / pi.
/// No Fresnel, no visibility term. (R.L)^4 is even in R.L: the lobe about the mirror direction
/// has a twin about -R (reachable above the horizon only at grazing views).
struct UnityBRDF3 {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double r = 0.5;  ///< perceptual roughness
  double rs = 1;   ///< specColor

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double nv = CosTheta(wo), nl = CosTheta(wi);
    if (nv < 0 || nl < 0) return {};
    Vec3 R = wo - 2 * nv * Vec3{0, 0, 1};
    double rl = Dot(R, wi), x = Sqr(Sqr(rl));
    return {rs * kUnityNHxRoughnessRange * UnityNHxRoughnessTexel(x, r) / Pi, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }
};

}  // namespace kiln
