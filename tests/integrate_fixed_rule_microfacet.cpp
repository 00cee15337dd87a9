// The microfacet fixed rules of baker/integrate/fixed_rule_microfacet.h (the bake method of the
// dfg and albedo tables of ggx-separable, beckmann, beckmann-separable and blinn-phong, and of
// ggx-fresnel-albedo) against adaptive half-vector quadrature at 1e-10, over (mu, alpha[, eta])
// grids that include mu = 0, mu = 1, alpha = 1e-12 (roughness 0), alpha = 1 and eta near 1.
// Target 1e-7, hard limit 1e-6 (the tables declare kFixedRuleBound, 6e-7).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

constexpr double kTarget = 1e-7;
const char* const kModels[] = {"ggx-separable", "beckmann", "beckmann-separable", "blinn-phong"};

/// The model at perceptual roughness r, as the tables build it.
AnyModel ModelAtR(const char* name, double r) {
  ModelParams p;
  p.roughness = r;
  return MakeModel(name, p);
}

/// alpha = max(r^2, MinAlpha), as MakeModel derives it.
double AlphaOf(double r) { return std::max(r * r, 1e-12); }

/// Views: the ends, the grazing layer (mu ~ alpha) and the bulk.
const double kMus[] = {0.0,  1e-9, 1e-6, 1e-4, 1e-3, 0.004, 0.012, 0.03, 0.07,
                       0.13, 0.22, 0.35, 0.5,  0.65, 0.8,   0.92,  0.99, 1.0};
/// Roughness: r = 0 (alpha = 1e-12) to r = 1 (alpha = 1), dense where the layer moves.
const double kRs[] = {0.0,  1e-3, 0.01, 0.03, 0.06, 0.1,  0.15, 0.2,  0.27, 0.35,
                      0.43, 0.5,  0.58, 0.66, 0.74, 0.82, 0.88, 0.94, 0.98, 1.0};

}  // namespace

namespace {

/// Where each model's rule errs most on the dense kMus x kRs grid (the [long] test below:
/// beckmann and blinn-phong 5.2e-8 at r = 0.15, mu = 1e-4 and 4e-8 to 4.7e-8 at r = 0.98,
/// mu = 0.22 to 0.35; beckmann-separable 6.3e-8 at r = 0.94 at every grazing view; ggx-separable
/// 1.5e-8 at r = 1e-3, mu = 1e-3), as (mu, r) index pairs, visited first.
std::vector<test::GridIndex> WorstPoints(const std::string& name) {
  if (name == "beckmann-separable") return {{3, 17}, {4, 17}};
  if (name == "ggx-separable") return {{4, 1}, {3, 1}};
  return {{3, 6}, {11, 18}, {10, 18}, {10, 19}};  // beckmann, blinn-phong
}

/// The (mu, r) points of the default test: kMus x kRs with its edges (mu = 0, 1, r = 0, 1) and
/// the grazing view mu = 1e-9 whole, one point of each 3 x 3 block of the interior (seeded), and
/// the model's worst points. block 1: the dense grid.
std::vector<test::GridIndex> Points(const std::string& name, size_t block) {
  return test::StratifiedGrid(std::size(kMus), std::size(kRs), block, 0x32F1 + name.size(), {1}, {},
                              WorstPoints(name));
}

struct Worst {
  double error = 0;
  std::string where;
  long long evals = 0;
};

/// The worst |rule - adaptive at 1e-10| over A, B and A + B of `name`'s rule (node counts `opt`)
/// at `points`. stopAbove >= 0: returns at the first point beyond it.
Worst MicrofacetWorst(const char* name, const MicrofacetRuleOptions& opt,
                      const std::vector<test::GridIndex>& points, double stopAbove = -1) {
  FixedRuleModel model;
  REQUIRE(FixedRuleModelFor(name, &model));
  Worst w;
  for (const test::GridIndex& p : points) {
    const double mu = kMus[p.i], r = kRs[p.j];
    IntegrationOptions io;
    io.tol = 1e-10;
    IntegrationStats st;
    std::array<double, 2> ref = SplitSumDFG(ModelAtR(name, r), mu, io, st);
    std::array<double, 2> got = FixedRuleMicrofacetDFG(model, mu, AlphaOf(r), opt, &w.evals);
    const double err[3] = {got[0] - ref[0], got[1] - ref[1], got[0] + got[1] - ref[0] - ref[1]};
    for (int c = 0; c < 3; ++c)
      if (std::abs(err[c]) > w.error) {
        w.error = std::abs(err[c]);
        w.where = "mu=" + std::to_string(mu) + " r=" + std::to_string(r) + " " +
                  (c == 0   ? "A"
                   : c == 1 ? "B"
                            : "A+B");
      }
    if (stopAbove >= 0 && w.error > stopAbove) break;
  }
  return w;
}

/// Each model's rule within kTarget at the points Points(model, block) gives.
void CheckMicrofacetGrid(size_t block) {
  for (const char* name : kModels) {
    FixedRuleModel model;
    REQUIRE(FixedRuleModelFor(name, &model));
    const std::vector<test::GridIndex> points = Points(name, block);
    Worst w = MicrofacetWorst(name, TunedMicrofacetRuleOptions(model), points);
    std::printf(
        "%-19s fixed rule vs adaptive 1e-10 at %zu points: worst %.3g at %s; %.0f evals/pt\n", name,
        points.size(), w.error, w.where.c_str(), double(w.evals) / points.size());
    INFO(name << ": worst " << w.error << " at " << w.where);
    CHECK(w.error <= kTarget);
  }
}

}  // namespace

