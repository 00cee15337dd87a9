// The diffuse fixed rule (baker/integrate/fixed_rule_diffuse.h, the bake method of every diffuse
// albedo table) against the adaptive reference at 1e-9, for every catalogue diffuse model over a
// stratified (mu, r) grid (tests/grid_sample.h) whose edges are whole: mu = 0, mu = 1, r = 0 and
// the top of the roughness range; the dense grid a [long] test.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "baker/integrate/fixed_rule_diffuse.h"
#include "baker/integrate/quantities.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "fresh_thread_memo.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

/// The view cosines of the grid: both ends, the grazing decades and the bulk.
std::vector<double> MuGrid() {
  std::vector<double> mu = {0, 1e-8, 1e-6, 1e-4, 1e-3, 3e-3, 0.01, 0.03};
  for (int i = 1; i <= 12; ++i) mu.push_back(i / 12.0);
  mu.push_back(0.999);
  return mu;
}

/// Roughness values spanning the model's range, ends included (one value for a model without).
std::vector<double> RoughnessGrid(const std::string& model) {
  const ModelInfo& info = *FindModel(model);
  for (const ParamInfo& p : info.params)
    if (p.name == "roughness") {
      std::vector<double> r;
      for (int i = 0; i <= 4; ++i) r.push_back(p.hi * i / 4.0);
      r.push_back(p.hi * 0.01);
      return r;
    }
  return {0};
}

AnyModel ModelAtRoughness(const std::string& model, double r) {
  ModelParams p;
  for (const ParamInfo& q : FindModel(model)->params)
    if (q.name == "roughness") p.roughness = r;
  return MakeModel(model, p);
}

struct Worst {
  double error = 0;
  std::string where;
};

/// The (mu, r) points of `model`'s grid (MuGrid x RoughnessGrid, as index pairs) the default
/// tests visit: the edges whole (mu = 0, 1 and 0.999; r = 0, 1% of the top and the top), one
/// point of each 3 x 3 block of the interior (seeded), and where the dense grid measured the
/// rule's largest errors: oren-nayar 8e-9 at mu = 1e-6 (r = 1.18 and the top),
/// hammon 2.3e-8 at mu = 1e-6, r = 1 (1.3e-8 at r = 0.75, 8.6e-9 at mu = 1e-8, r = 0.75): the
/// grazing views of rough lobes, where the adaptive reference is slow too. block 1: the dense
/// grid.
std::vector<test::GridIndex> Points(const std::string& model, size_t block) {
  const size_t nMu = MuGrid().size(), nR = RoughnessGrid(model).size();
  std::vector<size_t> edgeR;
  std::vector<test::GridIndex> worst;
  if (nR > 1) edgeR = {nR - 2};  // the top (the last value is 1% of it)
  if (model == "oren-nayar") worst = {{2, 3}};
  if (model == "hammon") worst = {{2, 3}, {1, 3}};
  return test::StratifiedGrid(nMu, nR, block, 0xD1F + model.size(), {nMu - 2}, edgeR, worst);
}

/// The rule's worst |fixed - adaptive at 1e-9| for `model` at Points(model, block), both rho
/// parts. stopAbove >= 0: returns as soon as one point errs by more than stopAbove (a check
/// that the error exceeds it needs no further point).
Worst WorstError(const std::string& model, const DiffuseRuleOptions& opt, size_t block,
                 double stopAbove = -1) {
  Worst w;
  IntegrationOptions ref;
  ref.tol = 1e-9;
  const std::vector<double> mus = MuGrid(), rs = RoughnessGrid(model);
  for (const test::GridIndex& p : Points(model, block)) {
    const double mu = mus[p.i], r = rs[p.j];
    AnyModel m = ModelAtRoughness(model, r);
    IntegrationStats st;
    RhoParts want = DirectionalAlbedo(m, mu, ref, st);
    RhoParts got = FixedRuleDiffuseAlbedo(m, mu, opt);
    double e = std::max(std::abs(got.lin - want.lin), std::abs(got.quad - want.quad));
    if (!(e <= w.error)) {
      w.error = e;
      w.where = "mu=" + std::to_string(mu) + " r=" + std::to_string(r);
    }
    if (stopAbove >= 0 && !(w.error <= stopAbove)) return w;
  }
  return w;
}

/// The bake rule of each model `pick` selects within kDiffuseRuleBound at Points(model, block).
template <class Pick>
void CheckDiffuseModels(Pick pick, size_t block) {
  int checked = 0;
  for (const std::string& model : CatalogueDiffuseModels()) {
    if (!pick(model)) continue;
    ++checked;
    Worst w = WorstError(model, {}, block);
    std::printf("diffuse fixed rule %-26s worst %.3g at %s\n", model.c_str(), w.error,
                w.where.c_str());
    INFO(model << ": worst " << w.error << " at " << w.where);
    CHECK(w.error <= kDiffuseRuleBound);
  }
  CHECK(checked > 0);
}

