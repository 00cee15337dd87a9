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
#include "glass_albedo_reference.h"
#include "glass_average_reference.h"
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

/// The texels of shard `shard` among `texels` (texel indices): texel i for (i + rotation) %
/// kTexelCheckShards == shard. Each kind rotates by its own index, so that the costly texels of
/// the small tables (the averages) spread over all shards; the shards together take every texel
/// once, and a texel two kinds both check lies in one shard for both when they rotate alike.
std::vector<size_t> ShardTexels(const std::vector<size_t>& texels, int shard, size_t rotation) {
  std::vector<size_t> out;
  for (size_t i : texels)
    if ((i + rotation) % kTexelCheckShards == static_cast<size_t>(shard)) out.push_back(i);
  return out;
}

/// The rotation ShardTexels deals kind k of `specs` by: its index, but a glass kind's t side
/// takes its r side's (ggx-dielectric-albedo-t that of -r, -t-exit that of -r-exit, the averages
/// alike), so that one shard holds both at a texel and their references share one integration
/// (test::SharedGlassAlbedo, test::NestedGlassAverage).
size_t ShardRotation(const std::vector<TableSpec>& specs, size_t k) {
  if (!test::IsGlassAverage(specs[k].quantity) && !test::IsGlassAlbedo(specs[k].quantity)) return k;
  std::string partner = specs[k].name;
  const std::string side = "-albedo-t";
  const size_t at = partner.find(side);
  if (at == std::string::npos) return k;
  partner.replace(at, side.size(), "-albedo-r");
  for (size_t j = 0; j < specs.size(); ++j)
    if (specs[j].name == partner) return j;
  return k;
}

/// The reference's tolerance in the texel check: a thousandth of the 1e-6 it proves and at most
/// a sixtieth of the smallest declared bake error (5.96e-8), so the reference's own error moves no
/// verdict (a texel off by 2e-6 stays more than 1e-6 from it).
constexpr double kTexelRefTol = 1e-9;
/// An average's nested adaptive reference (an integral over mu of E by adaptive quadrature: a
/// glass average takes 3e6 to 2e7 integrand evaluations a point, once for its r and t kinds,
/// test::GlassAverageReference), at its corners and worst-departing texels; a sixtieth of the
/// averages' smallest declared bake error (5.7e-7).
constexpr double kNestedRefTol = 1e-8;

/// A table of at most this many texels has every texel checked (every kind at size 5 but the
/// exit glass E pair, whose split mu axis gives 824).
constexpr size_t kEveryTexelMax = 128;
/// A larger table: its corners, its kBakeWorstNodes worst-departing texels and this many seeded
/// Latin-hypercube texels (verify::BakeCheckNodes, stratified over every axis).
constexpr int kSampledTexels = 128;

/// The texels the check compares (ShardTexels deals them): every one, or for a table of more
/// than kEveryTexelMax, the corners, the worst-departing and a stratified sample.
std::vector<size_t> CheckedTexels(const TableSpec& spec, const Table& t) {
  std::vector<size_t> out;
  if (spec.TexelCount() > kEveryTexelMax) {
    out = verify::BakeCheckNodes(spec, t, kSampledTexels, 0x74657874);
    std::sort(out.begin(), out.end());
    return out;
  }
  for (size_t i = 0; i < spec.TexelCount(); ++i) out.push_back(i);
  return out;
}

/// Whether `spec` is an average over mu with its own outer reference (QuantityInfo::
/// verifyReference: adaptive quadrature over mu of E by its 3D table's rule, which the E kinds'
/// own texels here hold to adaptive quadrature).
bool HasOuterReference(const TableSpec& spec) {
  return Describe(spec.quantity).verifyReference != nullptr;
}

/// The error of texel i of `t` (float32, relative above 1, the integral channels): against the
/// kind's outer reference for an average, else adaptive quadrature, both to kTexelRefTol; with
/// `nested` (an average's corners and worst-departing texels, verify::BakeCheckNodes) also
/// against adaptive quadrature of the whole integral, to kNestedRefTol.
double TexelError(const TableSpec& spec, const Table& t, size_t i, bool nested) {
  double x[3];
  NodeEvaluationPoint(spec, i, x);  // where the bake evaluates (a collapsed layer: its limit)
  IntegrationStats st;
  const auto outer = Describe(spec.quantity).verifyReference;
  std::vector<std::vector<double>> refs;
  // A glass E kind's: E_R and E_T from one integration (test::GlassAlbedoReference).
  refs.push_back(outer ? outer(spec, x, kTexelRefTol, st)
                 : test::IsGlassAlbedo(spec.quantity)
                     ? test::GlassAlbedoReference(spec, x, kTexelRefTol)
                     : EvaluateSpec(spec, x, kTexelRefTol, st));
  // A glass average's: E_avg_R and E_avg_T from one integration (test::GlassAverageReference).
  if (nested)
    refs.push_back(test::IsGlassAverage(spec.quantity)
                       ? test::GlassAverageReference(spec, x, kNestedRefTol)
                       : EvaluateSpec(spec, x, kNestedRefTol, st));
  const size_t nc = spec.channels.size();
  double worst = 0;
  for (const std::vector<double>& exact : refs)
    // A fitted table's coefficient channels are not integrals (firstIntegralChannel).
    for (size_t c = size_t(Describe(spec.quantity).firstIntegralChannel); c < nc; ++c)
      worst = std::max(worst,
                       std::abs(t.data[i * nc + c] - exact[c]) / std::max(1.0, std::abs(exact[c])));
  return worst;
}

