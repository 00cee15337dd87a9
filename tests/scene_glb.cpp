// The glb container: a committed one, one made from a .gltf's JSON, and broken headers.
#include <catch2/catch.hpp>

#include "baker/scene/glb.h"
#include "baker/scene/scene_error.h"
#include "cli_util.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

TEST_CASE("A .glb (JSON chunk + BIN chunk) plans like the same JSON", "[scene][glb]") {
  Plan plan = PlanSceneFile(ScenePath("box.glb"));
  CHECK(plan.format == "glb");
  CHECK(TableNames(plan) ==
        Names{"ggx-dfg-r0.2-0.9", "ggx-albedo-r0.2-0.9", "ggx-albedo-avg-r0.2-0.9"});
  // A glb made from merge.gltf's JSON (with a BIN chunk) plans exactly like the .gltf.
  std::string dir = SceneTempDir("glb");
  WriteText(dir + "/merge.glb", MakeGlb(ReadFile(ScenePath("merge.gltf")), std::string(36, '\0')));
  Plan glb = PlanSceneFile(dir + "/merge.glb");
  Plan gltf = PlanSceneFile(ScenePath("merge.gltf"));
  REQUIRE(TableNames(glb) == TableNames(gltf));
  for (size_t i = 0; i < glb.tables.size(); ++i)
    CHECK(glb.tables[i].spec.Hash() == gltf.tables[i].spec.Hash());
  RemoveTree(dir);
}

TEST_CASE("MakeGlb writes the layout the reader expects", "[scene][glb]") {
  std::string g = MakeGlb("{}", "ab");
  REQUIRE(g.size() == 12 + 8 + 4 + 8 + 4);
  CHECK(g.substr(0, 4) == "glTF");
  CHECK(IsGlb(g));
  CHECK(GlbJsonChunk(g, "x.glb") == "{}  ");  // space padding is valid JSON whitespace
}

TEST_CASE("Broken glb headers name the byte", "[scene][glb]") {
  struct Case {
    const char *file, *place, *text;
  } cases[] = {
      {"bad/glb_version1.glb", "byte 4 (glb version)", "glb version 1, kiln reads glTF 2.0"},
      {"bad/glb_bad_magic.glb", "byte 0 (glb magic)", "not a glTF binary"},
      {"bad/glb_bin_first.glb", "byte 16 (first chunk type)", "expected JSON"},
  };
  for (const Case& c : cases) {
    INFO(c.file);
    try {
      PlanSceneFile(ScenePath(c.file));
      FAIL("no error");
    } catch (const SceneError& e) {
      CHECK(e.Place() == c.place);
      CHECK(std::string(e.what()).find(c.text) != std::string::npos);
    }
  }
  std::string truncated = MakeGlb("{\"asset\": {\"version\": \"2.0\"}}");
  truncated.resize(truncated.size() - 4);
  try {
    GlbJsonChunk(truncated, "t.glb");
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.Place() == "byte 8 (glb length)");
  }
}
