// KHR_materials_clearcoat: a second GGX lobe with its own roughness, in the same ggx-dfg table.
#include <catch2/catch.hpp>

#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("Clearcoat: its roughness widens the dfg table, a zero factor has no effect", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("clearcoat.gltf"));
  // Base lobes at 0.5, the coat at 0.1: one dfg table over both; the albedo tables (multiple
  // scattering compensation of the base lobe) stay at 0.5.
  REQUIRE(TableNames(plan) == Names{"ggx-dfg-r0.1-0.5", "ggx-albedo-r0.5", "ggx-albedo-avg-r0.5"});
  const PlannedTable& dfg = plan.tables[0];
  const AxisSpec* r = FindAxis(dfg.spec, "roughness");
  CHECK(r->lo == 0.1);
  CHECK(r->hi == 0.5);
  CHECK(r->size == 73);  // the catalogue's sqrt-warped roughness spacing over [0.1, 0.5]
  CHECK(std::find(dfg.reasons.begin(), dfg.reasons.end(),
                  "'Car paint' (/materials/0): clearcoat GGX lobe, clearcoatRoughnessFactor 0.1") !=
        dfg.reasons.end());
  // 'Satin lacquer' has clearcoatFactor 0: its clearcoat roughness 0.9 must not widen the table.
  const PlanNote* none = FindNote(plan, SceneNote::Kind::NoEffect, "KHR_materials_clearcoat");
  REQUIRE(none);
  CHECK(none->materials == Names{"'Satin lacquer' (/materials/1)"});
}

TEST_CASE("A clearcoat roughness texture spans [0, clearcoatRoughnessFactor]", "[scene]") {
  Plan plan = PlanText(R"({"asset": {"version": "2.0"}, "textures": [{}], "materials": [{
      "pbrMetallicRoughness": {"roughnessFactor": 0.5},
      "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessFactor": 1,
                                                 "clearcoatRoughnessTexture": {"index": 0}}}}]})");
  CHECK(TableNames(plan) == Names{"ggx-dfg", "ggx-albedo-r0.5", "ggx-albedo-avg-r0.5"});
}
