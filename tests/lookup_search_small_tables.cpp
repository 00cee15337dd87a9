// Specification: the lookup-error search looks at every cell of a small table even when each
// reference point is costly. A glass average's point is a whole mu integral, so the automatic
// budget (2e7 integrand evaluations) bought 67 points, 3 of the 345 cells of
// ggx-dielectric-albedo-r-exit-avg, which then declared 8.3e-4 where a search of every cell found
// 9.8e-4. A table of at most 1,024 cells now gets every unprobed cell's centre and the worst of
// those probed in full (bake/lookup_error.cpp), so `kiln verify` with the bake's own budget
// evaluates at least one point per cell.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_util.h"

using kiln::test::RunKiln;
using nlohmann::json;

TEST_CASE("The search of a small table with a costly reference evaluates every cell",
          "[lookup-search]") {
  const std::string file =
      std::string(KILN_SOURCE_DIR) + "/luts/ggx-dielectric-albedo-t-exit-avg.exr";
  auto inspect = RunKiln("inspect " + file + " --json");
  REQUIRE(inspect.exitCode == 0);
  const json info = json::parse(inspect.out);
  long long cells = 1;
  for (const json& axis : info["axes"]) cells *= axis["size"].get<long long>() - 1;
  REQUIRE(cells == 31 * 23);

  auto verify = RunKiln("verify " + file + " --json -j 2");
  REQUIRE(verify.exitCode == 0);
  const json report = json::parse(verify.out)["tables"][0];
  INFO(verify.out);
  CHECK(report["ok"].get<bool>());
  // Fewer than a tenth of the cells fit the budget's full probes (9 points each) ...
  CHECK(report["points"].get<long long>() < 9 * cells);
  // ... yet every cell has its centre evaluated, and more cells than the budget's are searched.
  CHECK(report["points"].get<long long>() >= cells);
  CHECK(report["cells"].get<long long>() > 8);
}
