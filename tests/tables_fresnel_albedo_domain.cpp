// ggx-fresnel-albedo's domain starts where real dielectrics do, eta = 1.3 (ice 1.31, water
// 1.33): `kiln sample` refuses a point outside it in one line naming the domain, instead of
// clamping; `kiln plan` leaves the table out for an IOR below it and says so in a note; an IOR
// of exactly 1 reflects nothing (F = 0) and needs no table.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "baker/integrate/fixed_rule_microfacet.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"
#include "scene_util.h"
#include "test_util.h"

using namespace kiln;

namespace {
const std::string kTable = std::string(KILN_SOURCE_DIR) + "/luts/ggx-fresnel-albedo.exr";
}  // namespace

TEST_CASE("kiln sample prints E on ggx-fresnel-albedo and refuses eta outside [1.3, 3]",
          "[tables][fresnel][fresnel-albedo-domain][cli]") {
  // Water, r 0.5, mu 0.5: inside; the table's value within its declared bound.
  Table t = loadTable(kTable);
  auto r = test::RunKiln("sample " + kTable + " 0.5 0.5 1.33");
  REQUIRE(r.exitCode == 0);
  CHECK(std::stod(r.out) ==
        Approx(FixedRuleGGXFresnelAlbedo(0.5, 0.25, 1.33)).margin(t.lookupError.max));
  for (const char* outside : {"0.5 0.5 1.2", "0.5 0.5 1", "0.5 0.5 3.5", "0.5 1.5 1.5"}) {
    auto bad = test::RunKiln("sample " + kTable + " " + outside);
    INFO(outside << ": " << bad.err);
    CHECK(bad.exitCode != 0);
    CHECK(test::CountLines(bad.err) == 1);
    CHECK(bad.err.find("outside the domain") != std::string::npos);
    CHECK(bad.err.find("eta in [1.3, 3]") != std::string::npos);
  }
}

TEST_CASE(
    "kiln plan: an IOR in (1, 1.3) is left out of fresnel-albedo with a note, IOR 1 needs "
    "no table",
    "[tables][fresnel][fresnel-albedo-domain][scene]") {
  const auto gltf = [](const std::string& ior) {
    return test::OneMaterialGltf(
        R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.3},
        "extensions": {"KHR_materials_ior": {"ior": )" +
        ior + "}}}");
  };
  // Water is inside: a 2D slice of the table at eta 1.33.
  Plan water = test::PlanText(gltf("1.33"));
  CHECK(test::FindTable(water, "ggx-fresnel-albedo-r0.3-ior1.33"));
  // IOR 1: no interface, F = 0: a note, no dielectric table.
  Plan none = test::PlanText(gltf("1"));
  CHECK_FALSE(test::FindTable(none, "ggx-fresnel-albedo-r0.3-ior1"));
  CHECK(test::FindNote(none, SceneNote::Kind::NoTable, "KHR_materials_ior"));
  // IOR 1.2: below the domain: the plan goes on without that table and says so.
  std::string dir = test::SceneTempDir("fresnel-albedo-domain");
  test::WriteText(dir + "/m.gltf", gltf("1.2"));
  auto r = test::RunKiln("plan " + dir + "/m.gltf");
  INFO(r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("ggx-fresnel-albedo: eta 1.2 is outside its domain [1.3, 3]") !=
        std::string::npos);
  CHECK(r.out.find("ggx-dfg-r0.3") != std::string::npos);
  test::RemoveTree(dir);
}
