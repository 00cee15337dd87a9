// The GGX kernel's variants (baker/integrate/fixed_rule_dfg.h): separable Smith
// (FixedRuleGGXSeparableDFG, the bake method of ggx-separable's dfg, albedo and albedo-avg) and
// exact dielectric Fresnel (FixedRuleGGXFresnelKernel, ggx-fresnel-albedo's for eta >= 1.3),
// against adaptive half-vector quadrature at 1e-9 over stratified (mu, alpha[, eta]) grids
// (tests/grid_sample.h; the dense grids [long] tests) that include mu = 0, 1e-6, 1, alpha =
// MinAlpha (roughness 0) and alpha = 1, eta = 1.3 and 3. Target 1e-7 (the tables declare
// kFixedRuleBound, 6e-7). And: the kernel's three SIMD paths (AVX2, SSE2, portable) give the same
// bits for every variant.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

constexpr double kTarget = 1e-7;
/// The stratified grids' adaptive reference: a hundredth of kTarget.
constexpr double kGridReferenceTol = 1e-9;

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
/// Indices of ggx-fresnel-albedo's domain [1.3, 3].
const double kEtas[] = {1.3, 1.33, 1.45, 1.6, 1.8, 2.1, 2.4, 2.7, 3.0};

/// "mu=... r=..." for a message.
std::string Where(double mu, double r) {
  return "mu=" + std::to_string(mu) + " r=" + std::to_string(r);
}

/// The (mu, r) points of the separable variant's check: kMus x kRs with its edges (mu = 0, 1,
/// r = 0, 1) and the grazing view mu = 1e-9 whole, one point of each `block` x `block` block of
/// the interior (seeded), and where the dense grid (block 1, the [long] test below) measured the
/// rule's largest errors off the edges: 3.9e-8 and 3.6e-8 at r = 0.06, mu = 1e-6 and 1e-4,
/// 3.2e-8 to 3e-8 at r = 0.35, mu = 1e-6 to 1e-3, 2.7e-8 at r = 0.2, mu = 1e-6.
std::vector<test::GridIndex> SeparablePoints(size_t block) {
  return test::StratifiedGrid(std::size(kMus), std::size(kRs), block, 0x5E9A, {1}, {},
                              {{2, 4}, {3, 4}, {2, 9}, {3, 9}, {4, 9}, {2, 7}});
}

/// Worst |kernel - adaptive| of the separable variant with node counts `opt` (null: the bake's)
/// at `points` of kMus x kRs, over A, B and A + B; evals (optional) accumulates. stopAbove >= 0:
/// returns as soon as one point errs by more than stopAbove (a check that the error exceeds it
/// needs no further point).
double SeparableWorst(const FixedRuleOptions* opt, const std::vector<test::GridIndex>& points,
                      std::string& where, long long* evals, double stopAbove = -1) {
  double worst = 0;
  for (const test::GridIndex& p : points) {
    const double mu = kMus[p.i], r = kRs[p.j];
    IntegrationOptions io;
    io.tol = kGridReferenceTol;
    IntegrationStats st;
    std::array<double, 2> ref = SplitSumDFG(ModelAtR("ggx-separable", r), mu, io, st);
    std::array<double, 2> got = opt ? FixedRuleGGXSeparableDFG(mu, AlphaOf(r), *opt, evals)
                                    : FixedRuleGGXSeparableDFG(mu, AlphaOf(r), evals);
    const double err[3] = {got[0] - ref[0], got[1] - ref[1], got[0] + got[1] - ref[0] - ref[1]};
    for (double e : err)
      if (std::abs(e) > worst) {
        worst = std::abs(e);
        where = Where(mu, r);
      }
    if (stopAbove >= 0 && worst > stopAbove) return worst;
  }
  return worst;
}

/// The coarse node counts of the tests that must fail.
FixedRuleOptions Coarse() {
  FixedRuleOptions c;
  c.outerNodes = 4;
  c.bulkNodes = c.gradedNodes = c.deficitNodes = 3;
  c.nodesPerEFold = 0;
  return c;
}

}  // namespace