TEST_CASE(
    "Each microfacet model's fixed rule gives A and B within 1e-7 of adaptive quadrature at "
    "1e-10 over a stratified (mu, alpha) grid, its edges and worst points whole",
    "[integrate][fixed-rule][fixed-rule-microfacet]") {
  CheckMicrofacetGrid(3);
}

TEST_CASE(
    "Dense grid: each microfacet model's fixed rule gives A and B within 1e-7 of adaptive "
    "quadrature at 1e-10 over all of (mu, alpha) (long: run by hand)",
    "[integrate][fixed-rule][fixed-rule-microfacet][long]") {
  CheckMicrofacetGrid(1);
}

TEST_CASE(
    "Each microfacet model's rule with too few nodes misses the target on the stratified grid "
    "(the check can fail)",
    "[integrate][fixed-rule][fixed-rule-microfacet]") {
  MicrofacetRuleOptions coarse;
  coarse.outerNodes = 4;
  coarse.bulkNodes = coarse.gradedNodes = coarse.deficitNodes = coarse.lightNodes = 3;
  coarse.nodesPerEFold = 0;
  for (const char* name : kModels) {
    Worst w = MicrofacetWorst(name, coarse, Points(name, 3), kTarget);
    INFO(name << ": " << w.error << " at " << w.where);
    CHECK(w.error > kTarget);
  }
}

