// --json on kiln plan, inspect and verify: one JSON object on stdout with the keys the README
// lists; parsed here.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_util.h"

using kiln::test::ReadFile;
using kiln::test::RunKiln;
using kiln::test::TempDir;
using nlohmann::json;

TEST_CASE("kiln plan --json lists each table with its state, axes and reasons", "[cli][json]") {
  std::string dir = TempDir("plan_json");
  std::string scene = std::string(KILN_SOURCE_DIR) + "/tests/scenes/merge.gltf";
  auto r = RunKiln("plan " + scene + " --size 4 --json --out " + dir);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.empty());
  json doc = json::parse(r.out);
  CHECK(doc["scene"] == scene);
  CHECK(doc["format"] == "glTF");
  CHECK(doc["materials"] == 2);
  CHECK(doc["dir"] == dir);
  REQUIRE(doc["tables"].size() == 3);
  const json& dfg = doc["tables"][0];
  CHECK(dfg["name"] == "ggx-dfg-r0.3-0.6");
  CHECK(dfg["state"] == "missing");
  CHECK(dfg["file"] == dir + "/ggx-dfg-r0.3-0.6.exr");
  CHECK(dfg["quantity"] == "dfg");
  CHECK(dfg["model"] == "ggx");
  CHECK(dfg["channels"] == json::array({"A", "B"}));
  REQUIRE(dfg["axes"].size() == 2);
  CHECK(dfg["axes"][0]["name"] == "mu");
  CHECK(dfg["axes"][0]["size"] == 4);
  CHECK(dfg["axes"][0]["warp"] == "root4-layer");
  CHECK(dfg["axes"][1]["lo"] == 0.3);
  CHECK(dfg["axes"][1]["hi"] == 0.6);
  CHECK(dfg["texels"] == 8);
  CHECK(dfg["bytes_float32"] == 64);
  CHECK(dfg["scene_uses"]["roughness"] == "0.3..0.6");
  CHECK(dfg["needed_by"].size() == 2);
  CHECK(dfg["spec_hash"].get<std::string>().size() > 8);
  CHECK(doc["missing"] == 3);
  CHECK(doc["up_to_date"] == 0);
  CHECK(doc["stale"] == 0);
  bool unused = false;
  for (const json& n : doc["notes"]) unused |= n["kind"] == "unused";
  CHECK(unused);
  CHECK(doc["warnings"].is_array());

  REQUIRE(RunKiln("bake --quiet --scene " + scene + " --size 4 -j 2 --out " + dir).exitCode == 0);
  json after = json::parse(RunKiln("plan " + scene + " --size 4 --json --out " + dir).out);
  CHECK(after["up_to_date"] == 3);
  CHECK(after["tables"][0]["state"] == "up to date");
  // The spec hash the plan states is the one the bake stored.
  json manifest = json::parse(ReadFile(dir + "/manifest.json"));
  bool found = false;
  for (const json& e : manifest["tables"])
    if (e["name"] == "ggx-dfg-r0.3-0.6") found = e["spec_hash"] == after["tables"][0]["spec_hash"];
  CHECK(found);
  std::filesystem::remove_all(dir);
}

TEST_CASE("kiln inspect --json gives the attributes and channel ranges", "[cli][json]") {
  std::string file = std::string(KILN_SOURCE_DIR) + "/luts/ggx-dfg.exr";
  auto r = RunKiln("inspect " + file + " --json");
  REQUIRE(r.exitCode == 0);
  json doc = json::parse(r.out);
  CHECK(doc["file"] == file);
  CHECK(doc["name"] == "ggx-dfg");
  CHECK(doc["model"] == "ggx");
  CHECK(doc["quantity"] == "dfg");
  CHECK(doc["format"].is_number_integer());
  REQUIRE(doc["axes"].size() == 2);
  CHECK(doc["axes"][0]["name"] == "mu");
  CHECK(doc["axes"][0]["size"] == 128);
  CHECK(doc["axes"][1]["warp"] == "sqrt");
  CHECK(doc["bake_error"].get<double>() < 1e-6);
  CHECK(doc["lookup_error"]["max"].get<double>() > 0);
  CHECK(doc["lookup_error"]["filter"] == "linear");
  CHECK(doc["lookup_error"]["cubic_max"].get<double>() > 0);
  REQUIRE(doc["channels"].size() == 2);
  CHECK(doc["channels"][0]["min"].get<double>() >= 0);
  CHECK(doc["channels"][0]["max"].get<double>() <= 1);
  CHECK(doc["channels"][0]["meaning"].get<std::string>().size() > 0);
  json manifest = json::parse(ReadFile(std::string(KILN_SOURCE_DIR) + "/luts/manifest.json"));
  for (const json& e : manifest["tables"])
    if (e["name"] == "ggx-dfg") CHECK(e["spec_hash"] == doc["spec_hash"]);
  CHECK_FALSE(doc.contains("png"));
}

TEST_CASE("kiln verify --json reports every table, failures included", "[cli][json]") {
  std::string dir = TempDir("verify_json");
  REQUIRE(RunKiln("bake --quiet --only lambert-albedo,fresnel-dielectric-avg --size 5 -j 2 --out " +
                  dir)
              .exitCode == 0);
  auto r = RunKiln("verify " + dir + " --points 20 -j 2 --json");
  REQUIRE(r.exitCode == 0);
  json doc = json::parse(r.out);
  CHECK(doc["count"] == 2);
  CHECK(doc["failed"] == 0);
  REQUIRE(doc["tables"].size() == 2);
  const json& t = doc["tables"][0];
  CHECK(t["file"] == dir + "/fresnel-dielectric-avg.exr");
  CHECK(t["ok"] == true);
  CHECK(t["checked"] == true);
  CHECK(t["filter"] == "linear");
  CHECK(t["max"].get<double>() <= t["declared"].get<double>());
  CHECK(t["points"].get<long long>() > 20);
  CHECK(t.contains("rms"));
  CHECK(t.contains("off_corner"));
  CHECK(t.contains("where"));

  // A file that is not a table: its row says why, the exit status is 1, stdout is still JSON.
  std::ofstream(dir + "/junk.exr") << "not an exr";
  auto bad = RunKiln("verify " + dir + " --points 20 -j 2 --json");
  CHECK(bad.exitCode == 1);
  json badDoc = json::parse(bad.out);
  CHECK(badDoc["failed"] == 1);
  CHECK(badDoc["count"] == 3);
  bool junk = false;
  for (const json& row : badDoc["tables"])
    if (row["file"] == dir + "/junk.exr")
      junk = row["ok"] == false && !row["error"].get<std::string>().empty();
  CHECK(junk);
  CHECK(kiln::test::CountLines(bad.err) == 1);
  std::filesystem::remove_all(dir);
}