namespace {

/// The bake's separable rule within kTarget at SeparablePoints(block), at a few hundred
/// evaluations a point.
void CheckSeparableGrid(size_t block) {
  std::string where;
  long long evals = 0;
  const std::vector<test::GridIndex> points = SeparablePoints(block);
  const double worst = SeparableWorst(nullptr, points, where, &evals);
  std::printf(
      "ggx-separable kernel rule vs adaptive 1e-9 at %zu points: worst %.3g at %s; %.0f "
      "evals/pt\n",
      points.size(), worst, where.c_str(), double(evals) / points.size());
  INFO("worst " << worst << " at " << where);
  CHECK(worst <= kTarget);
  CHECK(evals <= 600LL * static_cast<long long>(points.size()));
}

}  // namespace

TEST_CASE(
    "The kernel's separable-Smith rule gives A, B and A + B within 1e-7 of adaptive quadrature "
    "at 1e-9 over a stratified (mu, alpha) grid, its edges and worst points whole",
    "[integrate][fixed-rule][fixed-rule-kernels]") {
  CheckSeparableGrid(3);
}

TEST_CASE(
    "Dense grid: the kernel's separable-Smith rule gives A, B and A + B within 1e-7 of adaptive "
    "quadrature at 1e-9 over all of (mu, alpha) (long: run by hand)",
    "[integrate][fixed-rule][fixed-rule-kernels][long]") {
  CheckSeparableGrid(1);
}

namespace {

/// Where the exact-Fresnel rule errs most on the dense grid (the [long] test below): 6.8e-8 at
/// mu = 1e-4, r = 0.58 to 0.74 (eta = 1.3 and 3 alike) and 5.9e-8 at mu = 1e-6, r = 0.03, as
/// (mu, r) index pairs visited at every eta.
const std::vector<test::GridIndex> kFresnelWorst = {{3, 12}, {3, 13}, {3, 14}, {2, 3}};

/// The (mu, r) points at eta = kEtas[k]: at the ends of the eta range (1.3, 3) the grid's edges
/// (mu = 0, 1, r = 0, 1) and the grazing view mu = 1e-9 whole and one point of each 3 x 3 block
/// of the interior; at the etas between, the edges whole and one point of each 4 x 4 block;
/// seeded by k; the worst points at every eta. block 0: the dense grid.
std::vector<test::GridIndex> FresnelPoints(size_t k, size_t block) {
  const bool end = k == 0 || k + 1 == std::size(kEtas);
  if (block == 0) return test::StratifiedGrid(std::size(kMus), std::size(kRs), 1, 0);
  return test::StratifiedGrid(std::size(kMus), std::size(kRs), end ? block : block + 1, 0xF7E5 + k,
                              end ? std::vector<size_t>{1} : std::vector<size_t>{}, {},
                              kFresnelWorst);
}

/// The worst |kernel - adaptive at 1e-9| of the exact-Fresnel rule (node counts `opt`, null:
/// the bake's) over every eta's FresnelPoints; stopAbove >= 0: returns at the first point beyond.
double FresnelWorst(const FixedRuleOptions* opt, size_t block, std::string& where, long long* evals,
                    int* points, double stopAbove = -1) {
  double worst = 0;
  for (size_t k = 0; k < std::size(kEtas); ++k)
    for (const test::GridIndex& p : FresnelPoints(k, block)) {
      const double mu = kMus[p.i], r = kRs[p.j], eta = kEtas[k];
      AnyModel m = ModelAtR("ggx", r);
      SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
      IntegrationOptions io;
      io.tol = kGridReferenceTol;
      IntegrationStats st;
      const double ref = DirectionalAlbedo(m, mu, io, st).lin;
      const double got = opt ? FixedRuleGGXFresnelKernel(mu, AlphaOf(r), eta, *opt, evals)
                             : FixedRuleGGXFresnelKernel(mu, AlphaOf(r), eta, evals);
      if (points) ++*points;
      if (std::abs(got - ref) > worst) {
        worst = std::abs(got - ref);
        where = "eta=" + std::to_string(eta) + " " + Where(mu, r);
      }
      if (stopAbove >= 0 && worst > stopAbove) return worst;
    }
  return worst;
}

/// The bake's exact-Fresnel rule within kTarget at FresnelWorst's points.
void CheckFresnelGrid(size_t block) {
  std::string where;
  long long evals = 0;
  int points = 0;
  const double worst = FresnelWorst(nullptr, block, where, &evals, &points);
  std::printf(
      "ggx-fresnel-albedo kernel rule vs adaptive 1e-9 at %d points: worst %.3g at %s; "
      "%.0f evals/pt\n",
      points, worst, where.c_str(), double(evals) / points);
  INFO("worst " << worst << " at " << where);
  CHECK(worst <= kTarget);
  CHECK(evals <= 700LL * points);
}

}  // namespace

