// kiln plan SCENE [--out DIR]: what the scene needs, why, its ranges and sizes, and what DIR has.
#include <catch2/catch.hpp>

#include "baker/scene/bake_scene.h"
#include "cli_util.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {
/// `kiln plan` is registered in main.cpp (kiln --help lists it).
bool PlanCommandExists() { return RunKiln("--help").out.find("\n  plan ") != std::string::npos; }
}  // namespace

TEST_CASE("kiln plan prints each table with reasons, axes, size and state", "[scene][cli]") {
  if (!PlanCommandExists()) {
    WARN("`kiln plan` is not registered in baker/cli/main.cpp yet: skipped");
    return;
  }
  std::string dir = SceneTempDir("cli_plan");
  auto r = RunKiln("plan '" + ScenePath("merge.gltf") + "' --out " + dir + " --size 4");
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("(glTF, 2 materials): 3 tables") != std::string::npos);
  CHECK(r.out.find("ggx-dfg-r0.3-0.6  [missing]") != std::string::npos);
  CHECK(r.out.find("axes: mu 0..1 (4, root4-layer) x roughness 0.3..0.6 (2, sqrt) = 8 texels") !=
        std::string::npos);
  CHECK(r.out.find("    'Brass' (/materials/1): base GGX lobe, roughnessFactor 0.6") !=
        std::string::npos);
  CHECK(r.out.find("unused material: no mesh primitive uses it ['Leftover' (/materials/2)]") !=
        std::string::npos);

  // After a bake of the same plan, every table is up to date.
  PlanOptions popt;
  popt.size = 4;
  BakeOptions fast;
  fast.threads = 2;
  fast.measureLookupError = false;
  BakePlan(PlanSceneFile(ScenePath("merge.gltf"), popt), dir, fast, false, false, nullptr);
  auto again = RunKiln("plan '" + ScenePath("merge.gltf") + "' --out " + dir + " --size 4");
  CHECK(again.out.find("3 up to date in " + dir) != std::string::npos);
  CHECK(again.out.find("[missing]") == std::string::npos);
  RemoveTree(dir);
}

TEST_CASE("kiln plan lists what needs no table, and warns about unknown required extensions",
          "[scene][cli]") {
  if (!PlanCommandExists()) {
    WARN("`kiln plan` is not registered in baker/cli/main.cpp yet: skipped");
    return;
  }
  auto lambert = RunKiln("plan '" + ScenePath("lambert_only.kiln.json") + "'");
  REQUIRE(lambert.exitCode == 0);
  CHECK(lambert.out.find("0 tables") != std::string::npos);
  CHECK(lambert.out.find("needs no table:\n  Lambert diffuse: its albedo is rho exactly") !=
        std::string::npos);
  auto sheen = RunKiln("plan '" + ScenePath("sheen_specular.gltf") + "'");
  CHECK(sheen.out.find("charlie-smith-albedo-r0.5") != std::string::npos);
  CHECK(sheen.out.find("KHR_materials_sheen: Charlie") == std::string::npos);
  auto required = RunKiln("plan '" + ScenePath("required_unknown.gltf") + "'");
  CHECK(required.exitCode == 0);
  CHECK(required.err.find("kiln: warning: ") == 0);
  CHECK(required.err.find("'EXT_future_brdf' is required but unknown to kiln") !=
        std::string::npos);
  CHECK(required.out.find("ggx-dfg-r0.25") != std::string::npos);
}
