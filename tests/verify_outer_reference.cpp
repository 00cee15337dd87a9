// `kiln verify --tol T --outer-reference`: an average's lookup search takes the bake-error
// check's reference (adaptive quadrature over mu of E by its 3D table's rule) at its cells and
// random points instead of nested adaptive quadrature (millions of integrand evaluations a point
// for the glass averages); the declared worst point keeps the nested one. The two references
// agree far below any lookup bound, the option needs --tol, and a glass average made wrong on
// purpose still fails its lookup bound with it.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/io/exr_writer.h"
#include "baker/io/texture_readers.h"
#include "baker/tables/spec.h"
#include "cli_util.h"
#include "committed_luts.h"

using namespace kiln;

TEST_CASE("An average's outer reference agrees with nested adaptive quadrature",
          "[verify][outer-reference]") {
  // The tables' lookup bounds are ~1e-4 and more; the two references agree to 1e-6 (the E rule
  // is held to adaptive quadrature by the 3D tables' own checks). Points off the nodes, on both
  // sides of the interface and for a microfacet conductor average.
  struct Case {
    const char* table;
    double x[3];
  };
  for (const Case& c : {Case{"ggx-dielectric-albedo-t-avg", {0.37, 1.63, 0}},
                        Case{"ggx-dielectric-albedo-r-exit-avg", {0.61, 1 / 1.27, 0}},
                        Case{"ggx-albedo-avg", {0.23, 0, 0}}}) {
    const Table t = LoadAnyTable(test::LutsDir() + "/" + c.table + ".exr");
    const TableSpec spec = SpecFromTable(t);
    const auto outer = Describe(spec.quantity).verifyReference;
    REQUIRE(outer != nullptr);
    IntegrationStats a, b;
    const double tol = 1e-7;
    const std::vector<double> cheap = outer(spec, c.x, tol, a);
    const std::vector<double> nested = EvaluateSpec(spec, c.x, tol, b);
    REQUIRE(cheap.size() == nested.size());
    INFO(c.table << ": outer " << cheap[0] << " (" << a.evals << " evaluations), nested "
                 << nested[0] << " (" << b.evals << ")");
    for (size_t ch = 0; ch < cheap.size(); ++ch) CHECK(std::abs(cheap[ch] - nested[ch]) < 1e-6);
  }
}

TEST_CASE("kiln verify --outer-reference needs --tol", "[verify][outer-reference][cli]") {
  test::CommandResult r =
      test::RunKiln("verify " + test::LutsDir() + "/ggx-albedo-avg.exr --outer-reference");
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("kiln: error: verify: --outer-reference needs --tol") != std::string::npos);
}

TEST_CASE("A glass average raised at one inner node fails kiln verify --outer-reference",
          "[verify][outer-reference][cli]") {
  // ggx-dielectric-albedo-t-avg with one inner node raised by 5e-3 (several times its declared
  // lookup bound): the cells around it rank first by their predicted error among the inner
  // cells, so the search of 8 cells (4 corners, then edge and inner cells alternately) reaches
  // them and measures the lookup error there against the outer reference. The declared worst
  // point is left where the bake found it (a corner), so only the search can find the node.
  constexpr double kRaise = 5e-3;
  Table t = LoadAnyTable(test::LutsDir() + "/ggx-dielectric-albedo-t-avg.exr");
  REQUIRE(t.dims() == 2);
  REQUIRE(t.lookupError.max < kRaise / 4);
  const size_t n0 = static_cast<size_t>(t.axes[0].axis.size);
  const size_t node = n0 * (static_cast<size_t>(t.axes[1].axis.size) / 2) + n0 / 2;
  t.data[node * t.channels.size()] += static_cast<float>(kRaise);
  const std::string dir = test::TempDir("verify_outer_reference");
  const std::string file = dir + "/ggx-dielectric-albedo-t-avg.exr";
  writeTable(file, t, false);
  const std::string flags =
      " --points 0 --cells 8 --budget 170 --tol 1e-6 --outer-reference "
      "--bake-nodes 0 -j 2 --json";
  test::CommandResult r = test::RunKiln("verify " + file + flags);
  INFO(r.out << r.err);
  CHECK(r.exitCode == 1);
  const nlohmann::json v = nlohmann::json::parse(r.out)["tables"][0];
  CHECK(v["max"].get<double>() > kRaise / 4);
  CHECK(v["max"].get<double>() > v["declared"].get<double>());
  std::filesystem::remove_all(dir);
}
