// glTF pbrMetallicRoughness -> the GGX tables over the roughness values the materials use.
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("Factors only: one roughness is a 2-node slice with a node exactly at it", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("metal_rough_factors.gltf"));
  REQUIRE(TableNames(plan) == Names{"ggx-dfg-r0.3", "ggx-albedo-r0.3", "ggx-albedo-avg-r0.3"});
  for (const PlannedTable& t : plan.tables) {
    const AxisSpec* r = FindAxis(t.spec, "roughness");
    REQUIRE(r);
    CHECK(r->size == 2);
    CHECK(r->lo == 0.3);  // node 0 is the material's roughness, exactly
    CHECK(t.ranges.at("roughness").Single());
    REQUIRE(t.reasons.size() == 1);
    CHECK(t.reasons[0] == "'Plastic' (/materials/0): base GGX lobe, roughnessFactor 0.3");
  }
  // mu keeps the catalogue's axis.
  CHECK(FindAxis(plan.tables[0].spec, "mu")->size == CatalogueTable("ggx-dfg").axes[0].size);
  // The diffuse lobe needs nothing, and the plan says so.
  const PlanNote* lambert = FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse");
  REQUIRE(lambert);
  CHECK(lambert->why == "its albedo is rho exactly");
  CHECK(lambert->materials == Names{"'Plastic' (/materials/0)"});
}

TEST_CASE("A roughness texture needs the whole axis: the catalogue's own tables", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("metal_rough_texture.gltf"));
  REQUIRE(TableNames(plan) == Names{"ggx-dfg", "ggx-albedo", "ggx-albedo-avg"});
  for (const PlannedTable& t : plan.tables)
    CHECK(t.spec.Hash() == CatalogueTable(t.spec.name).Hash());  // up to date with luts/ as baked
}

TEST_CASE("A texture multiplies the factor: roughness spans [0, factor]", "[scene]") {
  Plan plan = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"roughnessFactor": 0.5,
      "metallicRoughnessTexture": {"index": 0}}})")
                           .insert(1, R"("textures": [{}], )"));
  REQUIRE(TableNames(plan) ==
          Names{"ggx-dfg-r0-0.5", "ggx-albedo-r0-0.5", "ggx-albedo-avg-r0-0.5"});
  const AxisSpec* r = FindAxis(plan.tables[0].spec, "roughness");
  CHECK(r->lo == 0);
  CHECK(r->hi == 0.5);
  CHECK(r->size == 91);  // the catalogue's 128 sqrt-warped nodes that fall in [0, 0.5]
}

TEST_CASE("glTF defaults: a material without pbrMetallicRoughness has roughness 1", "[scene]") {
  Plan plan = PlanText(OneMaterialGltf(R"({"name": "bare"})"));
  CHECK(TableNames(plan) == Names{"ggx-dfg-r1", "ggx-albedo-r1", "ggx-albedo-avg-r1"});
  const AxisSpec* r = FindAxis(plan.tables[0].spec, "roughness");
  CHECK(r->hi == 1);  // the slice ends at the axis end: its last node is the value
  // Metallic 1 by default: no diffuse lobe, so no Lambert note.
  CHECK(FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse") == nullptr);
}

TEST_CASE("A primitive without a material uses glTF's default material", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("default_material.gltf"));
  CHECK(plan.materialCount == 1);
  REQUIRE(TableNames(plan) == Names{"ggx-dfg-r1", "ggx-albedo-r1", "ggx-albedo-avg-r1"});
  CHECK(plan.tables[0].reasons[0].find("default material (/meshes/0/primitives/0 has none)") == 0);
}

TEST_CASE("Specular-glossiness: roughness is 1 - glossiness", "[scene]") {
  Plan plan = PlanText(OneMaterialGltf(R"({"extensions": {"KHR_materials_pbrSpecularGlossiness":
      {"glossinessFactor": 0.75}}})"));
  CHECK(TableNames(plan) == Names{"ggx-dfg-r0.25", "ggx-albedo-r0.25", "ggx-albedo-avg-r0.25"});
}

TEST_CASE("A roughness animated through KHR_animation_pointer needs the whole axis", "[scene]") {
  Plan plan = PlanText(R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_animation_pointer"],
    "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 0.3}}],
    "animations": [{"channels": [{"sampler": 0, "target": {"path": "pointer", "extensions":
      {"KHR_animation_pointer": {"pointer": "/materials/0/pbrMetallicRoughness/roughnessFactor"}}}}],
      "samplers": [{"input": 0, "output": 1}]}]})");
  CHECK(TableNames(plan) == Names{"ggx-dfg", "ggx-albedo", "ggx-albedo-avg"});
  CHECK(FindNote(plan, SceneNote::Kind::NoTable, "KHR_animation_pointer"));
}

TEST_CASE("The size override shrinks every catalogue axis before narrowing", "[scene]") {
  PlanOptions opt;
  opt.size = 4;
  Plan plan = PlanSceneFile(ScenePath("metal_rough_texture.gltf"), opt);
  for (const PlannedTable& t : plan.tables)
    for (const AxisSpec& a : t.spec.axes) CHECK(a.size == 4);
}