namespace {

/// ggx-fresnel-albedo's grid: eta near 1 (the layer F ~ (eta - 1)^2) to 3, the views and
/// roughnesses of the layer mu ~ alpha.
const double kFresnelEtas[] = {1.0 + 1e-7, 1.0 + 1e-5, 1.0003, 1.003, 1.02, 1.07,
                               1.2,        1.45,       1.8,    2.4,   3.0};
const double kFresnelMus[] = {0.0, 1e-7, 1e-4, 1e-3, 0.006, 0.025, 0.08, 0.2, 0.45, 0.75, 1.0};
const double kFresnelRs[] = {0.0, 1e-3, 0.02, 0.08, 0.17, 0.3, 0.45, 0.62, 0.8, 1.0};

/// Where the rule errs most inside the dense grid (the [long] test below; its largest, 1.9e-8 at
/// mu = 0, r = 0, eta = 1 + 1e-5, lies on an edge): 8.1e-9 at mu = 1e-4, r = 0.17 and 5.6e-9 at
/// mu = 1e-4, r = 0.3 at every eta, 9.3e-9 at mu = 1e-7, r = 0.02, eta = 1 + 1e-7, as (mu, r)
/// index pairs visited at every eta.
const std::vector<test::GridIndex> kFresnelAlbedoWorst = {{2, 4}, {2, 5}, {1, 2}};

/// The (mu, r) points at eta = kFresnelEtas[k]: the grid's edges (mu = 0, 1, r = 0, 1) whole,
/// one point of each 3 x 3 block of the interior at the two etas nearest 1 and at 3, of each
/// 4 x 4 block at the etas between (seeded by k), and the worst points at every eta. block 0:
/// the dense grid.
std::vector<test::GridIndex> FresnelAlbedoPoints(size_t k, size_t block) {
  const size_t nMu = std::size(kFresnelMus), nR = std::size(kFresnelRs);
  if (block == 0) return test::StratifiedGrid(nMu, nR, 1, 0);
  const bool end = k < 2 || k + 1 == std::size(kFresnelEtas);
  return test::StratifiedGrid(nMu, nR, end ? block : block + 1, 0xFA1B + k, {}, {},
                              kFresnelAlbedoWorst);
}

/// The exact-Fresnel GGX albedo's rule within kTarget of adaptive quadrature at 1e-10 at every
/// eta's FresnelAlbedoPoints(k, block).
void CheckFresnelAlbedoGrid(size_t block) {
  double worst = 0;
  std::string where;
  long long evals = 0;
  int points = 0;
  for (size_t k = 0; k < std::size(kFresnelEtas); ++k)
    for (const test::GridIndex& p : FresnelAlbedoPoints(k, block)) {
      const double eta = kFresnelEtas[k], mu = kFresnelMus[p.i], r = kFresnelRs[p.j];
      AnyModel m = ModelAtR("ggx", r);
      SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
      IntegrationOptions opt;
      opt.tol = 1e-10;
      IntegrationStats st;
      const double ref = DirectionalAlbedo(m, mu, opt, st).lin;
      const double got = FixedRuleGGXFresnelAlbedo(mu, AlphaOf(r), eta, &evals);
      ++points;
      if (std::abs(got - ref) > worst) {
        worst = std::abs(got - ref);
        where =
            "eta=" + std::to_string(eta) + " mu=" + std::to_string(mu) + " r=" + std::to_string(r);
      }
    }
  std::printf(
      "ggx-fresnel-albedo fixed rule vs adaptive 1e-10 at %d points: worst %.3g at %s; "
      "%.0f evals/pt\n",
      points, worst, where.c_str(), double(evals) / points);
  INFO("worst " << worst << " at " << where);
  CHECK(worst <= kTarget);
}

}  // namespace

TEST_CASE(
    "The exact-Fresnel GGX albedo's fixed rule is within 1e-7 of adaptive quadrature at 1e-10 "
    "over (mu, alpha, eta), eta near 1 included",
    "[integrate][fixed-rule][fixed-rule-microfacet]") {
  CheckFresnelAlbedoGrid(3);
  CHECK(FixedRuleGGXFresnelAlbedo(0.3, 0.2, 1.0) == 0);  // F = 0 at eta = 1
}

TEST_CASE(
    "Dense grid: the exact-Fresnel GGX albedo's fixed rule is within 1e-7 of adaptive quadrature "
    "at 1e-10 over all of (mu, alpha, eta) (long: run by hand)",
    "[integrate][fixed-rule][fixed-rule-microfacet][long]") {
  CheckFresnelAlbedoGrid(0);
}

