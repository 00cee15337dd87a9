// Specification: a user's lobe (kiln/model_abi.h, baker/custom/) is a model like a built-in one.
// Compiled from its source into a cache, it evaluates, integrates by adaptive quadrature and
// tabulates; a GGX written by a user gives the built-in GGX's table within that table's bounds;
// its tables' spec hash holds the source's hash (an edited lobe makes them stale); a lobe that
// does not compile, breaks the ABI or returns NaN, infinite or negative values is refused with
// the compiler's lines or the directions where it happened.
#include <catch2/catch.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "baker/custom/custom_registry.h"
#include "baker/integrate/quantities.h"
#include "baker/tables/catalogue.h"
#include "custom_util.h"
#include "test_util.h"
#include "kiln/exr_loader.h"

using namespace kiln;
using namespace kiln::test;
using Catch::Matchers::Contains;

namespace {

double DirectionalAlbedoOf(const std::string& id, double mu, double r) {
  ModelParams p;
  p.roughness = r;
  IntegrationOptions opt;
  opt.tol = 1e-9;
  IntegrationStats stats;
  return DirectionalAlbedo(MakeModel(id, p), mu, opt, stats).lin;
}

/// Texel indices (axis 0 fastest) of an n0 x n1 table where a sharp lobe is hardest, stratified
/// with a fixed seed: in the first three rows of axis 1 (roughness 0, the layer's limit, and the
/// two smallest: on the catalogue's grid alpha < 1e-7, where mu nodes reach below 1e-12) the
/// first three nodes (the view on the horizon and the two most grazing), the last, and one node
/// of each three others; in the first three columns of axis 0, one row of each six; and every
/// ninth node of the rest with the last row and column. (Every node of those rows and every
/// third row of those columns: twice the adaptive integrals, most of them the costly grazing
/// ones, for what one of each block shows: the two tables differ by float rounding everywhere.)
std::vector<size_t> EdgesAndLattice(int n0, int n1) {
  constexpr int kRowBlock = 3, kColumnBlock = 6, kLattice = 9, kEdge = 3;
  Rng rng(0xED6E);
  auto pick = [&](int block) {
    return std::min(block - 1, static_cast<int>(rng.Uniform() * block));
  };
  std::vector<char> chosen(static_cast<size_t>(n0) * n1, 0);
  auto mark = [&](int i, int j) {
    if (i < n0 && j < n1) chosen[static_cast<size_t>(j) * n0 + i] = 1;
  };
  for (int j = 0; j < kEdge; ++j) {
    for (int i = 0; i < kEdge; ++i) mark(i, j);
    for (int b = kEdge; b < n0; b += kRowBlock) mark(b + pick(kRowBlock), j);
    mark(n0 - 1, j);
  }
  for (int i = 0; i < kEdge; ++i)
    for (int b = kEdge; b < n1; b += kColumnBlock) mark(i, b + pick(kColumnBlock));
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i)
      if ((i % kLattice == 0 || i == n0 - 1) && (j % kLattice == 0 || j == n1 - 1)) mark(i, j);
  std::vector<size_t> nodes;
  for (size_t k = 0; k < chosen.size(); ++k)
    if (chosen[k]) nodes.push_back(k);
  return nodes;
}

}  // namespace

TEST_CASE("a user's GGX evaluates as the built-in ggx and is integrated over half vectors",
          "[custom]") {
  const ModelInfo& info = ExampleLobe("user_ggx.cpp");
  CHECK(info.id == "user-ggx");
  CHECK(info.specular());
  CHECK(FindModel("user-ggx") == &info);
  for (double r : {0.1, 0.5, 1.0}) {
    ModelParams p;
    p.roughness = r;
    AnyModel user = MakeModel("user-ggx", p), ggx = MakeModel("ggx", p);
    for (double mu_l : {0.05, 0.4, 0.9})
      for (double phi : {0.0, 1.0, 3.0}) {
        Vec3 wo = ViewDirection(0.6), wi = DirectionFromMuPhi(mu_l, phi);
        CHECK(Evaluate(user, wo, wi) == Approx(Evaluate(ggx, wo, wi)).epsilon(1e-12));
      }
    CHECK(DirectionalAlbedoOf("user-ggx", 0.3, r) ==
          Approx(DirectionalAlbedoOf("ggx", 0.3, r)).margin(1e-8));
  }
}

TEST_CASE(
    "a sharp lobe cut by the horizon: E at mu = 0 is the limit from above, whatever the "
    "tolerance",
    "[custom]") {
  ExampleLobe("normalized_phong.cpp");  // alpha = 1e-3 at r = 1e-6: a Phong exponent of 2e6
  const double limit = DirectionalAlbedoOf("phong-normalized", 1e-9, 1e-6);
  for (double tol : {1e-7, 1e-9, 1e-11}) {
    IntegrationOptions opt;
    opt.tol = tol;
    IntegrationStats stats;
    ModelParams p;
    p.roughness = 1e-6;
    const double e = DirectionalAlbedo(MakeModel("phong-normalized", p), 0, opt, stats).lin;
    INFO("tol " << tol << ": E(0) = " << e << ", E(1e-9) = " << limit);
    CHECK(e == Approx(limit).margin(1e-9));
  }
}

