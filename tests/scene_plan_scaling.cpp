// The planner's work grows linearly with the number of materials: a scene of tens of thousands of
// materials (a large glb) plans in a fraction of a second. Plan::mergeProbes counts the entries the
// merge looks at, so the property is tested without timing anything.
#include <catch2/catch.hpp>

#include <string>

#include "baker/scene/scene.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {

/// A glTF asset of `count` materials, each with its own roughness and a clearcoat of its own
/// roughness (three base tables, one clearcoat dfg and a note per material).
std::string ManyMaterialsGltf(int count) {
  std::string materials;
  for (int i = 0; i < count; ++i) {
    std::string r = std::to_string((i % 100) / 100.0), cr = std::to_string((i * 7 % 100) / 100.0);
    materials += std::string(i ? "," : "") + R"({"name": "m)" + std::to_string(i) +
                 R"(", "pbrMetallicRoughness": {"roughnessFactor": )" + r +
                 R"(, "metallicFactor": 0.5}, "extensions": {"KHR_materials_clearcoat": )" +
                 R"({"clearcoatFactor": 1, "clearcoatRoughnessFactor": )" + cr + "}}}";
  }
  return R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_clearcoat"], )"
         R"("materials": [)" +
         materials + "]}";
}

}  // namespace

TEST_CASE("Planning looks at each need and note a bounded number of times", "[scene][plan]") {
  for (int count : {500, 2000}) {
    std::string dir = SceneTempDir("scaling");
    WriteText(dir + "/many.gltf", ManyMaterialsGltf(count));
    Scene scene = ReadScene(dir + "/many.gltf");
    Plan plan = PlanScene(scene);
    RemoveTree(dir);
    size_t entries = scene.needs.size() + scene.notes.size();
    INFO(count << " materials: " << entries << " needs and notes, " << plan.mergeProbes
               << " probes");
    CHECK(plan.materialCount == count);
    CHECK(plan.mergeProbes <= 4 * entries);
  }
}

TEST_CASE("A plan of many materials lists every material once in each reason and note",
          "[scene][plan]") {
  const int count = 300;
  Plan plan = PlanText(ManyMaterialsGltf(count));
  REQUIRE(TableNames(plan) == std::vector<std::string>{"ggx-dfg-r0-0.99", "ggx-albedo-r0-0.99",
                                                       "ggx-albedo-avg-r0-0.99"});
  // ggx-dfg: the base lobe and the clearcoat of every material.
  CHECK(FindTable(plan, "ggx-dfg-r0-0.99")->reasons.size() == 2 * count);
  CHECK(FindTable(plan, "ggx-albedo-r0-0.99")->reasons.size() == count);
  const PlanNote* lambert = FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse");
  REQUIRE(lambert);
  CHECK(lambert->materials.size() == count);
  CHECK(lambert->materials.front() == "'m0' (/materials/0)");
  CHECK(lambert->materials.back() == "'m299' (/materials/299)");
}
