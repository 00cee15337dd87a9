// Extensions without a table: reported with the reason, never fatal.
#include <catch2/catch.hpp>

#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;
using Kind = SceneNote::Kind;

TEST_CASE("Specular, iridescence, emissive strength, unknown: each reported with its reason",
          "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("sheen_specular.gltf"));
  CHECK(TableNames(plan) == Names{"ggx-dfg-r0.8", "ggx-albedo-r0.8", "ggx-albedo-avg-r0.8",
                                  "charlie-smith-albedo-r0.5"});
  CHECK(FindNote(plan, Kind::NotYet, "KHR_materials_sheen") == nullptr);  // scene_gltf_sheen.cpp
  const PlanNote* specular = FindNote(plan, Kind::NoTable, "KHR_materials_specular");
  REQUIRE(specular);
  CHECK(specular->why.find("ggx-dfg") != std::string::npos);
  CHECK(FindNote(plan, Kind::NoEffect, "KHR_materials_iridescence"));  // iridescenceFactor 0
  CHECK(FindNote(plan, Kind::NoTable, "KHR_materials_emissive_strength"));
  CHECK(FindNote(plan, Kind::NoTable, "KHR_texture_transform"));  // not a material extension
  const PlanNote* unknown = FindNote(plan, Kind::Unknown, "EXT_fancy_shading");
  REQUIRE(unknown);
  CHECK(unknown->materials == Names{"'Velvet' (/materials/0)"});
  CHECK(plan.warnings.empty());  // used, not required
}

TEST_CASE("An unknown required extension is a warning, the plan covers the rest", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("required_unknown.gltf"));
  CHECK(TableNames(plan) == Names{"ggx-dfg-r0.25", "ggx-albedo-r0.25", "ggx-albedo-avg-r0.25"});
  REQUIRE(plan.warnings.size() == 1);
  CHECK(plan.warnings[0].find("/extensionsRequired/0: 'EXT_future_brdf' is required but unknown") !=
        std::string::npos);
}

TEST_CASE("Unlit materials need nothing, anisotropy and iridescence are not yet tables",
          "[scene]") {
  Plan unlit = PlanText(OneMaterialGltf(R"({"extensions": {"KHR_materials_unlit": {}}})"));
  CHECK(unlit.tables.empty());
  CHECK(FindNote(unlit, Kind::NoTable, "KHR_materials_unlit"));
  Plan later = PlanText(OneMaterialGltf(R"({"extensions": {
      "KHR_materials_anisotropy": {"anisotropyStrength": 0.5},
      "KHR_materials_iridescence": {"iridescenceFactor": 1}}})"));
  CHECK(FindNote(later, Kind::NotYet, "KHR_materials_anisotropy"));
  CHECK(FindNote(later, Kind::NotYet, "KHR_materials_iridescence"));
}
