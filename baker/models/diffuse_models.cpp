// The diffuse models' descriptors (models/model_list.inc): light-space integrals, the diffuse
// fixed rule, the catalogue's diffuse group. The mu axis of an albedo table is sqrt unless a
// model states its own (tables/catalogue.cpp DiffuseMuAxis says why the angle warp suits the
// models smooth in theta_o).
#include "baker/models/model_list.h"

namespace kiln::model_list {
namespace {

/// The fields every diffuse model shares.
ModelInfo Diffuse(const char* id, const char* summary, const char* roughness,
                  std::vector<ParamInfo> params) {
  ModelInfo m;
  m.id = id;
  m.summary = summary;
  m.roughness = roughness;
  m.params = std::move(params);
  m.domain = IntegrationDomain::Light;
  m.rule = RuleFamily::Diffuse;
  m.catalogue = CatalogueGroup::Diffuse;
  return m;
}

}  // namespace

ModelInfo LambertModel() {
  ModelInfo m = Diffuse("lambert", "rho/pi (Lambert 1760)", "none", {Rho()});
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return Lambert{a.rho}; };
  m.albedoIsRho = true;  // E = rho exactly: a scene needs no table
  return m;
}

ModelInfo BurleyModel() {
  ModelInfo m = Diffuse("burley", "Disney diffuse (Burley 2012)", "r as is",
                        {Rough(1, "Disney roughness"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return BurleyDiffuse{a.roughness, a.rho}; };
  return m;
}

ModelInfo FrostbiteModel() {
  ModelInfo m = Diffuse("frostbite", "renormalised Disney diffuse (Lagarde 2014)", "r as is",
                        {Rough(1, "Disney roughness"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return FrostbiteDiffuse{a.roughness, a.rho}; };
  return m;
}

ModelInfo OrenNayarModel() {
  ModelInfo m = Diffuse("oren-nayar", "full Oren-Nayar with interreflection (Oren & Nayar 1994)",
                        kSigmaText, {Rough(kHalfPi, "sigma, radians"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = false;
  m.hasRho2 = true;
  m.make = [](const ModelArgs& a) -> AnyModel { return OrenNayar{a.roughness, a.rho}; };
  return m;
}

ModelInfo OrenNayarQualitativeModel() {
  ModelInfo m = Diffuse("oren-nayar-qualitative", "qualitative Oren-Nayar (Oren & Nayar 1994)",
                        kSigmaText, {Rough(kHalfPi, "sigma, radians"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return OrenNayarQualitative{a.roughness, a.rho, false};
  };
  m.muAxis = AxisDefault{0, 1, 64, Warp::Angle};
  return m;
}

ModelInfo OrenNayarQualitativeIrModel() {
  ModelInfo m =
      Diffuse("oren-nayar-qualitative-ir", "qualitative Oren-Nayar, A with 0.57 (interreflection)",
              kSigmaText, {Rough(kHalfPi, "sigma, radians"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return OrenNayarQualitative{a.roughness, a.rho, true};
  };
  m.muAxis = AxisDefault{0, 1, 64, Warp::Angle};
  return m;
}

ModelInfo FujiiModel() {
  ModelInfo m = Diffuse("fujii", "tiny improved Oren-Nayar (Fujii)", kSigmaText,
                        {Rough(kHalfPi, "sigma, radians"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = true;
  m.make = [](const ModelArgs& a) -> AnyModel { return FujiiOrenNayar{a.roughness, a.rho, false}; };
  return m;
}

ModelInfo FujiiNormalizedModel() {
  ModelInfo m = Diffuse("fujii-normalized", "energy-normalised improved Oren-Nayar (Fujii)",
                        "sigma' = r in [0,1]", {Rough(1, "sigma'"), Rho()});
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return FujiiOrenNayar{a.roughness, a.rho, true}; };
  m.muAxis = AxisDefault{0, 1, 64, Warp::Angle};
  return m;
}

ModelInfo GotandaFresnelModel() {
  ModelInfo m =
      Diffuse("gotanda-fresnel", "normalised Oren-Nayar with Fresnel (Gotanda 2014 eq. 33-34)",
              kSigmaText, {Rough(kHalfPi, "sigma, radians"), Rho(), F0(0)});
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = false;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return GotandaFresnelDiffuse{a.roughness, a.rho, a.f0};
  };
  return m;
}

ModelInfo GotandaGgxModel() {
  ModelInfo m = Diffuse("gotanda-ggx", "Oren-Nayar fitted to GGX + Smith (Gotanda 2014 eq. 35)",
                        kSigmaText, {Rough(1, "sigma, radians (the fit's range)"), Rho(), F0(0)});
  m.reciprocal = false;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return GotandaGGXDiffuse{a.roughness, a.rho, a.f0};
  };
  m.muAxis = AxisDefault{0, 1, 128, Warp::Angle};
  return m;
}

ModelInfo HammonModel() {
  ModelInfo m = Diffuse("hammon", "GGX diffuse (Hammon 2017)", "alpha = r^2 (Disney 2012)",
                        {Rough(1, "perceptual roughness r, alpha = r^2"), Rho()});
  m.reciprocal = true;
  m.energyConserving = false;
  m.nonNegative = true;
  m.hasRho2 = true;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return HammonDiffuse{AlphaFromPerceptual(a.roughness), a.rho};
  };
  return m;
}

ModelInfo ShirleyModel() {
  ModelInfo m = Diffuse("shirley", "coupled diffuse (Shirley et al. 1997)", "none", {Rho(), F0(0)});
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return ShirleyDiffuse{a.rho, a.f0}; };
  return m;
}

ModelInfo AshikhminShirleyDiffuseModel() {
  ModelInfo m = Diffuse("ashikhmin-shirley-diffuse", "coupled diffuse (Ashikhmin & Shirley 2000)",
                        "none", {Rho(), Rs(0)});
  m.reciprocal = true;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return AshikhminShirleyDiffuse{a.rho, a.rs}; };
  return m;
}

ModelInfo TriAceLambertModel() {
  ModelInfo m = Diffuse("triace-lambert", "energy-conserving Lambert (tri-Ace, Gotanda 2010)",
                        "none", {Rho(), Rs(0), F0(0)});
  m.reciprocal = false;
  m.energyConserving = true;
  m.nonNegative = true;
  m.hasRho2 = false;
  m.make = [](const ModelArgs& a) -> AnyModel { return TriAceLambert{a.rho, a.rs, a.f0}; };
  return m;
}

}  // namespace kiln::model_list
