// KHR_materials_ior / _transmission / _volume / _dispersion -> ggx-fresnel-albedo (mu, roughness,
// eta): one IOR drops the eta axis (the 3D table becomes 2D) and records it in the params.
#include <catch2/catch.hpp>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("IOR and transmission: the dielectric table at one IOR is 2D", "[scene]") {
  Plan plan = PlanSceneFile(ScenePath("transmission_ior.gltf"));
  REQUIRE(TableNames(plan) ==
          Names{"ggx-dfg", "ggx-albedo", "ggx-albedo-avg", "ggx-fresnel-albedo-ior1.5",
                "ggx-dielectric-albedo-r-ior1.5", "ggx-dielectric-albedo-t-ior1.5",
                "ggx-dielectric-albedo-r-avg-ior1.5", "ggx-dielectric-albedo-t-avg-ior1.5",
                "ggx-dielectric-albedo-r-exit-ior0.666667",
                "ggx-dielectric-albedo-t-exit-ior0.666667",
                "ggx-dielectric-albedo-r-exit-avg-ior0.666667",
                "ggx-dielectric-albedo-t-exit-avg-ior0.666667",
                "ggx-dielectric-btdf-split-sum-ior1.5"});
  const TableSpec& d = FindTable(plan, "ggx-fresnel-albedo-ior1.5")->spec;
  TableSpec full = CatalogueTable("ggx-fresnel-albedo");
  REQUIRE(full.axes.size() == 3);
  REQUIRE(d.axes.size() == 2);
  CHECK(d.axes[0].name == "mu");
  CHECK(d.axes[1].name == "roughness");  // textured: the whole axis
  CHECK(d.axes[1].size == full.axes[1].size);
  CHECK(d.params.at("eta") == 1.5);
  CHECK(d.ParamsText() == "eta=1.5");
  // Frosted glass (ior 1.5 + transmission + volume) and Varnish (KHR_materials_ior, default 1.5).
  CHECK(FindTable(plan, "ggx-fresnel-albedo-ior1.5")->reasons.size() == 2);
  CHECK(FindNote(plan, SceneNote::Kind::NoTable, "KHR_materials_volume"));
  // Chrome is fully metallic: its ior 1.8 has no dielectric layer to act on.
  const PlanNote* chrome = FindNote(plan, SceneNote::Kind::NoEffect, "KHR_materials_ior");
  REQUIRE(chrome);
  CHECK(chrome->materials == Names{"'Chrome' (/materials/2)"});
}

TEST_CASE("The 2D slice holds the 3D table's values at that IOR", "[scene]") {
  PlanOptions opt;
  opt.size = 3;
  Plan plan = PlanSceneFile(ScenePath("transmission_ior.gltf"), opt);
  const TableSpec& d = FindTable(plan, "ggx-fresnel-albedo-ior1.5")->spec;
  BakeOptions bopt;
  bopt.threads = 2;
  bopt.measureLookupError = false;
  Table t = BakeTable(d, bopt);
  TableSpec full = CatalogueTable("ggx-fresnel-albedo");
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      // Where the bake evaluates node (i, j) (the mu axis follows the roughness).
      double x[3] = {0, 0, 1.5};
      NodeEvaluationPoint(d, static_cast<size_t>(j * 3 + i), x);
      x[2] = 1.5;
      IntegrationStats st;
      double exact = EvaluateSpec(full, x, st)[0];
      CHECK(t.data[static_cast<size_t>(j * 3 + i)] == Approx(exact).margin(1e-6));
    }
}

TEST_CASE("One roughness and one IOR: a 1D table over mu", "[scene]") {
  Plan plan = PlanText(
      OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.1},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.33}}})"));
  const PlannedTable* t = FindTable(plan, "ggx-fresnel-albedo-r0.1-ior1.33");
  REQUIRE(t);
  REQUIRE(t->spec.axes.size() == 1);
  CHECK(t->spec.axes[0].name == "mu");
  // The catalogue's mu axis follows the roughness (root4-layer); with the roughness a
  // parameter there is no axis to read it from: root4, and the table is a valid 1D view.
  CHECK(t->spec.axes[0].warp == Warp::Root4);
  CHECK(t->spec.params.at("roughness") == 0.1);
  CHECK(t->spec.params.at("eta") == 1.33);
}

TEST_CASE("Dispersion spreads the IOR: ior -+ (ior - 1) 0.025 dispersion", "[scene]") {
  Plan plan = PlanText(
      OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {},
                     "KHR_materials_ior": {"ior": 1.5}, "KHR_materials_dispersion": {"dispersion": 2}}})"));
  const PlannedTable* t = FindTable(plan, "ggx-fresnel-albedo-r0-ior1.475-1.525");
  REQUIRE(t);
  // mu over eta: no layer warp reading the eta axis as a roughness.
  CHECK(!isLayerWarp(t->spec.axes[0].warp));
  CHECK(t->spec.axes.size() == 2);  // mu, eta (2 nodes: 0.05 is narrower than one catalogue cell)
  CHECK(FindAxis(t->spec, "eta")->size == 2);
}

TEST_CASE("Transmission 0, and ior 0 (F = 1), need no dielectric table", "[scene]") {
  Plan plan = PlanText(
      OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.5},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 0}, "KHR_materials_volume": {}}})"));
  CHECK(TableNames(plan) == Names{"ggx-dfg-r0.5", "ggx-albedo-r0.5", "ggx-albedo-avg-r0.5"});
  CHECK(FindNote(plan, SceneNote::Kind::NoEffect, "KHR_materials_transmission"));
  CHECK(FindNote(plan, SceneNote::Kind::NoEffect, "KHR_materials_volume"));
  Plan zero = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_ior": {"ior": 0}}})"));
  CHECK(TableNames(zero) == Names{"ggx-dfg-r1", "ggx-albedo-r1", "ggx-albedo-avg-r1"});
  CHECK(FindNote(zero, SceneNote::Kind::NoTable, "KHR_materials_ior"));
}