TEST_CASE(
    "a user's GGX albedo table equals the committed ggx-albedo within both tables' declared "
    "bake errors, at the sharpest roughness and the grazing views too",
    "[custom]") {
  ExampleLobe("user_ggx.cpp");
  const TableSpec user = CatalogueTable("user-ggx-albedo"), ggx = CatalogueTable("ggx-albedo");
  REQUIRE(user.axes.size() == ggx.axes.size());
  for (size_t d = 0; d < user.axes.size(); ++d) {
    CHECK(user.axes[d].size == ggx.axes[d].size);
    CHECK(user.axes[d].warp == ggx.axes[d].warp);
  }
  CHECK_FALSE(UsesFixedRule(user));  // adaptive quadrature, to the tolerance the method states
  CHECK_THAT(user.Method(), Contains("adaptive") && Contains("custom model 'user-ggx'"));
  const Table committed = loadTable(std::string(KILN_SOURCE_DIR) + "/luts/ggx-albedo.exr");
  REQUIRE(committed.bakeError >= 0);
  const std::vector<size_t> nodes = EdgesAndLattice(user.axes[0].size, user.axes[1].size);
  std::vector<double> values(nodes.size()), errors(nodes.size());
  tbb::task_arena(2).execute([&] {
    tbb::parallel_for(size_t(0), nodes.size(), [&](size_t k) {
      double x[2];
      NodeEvaluationPoint(user, nodes[k], x);  // where the bake evaluates the texel
      IntegrationStats stats;
      values[k] = EvaluateSpec(user, x, stats)[0];
      errors[k] = stats.errorEstimate;
    });
  });
  // The user table's declared error as its bake states it (bake.cpp: ten times the largest
  // estimate, at least the tolerance, and float32 rounding) over these nodes.
  const double userError =
      10 * std::max(*std::max_element(errors.begin(), errors.end()), user.tol) + 0x1p-24;
  const double bound = committed.bakeError + userError;
  const int n0 = user.axes[0].size;
  double worst = 0;
  size_t worstNode = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    double diff = std::abs(double(static_cast<float>(values[k])) - committed.data[nodes[k]]);
    if (diff > worst) worst = diff, worstNode = nodes[k];
  }
  INFO(nodes.size() << " nodes; worst difference " << worst << " at mu node " << worstNode % n0
                    << ", roughness node " << worstNode / n0 << "; bound " << bound);
  CHECK(worst <= bound);
}

TEST_CASE("a diffuse lobe is integrated over light directions by adaptive quadrature", "[custom]") {
  std::string src = WriteLobe("lambert", "my-lambert", false, "return 1 / 3.14159265358979323846;");
  const ModelInfo& info = LoadModelSource(src, CustomCache());
  CHECK_FALSE(info.specular());
  for (double mu : {0.0, 0.3, 1.0})
    CHECK(DirectionalAlbedoOf("my-lambert", mu, 0.5) == Approx(1).margin(1e-9));
  const TableSpec spec = CatalogueTable("my-lambert-albedo");
  CHECK_FALSE(UsesFixedRule(spec));
  CHECK_THROWS_WITH(CatalogueTable("my-lambert-dfg"), Contains("unknown table"));  // not specular
}

TEST_CASE(
    "a custom model's spec hash holds its source's hash: an edited lobe's tables are "
    "stale",
    "[custom]") {
  std::string a = WriteLobe("hash_a", "hash-lobe", false, "return 0.25;");
  LoadModelSource(a, CustomCache());
  const TableSpec before = CatalogueTable("hash-lobe-albedo");
  const std::string beforeHash = before.Hash();  // the spec hash reads the loaded lobe's
  CHECK_THAT(before.Method(), Contains(FileHash(a)));
  std::string b = WriteLobe("hash_b", "hash-lobe", false, "return 0.25;  // edited");
  LoadModelSource(b, CustomCache());
  const TableSpec after = CatalogueTable("hash-lobe-albedo");
  CHECK(before.name == after.name);
  CHECK(beforeHash != after.Hash());
  CHECK_THAT(after.Method(), Contains(FileHash(b)));
}

