// The sheen fixed rule (integrate/fixed_rule_sheen.h), each model's bake options
// (SheenRuleOptionsFor; charlie-smith's own: tests/integrate_fixed_rule_charlie_smith.cpp), against
// adaptive quadrature at 1000 times below the bound: below its declared bound (and the
// contract's 1e-6) on a stratified (mu, r) grid (tests/grid_sample.h) whose edges are whole:
// mu = 0, 1 and 1/2, the smallest roughness of the tables' domain (0.045 for all three) and 1;
// the grazing views 1e-6 and 1e-4 (charlie-smith: from its domain's 1e-4) in the sampled
// interior, the dense grid a [long] test; against the closed forms at mu = 0; fewer nodes
// measurably worse (the check can fail).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "baker/integrate/fixed_rule_sheen.h"
#include "baker/integrate/quantities.h"
#include "baker/models/sheen.h"
#include "fresh_thread_memo.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

AnyModel Sheen(const std::string& id, double r) {
  ModelParams p;
  p.roughness = r;
  return MakeModel(id, p);
}

/// The adaptive reference's tolerance: 1000 times below the bound checked.
constexpr double kReferenceTol = kSheenRuleBound / 1000;

double Adaptive(const AnyModel& m, double mu) {
  IntegrationOptions opt;
  opt.tol = kReferenceTol;
  IntegrationStats stats;
  return DirectionalAlbedo(m, mu, opt, stats).lin;
}

const double kMus[] = {0.0, 1e-6, 1e-4, 0.01, 0.07, 0.15, 0.25, 0.4, 0.5, 0.55, 0.7, 0.85, 1.0};
const double kRs[] = {kCharlieMinRoughness, 0.055, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0};

/// Where each model's rule errs most on the dense kMus x kRs grid (the [long] test below) off
/// its edges, as (mu, r) index pairs visited first: charlie 9e-8 at r = 0.055, mu = 0.01 (1e-7 at
/// the edge r = 0.045, mu = 0); charlie-smith 2.8e-7 at r = 0.055, mu = 0.01 and 2e-7 at
/// r = 0.055, mu = 1e-4 (3.2e-7 at the edge r = 0.045, mu = 0.01: its 10 x 6 nodes at the
/// sharpest lobes); the velvet's largest, 4.7e-8 at r = 1, mu = 0.01, lies on an edge.
std::vector<test::GridIndex> WorstPoints(const std::string& id) {
  if (id == "charlie") return {{3, 1}};
  if (id == "charlie-smith") return {{3, 1}, {2, 1}};
  return {};
}

/// The (mu, r) points of the default tests: the grid's edges (mu = 0 and 1, r = 0.045 and 1) and
/// Lambda's switch mu = 1/2 whole, one point of each 3 x 3 block of the interior (seeded), the
/// model's worst points. block 1: the dense grid.
std::vector<test::GridIndex> Points(const std::string& id, size_t block) {
  return test::StratifiedGrid(std::size(kMus), std::size(kRs), block, 0x5EE0 + id.size(), {8}, {},
                              WorstPoints(id));
}

/// The worst |rule - adaptive| of model `id` with options `opt` at `points`; stopAbove >= 0:
/// returns at the first point beyond it.
double SheenWorst(const std::string& id, const SheenRuleOptions& opt,
                  const std::vector<test::GridIndex>& points, std::string& where,
                  double stopAbove = -1) {
  double worst = 0;
  long long maxEvals = 0;
  for (const test::GridIndex& p : points) {
    const double mu = kMus[p.i], r = kRs[p.j];
    // charlie-smith's tables (and its rule's nodes) start at mu = 1e-4.
    if (id == "charlie-smith" && mu < kCharlieSmithMinMu) continue;
    AnyModel m = Sheen(id, r);
    long long evals = 0;
    double err = std::abs(FixedRuleSheenAlbedo(m, mu, opt, &evals) - Adaptive(m, mu));
    maxEvals = std::max(maxEvals, evals);
    if (err > worst) {
      worst = err;
      where = "mu = " + std::to_string(mu) + ", r = " + std::to_string(r);
    }
    if (stopAbove >= 0 && worst > stopAbove) break;
  }
  where += "; at most " + std::to_string(maxEvals) + " evaluations";
  return worst;
}

/// Model `id`'s bake rule within kSheenRuleBound at Points(id, block).
void CheckSheenGrid(const std::string& id, size_t block) {
  std::string where;
  double worst = SheenWorst(id, SheenRuleOptionsFor(id, false), Points(id, block), where);
  WARN(id << ": worst |fixed - adaptive| = " << worst << " at " << where);
  CHECK(worst < kSheenRuleBound);
  CHECK(kSheenRuleBound < 1e-6);
}

}  // namespace

// One test per model, each on the stratified grid.
TEST_CASE("The sheen fixed rule is within its declared bound of adaptive quadrature (charlie)",
          "[sheen][fixed-rule]") {
  CheckSheenGrid("charlie", 3);
}

TEST_CASE(
    "The sheen fixed rule is within its declared bound of adaptive quadrature (charlie-smith)",
    "[sheen][fixed-rule]") {
  CheckSheenGrid("charlie-smith", 3);
}

