// Sheen lobes: the Charlie NDF (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen
// BRDF") with the Neubelt & Pettineo 2013 visibility (Filament) or with Estevez & Kulla's fitted
// Smith Lambda (the glTF sample viewer's KHR_materials_sheen), and Ashikhmin & Premoze 2007's
// inverted-Gaussian velvet NDF with the same smooth visibility (Filament's older cloth model).
//
// Conventions (docs/models.md "Sheen"): f = D(h) V(o, l) with F = 1 and no colour (the sheen
// colour scales f outside); BRDF values exclude the cosine; wo (view) and wi (light) point away
// from the surface, normal +z; h = normalize(wo + wi); alpha = r^2 from the sheen roughness r.
// Integrated in light space (IntegrationDomain::Light): the lobes are smooth in (theta_l, phi)
// and concentrate at grazing half vectors (integrate/fixed_rule_sheen.h places panels there).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "baker/models/brdf.h"

namespace kiln {

/// The smallest sheen roughness of the Charlie models: Filament clamps its sheen roughness to
/// MIN_PERCEPTUAL_ROUGHNESS = 0.045 (alpha = 0.002025). As alpha -> 0 the Charlie NDF becomes
/// a delta on the horizon of half vectors and E(mu) -> 0 for every mu > 0 while E(0) stays
/// finite: the corner (mu, r) = (0, 0) is singular, so kiln's domain starts here and rejects
/// smaller values (MakeModel, the tables' roughness axis).
constexpr double kCharlieMinRoughness = 0.045;

/// The smallest roughness of every sheen table (the velvet's too, although the model takes 0):
/// below r ~ 0.03 the adaptive reference misses the velvet's spike of width alpha = r^2 at the
/// horizon (integrate/fixed_rule_sheen.cpp), and Filament clamps its cloth roughness to 0.045.
constexpr double kSheenTableMinRoughness = kCharlieMinRoughness;

/// The smallest view cosine of the charlie-smith tables: Filament's MIN_N_DOT_V. Below it the
/// fitted Lambda (finite but ~1e8 at mu = 0) and the clamp V <= 1 make E(mu) jump within
/// mu ~ 1e-8..1e-5 (docs/models.md "Sheen"), a layer of the fit no renderer looks up.
constexpr double kCharlieSmithMinMu = 1e-4;

/// Neubelt & Pettineo 2013 visibility V = 1 / (4 (mu_l + mu_o - mu_l mu_o)), as Filament's
/// V_Neubelt (no clamp). mu_o, mu_l in [0, 1], not both 0.
inline double NeubeltVisibility(double mu_o, double mu_l) {
  return 1 / (4 * (mu_l + mu_o - mu_l * mu_o));
}

/// sin^2(theta_h) and whether h is defined (wo + wi != 0).
inline double HalfSin2(Vec3 wo, Vec3 wi, bool* defined) {
  Vec3 s = wo + wi;
  double len2 = Dot(s, s);
  *defined = len2 > 0;
  return len2 > 0 ? Clamp((s.x * s.x + s.y * s.y) / len2, 0.0, 1.0) : 0;
}

/// Charlie NDF (Estevez & Kulla 2017 eq. 2): D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
/// normalised so that integral D cos(theta_h) dwh = 1 over the hemisphere; from sin^2(theta_h).
inline double CharlieD(double alpha, double sin2h) {
  if (sin2h <= 0) return 0;
  return (2 + 1 / alpha) * std::exp(std::log(sin2h) * (0.5 / alpha)) / (2 * Pi);
}

/// Estevez & Kulla 2017's fitted L(x) = a / (1 + b x^c) + d x + e, the five coefficients
/// interpolated between their r = 0 and r = 1 rows with t = (1 - alpha)^2 (p = t p0 + (1 - t) p1),
/// as the glTF sample viewer's lambdaSheenNumericHelper (its alphaG is kiln's alpha = r^2).
inline double CharlieSheenL(double x, double alpha) {
  double t = Sqr(1 - alpha);
  double a = Lerp(t, 21.5473, 25.3245), b = Lerp(t, 3.82987, 3.32435);
  double c = Lerp(t, 0.19823, 0.16801), d = Lerp(t, -1.97760, -1.27393);
  double e = Lerp(t, -4.32054, -4.85967);
  return a / (1 + b * std::pow(x, c)) + d * x + e;
}

/// Estevez & Kulla's Smith Lambda for the Charlie NDF: exp(L(mu)) for mu < 1/2, else
/// exp(2 L(1/2) - L(1 - mu)) (C1 at mu = 1/2). Finite at mu = 0 (a property of the fit).
/// Without the paper's terminator softening (Lambda^(1 + 2 (1 - mu_l)^8) on the light side):
/// the glTF sample viewer leaves it out, and it would break reciprocity.
inline double CharlieSheenLambda(double mu, double alpha) {
  if (mu < 0.5) return std::exp(CharlieSheenL(mu, alpha));
  return std::exp(2 * CharlieSheenL(0.5, alpha) - CharlieSheenL(1 - mu, alpha));
}

/// Ashikhmin & Premoze 2007 velvet NDF (inverted Gaussian, their eq. with A = 4), sigma = alpha:
/// D = (1 + 4 exp(-cot^2(theta_h) / alpha^2) / sin^4(theta_h)) / (pi (1 + 4 alpha^2)),
/// normalised (integral D cos = 1); as Filament's D_Ashikhmin without its sin^2 >= 2^-7 clamp.
/// alpha = 0 gives the uniform 1/pi.
inline double VelvetD(double alpha, double sin2h) {
  double a2 = alpha * alpha, norm = 1 / (Pi * (1 + 4 * a2));
  if (a2 <= 0 || sin2h <= 0) return norm;
  double cos2h = 1 - sin2h;
  return norm * (1 + 4 * std::exp(-cos2h / (a2 * sin2h)) / (sin2h * sin2h));
}

/// Charlie sheen with the Neubelt & Pettineo visibility (Filament's sheen and cloth):
/// f = D_Charlie(h) / (4 (mu_l + mu_o - mu_l mu_o)), F = 1. Zero below the horizon and where
/// both directions are on it.
struct CharlieSheen {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double alpha = 0.25;  ///< r^2, r >= kCharlieMinRoughness

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double mu_o = CosTheta(wo), mu_l = CosTheta(wi);
    if (mu_o < 0 || mu_l < 0 || mu_o + mu_l <= 0) return {};
    bool ok;
    double s2 = HalfSin2(wo, wi, &ok);
    return {ok ? CharlieD(alpha, s2) * NeubeltVisibility(mu_o, mu_l) : 0, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }
};

/// Charlie sheen with Estevez & Kulla's height-correlated Smith term as the glTF sample viewer
/// implements KHR_materials_sheen (V_Sheen, including its clamp of V to [0, 1]):
/// f = D_Charlie(h) min(1, 1 / ((1 + Lambda(mu_o) + Lambda(mu_l)) 4 mu_o mu_l)), F = 1.
/// The clamp matters: the fitted Lambda stays finite at grazing (Lambda(0) = e^(a + e)), so
/// without it E(mu) grows without bound as mu -> 0 (docs/models.md "Sheen"). It also gives the
/// limit at mu_o = 0 or mu_l = 0: f = D.
struct CharlieSmithSheen {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double alpha = 0.25;  ///< r^2, r >= kCharlieMinRoughness

