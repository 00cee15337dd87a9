// The kiln scene manifest: any kiln model, values or ranges, optional table kinds.
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("A Lambert-only scene needs no table, and says why", "[scene][manifest]") {
  Plan plan = PlanSceneFile(ScenePath("lambert_only.kiln.json"));
  CHECK(plan.format == "kiln scene");
  CHECK(plan.tables.empty());
  const PlanNote* lambert = FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse");
  REQUIRE(lambert);
  CHECK(lambert->why == "its albedo is rho exactly");
  CHECK(lambert->materials == Names{"'plaster' (/materials/0)", "'paper' (/materials/1)"});
}

TEST_CASE("Manifest: ranges, the whole axis, a dielectric, a conductor", "[scene][manifest]") {
  Plan plan = PlanSceneFile(ScenePath("manifest.kiln.json"));
  REQUIRE(TableNames(plan) == Names{"ggx-dfg-r0.05-0.6", "ggx-albedo-r0.05-0.6",
                                    "ggx-albedo-avg-r0.05-0.6", "burley-albedo",
                                    "burley-albedo-avg", "ggx-fresnel-albedo-r0.05-ior1.5",
                                    "fresnel-conductor-n0.47-k2.8"});
  // dfg: steel [0.2, 0.6] + glass 0.05 + gold 0.3; the albedo tables only steel and glass (gold
  // lists its tables).
  CHECK(FindTable(plan, "ggx-dfg-r0.05-0.6")->reasons.size() == 3);
  CHECK(FindTable(plan, "ggx-albedo-r0.05-0.6")->reasons.size() == 2);
  // "any": the catalogue's table itself.
  CHECK(FindTable(plan, "burley-albedo")->spec.Hash() == CatalogueTable("burley-albedo").Hash());
  // One roughness and one eta: both dropped into params, a 1D table over mu.
  const TableSpec& glass = FindTable(plan, "ggx-fresnel-albedo-r0.05-ior1.5")->spec;
  CHECK(glass.axes.size() == 1);
  CHECK(glass.ParamsText() == "eta=1.5;roughness=0.050000000000000003");
  // The conductor table reads its axes by position: n and k become 2-node slices at the values.
  const TableSpec& gold = FindTable(plan, "fresnel-conductor-n0.47-k2.8")->spec;
  REQUIRE(gold.axes.size() == 3);
  CHECK(gold.axes[1].lo == 0.47);
  CHECK(gold.axes[2].lo == 2.8);
  CHECK(FindNote(plan, SceneNote::Kind::NoTable, "Lambert diffuse")->materials ==
        Names{"'plaster' (/materials/4)"});
}

TEST_CASE("Manifest: an omitted axis parameter is the whole axis, tables: [] is nothing",
          "[scene][manifest]") {
  Plan plan = PlanText(R"({"kiln_scene": 1, "materials": [
      {"model": "oren-nayar"}, {"model": "ggx", "tables": []},
      {"model": "beckmann", "roughness": 0.5, "tables": ["dfg"]}]})",
                       "s.json");
  CHECK(TableNames(plan) ==
        Names{"oren-nayar-albedo", "oren-nayar-albedo-avg", "beckmann-dfg-r0.5"});
  CHECK(FindNote(plan, SceneNote::Kind::NoTable, "tables: []"));
  // Oren-Nayar's roughness runs to pi/2: the whole axis is the catalogue's.
  CHECK(FindAxis(plan.tables[0].spec, "roughness")->hi ==
        CatalogueTable("oren-nayar-albedo").axes[1].hi);
}
