// kiln bake / inspect from the command line: files, manifest, errors, committed luts/.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_util.h"

using kiln::test::ReadFile;
using kiln::test::RemoveTree;
using kiln::test::RunKiln;
using kiln::test::TempDir;

TEST_CASE("kiln bake --only writes the tables and a manifest, silently when not on a terminal",
          "[cli][bake]") {
  std::string dir = TempDir("bake");
  auto r = RunKiln("bake --out " + dir +
                   " --only fresnel-dielectric,lambert-albedo --size 5 -j 2 --header");
  REQUIRE(r.exitCode == 0);
  CHECK(r.out.empty());
  CHECK(!ReadFile(dir + "/fresnel-dielectric.exr").empty());
  CHECK(!ReadFile(dir + "/lambert-albedo.h").empty());
  auto manifest = nlohmann::json::parse(ReadFile(dir + "/manifest.json"));
  REQUIRE(manifest["tables"].size() == 2);
  CHECK(manifest["tables"][0]["name"] == "fresnel-dielectric");
  CHECK(manifest["tables"][1]["bake_error"].get<double>() < 1e-6);
  // A second --only bake adds to the manifest instead of replacing it.
  REQUIRE(RunKiln("bake --out " + dir + " --only blinn-phong-normalization --size 5").exitCode ==
          0);
  CHECK(nlohmann::json::parse(ReadFile(dir + "/manifest.json"))["tables"].size() == 3);
  auto inspect = RunKiln("inspect " + dir + "/fresnel-dielectric.exr");
  CHECK(inspect.exitCode == 0);
  CHECK(inspect.out.find("axis 1          eta [1, 3] 5 nodes, sqrt warp") != std::string::npos);
  RemoveTree(dir);
}

TEST_CASE("kiln bake refuses bad arguments with one line", "[cli][bake]") {
  for (const char* args :
       {"bake --only nope --out /tmp", "bake --size 0 --out /tmp", "bake --size 100000",
        "bake -j -1", "bake --roughness 3", "inspect /nonexistent.exr"}) {
    auto r = RunKiln(args);
    INFO(args << " -> " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(kiln::test::CountLines(r.err) == 1);
  }
}

TEST_CASE("The committed luts/ are what the bake command makes, bit for bit (cheap tables)",
          "[cli][bake]") {
  std::string dir = TempDir("rebake");
  const char* names[] = {"fresnel-dielectric", "blinn-phong-normalization", "lambert-albedo",
                         "shirley-albedo-avg"};
  std::string only;
  for (const char* n : names) only += std::string(only.empty() ? "" : ",") + n;
  REQUIRE(RunKiln("bake --out " + dir + " --only " + only).exitCode == 0);
  for (const char* n : names) {
    std::string committed = ReadFile(std::string(KILN_SOURCE_DIR) + "/luts/" + n + ".exr");
    INFO(n);
    REQUIRE(!committed.empty());
    CHECK(ReadFile(dir + "/" + n + ".exr") == committed);
  }
  RemoveTree(dir);
}