  /// 4 mu_o mu_l (1 + Lambda(mu_o) + Lambda(mu_l)) = 1 / V before the clamp.
  double InverseV(double mu_o, double mu_l) const {
    return InverseVGiven(mu_o, mu_l, CharlieSheenLambda(mu_o, alpha));
  }
  /// InverseV with lambdaO = Lambda(mu_o) = CharlieSheenLambda(mu_o, alpha) given (a caller with
  /// one view keeps it): InverseV's bits.
  double InverseVGiven(double mu_o, double mu_l, double lambdaO) const {
    return 4 * mu_o * mu_l * (1 + lambdaO + CharlieSheenLambda(mu_l, alpha));
  }
  /// Where the clamp V <= 1 switches (4 mu_o mu_l (1 + Lambda(mu_o) + Lambda(mu_l)) crosses 1),
  /// a condition on mu_l alone: a scan of ln(mu_l) from 1e-12 to 1 in quarter decades, each sign
  /// change refined by 60 bisections in ln(mu_l). Ascending, deterministic; none for mu_o <= 0.
  std::vector<double> ClampSwitches(double mu_o) const {
    std::vector<double> roots;
    if (!(mu_o > 0)) return roots;
    const double lambdaO = CharlieSheenLambda(mu_o, alpha);  // (InverseV's, once)
    auto g = [&](double lnMu) { return InverseVGiven(mu_o, std::exp(lnMu), lambdaO) - 1; };
    const double lo = std::log(1e-12), step = std::log(10.0) / 4;
    const int n = static_cast<int>(std::ceil(-lo / step));
    double a = lo, ga = g(a);
    for (int i = 1; i <= n; ++i) {
      double b = i == n ? 0 : lo + i * step, gb = g(b);
      if ((ga > 0) != (gb > 0)) {
        double x0 = a, x1 = b, g0 = ga;
        for (int k = 0; k < 60; ++k) {
          double xm = 0.5 * (x0 + x1), gm = g(xm);
          if ((gm > 0) == (g0 > 0)) {
            x0 = xm;
            g0 = gm;
          } else {
            x1 = xm;
          }
        }
        roots.push_back(std::exp(0.5 * (x0 + x1)));
      }
      a = b;
      ga = gb;
    }
    return roots;
  }
  /// The light cosines mu_l at which f(o, l) has a kink for view cosine mu_o (the adaptive
  /// light-space integrator's panel boundaries): Lambda's switch at mu_l = 1/2 and the clamp's
  /// switches (ClampSwitches).
  std::vector<double> LightMuKinks(double mu_o) const {
    std::vector<double> k = ClampSwitches(mu_o);
    k.push_back(0.5);
    return k;
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const { return {FWith(wo, wi, nullptr), 0}; }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }
  /// f with lambdaO = CharlieSheenLambda(CosTheta(wo), alpha) given (a caller with one view
  /// keeps it): f's bits.
  double FGivenLambdaO(Vec3 wo, Vec3 wi, double lambdaO) const { return FWith(wo, wi, &lambdaO); }

