// The BSDF models (ModelInfo::bsdf): kept apart from AllModels(), whose models are BRDFs over the
// upper hemisphere that AnyModel holds and every BRDF test walks.
#include "baker/models/registry.h"

namespace kiln {

const std::vector<ModelInfo>& AllBsdfModels() {
  static const std::vector<ModelInfo> models = [] {
    ModelInfo m;
    m.id = "ggx-dielectric";
    m.summary =
        "rough dielectric: GGX reflection + refraction, height-correlated Smith, exact Fresnel "
        "(Walter 2007)";
    m.roughness = "alpha = r^2 (Disney 2012); r = 0: the smooth interface, exact";
    m.params = {{"roughness", 0, 1, 0.5, "perceptual roughness r, alpha = r^2"},
                {"eta", 0.01, 100, 1.5,
                 "inside / outside index seen from the view (< 1: leaving a denser medium)"}};
    m.reciprocal = true;  // with its n^2 factor: f_t(o, i) / n_o^2 = f_t(i, o) / n_i^2
    m.energyConserving = true;
    m.nonNegative = true;
    m.hasRho2 = false;
    m.domain = IntegrationDomain::HalfVector;
    m.bsdf = true;
    return std::vector<ModelInfo>{m};
  }();
  return models;
}

const ModelInfo* FindBsdfModel(const std::string& id) {
  for (const ModelInfo& m : AllBsdfModels())
    if (m.id == id) return &m;
  return nullptr;
}

}  // namespace kiln
