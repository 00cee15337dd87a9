// KHR_materials_sheen: the charlie-smith albedo table (the spec's albedo scaling; the same
// integral as its dfg) over the materials' sheenRoughness
// range, narrowed like the other roughness axes; a sheen roughness below the tables' domain
// (0.045) is clamped there with a note; the whole range plans the default catalogue's own table.
#include <catch2/catch.hpp>

#include "baker/tables/catalogue.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;
using Kind = SceneNote::Kind;

TEST_CASE("Sheen maps to the charlie-smith albedo over the sheenRoughness range",
          "[scene][sheen]") {
  Plan plan = PlanSceneFile(ScenePath("sheen.gltf"));
  Names names = TableNames(plan);
  INFO(::Catch::Detail::stringify(names));
  CHECK(std::find(names.begin(), names.end(), "charlie-smith-albedo-r0.3-0.6") != names.end());
  int sheenTables = 0;
  for (const PlannedTable& t : plan.tables) {
    if (t.spec.model != "charlie-smith") continue;
    ++sheenTables;
    CHECK(t.spec.quantity == Quantity::Albedo);
    const AxisSpec* r = FindAxis(t.spec, "roughness");
    REQUIRE(r);
    CHECK(r->lo == 0.3);
    CHECK(r->hi == 0.6);
  }
  CHECK(sheenTables == 1);
  // 'No sheen' (sheenColorFactor 0) does not widen the axis to its 0.9.
  const PlanNote* none = FindNote(plan, Kind::NoEffect, "KHR_materials_sheen");
  REQUIRE(none);
  CHECK(none->materials == Names{"'No sheen' (/materials/2)"});
  CHECK(FindNote(plan, Kind::NotYet, "KHR_materials_sheen") == nullptr);
}

TEST_CASE("A sheen roughness below 0.045 is clamped to the tables' domain, with a note",
          "[scene][sheen]") {
  Plan plan = PlanText(OneMaterialGltf(R"({"extensions": {
      "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1]}}})"));
  bool found = false;
  for (const PlannedTable& t : plan.tables) {
    if (t.spec.model != "charlie-smith") continue;
    found = true;
    const AxisSpec* r = FindAxis(t.spec, "roughness");
    REQUIRE(r);
    CHECK(r->lo == 0.045);
  }
  CHECK(found);
  const PlanNote* clamped = FindNote(plan, Kind::NoEffect, "KHR_materials_sheen");
  REQUIRE(clamped);
  CHECK(clamped->why.find("clamped to 0.045") != std::string::npos);
}

TEST_CASE("A sheen roughness texture plans the default catalogue's charlie-smith-albedo (luts/)",
          "[scene][sheen]") {
  // sheenRoughnessTexture x 1: roughness 0..1, clamped to the tables' 0.045..1, the whole axis:
  // the spec, hence the file, is the catalogue's own, which is in the default catalogue (and
  // luts/) since charlie-smith's tables joined it.
  Plan plan = PlanText(R"({"asset": {"version": "2.0"}, "textures": [{}], "materials": [
      {"extensions": {"KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1],
       "sheenRoughnessFactor": 1, "sheenRoughnessTexture": {"index": 0}}}}]})");
  const PlannedTable* sheen = nullptr;
  for (const PlannedTable& t : plan.tables)
    if (t.spec.model == "charlie-smith") sheen = &t;
  REQUIRE(sheen);
  CHECK(sheen->spec.name == "charlie-smith-albedo");
  const TableSpec whole = CatalogueTable("charlie-smith-albedo");
  CHECK(sheen->spec.Hash() == whole.Hash());
  bool inDefault = false;
  for (const TableSpec& s : DefaultCatalogue({}))
    inDefault |= s.name == "charlie-smith-albedo" && s.Hash() == whole.Hash();
  CHECK(inDefault);
  CHECK(SheenTableInDefaultCatalogue("charlie-smith-albedo"));
}
