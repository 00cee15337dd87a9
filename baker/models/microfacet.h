// Microfacet distributions and Smith masking: Walter et al. 2007 "Microfacet Models for
// Refraction through Rough Surfaces", Heitz 2014 "Understanding the Masking-Shadowing Function".
// Conventions: alpha is the microfacet roughness (alpha = r^2 from perceptual r); D(wm) is
// normalised so that integral D(wm) cos(theta_m) dwm = 1; Lambda is Smith's auxiliary function.
#pragma once
#include <algorithm>
#include <cmath>

#include "baker/math/vec3.h"
#include "baker/models/roughness.h"

namespace kiln {

/// How the integrators walk the microfacet normals of a distribution: v in (0, 1] is the
/// complementary CDF of a polar density (v = 1 at theta_m = 0), so that equal steps in v carry
/// equal weight and a sharp lobe is no harder to integrate than a broad one.
struct PolarParam {
  double sinTheta = 0, cosTheta = 1;
};

/// Trowbridge-Reitz / GGX (Walter 2007 eq. 33): D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
struct GGXDistribution {
  double alpha = MinAlpha;
  static constexpr const char* kName = "GGX";

  double D(Vec3 wm) const {
    double tan2 = Tan2Theta(wm);
    if (!std::isfinite(tan2)) return 0;
    double a2 = alpha * alpha, cos4 = Sqr(Sqr(CosTheta(wm)));
    return 1 / (Pi * a2 * cos4 * Sqr(1 + tan2 / a2));
  }
  /// mu * Lambda(mu) for mu = cos(theta) in [0, 1], without cancellation; alpha/2 at mu = 0.
  double MuLambda(double mu) const {
    double s2 = std::max(0.0, 1 - mu * mu), a2 = alpha * alpha;
    double den = 2 * (std::sqrt(mu * mu + a2 * s2) + mu);
    return den > 0 ? a2 * s2 / den : 0;
  }
  /// Smith Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2.
  double Lambda(double mu) const { return mu > 0 ? MuLambda(mu) / mu : INFINITY; }
  /// Polar angle for the complementary CDF v of D cos: tan^2 = alpha^2 (1 - v) / v.
  PolarParam FromV(double v) const {
    double tan2 = Sqr(alpha) * (1 - v) / v;
    double c = 1 / std::sqrt(1 + tan2);
    return {std::sqrt(tan2) * c, c};
  }
  double VFromTheta(double theta) const {
    if (theta >= Pi / 2) return 0;
    double a2 = alpha * alpha;
    return a2 / (a2 + Sqr(std::tan(theta)));
  }
};

/// Beckmann (Walter 2007 eq. 25): D = exp(-tan^2/alpha^2) / (pi alpha^2 cos^4).
struct BeckmannDistribution {
  double alpha = MinAlpha;
  static constexpr const char* kName = "Beckmann";

  double D(Vec3 wm) const {
    double tan2 = Tan2Theta(wm);
    if (!std::isfinite(tan2)) return 0;
    double a2 = alpha * alpha, cos4 = Sqr(Sqr(CosTheta(wm)));
    return std::exp(-tan2 / a2) / (Pi * a2 * cos4);
  }
  /// mu * Lambda(mu) with a = mu / (alpha sin):  Lambda = (erf(a) - 1)/2 + exp(-a^2)/(2 a
  /// sqrt(pi)).
  double MuLambda(double mu) const {
    double s = SafeSqrt(1 - mu * mu);
    if (s == 0) return 0;
    double a = mu / (alpha * s);
    if (!std::isfinite(a)) return 0;
    return std::max(0.0, (-mu * std::erfc(a) + alpha * s * std::exp(-a * a) * InvSqrtPi) / 2);
  }
  double Lambda(double mu) const { return mu > 0 ? MuLambda(mu) / mu : INFINITY; }
  /// tan^2 = -alpha^2 ln v.
  PolarParam FromV(double v) const {
    double tan2 = -Sqr(alpha) * std::log(v);
    double c = 1 / std::sqrt(1 + tan2);
    return {std::sqrt(tan2) * c, c};
  }
  double VFromTheta(double theta) const {
    if (theta >= Pi / 2) return 0;
    return std::exp(-Sqr(std::tan(theta) / alpha));
  }
};

/// Blinn-Phong (Blinn 1977, normalised for D cos): D = (s + 2)/(2 pi) (n.h)^s, s = 2/alpha^2 - 2,
/// with Beckmann's Lambda at the same alpha (Walter 2007).
struct BlinnPhongDistribution {
  double alpha = MinAlpha;
  static constexpr const char* kName = "Blinn-Phong";

