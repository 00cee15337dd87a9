// `kiln verify` also measures the lookup error at the point the table declares as its worst
// (kiln.lookup_error.where, where the bake's own search found its max): a search whose budget
// stops in the corner cells (a costly reference) still checks the bound where the bake found it
// tightest.
#include <catch2/catch.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/io/exr_writer.h"
#include "baker/io/texture_readers.h"
#include "cli_util.h"
#include "committed_luts.h"

using namespace kiln;

TEST_CASE("kiln verify measures the lookup error at the table's declared worst point",
          "[verify][cli]") {
  // A 1D table with its node 40 (far from the corner cells) raised by 1e-2, hundreds of times
  // its declared lookup error, and kiln.lookup_error.where naming that node. The check does not
  // depend on the reference's cost: fresnel-dielectric-avg's is cheap (a 1D integral), where an
  // albedo average's nested adaptive quadrature at 1e-8 takes ~30 ms a point.
  constexpr double kRaise = 1e-2;
  constexpr const char* kTable = "fresnel-dielectric-avg";
  Table t = LoadAnyTable(test::LutsDir() + "/" + kTable + ".exr");
  REQUIRE(t.dims() == 1);
  REQUIRE(t.lookupError.max < kRaise / 10);
  const int node = 40;
  REQUIRE(t.axes[0].axis.size > node + 10);
  t.data[static_cast<size_t>(node) * t.channels.size()] += static_cast<float>(kRaise);
  char where[128];
  std::snprintf(where, sizeof where, "max %.3g at %s=%.6g, bound = 1.5 x max", t.lookupError.max,
                t.axes[0].name.c_str(), t.axes[0].axis.node(node));
  t.lookupError.where = where;
  const std::string dir = test::TempDir("verify_declared_worst");
  const std::string file = dir + "/" + kTable + ".exr";
  writeTable(file, t, false);

  // A search of one cell and two reference evaluations: the corner cell only.
  test::CommandResult r = test::RunKiln(
      "verify " + file + " --budget 2 --cells 1 --points 0 --bake-nodes 0 --tol 1e-8 --json");
  INFO(r.out << r.err);
  CHECK(r.exitCode == 1);
  const nlohmann::json v = nlohmann::json::parse(r.out)["tables"][0];
  CHECK(v["ok"] == false);
  CHECK(v["max"].get<double>() > kRaise / 2);  // found at the declared point
  CHECK(v["where"].get<std::string>().find(t.axes[0].name + "=") == 0);
  // The unchanged table passes the same check, its declared point included.
  r = test::RunKiln("verify " + test::LutsDir() + "/" + kTable +
                    ".exr --budget 2 --cells 1 --points 0 --bake-nodes 0 --tol 1e-8 --json");
  CHECK(r.exitCode == 0);
  std::filesystem::remove_all(dir);
}
