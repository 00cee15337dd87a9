// Identical needs from several materials merge into one table over the union of their values.
#include <catch2/catch.hpp>

#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("Two materials, one table per kind over the union of their roughness", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("merge.gltf"));
  REQUIRE(TableNames(plan) ==
          Names{"ggx-dfg-r0.3-0.6", "ggx-albedo-r0.3-0.6", "ggx-albedo-avg-r0.3-0.6"});
  for (const PlannedTable& t : plan.tables) {
    CHECK(t.reasons == Names{"'Steel' (/materials/0): base GGX lobe, roughnessFactor 0.3",
                             "'Brass' (/materials/1): base GGX lobe, roughnessFactor 0.6"});
    const AxisSpec* r = FindAxis(t.spec, "roughness");
    CHECK(r->lo == 0.3);
    CHECK(r->hi == 0.6);
    // The catalogue's sqrt-warped roughness spacing over [0.3, 0.6] (128 nodes; 64 for the
    // average).
    CHECK(r->size == (QuantityName(t.spec.quantity) == std::string("albedo-avg") ? 18 : 36));
    CHECK(r->warp == Warp::Linear);
  }
  // 'Leftover' is on no mesh: unused, so its roughness 0.05 does not widen anything.
  const PlanNote* unused = FindNote(plan, SceneNote::Kind::Unused, "unused material");
  REQUIRE(unused);
  CHECK(unused->materials == Names{"'Leftover' (/materials/2)"});
  CHECK(plan.materialCount == 2);
}

TEST_CASE("Notes of several materials merge into one line listing them", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("clearcoat.gltf"));
  const PlanNote* lambert = FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse");
  REQUIRE(lambert);
  CHECK(lambert->materials ==
        Names{"'Car paint' (/materials/0)", "'Satin lacquer' (/materials/1)"});
}

TEST_CASE("Table names in a plan are unique", "[scene]") {
  for (const char* f :
       {"merge.gltf", "clearcoat.gltf", "transmission_ior.gltf", "manifest.kiln.json", "box.glb"}) {
    Names names = TableNames(PlanSceneFile(ScenePath(f)));
    Names sorted = names;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  }
}