/// The small bake of `spec` the texel check reads (shared by the tests of one process).
const Table& TexelCheckBake(const TableSpec& spec) {
  BakeOptions opt;
  opt.measureLookupError = false;
  return test::CachedBake(spec, opt);
}

/// Re-integrates shard `shard` of the checked texels (CheckedTexels, ShardTexels) of each of
/// OneOfEachKind(5)
/// (TexelReferences) and compares them with what the bake stored (float32), relative above 1.
/// The shards run in one process share the bakes (test::CachedBake). An average's corners and
/// worst-departing texels (those whose value departs most from the line through their
/// neighbours: a texel off its function) are also held to nested adaptive quadrature.
void CheckTexelsAgainstExact(int shard) {
  const std::vector<TableSpec> specs = OneOfEachKind(5);
  for (size_t k = 0; k < specs.size(); ++k) {
    const TableSpec& spec = specs[k];
    const Table& t = TexelCheckBake(spec);
    std::vector<size_t> nested;
    if (HasOuterReference(spec)) nested = verify::BakeCheckNodes(spec, t, 0, 0);
    const std::vector<size_t> checked = CheckedTexels(spec, t);
    double worst = 0;
    for (size_t i : ShardTexels(checked, shard, ShardRotation(specs, k))) {
      const bool both = std::find(nested.begin(), nested.end(), i) != nested.end();
      worst = std::max(worst, TexelError(spec, t, i, both));
    }
    INFO(spec.name << " worst texel error " << worst << " declared " << t.bakeError);
    CHECK(worst < 1e-6);
    CHECK(worst <= t.bakeError);
    CHECK(t.bakeError < 1e-6);
  }
}

}  // namespace

TEST_CASE("The texel check's shards take every texel once", "[bake]") {
  for (size_t n : {1, 5, 25, 60, 61, 125, 1000})
    for (size_t rotation : {0, 3, 17}) {
      std::vector<size_t> texels(n);
      for (size_t i = 0; i < n; ++i) texels[i] = 3 * i + i % 2;  // a sparse, uneven selection
      std::vector<int> taken(n, 0);
      for (int shard = 0; shard < kTexelCheckShards; ++shard)
        for (size_t t : ShardTexels(texels, shard, rotation)) ++taken[(t - t % 3) / 3];
      for (size_t i = 0; i < n; ++i) {
        INFO("n " << n << " rotation " << rotation << " texel " << i);
        CHECK(taken[i] == 1);
      }
    }
}

TEST_CASE("A texel off by 2e-6 fails the texel check wherever it lies", "[bake]") {
  // Every texel of a 2D E table, a 1D average and a glass average (whose checked texels were
  // once only its corners, worst-departing and 4 sampled ones of 25), raised or lowered by 2e-6
  // in turn: one of the shards checks it and finds it more than 1e-6 from its reference.
  for (const char* name : {"ggx-albedo", "ggx-albedo-avg", "ggx-dielectric-albedo-t-avg"}) {
    const std::vector<TableSpec> specs = OneOfEachKind(5);
    size_t k = 0;
    while (k < specs.size() && specs[k].name != name) ++k;
    REQUIRE(k < specs.size());
    const TableSpec& spec = specs[k];
    const Table& baked = TexelCheckBake(spec);
    const std::vector<size_t> checked = CheckedTexels(spec, baked);
    REQUIRE(spec.TexelCount() <= kEveryTexelMax);
    const size_t nc = spec.channels.size(), first = Describe(spec.quantity).firstIntegralChannel;
    for (size_t i = 0; i < spec.TexelCount(); ++i) {
      int shards = 0;
      for (int shard = 0; shard < kTexelCheckShards; ++shard)
        for (size_t j : ShardTexels(checked, shard, ShardRotation(specs, k))) shards += j == i;
      Table wrong = baked;
      wrong.data[i * nc + first] += i % 2 ? -2e-6f : 2e-6f;
      INFO(name << " texel " << i);
      CHECK(shards == 1);
      CHECK(TexelError(spec, wrong, i, false) > 1e-6);
    }
  }
}

TEST_CASE("The glass E kinds' shared reference is EvaluateSpec's, one integration for r and t",
          "[bake]") {
  // At texels of each glass E kind at size 5 (by a corner, the middle, by the far corner), at a
  // tolerance the check's 1e-9 shares the code path with: the same bits as EvaluateSpec, the t
  // side's from the r side's integration.
  for (const TableSpec& spec : OneOfEachKind(5)) {
    if (!test::IsGlassAlbedo(spec.quantity)) continue;
    for (size_t i : {size_t(1), spec.TexelCount() / 2, spec.TexelCount() - 2}) {
      double x[3];
      NodeEvaluationPoint(spec, i, x);
      IntegrationStats st;
      const std::vector<double> own = EvaluateSpec(spec, x, 1e-6, st);
      const std::vector<double> shared = test::GlassAlbedoReference(spec, x, 1e-6);
      INFO(spec.name << " texel " << i << " mu " << x[0] << " r " << x[1] << " eta " << x[2]);
      REQUIRE(shared.size() == own.size());
      CHECK(shared[0] == own[0]);
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
