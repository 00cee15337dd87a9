// Derived tables (issue #13): a microfacet albedo table baked in the same run as its model's dfg
// table takes its texels from the dfg's node values (E = A + B at F = 1) instead of integrating
// again, and its file is the one a bake of the albedo alone writes, byte for byte.
#include <catch2/catch.hpp>

#include <cstring>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "cli_util.h"
#include "test_bake_cache.h"

using namespace kiln;
using namespace kiln::test;

namespace {

bool SameTexels(const Table& a, const Table& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE(
    "A microfacet or sheen albedo derived from its dfg's node values has its own rule's texels",
    "[bake][derived]") {
  std::vector<std::string> models = CatalogueMicrofacetModels();
  for (const std::string& m : CatalogueSheenModels()) models.push_back(m);  // a copy of DFV
  for (const std::string& model : models) {
    INFO(model);
    const TableSpec dfg = test::SmallSpec(Quantity::Dfg, model),
                    albedo = test::SmallSpec(Quantity::Albedo, model);
    NodeValueCache cache({dfg, albedo});
    BakeOptions opt;
    opt.threads = 2;
    opt.measureLookupError = false;
    // The albedo alone: its own fixed rule (no source kept yet).
    REQUIRE(cache.SourceFor(albedo) == nullptr);
    BakeStats ownStats;
    Table own = BakeTable(albedo, opt, &ownStats);
    CHECK(ownStats.derivedFrom.empty());
    CHECK(ownStats.evals > 0);
    // The dfg keeps its node values; the albedo then derives from them.
    NodeValues* keep = cache.KeepFor(dfg);
    REQUIRE(keep != nullptr);
    CHECK(cache.KeepFor(albedo) == nullptr);  // nothing derives from the albedo
    BakeTable(dfg, opt, nullptr, nullptr, keep);
    const NodeValues* from = cache.SourceFor(albedo);
    REQUIRE(from == keep);
    BakeStats derivedStats;
    Table derived = BakeTable(albedo, opt, &derivedStats, from);
    CHECK(derivedStats.derivedFrom == dfg.name);
    CHECK(derivedStats.evals == 0);
    CHECK(SameTexels(own, derived));
    CHECK(derived.bakeError == own.bakeError);
    CHECK(derived.specHash == own.specHash);
    CHECK(derived.method == own.method);
  }
}

TEST_CASE("Only a dfg of the same model, nodes and channels serves as an albedo's source",
          "[bake][derived]") {
  const TableSpec albedo = test::SmallSpec(Quantity::Albedo, "beckmann");
  TableSpec otherNodes = test::SmallSpec(Quantity::Dfg, "beckmann");
  otherNodes.axes[1].size = 10;
  const TableSpec otherModel = test::SmallSpec(Quantity::Dfg, "ggx");
  NodeValueCache cache({otherNodes, otherModel, albedo});
  CHECK(cache.KeepFor(otherNodes) == nullptr);
  CHECK(cache.KeepFor(otherModel) == nullptr);
  CHECK(cache.SourceFor(albedo) == nullptr);
  // A diffuse albedo has its own rule; a fit-free kind without the hook never derives.
  CHECK(NodeValueCache({test::SmallSpec(Quantity::Albedo, "burley")})
            .SourceFor(test::SmallSpec(Quantity::Albedo, "burley")) == nullptr);
}

TEST_CASE("kiln bake derives an albedo after its dfg, and writes the bytes a bake of it alone does",
          "[cli][bake][derived]") {
  std::string both = TempDir("derived_both"), alone = TempDir("derived_alone");
  auto run = RunKiln("bake --out " + both + " --only beckmann-dfg,beckmann-albedo --size 12 -j 2");
  REQUIRE(run.exitCode == 0);
  CHECK(run.err.find("texels from beckmann-dfg") != std::string::npos);
  auto single = RunKiln("bake --out " + alone + " --only beckmann-albedo --size 12 -j 2");
  REQUIRE(single.exitCode == 0);
  CHECK(single.err.find("texels from") == std::string::npos);
  CHECK(ReadFile(both + "/beckmann-albedo.exr") == ReadFile(alone + "/beckmann-albedo.exr"));
  // The manifest says where the texels came from, and the evaluations stay with the source.
  std::string manifest = ReadFile(both + "/manifest.json");
  CHECK(manifest.find("\"texels_from\": \"beckmann-dfg\"") != std::string::npos);
  CHECK(ReadFile(alone + "/manifest.json").find("texels_from") == std::string::npos);
  RemoveTree(both);
  RemoveTree(alone);
}