TEST_CASE(
    "The kernel's exact-Fresnel rule gives the GGX albedo with FrDielectric within 1e-7 of "
    "adaptive quadrature at 1e-9 over a stratified (mu, alpha, eta in [1.3, 3]) grid",
    "[integrate][fixed-rule][fixed-rule-kernels]") {
  CheckFresnelGrid(3);
  CHECK(FixedRuleGGXFresnelKernel(0.3, 0.2, 1.0) == 0);  // F = 0 at eta = 1
}

TEST_CASE(
    "Dense grid: the kernel's exact-Fresnel rule is within 1e-7 of adaptive quadrature at 1e-9 "
    "over all of (mu, alpha, eta) (long: run by hand)",
    "[integrate][fixed-rule][fixed-rule-kernels][long]") {
  CheckFresnelGrid(0);
}

TEST_CASE("The exact-Fresnel rule with too few nodes misses the target on the stratified grid",
          "[integrate][fixed-rule][fixed-rule-kernels]") {
  const FixedRuleOptions coarse = Coarse();
  std::string where;
  CHECK(FresnelWorst(&coarse, 3, where, nullptr, nullptr, kTarget) > kTarget);
}

TEST_CASE("Too few nodes miss the kernel variants' target: their accuracy checks can fail",
          "[integrate][fixed-rule][fixed-rule-kernels]") {
  const FixedRuleOptions coarse = Coarse();
  std::string where;
  CHECK(SeparableWorst(&coarse, SeparablePoints(3), where, nullptr, kTarget) >
        kTarget);  // the first point beyond
  double worst = 0;
  for (double r : {0.1, 0.5, 1.0})
    for (double mu : {0.01, 0.3}) {
      AnyModel m = ModelAtR("ggx", r);
      SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, 1.5, 0});
      IntegrationOptions io;
      io.tol = 1e-10;
      IntegrationStats st;
      const double ref = DirectionalAlbedo(m, mu, io, st).lin;
      worst =
          std::max(worst, std::abs(FixedRuleGGXFresnelKernel(mu, AlphaOf(r), 1.5, coarse) - ref));
    }
  CHECK(worst > kTarget);
}

TEST_CASE(
    "The kernel's AVX2, SSE2 and portable paths give the same bits for every variant (ggx, "
    "ggx-separable, exact Fresnel)",
    "[integrate][fixed-rule][fixed-rule-kernels]") {
  if (!SimdPathAvailable(SimdPath::AVX2)) WARN("no AVX2 on this CPU: AVX2 runs as the widest path");
  const SimdPath paths[] = {SimdPath::AVX2, SimdPath::SSE2, SimdPath::Portable};
  int compared = 0;
  for (double r : {0.0, 0.01, 0.1, 0.35, 0.7, 1.0})
    for (double mu : {0.0, 1e-6, 0.003, 0.05, 0.4, 0.9, 1.0}) {
      const double a = AlphaOf(r);
      std::array<double, 2> dfg[3], sep[3];
      double fr[3][2];
      for (int i = 0; i < 3; ++i) {
        FixedRuleOptions o = TunedFixedRuleOptions(a);
        o.simd = paths[i];
        dfg[i] = FixedRuleGGXDFG(mu, a, o);
        o = TunedSeparableRuleOptions(a);
        o.simd = paths[i];
        sep[i] = FixedRuleGGXSeparableDFG(mu, a, o);
        o = TunedFresnelKernelOptions(a);
        o.simd = paths[i];
        fr[i][0] = FixedRuleGGXFresnelKernel(mu, a, 1.3, o);
        fr[i][1] = FixedRuleGGXFresnelKernel(mu, a, 3.0, o);
      }
      for (int i = 1; i < 3; ++i) {
        INFO(Where(mu, r) << " path " << i);
        for (int c = 0; c < 2; ++c) {
          CHECK(dfg[i][c] == dfg[0][c]);
          CHECK(sep[i][c] == sep[0][c]);
          CHECK(fr[i][c] == fr[0][c]);
        }
      }
      ++compared;
      // The default (widest) path is one of them.
      CHECK(FixedRuleGGXSeparableDFG(mu, a)[0] == sep[0][0]);
    }
  CHECK(compared == 42);
}