TEST_CASE(
    "The sheen fixed rule is within its declared bound of adaptive quadrature (ashikhmin-velvet)",
    "[sheen][fixed-rule]") {
  CheckSheenGrid("ashikhmin-velvet", 3);
}

TEST_CASE(
    "Dense grid: the sheen fixed rule is within its declared bound of adaptive quadrature over "
    "all of (mu, r) (long: run by hand)",
    "[sheen][fixed-rule][long]") {
  for (const char* id : {"charlie", "charlie-smith", "ashikhmin-velvet"}) CheckSheenGrid(id, 1);
}

TEST_CASE("Each sheen model's rule with too few nodes misses the bound on the stratified grid",
          "[sheen][fixed-rule]") {
  for (const char* id : {"charlie", "charlie-smith", "ashikhmin-velvet"}) {
    SheenRuleOptions coarse = SheenRuleOptionsFor(id, false);
    coarse.tNodes = coarse.sNodes = 2;
    coarse.mirrorPanels = 0;
    std::string where;
    double worst = SheenWorst(id, coarse, Points(id, 3), where, kSheenRuleBound);
    INFO(id << ": " << worst << " at " << where);
    CHECK(worst > kSheenRuleBound);
  }
}

TEST_CASE("The sheen fixed rule matches the closed forms of E(0)", "[sheen][fixed-rule]") {
  // At mu_o = 0, V mu_l = 1/4 (Neubelt) and l = 2 (o.h) h - o: E(0) = 2 int_0^{pi/2} D(theta)
  // sin^2(theta) dtheta. Charlie: (2 + 1/alpha) / pi times the Wallis integral of sin^(1/alpha+2);
  // velvet: (1/2 + 4 alpha / sqrt(pi)) / (1 + 4 alpha^2), alpha = r^2 (also below the tables'
  // 0.045, where the adaptive reference misses the spike).
  for (double r : {0.01, 0.02, kCharlieMinRoughness, 0.3, 1.0}) {
    double alpha = r * r;
    double velvet = (0.5 + 4 * alpha / std::sqrt(Pi)) / (1 + 4 * alpha * alpha);
    INFO("r = " << r);
    CHECK(std::abs(FixedRuleSheenAlbedo(Sheen("ashikhmin-velvet", r), 0) - velvet) < 1e-7);
    if (r < kCharlieMinRoughness) continue;
    double n = 1 / alpha + 2;
    double wallis = std::sqrt(Pi) / 2 * std::exp(std::lgamma((n + 1) / 2) - std::lgamma(n / 2 + 1));
    double charlie = (2 + 1 / alpha) / Pi * wallis;
    CHECK(std::abs(FixedRuleSheenAlbedo(Sheen("charlie", r), 0) - charlie) < 2e-7 * charlie);
  }
}

TEST_CASE("The sheen fixed rule without its mirror grading misses the bound (the test can fail)",
          "[sheen][fixed-rule]") {
  SheenRuleOptions coarse;
  coarse.mirrorPanels = 0;
  AnyModel m = Sheen("charlie", 1.0);
  double err = std::abs(FixedRuleSheenAlbedo(m, 1.0, coarse) - Adaptive(m, 1.0));
  CHECK(err > kSheenRuleBound);
}

TEST_CASE("The sheen fixed rule is deterministic and refuses a non-sheen model",
          "[sheen][fixed-rule]") {
  AnyModel m = Sheen("charlie-smith", 0.3);
  CHECK(FixedRuleSheenAlbedo(m, 0.2) == FixedRuleSheenAlbedo(m, 0.2));
  CHECK_THROWS_WITH(FixedRuleSheenAlbedo(MakeModel("ggx", {}), 0.5),
                    Catch::Contains("needs a sheen model"));
}

TEST_CASE(
    "The sheen rule's per-thread azimuth memo changes no bit: models, roughness and node counts "
    "interleaved, in either order, on a fresh thread each",
    "[sheen][fixed-rule]") {
  const char* const models[] = {"charlie", "charlie-smith", "ashikhmin-velvet"};
  const SheenRuleOptions counts[] = {SheenRuleOptionsFor(SheenRule::Neubelt, false),
                                     SheenRuleOptionsFor(SheenRule::Neubelt, true)};
  const std::vector<double> mus = {0.0, 1e-8, 0.03, 0.5, 0.03, 1.0, 0.5, 0.0};
  struct Got {
    double e;
    long long evals;
  };
  auto cases = [&](double mu, std::vector<Got>& out) {
    for (const char* name : models)
      for (double r : {0.2, 0.9})
        for (const SheenRuleOptions& opt : counts) {
          long long e = 0;
          const double v = FixedRuleSheenAlbedo(Sheen(name, r), mu, opt, &e);
          out.push_back({v, e});
        }
  };
  const size_t per = std::size(models) * 2 * std::size(counts);
  const std::vector<Got> forward =
      test::RequireSameInEitherOrder<Got>(mus, per, cases, [](const Got& a, const Got& b) {
        CHECK(a.e == b.e);
        CHECK(a.evals == b.evals);
      });
  // The node counts reach the result (the memo keys on them): the search's differ from the bake's.
  CHECK(forward[2 * per].evals != forward[2 * per + 1].evals);
}
