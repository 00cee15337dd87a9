// kiln plan --check: exit 1 when a table is missing or stale, 0 when every one is up to date;
// plan without --check exits 0 either way.
#include <catch2/catch.hpp>
#include <filesystem>

#include "cli_util.h"

using kiln::test::RunKiln;

TEST_CASE("kiln plan --check exits 1 while something is missing or stale, then 0",
          "[cli][plan][check]") {
  std::string dir = "/tmp/kiln_test_plan_check_" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::string scene = std::string(KILN_SOURCE_DIR) + "/tests/scenes/merge.gltf";
  std::string plan = "plan " + scene + " --size 4 --out " + dir;
  auto missing = RunKiln(plan + " --check");
  CHECK(missing.exitCode == 1);
  CHECK(missing.out.find("[missing]") != std::string::npos);  // the report is still printed
  CHECK(missing.err ==
        "kiln: error: plan --check: 3 of 3 table(s) missing or stale in " + dir + "\n");
  CHECK(RunKiln(plan).exitCode == 0);  // without --check: 0

  REQUIRE(RunKiln("bake --quiet --scene " + scene + " --size 4 -j 2 --out " + dir).exitCode == 0);
  auto ready = RunKiln(plan + " --check");
  CHECK(ready.exitCode == 0);
  CHECK(ready.err.empty());

  // A table baked at another size is stale: 1 again.
  REQUIRE(RunKiln("bake --quiet --scene " + scene + " --size 5 -j 2 --out " + dir).exitCode == 0);
  auto stale = RunKiln(plan + " --check");
  CHECK(stale.exitCode == 1);
  CHECK(stale.out.find("[stale]") != std::string::npos);
  CHECK(RunKiln(plan).exitCode == 0);
  std::filesystem::remove_all(dir);
}
