// The bake: every texel within 1e-6 of the exact integral for every table kind, bit-identical
// output for any thread count, self-describing metadata.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "baker/verify/bake_error.h"
#include "cli_util.h"
#include "test_bake_cache.h"
#include "test_util.h"

using namespace kiln;

namespace {

/// One small spec of every table kind the catalogue has.
std::vector<TableSpec> OneOfEachKind(int size) {
  CatalogueOptions opt;
  opt.size = size;
  std::vector<TableSpec> out;
  std::set<std::string> kinds;
  for (const TableSpec& s : DefaultCatalogue(opt)) {
    const ModelInfo* m = FindModel(s.model);
    std::string kind = QuantityName(s.quantity) + std::string(m ? (m->specular() ? "/specular"
                                                                   : m->hasRho2  ? "/rho2"
                                                                                 : "/diffuse")
                                                                : "");
    if (kinds.insert(kind).second) out.push_back(s);
  }
  return out;
}

}  // namespace

TEST_CASE("The catalogue names are the file-name contract", "[bake]") {
  std::set<std::string> names;
  for (const TableSpec& s : DefaultCatalogue()) CHECK(names.insert(s.name).second);
  for (const char* m : {"ggx", "ggx-separable", "beckmann", "beckmann-separable", "blinn-phong"})
    for (const char* suffix : {"-dfg", "-albedo", "-albedo-avg"})
      CHECK(names.count(std::string(m) + suffix) == 1);
  for (const char* n : {"ggx-fresnel-albedo", "ggx-fresnel-albedo-avg", "fresnel-dielectric",
                        "fresnel-dielectric-avg", "fresnel-conductor", "blinn-phong-normalization",
                        "oren-nayar-brdf", "gotanda-ggx-brdf", "lambert-albedo",
                        "hammon-albedo-avg", "triace-lambert-albedo", "fujii-normalized-albedo"})
    CHECK(names.count(n) == 1);
  CHECK_THROWS_WITH(CatalogueTable("ggx-dgf"), Catch::Contains("unknown table 'ggx-dgf'"));
}

namespace {

/// The shards of the check below: CTest runs each as a test of its own (in parallel with -j).
constexpr int kTexelCheckShards = 8;

/// The sampled texels of a table of n texels: every 7th of a table of more than 60, else every
/// one; shard s takes the j-th of them for (j + rotation) % kTexelCheckShards == s. Each kind
/// rotates by its own index, so that the few costly texels of the small tables (the averages)
/// spread over all shards, and the shards together check every sampled texel once.
std::vector<size_t> ShardTexels(size_t n, int shard, size_t rotation) {
  std::vector<size_t> out;
  const size_t step = n > 60 ? 7 : 1;
  for (size_t i = 0, j = rotation; i < n; i += step, ++j)
    if (j % kTexelCheckShards == static_cast<size_t>(shard)) out.push_back(i);
  return out;
}

/// The reference's tolerance in the texel check of an average: a thousandth of the 1e-6 it
/// proves and at most a sixtieth of the smallest declared bake error (5.96e-8), so the
/// reference's own error moves no verdict. The other kinds take kTexelRefTolE (cheap there).
constexpr double kTexelRefTol = 1e-9;
constexpr double kTexelRefTolE = 1e-11;

/// Seeded Latin-hypercube texels of a 2D average's check, besides its corners and its
/// worst-departing texels.
constexpr int kAverageSampleTexels = 4;

/// The texels the check compares, of which ShardTexels deals the shards theirs: every one of a
/// table of E (every 7th above 60 texels, ShardTexels), every one of a 1D average; a 2D average
/// (each texel an integral of integrals: ~1e7 integrand evaluations for the glass averages)
/// at the nodes `kiln verify` checks (verify::BakeCheckNodes, its own seed): every corner, the
/// kBakeWorstNodes texels that depart most from the line through their neighbours (where a
/// texel off its function shows), and kAverageSampleTexels Latin-hypercube texels.
std::vector<size_t> CheckedTexels(const TableSpec& spec, const Table& t) {
  const bool average = std::string(QuantityName(spec.quantity)).find("avg") != std::string::npos;
  if (average && spec.axes.size() >= 2) {
    std::vector<size_t> nodes = verify::BakeCheckNodes(spec, t, kAverageSampleTexels, 0x74657874);
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  }
  std::vector<size_t> all(spec.TexelCount());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

/// Re-integrates shard `shard` of the sampled texels (ShardTexels) of each of OneOfEachKind(5)
/// by adaptive quadrature (kTexelRefTol for an average, whose reference is an integral of
/// integrals: the glass averages take ~20M integrand evaluations a texel at 1e-10, 30% fewer at
/// 1e-9; kTexelRefTolE for the others) and compares them with what the bake stored (float32).
/// The shards run in one process share the bakes (test::CachedBake).
void CheckTexelsAgainstExact(int shard) {
  const std::vector<TableSpec> specs = OneOfEachKind(5);
  for (size_t k = 0; k < specs.size(); ++k) {
    const TableSpec& spec = specs[k];
    BakeOptions opt;
    opt.measureLookupError = false;
    const Table& t = test::CachedBake(spec, opt);
    const size_t nc = spec.channels.size();
    const std::vector<size_t> checked = CheckedTexels(spec, t);
    double worst = 0;
    for (size_t j : ShardTexels(checked.size(), shard, k)) {
      const size_t i = checked[j];
      double x[3];
      NodeEvaluationPoint(spec, i, x);  // where the bake evaluates (a collapsed layer: its limit)
      IntegrationStats st;
      std::vector<double> exact = EvaluateSpec(
          spec, x,
          std::string(QuantityName(spec.quantity)).find("avg") != std::string::npos ? kTexelRefTol
                                                                                    : kTexelRefTolE,
          st);
      // A fitted table's coefficient channels are not integrals
      // (QuantityInfo::firstIntegralChannel).
      for (size_t c = size_t(Describe(spec.quantity).firstIntegralChannel); c < nc; ++c)
        worst = std::max(
            worst, std::abs(t.data[i * nc + c] - exact[c]) / std::max(1.0, std::abs(exact[c])));
    }
    INFO(spec.name << " worst texel error " << worst << " declared " << t.bakeError);
    CHECK(worst < 1e-6);
    CHECK(worst <= t.bakeError);
    CHECK(t.bakeError < 1e-6);
  }
}

}  // namespace

TEST_CASE("The texel check's shards take every sampled texel once", "[bake]") {
  for (size_t n : {1, 5, 25, 60, 61, 125, 1000})
    for (size_t rotation : {0, 3, 17}) {
      std::vector<int> taken(n, 0);
      for (int shard = 0; shard < kTexelCheckShards; ++shard)
        for (size_t i : ShardTexels(n, shard, rotation)) ++taken[i];
      const size_t step = n > 60 ? 7 : 1;
      for (size_t i = 0; i < n; ++i) {
        INFO("n " << n << " rotation " << rotation << " texel " << i);
        CHECK(taken[i] == (i % step == 0 ? 1 : 0));
      }
    }
}

// Every texel of every table kind is within 1e-6 of the exact integral (relative above 1),
// checked at a sample of texels dealt into shards (CheckTexelsAgainstExact), one test each.
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 1 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(0);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 2 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(1);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 3 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(2);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 4 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(3);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 5 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(4);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 6 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(5);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 7 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(6);
}
TEST_CASE("Every texel of every table kind is within 1e-6 of the exact integral, shard 8 of 8",
          "[bake]") {
  CheckTexelsAgainstExact(7);
}

