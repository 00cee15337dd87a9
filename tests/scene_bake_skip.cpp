// kiln bake --scene: bakes what the plan needs, skips what is up to date (same bytes, same mtime).
#include <sys/stat.h>
#include <utime.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "baker/scene/bake_scene.h"
#include "baker/scene/plan_report.h"
#include "cli_util.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;
using Names = std::vector<std::string>;

namespace {
long long MTimeNs(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return -1;
  return static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
}
BakeOptions Fast() {
  BakeOptions o;
  o.threads = 2;
  o.lookupBudget = 20;
  return o;
}
}  // namespace

TEST_CASE("A scene bake skips the up-to-date files and leaves them untouched", "[scene][bake]") {
  std::string dir = SceneTempDir("skip");
  PlanOptions popt;
  popt.size = 4;
  Plan plan = PlanSceneFile(ScenePath("merge.gltf"), popt);
  for (const PlannedTable& t : plan.tables) CHECK(StateOf(t.spec, dir) == TableState::Missing);

  SceneBakeResult first = BakePlan(plan, dir, Fast(), false, false, nullptr);
  CHECK(first.baked == TableNames(plan));
  CHECK(first.skipped.empty());
  for (const PlannedTable& t : plan.tables) CHECK(StateOf(t.spec, dir) == TableState::UpToDate);
  auto manifest = nlohmann::json::parse(ReadFile(dir + "/manifest.json"));
  CHECK(manifest["tables"].size() == 3);

  // Age the files, re-run: nothing baked, every file keeps its bytes and its (old) mtime.
  std::vector<std::string> bytes;
  for (const PlannedTable& t : plan.tables) {
    std::string path = dir + "/" + t.spec.name + ".exr";
    bytes.push_back(ReadFile(path));
    utimbuf old{946684800, 946684800};  // 2000-01-01
    REQUIRE(utime(path.c_str(), &old) == 0);
  }
  SceneBakeResult second = BakePlan(plan, dir, Fast(), false, false, nullptr);
  CHECK(second.baked.empty());
  CHECK(second.skipped == TableNames(plan));
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    std::string path = dir + "/" + plan.tables[i].spec.name + ".exr";
    CHECK(MTimeNs(path) == 946684800LL * 1000000000LL);
    CHECK(ReadFile(path) == bytes[i]);
  }

  // Another spec under the same name (a different size) is stale and re-baked.
  popt.size = 5;
  Plan bigger = PlanSceneFile(ScenePath("metal_rough_texture.gltf"), popt);
  popt.size = 4;
  Plan smaller = PlanSceneFile(ScenePath("metal_rough_texture.gltf"), popt);
  BakePlan(Plan{smaller.scenePath, smaller.format, 1, {smaller.tables[2]}, {}, {}}, dir, Fast(),
           false, false, nullptr);
  CHECK(StateOf(bigger.tables[2].spec, dir) == TableState::Stale);
  RemoveTree(dir);
}

TEST_CASE("With --header, a skipped table whose header is missing gets one", "[scene][bake]") {
  std::string dir = SceneTempDir("header");
  PlanOptions popt;
  popt.size = 3;
  Plan plan = PlanSceneFile(ScenePath("metal_rough_factors.gltf"), popt);
  Plan one{plan.scenePath,   plan.format, 1,
           {plan.tables[2]}, {},          {}};  // ggx-albedo-avg-r0.3: 2 texels
  BakePlan(one, dir, Fast(), false, false, nullptr);
  std::string h = dir + "/ggx-albedo-avg-r0.3.h";
  CHECK(ReadFile(h).empty());
  SceneBakeResult r = BakePlan(one, dir, Fast(), false, true, nullptr);
  CHECK(r.skipped == Names{"ggx-albedo-avg-r0.3"});
  CHECK(ReadFile(h).find("ggx_albedo_avg_r0_3") != std::string::npos);
  RemoveTree(dir);
}

TEST_CASE("The scene bake reports baked, skipped and the time", "[scene][bake]") {
  std::string dir = SceneTempDir("report");
  PlanOptions popt;
  popt.size = 3;
  std::string scene = ScenePath("metal_rough_factors.gltf");
  Plan plan = PlanSceneFile(scene, popt);
  auto report = [&] {
    std::FILE* log = std::tmpfile();
    BakePlan(plan, dir, Fast(), false, false, log);
    std::rewind(log);
    std::string text;
    for (int c; (c = std::fgetc(log)) != EOF;) text += static_cast<char>(c);
    std::fclose(log);
    return text;
  };
  std::string first = report();
  CHECK(first.find("baked   ggx-dfg-r0.3 ") == 0);
  CHECK(first.find("scene " + scene + ": 3 baked, 0 skipped (up to date) in ") !=
        std::string::npos);
  std::string second = report();
  CHECK(second.find("skipped ggx-dfg-r0.3 ") == 0);
  CHECK(second.find(": 0 baked, 3 skipped (up to date) in ") != std::string::npos);
  // BakeScene (what `kiln bake --scene` calls) prints the same report on stderr and returns 0.
  std::fflush(stdout);
  CHECK(BakeScene(scene, dir, Fast(), false, false, popt) == 0);
  RemoveTree(dir);
}
