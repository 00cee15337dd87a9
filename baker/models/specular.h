// Specular lobes: the Torrance-Sparrow / Cook-Torrance microfacet BRDF (seed 001; Walter et al.
// 2007), tri-Ace's normalised Blinn-Phong (Gotanda 2010, seed 004) and the Ashikhmin & Shirley
// 2000 anisotropic Phong lobe (seed 004).
//
// Half-vector integration (integrate/hemisphere.h) walks microfacet normals wm by (v, phi_h),
// v the complementary CDF of a polar density q(theta_h) (normalised over sin dtheta dphi).
// With l = reflect(o, wm), dl = 4 (o.h) dwm, so
//     E(o) = integral f mu_l dl = integral_0^1 dv integral_0^2pi dphi_h  f mu_l 4 (o.h) / (2 pi q).
// HalfWeight() returns that integrand, with q cancelled analytically (no 0/0 where D underflows).
#pragma once
#include <algorithm>

#include "baker/models/brdf.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"

namespace kiln {

/// One microfacet normal of a half-vector integration and the directions it implies.
struct HalfSample {
  Vec3 wo, wm, wi;
  double mu_o, mu_l;      ///< n.o, n.l (mu_l > 0 inside the integration domain)
  double cosTheta_h, oh;  ///< n.h, o.h
};

/// Torrance-Sparrow: f = D(h) G(o, l) F(o.h) / (4 mu_o mu_l), zero unless mu_o, mu_l > 0.
/// Dist is GGXDistribution, BeckmannDistribution or BlinnPhongDistribution; G per SmithForm.
template <class Dist>
struct MicrofacetBRDF {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  Dist dist;
  SmithForm form = SmithForm::HeightCorrelated;
  Fresnel fresnel;