TEST_CASE("A bake is bit-identical for 1, 2 and 3 threads and across runs", "[bake]") {
  for (const char* name : {"ggx-dfg", "oren-nayar-albedo", "ggx-fresnel-albedo"}) {
    CatalogueOptions copt;
    copt.size = 5;
    TableSpec spec = CatalogueTable(name, copt);
    BakeOptions a, b, c;
    a.threads = 1;
    b.threads = 2;
    c.threads = 3;
    Table ta = BakeTable(spec, a), tb = BakeTable(spec, b), tc = BakeTable(spec, c),
          td = BakeTable(spec, b);
    INFO(name);
    CHECK(ta.data == tb.data);
    CHECK(ta.data == tc.data);
    CHECK(tb.data == td.data);
    CHECK(ta.lookupError.max == tb.lookupError.max);
    CHECK(ta.bakeError == tc.bakeError);
  }
}

TEST_CASE("A baked table describes itself", "[bake]") {
  CatalogueOptions copt;
  copt.size = 5;
  TableSpec spec = CatalogueTable("oren-nayar-albedo", copt);
  Table t = BakeTable(spec, BakeOptions{});
  CHECK(t.name == "oren-nayar-albedo");
  CHECK(t.model == "oren-nayar");
  CHECK(t.quantity == "albedo");
  CHECK(t.channels == std::vector<std::string>{"E_rho", "E_rho2"});
  REQUIRE(t.dims() == 2);
  CHECK(t.axes[0].name == "mu");
  CHECK(t.axes[1].name == "roughness");
  CHECK(t.axes[1].axis.hi == Approx(Pi / 2));
  CHECK(t.specHash == spec.Hash());
  CHECK(t.lookupError.max >= 0);
  CHECK(!t.method.empty());
  std::string problem;
  CHECK(validateTable(t, problem));
  // The spec hash changes with anything that changes the texels.
  TableSpec other = spec;
  other.axes[0].size = 6;
  CHECK(other.Hash() != spec.Hash());
  other = spec;
  other.tol = 1e-9;
  CHECK(other.Hash() != spec.Hash());
}

TEST_CASE("Absurd table shapes are refused with a clear message", "[bake]") {
  TableSpec spec = CatalogueTable("fresnel-dielectric");
  spec.axes[0].size = 0;
  CHECK_THROWS_WITH(BakeTable(spec, BakeOptions{}), Catch::Contains("axis mu"));
  spec.axes[0].size = 1000000;
  CHECK_THROWS_WITH(BakeTable(spec, BakeOptions{}), Catch::Contains("absurd"));
}
