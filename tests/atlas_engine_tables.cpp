// The error atlas's table approximations (baker/atlas/atlas_tables.h, docs/atlas/tables.md): each
// engine formula reproduces its published form or the engine's own data, and the atlas measures
// it against the exact integrals of the kiln table it stands for.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "baker/atlas/atlas_tables.h"
#include "baker/fit/engine_approximations.h"
#include "baker/integrate/hemisphere.h"
#include "baker/tables/catalogue.h"
#include "stress_util.h"

using namespace kiln;

namespace {

/// The approximation at (mu, roughness) as the atlas evaluates it.
std::vector<float> At(FitEvaluator f, float mu, float r) {
  const float x[2] = {mu, r};
  std::vector<float> out(4, 0.0f);
  f(FitForm(), x, out.data());
  return out;
}

}  // namespace

TEST_CASE("Karis's EnvBRDFApprox gives its published formula's values", "[atlas][engines]") {
  // The formula of Karis 2014 evaluated in double by hand (docs/fits.md quotes it).
  auto ab = At(KarisEnvBrdfApprox, 1.0f, 0.0f);
  CHECK(ab[0] == Approx(0.994127).margin(2e-6));
  CHECK(ab[1] == Approx(0.005873).margin(2e-6));
  ab = At(KarisEnvBrdfApprox, 0.5f, 0.5f);
  CHECK(ab[0] == Approx(0.703244).margin(2e-6));
  CHECK(ab[1] == Approx(0.021756).margin(2e-6));
}

TEST_CASE("Lazarov's gloss follows Black Ops's exponent 8192^g matched by n = 2/alpha^2 - 2",
          "[atlas][engines]") {
  CHECK(LazarovGloss(0.0f) == 1.0f);
  CHECK(LazarovGloss(1.0f) == 0.0f);
  // n = 8192^0.5 = 90.51 at alpha^2 = 2 / (n + 2).
  const float half = static_cast<float>(std::pow(2.0 / (std::sqrt(8192.0) + 2.0), 0.25));
  CHECK(LazarovGloss(half) == Approx(0.5).margin(1e-5));
  CHECK(LazarovGloss(0.3f) == Approx(0.610471).margin(1e-5));
}

TEST_CASE("Lazarov's EnvironmentBRDF gives its published formula's values as (A, B)",
          "[atlas][engines]") {
  // g = 1, mu = 1: a0 = min(0.475, 2^-9.28) / 0.96 + 0.0025 / 0.96, a1 = 1.
  auto ab = At(LazarovEnvironmentBrdf, 1.0f, 0.0f);
  CHECK(ab[1] == Approx(0.004280).margin(2e-6));
  CHECK(ab[0] + ab[1] == Approx(1.0).margin(1e-6));
  // g = 1, mu = 0: a0 = 0.475 / 0.96 + 0.0025 / 0.96.
  ab = At(LazarovEnvironmentBrdf, 0.0f, 0.0f);
  CHECK(ab[1] == Approx(0.497396).margin(2e-6));
  ab = At(LazarovEnvironmentBrdf, 0.1f, 0.3f);
  CHECK(ab[0] == Approx(0.722718).margin(1e-5));
  CHECK(ab[1] == Approx(0.179900).margin(1e-5));
  // g = 0: a0 = -0.015625 saturates to 0 at f0 = 0; a1 = 0.75.
  ab = At(LazarovEnvironmentBrdf, 0.2f, 1.0f);
  CHECK(ab[1] == 0.0f);
  CHECK(ab[0] == Approx(0.75).margin(1e-6));
}

TEST_CASE("three.js's sheen approximations give their published formulas' values",
          "[atlas][engines]") {
  CHECK(At(ThreeSheenAlbedo, 1.0f, 1.0f)[0] == Approx(0.163703).margin(2e-6));
  CHECK(At(ThreeSheenAlbedo, 0.5f, 0.5f)[0] == Approx(0.135314).margin(2e-6));
  CHECK(At(ThreeSheenAlbedo, 0.0f, 0.1f)[0] == Approx(0.307835).margin(2e-6));
  // Former: E = pi saturate(DG / pi).
  CHECK(At(ThreeSheenAlbedoFormer, 1.0f, 1.0f)[0] == Approx(0.084005).margin(2e-6));
  CHECK(At(ThreeSheenAlbedoFormer, 0.2f, 0.045f)[0] == Approx(0.205527).margin(2e-6));
  CHECK(At(ThreeSheenAlbedoFormer, 0.0f, 0.1f)[0] == Approx(3.14159265).margin(1e-6));
}