 private:
  /// f, Lambda(mu_o) from *lambdaO when given.
  double FWith(Vec3 wo, Vec3 wi, const double* lambdaO) const {
    double mu_o = CosTheta(wo), mu_l = CosTheta(wi);
    if (mu_o < 0 || mu_l < 0 || mu_o + mu_l <= 0) return 0;
    bool ok;
    double s2 = HalfSin2(wo, wi, &ok);
    double inv = lambdaO ? InverseVGiven(mu_o, mu_l, *lambdaO) : InverseV(mu_o, mu_l);
    return ok ? CharlieD(alpha, s2) * (inv > 1 ? 1 / inv : 1.0) : 0;
  }
};

/// Ashikhmin & Premoze 2007 velvet: f = D_velvet(h) / (4 (mu_l + mu_o - mu_l mu_o)), F = 1
/// (their smooth denominator, Filament's cloth with V_Neubelt). alpha = r^2.
struct AshikhminVelvet {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::Light;
  double alpha = 0.25;

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double mu_o = CosTheta(wo), mu_l = CosTheta(wi);
    if (mu_o < 0 || mu_l < 0 || mu_o + mu_l <= 0) return {};
    bool ok;
    double s2 = HalfSin2(wo, wi, &ok);
    return {ok ? VelvetD(alpha, s2) * NeubeltVisibility(mu_o, mu_l) : 0, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }
};

}  // namespace kiln
