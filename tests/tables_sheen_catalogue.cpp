// The sheen tables (charlie, charlie-smith, ashikhmin-velvet x dfg, albedo, albedo-avg): in the
// catalogue over each model's table domain (roughness from 0.045; charlie-smith's mu from 1e-4),
// all nine in the default catalogue, baked by the sheen fixed rule
// within 1e-6 of adaptive quadrature; the cloth DFG holds the albedo's bits; the search rule
// within kSearchRuleBound of the bake rule; byte-identical for -j 1 and -j 2.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "baker/bake/bake.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/integrate/fixed_rule_sheen.h"
#include "baker/models/registry.h"
#include "baker/models/sheen.h"
#include "baker/tables/catalogue.h"
#include "cli_util.h"

using namespace kiln;
using kiln::test::ReadFile;
using kiln::test::RunKiln;
using kiln::test::TempDir;

namespace {
const char* kSheen[] = {"charlie", "charlie-smith", "ashikhmin-velvet"};

bool Listed(const std::vector<TableSpec>& specs, const std::string& name) {
  return std::any_of(specs.begin(), specs.end(),
                     [&](const TableSpec& s) { return s.name == name; });
}
}  // namespace

TEST_CASE("dfg, albedo and albedo-avg of each sheen model: in the catalogue on its domain",
          "[sheen][tables]") {
  std::vector<TableSpec> def = DefaultCatalogue({}), onRequest = OnRequestTables({});
  for (const char* m : kSheen) {
    for (const char* suffix : {"-dfg", "-albedo", "-albedo-avg"}) {
      std::string name = std::string(m) + suffix;
      TableSpec s = CatalogueTable(name);
      INFO(name);
      CHECK(s.model == m);
      const AxisSpec& r = s.axes.back();
      CHECK(r.name == "roughness");
      CHECK(r.lo == kSheenTableMinRoughness);
      CHECK(r.hi == 1);
      CHECK(UsesFixedRule(s));
      if (s.axes.size() == 2) CHECK(s.axes[0].lo == (m == std::string("charlie-smith") ? 1e-4 : 0));
      // All nine in the default catalogue (README "Sheen"), none on request; each in exactly
      // one of the two lists.
      const bool inDefault = true;
      CHECK(SheenTableInDefaultCatalogue(name) == inDefault);
      CHECK(Listed(def, name) == inDefault);
      CHECK(Listed(onRequest, name) == !inDefault);
    }
    CHECK(CatalogueTable(std::string(m) + "-dfg").channels == std::vector<std::string>{"DFV"});
  }
}

TEST_CASE("Sheen albedo texels are within 1e-6 of adaptive quadrature (corners included)",
          "[sheen][tables]") {
  CatalogueOptions opt;
  opt.size = 3;
  for (const char* m : kSheen)
    for (const char* suffix : {"-albedo"}) {
      TableSpec spec = CatalogueTable(std::string(m) + suffix, opt);
      BakeOptions bo;
      bo.measureLookupError = false;
      Table t = BakeTable(spec, bo);
      double worst = 0;
      for (size_t i = 0; i < spec.TexelCount(); ++i) {
        double x[3];
        NodeEvaluationPoint(spec, i, x);
        IntegrationStats st;
        double exact = EvaluateSpec(spec, x, 1e-10, st)[0];
        worst = std::max(worst, std::abs(t.data[i] - exact));
      }
      INFO(spec.name << " worst texel error " << worst << ", declared " << t.bakeError);
      CHECK(worst < 1e-6);
      CHECK(t.bakeError < 1e-6);
    }
}

TEST_CASE("The cloth DFG holds exactly the albedo's numbers (the same integral, the same rule)",
          "[sheen][tables]") {
  CatalogueOptions opt;
  opt.size = 4;
  for (const char* m : kSheen) {
    BakeOptions bo;
    bo.measureLookupError = false;
    Table dfg = BakeTable(CatalogueTable(std::string(m) + "-dfg", opt), bo);
    Table albedo = BakeTable(CatalogueTable(std::string(m) + "-albedo", opt), bo);
    INFO(m);
    CHECK(dfg.data == albedo.data);
  }
}