TEST_CASE(
    "a loaded lobe is a registered model descriptor: rule family None, its code hash, its tables "
    "by name, one entry after a reload",
    "[custom][descriptor]") {
  std::string a = WriteLobe("desc_a", "desc-lobe", true, "return 0.5;");
  const ModelInfo& first = LoadModelSource(a, CustomCache());
  CHECK(FindModel("desc-lobe") == &first);  // the registry's own entry, no second registry
  CHECK(first.rule == RuleFamily::None);
  CHECK(first.codeHash == FileHash(a));
  CHECK(first.tablesByName);
  CHECK(first.catalogue == CatalogueGroup::None);  // never in a plain `kiln bake`
  AnyModel model = MakeModel(first, ModelParams{});
  CHECK(std::holds_alternative<CustomSpecularModel>(model));
  CHECK(std::get<CustomSpecularModel>(model).lobe == FindCustomLobe("desc-lobe"));
  // E and DFG by adaptive quadrature (the average's mu rule sums that E).
  for (const char* table : {"desc-lobe-albedo", "desc-lobe-dfg"})
    CHECK_FALSE(UsesFixedRule(CatalogueTable(table)));
  CHECK(CatalogueTable("desc-lobe-albedo-avg").model == "desc-lobe");
  std::string b = WriteLobe("desc_b", "desc-lobe", true, "return 0.5;  // edited");
  const ModelInfo& second = LoadModelSource(b, CustomCache());
  CHECK(second.codeHash == FileHash(b));
  size_t entries = 0;
  for (const ModelInfo& m : AllModels()) entries += m.codeHash == second.codeHash;
  CHECK(entries == 1);
  CHECK(FindModel("desc-lobe") == &second);
  CHECK(std::get<CustomSpecularModel>(model).lobe->hash == FileHash(a));  // the old lobe lives
}

TEST_CASE("a lobe's NaN, infinite or negative value is named with its directions", "[custom]") {
  std::string src = WriteLobe("bad_values", "bad-values", false,
                              "if (wi[2] < 0.25) return r > 0.5 ? -1.0 : NAN;\n"
                              "if (wi[2] > 0.99 && r < 0.05) return INFINITY;\n"
                              "return 0.3;");
  LoadModelSource(src, CustomCache());
  const UnregisterAtExit unload{"bad-values"};
  CHECK_THROWS_WITH(DirectionalAlbedoOf("bad-values", 0.5, 0.3),
                    Contains("model 'bad-values'") && Contains("f = nan at wo = (") &&
                        Contains("wi = (") && Contains("bad_values.cpp"));
  CHECK_THROWS_WITH(DirectionalAlbedoOf("bad-values", 0.5, 0.8), Contains("f = -1 at wo = ("));
  CHECK_THROWS_WITH(DirectionalAlbedoOf("bad-values", 0.5, 0.01), Contains("f = inf at wo = ("));
}

TEST_CASE("a lobe that does not compile is refused with the compiler's lines", "[custom]") {
  std::string src = WriteLobe("broken", "broken-lobe", false, "return 0.3 +;");
  try {
    LoadModelSource(src, CustomCache());
    FAIL("a broken source loaded");
  } catch (const std::invalid_argument& e) {
    std::string what = e.what();
    CHECK_THAT(what, Contains("cannot compile " + src));
    CHECK_THAT(what, Contains("broken.cpp:") && Contains("error:"));  // the compiler's own lines
  }
  CHECK(FindModel("broken-lobe") == nullptr);
  // No temporary left behind (another test process of the run may be storing one of its own).
  const std::string ours = ".so.tmp." + std::to_string(getpid());
  for (const auto& entry : std::filesystem::directory_iterator(CustomCache())) {
    const std::string name = entry.path().filename().string();
    const bool temporary = name.find(".so.tmp.") != std::string::npos;
    const bool mine = temporary && name.size() > ours.size() &&
                      name.compare(name.size() - ours.size(), ours.size(), ours) == 0;
    INFO(name);
    CHECK((entry.path().extension() == ".so" || temporary));
    CHECK_FALSE(mine);
  }
}

TEST_CASE("a lobe that breaks the ABI is refused naming what it lacks", "[custom]") {
  std::string src = WriteLobe("clash", "ggx", true, "return 0.3;");
  CHECK_THROWS_WITH(LoadModelSource(src, CustomCache()), Contains("'ggx' is a built-in model's"));
  CHECK(FindCustomModel("ggx") == nullptr);
}

TEST_CASE("the example lobes load: a normalised Phong and a custom sheen with a parameter",
          "[custom]") {
  const ModelInfo& phong = ExampleLobe("normalized_phong.cpp");
  CHECK(phong.specular());
  CHECK(phong.energyConserving);
  for (double r : {0.2, 0.6, 1.0}) CHECK(DirectionalAlbedoOf(phong.id, 1, r) <= 1 + 1e-9);
  const ModelInfo& sheen = ExampleLobe("custom_sheen.cpp");
  CHECK_FALSE(sheen.specular());
  REQUIRE(sheen.params.size() == 2);
  CHECK(sheen.params[1].name == "rho");
  ModelParams half;
  half.roughness = 0.4;
  half.rho = 0.5;
  ModelParams full = half;
  full.rho.reset();  // the default, 1
  Vec3 wo = ViewDirection(0.5), wi = DirectionFromMuPhi(0.3, 2.0);
  CHECK(Evaluate(MakeModel(sheen.id, half), wo, wi) ==
        Approx(0.5 * Evaluate(MakeModel(sheen.id, full), wo, wi)).epsilon(1e-14));
  half.rho = 2;
  CHECK_THROWS_WITH(MakeModel(sheen.id, half), Contains("outside [0, 1]"));
}
