// Bad scene files: one line naming the file and the place (a JSON pointer), from the library
// (SceneError) and from `kiln plan` / BakeScene (non-zero exit).
#include <catch2/catch.hpp>

#include "baker/scene/bake_scene.h"
#include "baker/scene/scene_error.h"
#include "cli_util.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {

struct BadFile {
  const char* file;
  const char* place;
  const char* problem;
};

const BadFile kBadFiles[] = {
    {"bad/not_json.gltf", "line 4, column 42", "not valid JSON"},
    {"bad/gltf_version1.gltf", "/asset/version", "glTF 1.0 is not supported: kiln reads glTF 2.x"},
    {"bad/dangling_material.gltf", "/meshes/0/primitives/1/material",
     "material 2 does not exist (the file has 2 materials)"},
    {"bad/dangling_texture.gltf",
     "/materials/1/extensions/KHR_materials_clearcoat/clearcoatRoughnessTexture/index",
     "texture 1 does not exist (the file has 1 texture)"},
    {"bad/roughness_out_of_range.gltf", "/materials/3/pbrMetallicRoughness/roughnessFactor",
     "1.5 is outside [0, 1]"},
    {"bad/ior_invalid.gltf", "/materials/0/extensions/KHR_materials_ior/ior",
     "0.5 is not a valid IOR (>= 1, or exactly 0)"},
    {"bad/unknown_model.kiln.json", "/materials/1/model", "unknown model 'ggxx'"},
    {"bad/manifest_out_of_range.kiln.json", "/materials/0/roughness/1",
     "roughness 1.4 is outside [0, 1]"},
    {"bad/manifest_unknown_key.kiln.json", "/materials/0/rougness",
     "model 'ggx' takes no parameter 'rougness'"},
    {"bad/manifest_version2.kiln.json", "/kiln_scene", "version 2, kiln reads version 1"},
    {"bad/manifest_bad_table.kiln.json", "/materials/0/tables/0",
     "model 'lambert' has no dfg table"},
    {"bad/glb_version1.glb", "byte 4 (glb version)", "glb version 1"},
};

/// `kiln plan` is registered in main.cpp (kiln --help lists it).
bool PlanCommandExists() { return RunKiln("--help").out.find("\n  plan ") != std::string::npos; }

}  // namespace

TEST_CASE("Every bad file: SceneError names the file and the place", "[scene][errors]") {
  for (const BadFile& b : kBadFiles) {
    INFO(b.file);
    std::string path = ScenePath(b.file);
    try {
      PlanSceneFile(path);
      FAIL("no error");
    } catch (const SceneError& e) {
      CHECK(e.File() == path);
      CHECK(e.Place() == b.place);
      std::string what = e.what();
      CHECK(what == path + ": " + b.place + ": " +
                        what.substr(path.size() + 2 + std::string(b.place).size() + 2));
      CHECK(what.find(b.problem) != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("More bad values, each at its pointer", "[scene][errors]") {
  struct Case {
    const char *text, *file, *place;
  } cases[] = {
      {R"({"asset": {}})", "a.gltf", "/asset/version"},
      {R"({"materials": []})", "a.gltf", "/"},  // neither glTF nor kiln scene
      {R"({"asset": {"version": "2.0", "minVersion": "2.1"}})", "a.gltf", "/asset/minVersion"},
      {R"({"asset": {"version": "2.0"}, "materials": [{"pbrMetallicRoughness": {"roughnessFactor": "rough"}}]})",
       "a.gltf", "/materials/0/pbrMetallicRoughness/roughnessFactor"},
      {R"({"asset": {"version": "2.0"}, "materials": [{"extensions": {"KHR_materials_clearcoat":
          {"clearcoatFactor": 1, "clearcoatRoughnessFactor": -0.1}}}]})",
       "a.gltf", "/materials/0/extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor"},
      {R"({"asset": {"version": "2.0"}, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {}}}]})",
       "a.gltf", "/materials/0/pbrMetallicRoughness/baseColorTexture"},
      {R"({"asset": {"version": "2.0"}, "textures": [{"source": 3}]})", "a.gltf",
       "/textures/0/source"},
      {R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"material": -1}]}]})", "a.gltf",
       "/meshes/0/primitives/0/material"},
      // sheenColorFactor is held to [0, 1] like every other factor.
      {R"({"asset": {"version": "2.0"}, "materials": [{"extensions": {"KHR_materials_sheen":
          {"sheenColorFactor": [2, 2, 2]}}}]})",
       "a.gltf", "/materials/0/extensions/KHR_materials_sheen/sheenColorFactor/0"},
      {R"({"asset": {"version": "2.0"}, "materials": [{"extensions": {"KHR_materials_sheen":
          {"sheenColorFactor": [0.5, 1e308, 0]}}}]})",
       "a.gltf", "/materials/0/extensions/KHR_materials_sheen/sheenColorFactor/1"},
      {R"({"asset": {"version": "2.0"}, "materials": [{"extensions": {"KHR_materials_sheen":
          {"sheenColorFactor": [0.5, 0.5, -0.1]}}}]})",
       "a.gltf", "/materials/0/extensions/KHR_materials_sheen/sheenColorFactor/2"},
      {R"({"kiln_scene": 1, "materials": [{"model": "ggx", "roughness": [0.6, 0.2]}]})", "s.json",
       "/materials/0/roughness"},
      {R"({"kiln_scene": 1, "materials": [{"model": "ggx", "f0": 0.04, "eta": 1.5}]})", "s.json",
       "/materials/0"},
      {R"({"kiln_scene": 1, "materials": [{"roughness": 0.3}]})", "s.json", "/materials/0"},
      {R"({"kiln_scene": 1, "materials": [{"model": "ggx", "tables": ["dgf"]}]})", "s.json",
       "/materials/0/tables/0"},
      {R"({"kiln_scene": 1, "materials": [{"model": "ggx", "roughness": "rough"}]})", "s.json",
       "/materials/0/roughness"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    try {
      PlanText(c.text, c.file);
      FAIL("no error");
    } catch (const SceneError& e) {
      CHECK(e.Place() == c.place);
    }
  }
}

TEST_CASE("A missing file is an error naming it", "[scene][errors]") {
  CHECK_THROWS_WITH(PlanSceneFile("/nonexistent/scene.gltf"),
                    "/nonexistent/scene.gltf: cannot open the file");
}

TEST_CASE("kiln plan: a bad file is one line on stderr naming file and place, exit 1",
          "[scene][errors][cli]") {
  if (!PlanCommandExists()) {
    WARN("`kiln plan` is not registered in baker/cli/main.cpp yet: skipped");
    return;
  }
  for (const BadFile& b : kBadFiles) {
    INFO(b.file);
    auto r = RunKiln("plan '" + ScenePath(b.file) + "' --out /tmp");
    CHECK(r.exitCode == 1);
    CHECK(r.out.empty());
    CHECK(CountLines(r.err) == 1);
    CHECK(r.err.find("kiln: error: " + ScenePath(b.file) + ": " + b.place + ": ") == 0);
  }
}

TEST_CASE("BakeScene: a bad file returns 1 and writes nothing", "[scene][errors]") {
  std::string dir = SceneTempDir("bad_bake");
  CHECK(BakeScene(ScenePath("bad/roughness_out_of_range.gltf"), dir, BakeOptions{}, false, false) ==
        1);
  CHECK((!std::filesystem::exists(dir) || std::filesystem::is_empty(dir)));
  RemoveTree(dir);
}
