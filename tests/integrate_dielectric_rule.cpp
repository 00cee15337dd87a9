// The glass tables' fixed rule (baker/integrate/dielectric_albedo.cpp, FixedRuleDielectricAlbedo
// with its tuned node counts by panel weight): within kDielectricRuleBound of the adaptive
// reference at 1e-10 over a dense grid of the tables' domain that the tuning did not see (mu = 0,
// 1e-6 and 1, the smallest roughness node of the tables and 1, eta at both ends of either side
// and next to 1.1), at a fraction of the evaluations of one node count for every panel; a coarser
// rule fails on the same grid (the grid can tell).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/models/roughness.h"

using namespace kiln;

namespace {

const double kMus[] = {0.0, 1e-6, 1e-4, 0.01, 0.07, 0.25, 0.5, 0.66, 0.83, 0.94, 0.999, 1.0};
// 1/39^2: the tables' first roughness node above 0 (40 nodes, sqrt warp).
const double kRs[] = {1.0 / (39 * 39), 0.004, 0.03, 0.12, 0.35, 0.7, 1.0};
const double kEtas[] = {1.1, 1.1001, 1.15, 2.0, 3.0, 1 / 1.1, 1 / 1.1001, 1 / 1.15, 0.56, 1 / 3.0};

struct GridResult {
  double worst = 0;
  long long evals = 0;
  int points = 0;
};

/// The worst |fixed - adaptive| over the grid (both channels) and the fixed rule's evaluations.
GridResult OverGrid(const DielectricRuleOptions* opt) {
  GridResult g;
  for (double eta : kEtas)
    for (double mu : kMus)
      for (double r : kRs) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        IntegrationOptions io;
        io.tol = 1e-10;
        io.maxPanels = 2000;
        IntegrationStats stats;
        const std::array<double, 2> a = DielectricAlbedo(mu, alpha, eta, io, stats);
        const std::array<double, 2> f =
            opt ? FixedRuleDielectricAlbedo(mu, alpha, eta, *opt, &g.evals)
                : FixedRuleDielectricAlbedo(mu, alpha, eta, &g.evals);
        g.worst = std::max({g.worst, std::abs(a[0] - f[0]), std::abs(a[1] - f[1])});
        ++g.points;
      }
  return g;
}

}  // namespace

TEST_CASE("the glass rule stays within its bound of adaptive quadrature on the tables' domain",
          "[dielectric][glass-rule]") {
  const GridResult tuned = OverGrid(nullptr);
  std::printf("glass rule: worst |fixed - adaptive| %.3g over %d points, %.0f evaluations each\n",
              tuned.worst, tuned.points, double(tuned.evals) / tuned.points);
  CHECK(tuned.worst < kDielectricRuleBound);
}

TEST_CASE("the glass rule's graded node counts cost under a third of one count for all panels",
          "[dielectric][glass-rule]") {
  const DielectricRuleOptions uniform;  // 24 x 16 nodes on every panel, ratio 4 everywhere
  long long tuned = 0, flat = 0;
  for (double eta : kEtas)
    for (double mu : kMus)
      for (double r : kRs) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        FixedRuleDielectricAlbedo(mu, alpha, eta, &tuned);
        FixedRuleDielectricAlbedo(mu, alpha, eta, uniform, &flat);
      }
  std::printf("glass rule: %lld evaluations graded, %lld uniform\n", tuned, flat);
  CHECK(3 * tuned < flat);
}

TEST_CASE("a coarser glass rule leaves its bound: the grid detects under-resolution",
          "[dielectric][glass-rule]") {
  DielectricRuleOptions coarse = TunedDielectricRuleOptions();
  for (int k = 0; k < 4; ++k) {
    coarse.outerNodes[k] = std::max(2, coarse.outerNodes[k] / 2);
    coarse.innerNodes[k] = std::max(2, coarse.innerNodes[k] / 2);
  }
  const GridResult g = OverGrid(&coarse);
  CHECK(g.worst > kDielectricRuleBound);
}

TEST_CASE("the glass rule gives the same bits on every call", "[dielectric][glass-rule]") {
  // The second call finds the first's result in the rule's memo (albedo-r and albedo-t share
  // one integration): the same bits and the same evaluations charged as integrating again.
  const DielectricRuleOptions tunedOptions = TunedDielectricRuleOptions();
  for (double eta : {1.1, 1 / 1.1})
    for (double mu : {0.0, 0.3, 1.0}) {
      long long e1 = 0, e2 = 0, e3 = 0;
      const std::array<double, 2> a = FixedRuleDielectricAlbedo(mu, 0.05, eta, &e1);
      const std::array<double, 2> b = FixedRuleDielectricAlbedo(mu, 0.05, eta, &e2);
      const std::array<double, 2> c = FixedRuleDielectricAlbedo(mu, 0.05, eta, tunedOptions, &e3);
      CHECK(a[0] == b[0]);
      CHECK(a[1] == b[1]);
      CHECK(a[0] == c[0]);
      CHECK(a[1] == c[1]);
      CHECK(e1 == e2);
      CHECK(e1 == e3);
    }
}
