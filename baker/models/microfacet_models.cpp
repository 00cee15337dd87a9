// The microfacet and Phong specular lobes' descriptors (models/model_list.inc): half-vector
// integrals; the microfacet fixed rule for the models it is tuned for, adaptive quadrature for
// the others (rule family None).
#include "baker/models/model_list.h"

namespace kiln::model_list {
namespace {

/// The microfacet lobes' roughness text: r = 0 is the smooth limit in their integrals
/// (QuantityInfo::smoothLimit).
constexpr const char* kLobeText =
    "alpha = max(r^2, 1e-12) for r > 0 (Disney 2012); r = 0: the mirror, exact";

/// The fields every specular lobe shares: perceptual roughness, f0 / eta / k Fresnel.
ModelInfo Specular(const char* id, const char* summary) {
  ModelInfo m;
  m.id = id;
  m.summary = summary;
  m.roughness = kLobeText;
  m.params = {Rough(1, "perceptual roughness r, alpha = r^2"), F0(1), Eta(), K()};
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = true;
  m.domain = IntegrationDomain::HalfVector;
  return m;
}

/// A microfacet lobe MicrofacetBRDF<D> with Smith form `form`, baked by the microfacet rule
/// with NDF `ndf`.
template <class D>
ModelInfo Microfacet(const char* id, const char* summary, SmithForm form, MicrofacetNdf ndf) {
  ModelInfo m = Specular(id, summary);
  m.make = [form](const ModelArgs& a) -> AnyModel {
    D dist;
    dist.alpha = a.alpha;
    return MicrofacetBRDF<D>{dist, form, a.fresnel};
  };
  m.rule = RuleFamily::Microfacet;
  m.microfacetNdf = ndf;
  m.separableSmith = form == SmithForm::Separable;
  return m;
}

}  // namespace

ModelInfo GgxModel() {
  ModelInfo m =
      Microfacet<GGXDistribution>("ggx", "GGX, height-correlated Smith (Walter 2007, Heitz 2014)",
                                  SmithForm::HeightCorrelated, MicrofacetNdf::GGX);
  m.kernel = MicrofacetKernel::GgxHeightCorrelated;
  m.catalogue = CatalogueGroup::Microfacet;
  m.fresnelTables = true;
  m.ltcCatalogue = 1;
  m.ltcSelfNormalisedError = true;
  return m;
}

ModelInfo GgxSeparableModel() {
  ModelInfo m = Microfacet<GGXDistribution>("ggx-separable", "GGX, separable Smith",
                                            SmithForm::Separable, MicrofacetNdf::GGX);
  m.kernel = MicrofacetKernel::GgxSeparable;
  m.fixedRuleVersion = "3";  // by the GGX kernel
  m.catalogue = CatalogueGroup::Microfacet;
  m.ltcOnRequest = 2;
  return m;
}

ModelInfo GgxVCavityModel() {
  ModelInfo m = Specular("ggx-vcavity", "GGX, Cook-Torrance V-cavity G");
  m.make = [](const ModelArgs& a) -> AnyModel {
    GGXDistribution dist;
    dist.alpha = a.alpha;
    return MicrofacetBRDF<GGXDistribution>{dist, SmithForm::VCavity, a.fresnel};
  };
  m.rule = RuleFamily::None;  // no fixed rule takes the V-cavity G: adaptive quadrature
  m.ltcOnRequest = 10;
  return m;
}

ModelInfo BeckmannModel() {
  ModelInfo m =
      Microfacet<BeckmannDistribution>("beckmann", "Beckmann, height-correlated Smith",
                                       SmithForm::HeightCorrelated, MicrofacetNdf::Beckmann);
  m.fixedRuleVersion = "4";  // 3: fewer nodes; 4: one-exp Lambda, SIMD nodes (last bits)
  m.catalogue = CatalogueGroup::Microfacet;
  m.ltcCatalogue = 2;
  m.ltcSelfNormalisedError = true;
  return m;
}

ModelInfo BeckmannSeparableModel() {
  ModelInfo m = Microfacet<BeckmannDistribution>("beckmann-separable", "Beckmann, separable Smith",
                                                 SmithForm::Separable, MicrofacetNdf::Beckmann);
  m.fixedRuleVersion = "4";
  m.catalogue = CatalogueGroup::Microfacet;
  m.ltcOnRequest = 3;
  return m;
}

ModelInfo BlinnPhongModel() {
  ModelInfo m = Microfacet<BlinnPhongDistribution>(
      "blinn-phong", "Blinn-Phong NDF s = 2/alpha^2 - 2, Beckmann Smith height-correlated",
      SmithForm::HeightCorrelated, MicrofacetNdf::BlinnPhong);
  m.energyConserving = false;
  m.fixedRuleVersion = "4";
  m.catalogue = CatalogueGroup::Microfacet;
  // Its albedo climbs to sqrt(pi) at r = 1 with a curvature of ~70: 128 sqrt nodes (spacing
  // 2 / 127 there) left 2e-3 of lookup error, so it gets 256 (a linear axis errs more near
  // r = 0: 1e-2 in its first cell, measured).
  m.roughnessAxis = AxisDefault{0, 1, 256, Warp::Sqrt};
  m.ltcCatalogue = 3;
  m.ltcSelfNormalisedError = true;
  return m;
}

ModelInfo BlinnPhongNormalizedModel() {
  ModelInfo m =
      Specular("blinn-phong-normalized", "normalised Blinn-Phong (tri-Ace, Gotanda 2010)");
  m.roughness = "alpha = r^2, s = 2/alpha^2 - 2";
  m.params = {Rough(1, "perceptual roughness r, s = 2/r^4 - 2"), Rs(1), F0(1), Eta(), K()};
  m.make = [](const ModelArgs& a) -> AnyModel {
    return NormalizedBlinnPhong{BlinnPhongExponentFromAlpha(a.alpha), a.rs, a.fresnel};
  };
  m.rule = RuleFamily::None;
  return m;
}

ModelInfo AshikhminShirleyModel() {
  ModelInfo m =
      Specular("ashikhmin-shirley", "anisotropic Phong specular (Ashikhmin & Shirley 2000)");
  m.roughness = "alpha = r^2, n_u = n_v = 2/alpha^2 - 2 unless nu, nv given";
  m.params = {Rough(1, "perceptual roughness r"),
              {"nu", 0, 1e7, 0, "exponent along u (overrides r)"},
              {"nv", 0, 1e7, 0, "exponent along v (overrides r)"},
              F0(1),
              Eta(),
              K()};
  m.make = [](const ModelArgs& a) -> AnyModel {
    const double s = BlinnPhongExponentFromAlpha(a.alpha);
    const double nu = a.nu ? *a.nu : s, nv = a.nv ? *a.nv : (a.nu ? *a.nu : s);
    return AshikhminShirleySpecular{nu, nv, a.fresnel};
  };
  m.rule = RuleFamily::None;
  return m;
}

}  // namespace kiln::model_list