  double Exponent() const { return BlinnPhongExponentFromAlpha(alpha); }
  double D(Vec3 wm) const {
    double c = CosTheta(wm);
    if (c <= 0) return 0;
    double s = Exponent();
    return (s + 2) / (2 * Pi) * std::pow(c, s);
  }
  double MuLambda(double mu) const { return BeckmannDistribution{alpha}.MuLambda(mu); }
  double Lambda(double mu) const { return BeckmannDistribution{alpha}.Lambda(mu); }
  /// v = cos^(s+2): cos = v^(1/(s+2)), sin^2 = -expm1(2 ln v / (s + 2)).
  PolarParam FromV(double v) const {
    double p = Exponent() + 2, lv = std::log(v);
    double s2 = -std::expm1(2 * lv / p);
    return {SafeSqrt(s2), std::exp(lv / p)};
  }
  double VFromTheta(double theta) const {
    if (theta >= Pi / 2) return 0;
    return std::pow(std::cos(theta), Exponent() + 2);
  }
};

/// The polar density cos^(p-1) sin, normalised: v = cos^p. Used where a lobe is a power of n.h
/// but not a normalised NDF (normalised Blinn-Phong, Ashikhmin-Shirley).
struct CosinePowerParam {
  double p = 1;
  PolarParam FromV(double v) const {
    double lv = std::log(v);
    return {SafeSqrt(-std::expm1(2 * lv / p)), std::exp(lv / p)};
  }
  double VFromTheta(double theta) const {
    if (theta >= Pi / 2) return 0;
    return std::pow(std::cos(theta), p);
  }
};

/// Which masking-shadowing term a microfacet BRDF uses.
enum class SmithForm {
  HeightCorrelated,  ///< G = 1 / (1 + Lambda(o) + Lambda(l))      (Heitz 2014 eq. 99)
  Separable,         ///< G = 1 / ((1 + Lambda(o))(1 + Lambda(l))) (Heitz 2014 eq. 98)
  VCavity            ///< Cook-Torrance: min(1, 2 nh no / oh, 2 nh nl / oh) (seed 004)
};

/// G(o, l) / mu_o at one view mu_o, finite as mu_o -> 0 (the integrators divide by mu_o; this
/// form does not), with the view's own terms (mu_o + mu_o Lambda(o), 1 / mu_o) computed once: for
/// the adaptive references' many light directions at one view. dist must outlive it.
template <class Dist>
struct GOverMuOAtView {
  const Dist* dist;
  SmithForm form;
  double mu_o;
  double viewSum = 0;  ///< mu_o + MuLambda(mu_o) (the Smith forms)
  double invMu = 0;    ///< 1 / mu_o, infinity at mu_o = 0 (the V-cavity form)

  /// The view's terms of GOverMuO(d, f, mu_o, ...) for mu_o in [0, 1].
  GOverMuOAtView(const Dist& d, SmithForm f, double mu) : dist(&d), form(f), mu_o(mu) {
    if (form == SmithForm::VCavity)
      invMu = mu_o > 0 ? 1 / mu_o : INFINITY;
    else
      viewSum = mu_o + dist->MuLambda(mu_o);
  }
  /// G / mu_o at mu_l in [0, 1]; cosTheta_h = n.h, oh = o.h > 0.
  double operator()(double mu_l, double cosTheta_h, double oh) const {
    if (mu_l <= 0) return 0;
    switch (form) {
      case SmithForm::HeightCorrelated:
        return 1 / (viewSum + mu_o * dist->MuLambda(mu_l) / mu_l);
      case SmithForm::Separable:
        return 1 / (viewSum * (1 + dist->MuLambda(mu_l) / mu_l));
      case SmithForm::VCavity: {
        if (oh <= 0) return 0;
        double g = 2 * cosTheta_h / oh;
        double b = mu_o > 0 ? g * mu_l / mu_o : INFINITY;
        return std::min({invMu, g, b});
      }
    }
    return 0;
  }
};

/// G(o, l) / mu_o, finite as mu_o -> 0 (GOverMuOAtView at mu_o, for one light direction).
/// mu_o, mu_l in [0, 1]; cosTheta_h = n.h, oh = o.h > 0.
template <class Dist>
double GOverMuO(const Dist& dist, SmithForm form, double mu_o, double mu_l, double cosTheta_h,
                double oh) {
  if (mu_l <= 0) return 0;
  return GOverMuOAtView<Dist>(dist, form, mu_o)(mu_l, cosTheta_h, oh);
}

/// Smith G1(w) = 1 / (1 + Lambda(w)).
template <class Dist>
double G1(const Dist& dist, double mu) {
  return mu > 0 ? mu / (mu + dist.MuLambda(mu)) : 0;
}

}  // namespace kiln