TEST_CASE(
    "ggx-separable's dfg and albedo and ggx-fresnel-albedo are baked by the kernel's rules, "
    "within the bound of the adaptive reference",
    "[integrate][fixed-rule][fixed-rule-kernels][tables]") {
  for (const char* name : {"ggx-separable-dfg", "ggx-separable-albedo"}) {
    TableSpec spec = CatalogueTable(name);
    REQUIRE(UsesFixedRule(spec));
    CHECK(spec.Method().find("separable Smith as G1(l)") != std::string::npos);
    const double x[2] = {0.07, 0.63};
    IntegrationStats fixed, adaptive;
    std::vector<double> got = EvaluateSpec(spec, x, fixed);
    std::vector<double> ref = EvaluateSpec(spec, x, 1e-10, adaptive);
    REQUIRE(got.size() == ref.size());
    for (size_t c = 0; c < got.size(); ++c) CHECK(std::abs(got[c] - ref[c]) <= kTarget);
    CHECK(fixed.evals < 600);
  }
  TableSpec fa = CatalogueTable("ggx-fresnel-albedo");
  REQUIRE(UsesFixedRule(fa));
  CHECK(fa.Method().find("GGX kernel") != std::string::npos);
  for (double eta : {1.3, 2.2}) {
    const double x[3] = {0.05, 0.3, eta};
    IntegrationStats fixed, adaptive;
    const double got = EvaluateSpec(fa, x, fixed)[0], ref = EvaluateSpec(fa, x, 1e-10, adaptive)[0];
    CHECK(std::abs(got - ref) <= kTarget);
  }
  // The kind's own spec holds E: the kernel from eta = 1.3, the generic rule below (kiln
  // integrate and scenes reach eta near 1).
  const QuantityInfo& q = Describe(Quantity::FresnelAlbedo);
  TableSpec e = q.makeSpec("ggx", q.defaultAxes("ggx"));
  REQUIRE(UsesFixedRule(e));
  for (double eta : {1.2, 1.3, 2.2}) {
    const double x[3] = {0.05, 0.3, eta};
    IntegrationStats st;
    const double kernel = FixedRuleGGXFresnelKernel(0.05, 0.09, eta);
    const double generic = FixedRuleGGXFresnelAlbedo(0.05, 0.09, eta);
    INFO("eta " << eta);
    CHECK(EvaluateSpec(e, x, st)[0] == (eta >= kFresnelKernelEtaMin ? kernel : generic));
    CHECK(kernel != generic);
    CHECK(std::abs(kernel - generic) <= 2 * kTarget);
  }
}

TEST_CASE(
    "Off the grids: the kernel variants at random (mu, alpha[, eta]) points, a third of them in "
    "the grazing layer, stay within 1e-7 (long: run by hand)",
    "[integrate][fixed-rule-kernels][long]") {
  unsigned long long state = 2024;
  auto uniform = [&] {  // 53-bit LCG draw in [0, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1p-53;
  };
  auto draw = [&](double& mu, double& r) {
    r = uniform();
    mu = uniform();
    if (uniform() < 1.0 / 3) mu = std::min(1.0, r * r * std::pow(10.0, 2 * uniform() - 1.5));
  };
  double worstSeparable = 0, worstFresnel = 0;
  for (int i = 0; i < 400; ++i) {
    double mu, r;
    draw(mu, r);
    IntegrationOptions io;
    io.tol = 1e-10;
    IntegrationStats st;
    std::array<double, 2> ref = SplitSumDFG(ModelAtR("ggx-separable", r), mu, io, st);
    std::array<double, 2> got = FixedRuleGGXSeparableDFG(mu, AlphaOf(r));
    worstSeparable =
        std::max({worstSeparable, std::abs(got[0] - ref[0]), std::abs(got[1] - ref[1])});
    const double eta = 1.3 + 1.7 * uniform();
    AnyModel m = ModelAtR("ggx", r);
    SetFresnel(m, Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0});
    const double e = DirectionalAlbedo(m, mu, io, st).lin;
    worstFresnel =
        std::max(worstFresnel, std::abs(FixedRuleGGXFresnelKernel(mu, AlphaOf(r), eta) - e));
  }
  std::printf("kernel rules, 400 random points: separable worst %.3g, exact Fresnel worst %.3g\n",
              worstSeparable, worstFresnel);
  CHECK(worstSeparable <= kTarget);
  CHECK(worstFresnel <= kTarget);
}