TEST_CASE("The microfacet fixed rules are deterministic and cost a fixed, bounded evaluation count",
          "[integrate][fixed-rule][fixed-rule-microfacet]") {
  for (const char* name : kModels) {
    FixedRuleModel model;
    REQUIRE(FixedRuleModelFor(name, &model));
    for (double mu : {0.0, 0.02, 0.5, 1.0})
      for (double r : {0.0, 0.3, 1.0}) {
        long long e1 = 0, e2 = 0;
        std::array<double, 2> a = FixedRuleMicrofacetDFG(model, mu, AlphaOf(r), &e1);
        std::array<double, 2> b = FixedRuleMicrofacetDFG(model, mu, AlphaOf(r), &e2);
        CHECK(a[0] == b[0]);
        CHECK(a[1] == b[1]);
        CHECK(e1 == e2);
        CHECK(e1 <= 4000);
      }
  }
  long long e1 = 0, e2 = 0;
  CHECK(FixedRuleGGXFresnelAlbedo(0.01, 0.05, 1.01, &e1) ==
        FixedRuleGGXFresnelAlbedo(0.01, 0.05, 1.01, &e2));
  CHECK(e1 == e2);
  CHECK(e1 <= 4000);
}

TEST_CASE(
    "The GGX nodes' AVX-512F lanes give the one-node-at-a-time rule's bits: the DFG (both Smith "
    "forms) and the exact-Fresnel albedo, from the normal to grazing, eta near 1 to 3",
    "[integrate][fixed-rule][fixed-rule-microfacet]") {
  const FixedRuleModel models[] = {{FixedRuleNdf::GGX, false}, {FixedRuleNdf::GGX, true}};
  int compared = 0;
  for (double mu : {0.0, 1e-9, 1e-4, 0.013, 0.2, 0.5, 0.87, 1.0})
    for (double alpha : {1e-12, 1e-4, 0.02, 0.1, 0.37, 0.8, 1.0}) {
      INFO("mu " << mu << " alpha " << alpha);
      for (const FixedRuleModel& m : models) {
        long long e1 = 0, e2 = 0;
        dielectric_simd::SetEnabled(true);
        const std::array<double, 2> fast = FixedRuleMicrofacetDFG(m, mu, alpha, &e1);
        dielectric_simd::SetEnabled(false);
        const std::array<double, 2> scalar = FixedRuleMicrofacetDFG(m, mu, alpha, &e2);
        CHECK(fast[0] == scalar[0]);
        CHECK(fast[1] == scalar[1]);
        CHECK(e1 == e2);
        ++compared;
      }
      for (double eta : {1.0001, 1.01, 1.1, 1.29, 1.5, 3.0}) {
        INFO("eta " << eta);
        long long e1 = 0, e2 = 0;
        dielectric_simd::SetEnabled(true);
        const double fast = FixedRuleGGXFresnelAlbedo(mu, alpha, eta, &e1);
        dielectric_simd::SetEnabled(false);
        const double scalar = FixedRuleGGXFresnelAlbedo(mu, alpha, eta, &e2);
        CHECK(fast == scalar);
        CHECK(e1 == e2);
        ++compared;
      }
    }
  dielectric_simd::SetEnabled(true);
  CHECK(compared == 8 * 7 * 8);
}

TEST_CASE("Too few nodes miss the target: the accuracy checks can fail",
          "[integrate][fixed-rule][fixed-rule-microfacet]") {
  MicrofacetRuleOptions coarse;
  coarse.outerNodes = 4;
  coarse.bulkNodes = coarse.gradedNodes = coarse.deficitNodes = coarse.lightNodes = 3;
  coarse.nodesPerEFold = 0;
  FixedRuleModel beckmann{FixedRuleNdf::Beckmann, false};
  double worst = 0;
  for (double r : {0.1, 0.5, 1.0})
    for (double mu : {0.01, 0.3}) {
      IntegrationOptions opt;
      opt.tol = 1e-10;
      IntegrationStats st;
      std::array<double, 2> ref = SplitSumDFG(ModelAtR("beckmann", r), mu, opt, st);
      std::array<double, 2> got = FixedRuleMicrofacetDFG(beckmann, mu, AlphaOf(r), coarse);
      worst = std::max({worst, std::abs(got[0] - ref[0]), std::abs(got[1] - ref[1])});
    }
  CHECK(worst > kTarget);
}