bool SlowReference(const std::string& model) { return model == "oren-nayar" || model == "hammon"; }

}  // namespace

// One test for each model whose grazing references take seconds, one for the others.
TEST_CASE(
    "oren-nayar's fixed rule is within its bound of adaptive quadrature at 1e-9 over a "
    "stratified (mu, r) grid, its edges and worst points whole",
    "[integrate][fixed-rule-diffuse]") {
  CheckDiffuseModels([](const std::string& m) { return m == "oren-nayar"; }, 3);
}

TEST_CASE(
    "hammon's fixed rule is within its bound of adaptive quadrature at 1e-9 over a stratified "
    "(mu, r) grid, its edges and worst points whole",
    "[integrate][fixed-rule-diffuse]") {
  CheckDiffuseModels([](const std::string& m) { return m == "hammon"; }, 3);
}

TEST_CASE(
    "Every other diffuse model's fixed rule is within its bound of adaptive quadrature at 1e-9 "
    "over a stratified (mu, r) grid, its edges whole",
    "[integrate][fixed-rule-diffuse]") {
  CheckDiffuseModels([](const std::string& m) { return !SlowReference(m); }, 3);
}

TEST_CASE(
    "Dense grid: every diffuse model's fixed rule is within its bound of adaptive quadrature at "
    "1e-9 over all of (mu, r) (long: run by hand)",
    "[integrate][fixed-rule-diffuse][long]") {
  CheckDiffuseModels([](const std::string&) { return true; }, 1);
}

TEST_CASE("The diffuse rule with too few nodes misses the bound (the check can fail)",
          "[integrate][fixed-rule-diffuse]") {
  DiffuseRuleOptions coarse;
  coarse.thetaNodes = 2;
  coarse.phiNodes = 2;
  // The stratified grid of the tests above, walked until the first point beyond the bound.
  for (const char* model : {"oren-nayar", "hammon"}) {
    Worst w = WorstError(model, coarse, 3, kDiffuseRuleBound);
    INFO(model << ": " << w.error << " at " << w.where);
    CHECK(w.error > kDiffuseRuleBound);
  }
}

TEST_CASE("The diffuse rule is deterministic and refuses a specular model",
          "[integrate][fixed-rule-diffuse]") {
  AnyModel m = ModelAtRoughness("hammon", 0.7);
  for (double mu : {0.0, 0.3, 1.0}) {
    long long e1 = 0, e2 = 0;
    RhoParts a = FixedRuleDiffuseAlbedo(m, mu, {}, &e1), b = FixedRuleDiffuseAlbedo(m, mu, {}, &e2);
    CHECK(a.lin == b.lin);
    CHECK(a.quad == b.quad);
    CHECK(e1 == e2);
    CHECK(e1 > 0);
  }
  CHECK_THROWS_AS(FixedRuleDiffuseAlbedo(ModelAtRoughness("ggx", 0.5), 0.5), std::invalid_argument);
}

TEST_CASE(
    "The diffuse rule's per-thread node memo changes no bit: models of every grading and node "
    "counts interleaved, in either order, on a fresh thread each",
    "[integrate][fixed-rule-diffuse]") {
  // hammon grades theta and phi, oren-nayar theta alone, burley neither: the same mu with each.
  const char* const models[] = {"hammon", "oren-nayar", "burley"};
  const DiffuseRuleOptions counts[] = {{}, {6, 4}};
  const std::vector<double> mus = {0.0, 1e-6, 0.02, 0.5, 0.02, 1.0, 0.5, 0.0};
  struct Got {
    double lin, quad;
    long long evals;
  };
  auto cases = [&](double mu, std::vector<Got>& out) {
    for (const char* name : models)
      for (const DiffuseRuleOptions& opt : counts) {
        long long e = 0;
        RhoParts p = FixedRuleDiffuseAlbedo(ModelAtRoughness(name, 0.6), mu, opt, &e);
        out.push_back({p.lin, p.quad, e});
      }
  };
  const size_t per = std::size(models) * std::size(counts);
  const std::vector<Got> forward =
      test::RequireSameInEitherOrder<Got>(mus, per, cases, [](const Got& a, const Got& b) {
        CHECK(a.lin == b.lin);
        CHECK(a.quad == b.quad);
        CHECK(a.evals == b.evals);
      });
  // The node counts reach the result (the memo keys on them): 6 x 4 differs from 8 x 8.
  CHECK(forward[2 * per].lin != forward[2 * per + 1].lin);
}
