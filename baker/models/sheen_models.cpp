// The sheen lobes' descriptors (models/model_list.inc, models/sheen.h): light-space integrals,
// no smooth limit, the sheen fixed rule; the Charlie models start at r = kCharlieMinRoughness
// (singular corner below, docs/models.md). Their catalogue axes (tables/catalogue.cpp says why):
// E(mu) has a layer of width ~ r at mu = 0 and, inside it, the mu ln mu of the Neubelt pole
// (charlie, velvet): root4 mu axes; the Charlie models' E(0) ~ 0.4 / r: log roughness axes.
#include "baker/models/model_list.h"

namespace kiln::model_list {
namespace {

/// The fields the sheen lobes share.
ModelInfo Sheen(const char* id, const char* summary, const char* roughness, ParamInfo rough) {
  ModelInfo m;
  m.id = id;
  m.summary = summary;
  m.roughness = roughness;
  m.params = {std::move(rough)};
  m.reciprocal = true;
  m.nonNegative = true;
  m.domain = IntegrationDomain::Light;
  m.rule = RuleFamily::Sheen;
  m.catalogue = CatalogueGroup::Sheen;
  m.schlickFresnel = false;
  return m;
}

}  // namespace

ModelInfo CharlieModel() {
  ModelInfo m = Sheen(
      "charlie",
      "Charlie sheen NDF (Estevez & Kulla 2017), Neubelt & Pettineo 2013 visibility (Filament)",
      "alpha = r^2, r in [0.045, 1] (Filament's clamp)",
      {"roughness", kCharlieMinRoughness, 1, 0.5, "sheen roughness r, alpha = r^2"});
  m.make = [](const ModelArgs& a) -> AnyModel {
    return CharlieSheen{AlphaFromPerceptual(a.roughness)};
  };
  m.fixedRuleVersion = "3";    // 3: the NDF's exp and log inline, SIMD rows (last bits)
  m.averageRuleVersion = "4";  // 3: the Charlie pair's own mu panels; 4: as fixedRuleVersion 3
  // The steepest layer (E(0) = 8.9 at r = 0.045): 192 nodes keep the lookup error below 1e-3
  // (trial bakes with 128 log-warped roughness nodes: 1.7e-3 with 128, 9.9e-4 with 192).
  m.muAxis = AxisDefault{0, 1, 192, Warp::Root4};
  // Relative error h^2 / (4 r^2) under linear interpolation: a log axis (constant h / r), 128
  // nodes (2.6e-3 of lookup error with 64), from kSheenTableMinRoughness.
  m.roughnessAxis = AxisDefault{kSheenTableMinRoughness, 1, 128, Warp::Log};
  m.ltcOnRequest = 1;
  m.ltcRoughnessLo = kSheenTableMinRoughness;  // below it the NDF collapses onto the horizon
  return m;
}

ModelInfo CharlieSmithModel() {
  ModelInfo m =
      Sheen("charlie-smith",
            "Charlie sheen NDF, Estevez & Kulla 2017 fitted Smith Lambda (KHR_materials_sheen)",
            "alpha = r^2, r in [0.045, 1]; Lambda fit interpolated in (1 - alpha)^2",
            {"roughness", kCharlieMinRoughness, 1, 0.5, "sheen roughness r, alpha = r^2"});
  m.make = [](const ModelArgs& a) -> AnyModel {
    return CharlieSmithSheen{AlphaFromPerceptual(a.roughness)};
  };
  m.sheenRule = SheenRule::FittedSmith;
  m.fixedRuleVersion = "4";  // 3: its own node counts; 4: the NDF's exp and log inline, SIMD
  m.averageRuleVersion = "4";
  m.averageKink = 0.5;  // Lambda(mu)'s C1 switch
  // From mu = 1e-4, Filament's MIN_N_DOT_V: below it the fitted Lambda's clamp V <= 1 makes E
  // jump (1.63 at mu = 1e-8, 0.82 at 1e-6, 0.59 at 1e-4 for r = 0.386), a layer of the fit no
  // renderer looks up. Without the grazing peak of E(0) its grid can be smaller: 112 mu x 96
  // roughness nodes declare 7.7e-4 (trial bakes: 5.8e-4 with 128 x 128, 7.5e-4 with 128 x 96,
  // 1.0e-3 with 96 x 128 and with 128 x 80).
  m.muAxis = AxisDefault{kCharlieSmithMinMu, 1, 112, Warp::Root4};
  m.roughnessAxis = AxisDefault{kSheenTableMinRoughness, 1, 96, Warp::Log};
  m.ltcCatalogue = 4;
  m.ltcRoughnessLo = kSheenTableMinRoughness;
  // Its N.V = 0 row: E(0) = 1.96 but E(1e-4) = 1.26 at r = 0.1 (the Lambda fit is singular at
  // grazing): the norm there is E(1e-4), where charlie-smith-albedo starts.
  m.ltcNormMuLo = kCharlieSmithMinMu;
  m.ltcNormNote =
      ", at mu below 1e-4 (the N.V = 0 row) the value at mu = 1e-4, where the model's albedo "
      "starts (charlie-smith-albedo)";
  m.ltcRuleVersion = "fit4o-rule3-mu0-1e-4-p10";
  return m;
}

ModelInfo AshikhminVelvetModel() {
  ModelInfo m = Sheen(
      "ashikhmin-velvet",
      "inverted-Gaussian velvet NDF (Ashikhmin & Premoze 2007), Neubelt visibility (Filament)",
      "sigma = alpha = r^2, r in [0, 1]",
      {"roughness", 0, 1, 0.5, "cloth roughness r, sigma = alpha = r^2"});
  m.energyConserving = true;
  m.make = [](const ModelArgs& a) -> AnyModel {
    return AshikhminVelvet{AlphaFromPerceptual(a.roughness)};
  };
  m.fixedRuleVersion = "3";    // the NDF's exp inline, SIMD rows (last bits)
  m.averageSheenLayer = 1e-4;  // the finest layer of the sheens' E at mu = 0
  // Smooth in r: 48 x 48 (7.7e-4 of lookup error).
  m.muAxis = AxisDefault{0, 1, 48, Warp::Root4};
  m.roughnessAxis = AxisDefault{kSheenTableMinRoughness, 1, 48, Warp::Linear};
  m.ltcOnRequest = 9;  // its NDF is uniform at r = 0: from 0
  return m;
}

}  // namespace kiln::model_list