  double G(double mu_o, double mu_l, double cosTheta_h, double oh) const {
    return mu_o * GOverMuO(dist, form, mu_o, mu_l, cosTheta_h, oh);
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double mu_o = CosTheta(wo), mu_l = CosTheta(wi);
    if (mu_o <= 0 || mu_l <= 0) return {};
    Vec3 wm = Normalize(wo + wi);
    double oh = Dot(wo, wm);
    double value = dist.D(wm) * G(mu_o, mu_l, CosTheta(wm), oh) * fresnel(oh) / (4 * mu_o * mu_l);
    return {std::isfinite(value) ? value : 0, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // Half-vector integration: q = D cos(theta_h), so f mu_l 4 (o.h)/(2 pi q) = G F (o.h)/(2 pi mu_o
  // n.h).
  PolarParam FromV(double v) const { return dist.FromV(v); }
  double VFromTheta(double theta) const { return dist.VFromTheta(theta); }
  double HalfWeight(const HalfSample& s) const { return HalfWeightAtView(s.mu_o)(s); }
  /// HalfWeight at one view (the adaptive references' per-view form): w(s) for samples with
  /// s.mu_o = mu_o, the view's masking terms computed once. The model must outlive it.
  struct ViewHalfWeight {
    const MicrofacetBRDF* m;
    GOverMuOAtView<Dist> g;
    double operator()(const HalfSample& s) const {
      return g(s.mu_l, s.cosTheta_h, s.oh) * m->fresnel(s.oh) * s.oh / (2 * Pi * s.cosTheta_h);
    }
  };
  /// The per-view HalfWeight at view cosine mu_o (ViewHalfWeight).
  ViewHalfWeight HalfWeightAtView(double mu_o) const {
    return {this, GOverMuOAtView<Dist>(dist, form, mu_o)};
  }
  /// cos(phi_h) where the V-cavity min() switches branch, at polar angle (sinTheta_h, cosTheta_h):
  /// 2 nh mu_o = oh, 2 nh mu_l = oh, and mu_l = mu_o. None for the Smith forms.
  /// The mu_l below which masking of l bends (alpha: Lambda's scale); see IntegrateHalfVector.
  double MaskingScale() const { return dist.alpha; }
  int PhiKinks(double mu_o, double sinTheta_o, PolarParam h, double* cosPhi) const {
    if (form != SmithForm::VCavity || sinTheta_o <= 0 || h.sinTheta <= 0) return 0;
    double st = sinTheta_o * h.sinTheta, c = h.cosTheta;
    int count = 0;
    cosPhi[count++] = mu_o * c / st;  // o.h = 2 nh mu_o
    double den = 4 * c * c - 1;       // o.h (4 nh^2 - 1) = 2 nh mu_o
    if (den > 0) cosPhi[count++] = (2 * c * mu_o / den - mu_o * c) / st;
    cosPhi[count++] = mu_o * h.sinTheta / (c * sinTheta_o);  // mu_l = mu_o
    return count;
  }
  int ThetaKinks(double theta_o, double* theta) const {
    if (form != SmithForm::VCavity) return 0;
    theta[0] = theta_o;           // mu_l = mu_o curve leaves phi = 0
    theta[1] = Pi / 2 - theta_o;  // o.h = 2 nh mu_o enters at phi = 0
    return 2;
  }
};

/// tri-Ace normalised Blinn-Phong: f = R_s (s + 2)/(4 pi (2 - 2^(-s/2))) F(o.h) (n.h)^s,
/// s = 2/alpha^2 - 2. The factor makes integral over o of f = R_s F for l = n (seed 004).
struct NormalizedBlinnPhong {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  double s = 0;   ///< exponent
  double rs = 1;  ///< specular reflectance R_s
  Fresnel fresnel;

  /// The exact normalisation (s + 2) / (4 pi (2 - 2^(-s/2))).
  static double Normalization(double s) { return (s + 2) / (4 * Pi * (2 - std::exp2(-s / 2))); }
  /// tri-Ace's linear approximation (s + 2.04) / (8 pi).
  static double NormalizationApprox(double s) { return (s + 2.04) / (8 * Pi); }

  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    if (CosTheta(wo) <= 0 || CosTheta(wi) <= 0) return {};
    Vec3 wm = Normalize(wo + wi);
    double nh = std::max(0.0, CosTheta(wm));
    return {rs * Normalization(s) * fresnel(Dot(wo, wm)) * std::pow(nh, s), 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // q = (s + 1) cos^s / (2 pi): f mu_l 4 (o.h) / (2 pi q) = 4 N_s R_s F mu_l (o.h) / (s + 1).
  PolarParam FromV(double v) const { return CosinePowerParam{s + 1}.FromV(v); }
  double VFromTheta(double theta) const { return CosinePowerParam{s + 1}.VFromTheta(theta); }
  double HalfWeight(const HalfSample& h) const { return Weight(rs * HalfWeightFactor(), h); }
  /// (s + 2) / (pi (s + 1) (2 - 2^(-s/2))), the sample-independent factor of HalfWeight.
  double HalfWeightFactor() const { return (s + 2) / (Pi * (s + 1) * (2 - std::exp2(-s / 2))); }
  /// HalfWeight given its factor rsK = rs HalfWeightFactor(): rsK F(o.h) mu_l (o.h), left to right.
  double Weight(double rsK, const HalfSample& h) const {
    return rsK * fresnel(h.oh) * h.mu_l * h.oh;
  }
  /// HalfWeight with rs HalfWeightFactor() computed once: the same bits.
  struct ViewHalfWeight {
    const NormalizedBlinnPhong* m;
    double rsK;  ///< rs HalfWeightFactor()
    double operator()(const HalfSample& h) const { return m->Weight(rsK, h); }
  };
  /// The per-view HalfWeight (ViewHalfWeight; it does not depend on the view). The model must
  /// outlive it.
  ViewHalfWeight HalfWeightAtView(double) const { return {this, rs * HalfWeightFactor()}; }
  double MaskingScale() const { return 0; }  // no masking term
  int PhiKinks(double, double, PolarParam, double*) const { return 0; }
  int ThetaKinks(double, double*) const { return 0; }
};

/// Ashikhmin-Shirley 2000 anisotropic Phong specular (seed 004):
/// f = sqrt((n_u + 1)(n_v + 1))/(8 pi) (n.h)^((n_u h_u^2 + n_v h_v^2)/(1 - (n.h)^2))
///     / ((h.o) max(mu_l, mu_o)) F(o.h), tangent u = +x, v = +y.
struct AshikhminShirleySpecular {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  double nu = 1, nv = 1;
  Fresnel fresnel;

  double Exponent(Vec3 wm) const {
    double s2 = Sin2Theta(wm);
    if (s2 <= 0) return (nu + nv) / 2;
    return (nu * wm.x * wm.x + nv * wm.y * wm.y) / s2;
  }
  RhoParts Parts(Vec3 wo, Vec3 wi) const {
    double mu_o = CosTheta(wo), mu_l = CosTheta(wi);
    if (mu_o <= 0 || mu_l <= 0) return {};
    Vec3 wm = Normalize(wo + wi);
    double oh = Dot(wo, wm), nh = std::max(0.0, CosTheta(wm));
    if (oh <= 0) return {};
    double value = std::sqrt((nu + 1) * (nv + 1)) / (8 * Pi) * std::pow(nh, Exponent(wm)) /
                   (oh * std::max(mu_l, mu_o)) * fresnel(oh);
    return {value, 0};
  }
  double f(Vec3 wo, Vec3 wi) const { return Parts(wo, wi).lin; }

  // q = (p) cos^(p-1) / (2 pi) with p = min(n_u, n_v) + 1, so
  // f mu_l 4 (o.h)/(2 pi q) = sqrt((n_u+1)(n_v+1)) cos^(e - p + 1) F mu_l / (2 pi p max(mu_l,
  // mu_o)).
  double P() const { return std::min(nu, nv) + 1; }
  PolarParam FromV(double v) const { return CosinePowerParam{P()}.FromV(v); }
  double VFromTheta(double theta) const { return CosinePowerParam{P()}.VFromTheta(theta); }
  double HalfWeight(const HalfSample& h) const {
    double p = P();
    return Weight(p, std::sqrt((nu + 1) * (nv + 1)) / p, h);
  }
  /// HalfWeight given p = P() and its factor norm = sqrt((n_u + 1)(n_v + 1)) / p, in its order.
  double Weight(double p, double norm, const HalfSample& h) const {
    double e = Exponent(h.wm);
    double c = e > p - 1 ? std::pow(h.cosTheta_h, e - p + 1) : 1.0;
    return norm * c * fresnel(h.oh) * h.mu_l / (2 * Pi * std::max(h.mu_l, h.mu_o));
  }
  /// HalfWeight with P() and sqrt((n_u + 1)(n_v + 1)) / P() computed once: the same bits.
  struct ViewHalfWeight {
    const AshikhminShirleySpecular* m;
    double p, norm;
    double operator()(const HalfSample& h) const { return m->Weight(p, norm, h); }
  };
  /// The per-view HalfWeight (ViewHalfWeight; it does not depend on the view). The model must
  /// outlive it.
  ViewHalfWeight HalfWeightAtView(double) const {
    double p = P();
    return {this, p, std::sqrt((nu + 1) * (nv + 1)) / p};
  }
  double MaskingScale() const { return 0; }  // no masking term
  /// max(mu_l, mu_o) switches where mu_l = mu_o: cos(phi_h) = tan(theta_h) / tan(theta_o).
  int PhiKinks(double mu_o, double sinTheta_o, PolarParam h, double* cosPhi) const {
    if (sinTheta_o <= 0 || h.cosTheta <= 0) return 0;
    cosPhi[0] = mu_o * h.sinTheta / (h.cosTheta * sinTheta_o);
    return 1;
  }
  int ThetaKinks(double theta_o, double* theta) const {
    theta[0] = theta_o;
    return 1;
  }
};

}  // namespace kiln