TEST_CASE(
    "The catalogue's dfg, albedo and fresnel-albedo tables of these models are baked by the "
    "fixed rules, and stay within the bound of the adaptive reference",
    "[integrate][fixed-rule][fixed-rule-microfacet][tables]") {
  for (const char* model : kModels)
    for (const char* kind : {"dfg", "albedo"}) {
      TableSpec spec = CatalogueTable(std::string(model) + "-" + kind);
      REQUIRE(UsesFixedRule(spec));
      CHECK(spec.Method().find("fixed Gauss-Legendre rule") != std::string::npos);
      const double x[2] = {0.07, 0.63};
      IntegrationStats fixed, adaptive;
      std::vector<double> got = EvaluateSpec(spec, x, fixed);
      std::vector<double> ref = EvaluateSpec(spec, x, 1e-10, adaptive);  // the reference
      REQUIRE(got.size() == ref.size());
      for (size_t c = 0; c < got.size(); ++c) CHECK(std::abs(got[c] - ref[c]) <= kTarget);
      CHECK(fixed.evals * 10 < adaptive.evals);
    }
  TableSpec fa = CatalogueTable("ggx-fresnel-albedo");
  REQUIRE(UsesFixedRule(fa));
  const double x[3] = {0.05, 0.3, 1.01};
  IntegrationStats fixed, adaptive;
  double got = EvaluateSpec(fa, x, fixed)[0], ref = EvaluateSpec(fa, x, 1e-10, adaptive)[0];
  CHECK(std::abs(got - ref) <= kTarget);
  TableSpec below = fa;  // eta < 1 (total internal reflection) is not the rule's
  below.axes[2].lo = 0.5;
  CHECK_FALSE(UsesFixedRule(below));
}

TEST_CASE(
    "Off the grids: random (mu, alpha[, eta]) points, a third of them in the grazing layer, stay "
    "within 1e-7 (long: run by hand)",
    "[integrate][fixed-rule-microfacet][long]") {
  unsigned long long state = 12345;
  auto uniform = [&] {  // 53-bit LCG draw in [0, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1p-53;
  };
  auto draw = [&](double& mu, double& r) {
    r = uniform();
    mu = uniform();
    if (uniform() < 1.0 / 3) mu = std::min(1.0, r * r * std::pow(10.0, 2 * uniform() - 1.5));
  };
  for (const char* name : kModels) {
    FixedRuleModel model;
    REQUIRE(FixedRuleModelFor(name, &model));
    double worst = 0;
    for (int i = 0; i < 400; ++i) {
      double mu, r;
      draw(mu, r);
      IntegrationOptions opt;
      opt.tol = 1e-10;
      IntegrationStats st;
      std::array<double, 2> ref = SplitSumDFG(ModelAtR(name, r), mu, opt, st);
      std::array<double, 2> got = FixedRuleMicrofacetDFG(model, mu, AlphaOf(r));
      worst = std::max({worst, std::abs(got[0] - ref[0]), std::abs(got[1] - ref[1])});
    }
    std::printf("%-19s 400 random points: worst %.3g\n", name, worst);
    CHECK(worst <= kTarget);
  }
  double worst = 0;
  for (int i = 0; i < 600; ++i) {
    double mu, r;
    draw(mu, r);
    double eta = uniform() < 0.5 ? 1 + std::pow(10.0, -7 + 6 * uniform()) : 1 + 2 * uniform();
    AnyModel m = ModelAtR("ggx", r);
    SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
    IntegrationOptions opt;
    opt.tol = 1e-10;
    IntegrationStats st;
    double ref = DirectionalAlbedo(m, mu, opt, st).lin;
    worst = std::max(worst, std::abs(FixedRuleGGXFresnelAlbedo(mu, AlphaOf(r), eta) - ref));
  }
  std::printf("ggx-fresnel-albedo 600 random points: worst %.3g\n", worst);
  CHECK(worst <= kTarget);
}