TEST_CASE("The sheen search rule is within kSearchRuleBound of the bake rule, at its charge",
          "[sheen][tables]") {
  for (const char* m : kSheen) {
    TableSpec spec = CatalogueTable(std::string(m) + "-albedo");
    double worst = 0;
    long long bakeEvals = 0, searchCharged = 0;
    for (int j = 0; j <= 6; ++j)
      for (int i = 0; i <= 8; ++i) {
        double x[2] = {std::pow(i / 8.0, 4),
                       kSheenTableMinRoughness + (1 - kSheenTableMinRoughness) * j / 6.0};
        if (i == 1) x[0] = 1e-9;
        x[0] = std::max(x[0], spec.axes[0].lo);
        IntegrationStats bake, search;
        double want = EvaluateSpec(spec, x, bake)[0];
        double got = SearchReference(spec, x, search)[0];
        bakeEvals += bake.evals;
        searchCharged += search.evals;
        worst = std::max(worst, std::abs(got - want));
        CHECK(search.errorEstimate == kSearchRuleBound);
      }
    INFO(m << ": worst |search - bake| " << worst);
    CHECK(worst < kSearchRuleBound);
    // The charge does not overstate the saving: the search's charged count is at most the bake
    // rule's evaluations at the same points.
    CHECK(searchCharged <= bakeEvals);
  }
}

TEST_CASE("The charlie-smith tables start at mu = 1e-4 (Filament's MIN_N_DOT_V)",
          "[sheen][tables]") {
  TableSpec spec = CatalogueTable("charlie-smith-albedo");
  CHECK(spec.axes[0].lo == kCharlieSmithMinMu);
  CHECK(kCharlieSmithMinMu == 1e-4);
}

TEST_CASE(
    "A sheen albedo baked after its cloth DFG takes the DFG's texels and lookup-error "
    "report: the bytes of a bake of the albedo alone",
    "[sheen][tables][cli][derived]") {
  std::string dir = TempDir("sheen-shared");
  auto both = RunKiln("bake --out " + dir +
                      "/both --only charlie-smith-dfg,charlie-smith-albedo "
                      "--size 6 -j 2");
  auto alone = RunKiln("bake --out " + dir + "/alone --only charlie-smith-albedo --size 6 -j 2");
  REQUIRE(both.exitCode == 0);
  REQUIRE(alone.exitCode == 0);
  CHECK(both.err.find("texels from charlie-smith-dfg") != std::string::npos);
  CHECK(alone.err.find("texels from") == std::string::npos);
  std::string a = ReadFile(dir + "/both/charlie-smith-albedo.exr");
  REQUIRE(!a.empty());
  CHECK(a == ReadFile(dir + "/alone/charlie-smith-albedo.exr"));
  // The albedo's report is the dfg's (the same search), and kiln verify repeats it.
  auto verify = RunKiln("verify " + dir + "/both -j 2");
  CHECK(verify.exitCode == 0);
}

TEST_CASE("Sheen tables bake to the same bytes with -j 1 and -j 2", "[sheen][tables][cli]") {
  std::string dir = TempDir("sheen-j");
  const char* only = "charlie-albedo,charlie-smith-dfg,ashikhmin-velvet-albedo-avg";
  auto one =
      RunKiln("bake --out " + dir + "/j1 --only " + only + " --size 4 -j 1 -q --no-lookup-error");
  auto two =
      RunKiln("bake --out " + dir + "/j2 --only " + only + " --size 4 -j 2 -q --no-lookup-error");
  REQUIRE(one.exitCode == 0);
  REQUIRE(two.exitCode == 0);
  for (const char* t : {"charlie-albedo", "charlie-smith-dfg", "ashikhmin-velvet-albedo-avg"}) {
    std::string a = ReadFile(dir + "/j1/" + t + ".exr"), b = ReadFile(dir + "/j2/" + t + ".exr");
    INFO(t);
    REQUIRE(!a.empty());
    CHECK(a == b);
  }
}