TEST_CASE("three.js's DFGLUTData lookup returns the engine's texels at their centres",
          "[atlas][engines]") {
  std::ifstream in(std::string(KILN_SOURCE_DIR) + "/tests/engines/three_dfg_lut.csv");
  std::string line;
  int texels = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;
    int row = 0, col = 0;
    double scale = 0, bias = 0;
    REQUIRE(std::sscanf(line.c_str(), "%d,%d,%lf,%lf", &row, &col, &scale, &bias) == 4);
    // v = mu indexes the rows, u = roughness the columns.
    auto ab = At(ThreeDfgLutLookup, (row + 0.5f) / 16, (col + 0.5f) / 16);
    INFO("texel row " << row << " col " << col);
    CHECK(ab[0] == Approx(scale).margin(1e-6));
    CHECK(ab[1] == Approx(bias).margin(1e-6));
    ++texels;
  }
  CHECK(texels == 256);
}

TEST_CASE("every table approximation stands for a (mu, roughness) table of the catalogue",
          "[atlas][engines]") {
  for (const TableApproximation& t : TableApproximations()) {
    INFO(t.name);
    const TableSpec spec = CatalogueTable(t.table);
    REQUIRE(spec.axes.size() == 2);
    CHECK(spec.axes[0].name == "mu");
    CHECK(spec.axes[1].name == "roughness");
    CHECK(spec.channels.size() <= 4);
    CHECK(t.eval != nullptr);
  }
}

TEST_CASE("the atlas measures EnvBRDFApprox's max at 0.500 against the exact GGX DFG",
          "[atlas][engines]") {
  AtlasOptions opt;
  opt.muNodes = opt.roughnessNodes = 3;
  opt.threads = 2;
  const TableApproximationResult r = ComputeTableApproximation(TableApproximations().front(), opt);
  REQUIRE(r.approx.name == "karis-envbrdfapprox");
  CHECK(r.report.max == Approx(0.500).margin(1e-3));
  CHECK(r.report.maxOffJump == Approx(0.500).margin(1e-3));
  REQUIRE(r.report.where.size() == 2);
  CHECK(r.report.where[0] < 0.01);  // grazing
  CHECK(r.report.where[1] > 0.9);   // rough
  // The CSV grid: exact values are the table's own integrals at the grid's points.
  const std::string csv = TableApproximationCsv(r);
  CHECK(csv.rfind("mu,roughness,exact_A,exact_B,approx_A,approx_B,max_abs_err\n", 0) == 0);
  REQUIRE(r.mu.size() == 9);
  const TableSpec spec = CatalogueTable("ggx-dfg");
  const double x[2] = {r.mu[4], r.roughness[4]};
  IntegrationStats stats;
  const std::vector<double> e = EvaluateSpec(spec, x, stats);
  CHECK(x[0] == Approx(0.5));
  CHECK(r.exact[8] == e[0]);
  CHECK(r.exact[9] == e[1]);
}

TEST_CASE("kiln atlas --section tables writes the approximations and tables.md only",
          "[atlas][cli]") {
  using namespace kiln::stress;
  ScratchDir dir("atlas_tables");
  auto r = RunKilnFor(120, "atlas --out " + Quote(dir.path.string()) +
                               " --section tables --only three-sheen --grid 3 -j 2");
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(std::filesystem::exists(dir.path / "three-sheen.csv"));
  CHECK(std::filesystem::exists(dir.path / "three-sheen.png"));
  CHECK(std::filesystem::exists(dir.path / "tables.md"));
  CHECK(!std::filesystem::exists(dir.path / "README.md"));
  auto bad = RunKilnFor(60, "atlas --out " + Quote(dir.path.string()) + " --section table");
  CHECK(IsCleanRefusal(bad));
  auto pair = RunKilnFor(
      60, "atlas --out " + Quote(dir.path.string()) + " --section tables --only lambert");
  CHECK(IsCleanRefusal(pair));
  CHECK(pair.err.find("unknown approximation 'lambert'") != std::string::npos);
}
