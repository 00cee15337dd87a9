// The exit side's E_R by total internal reflection's complement (dielectric_albedo.cpp,
// DielectricRuleOptions::exitTirComplement): E_R = E_1 - integral over the cap c > c_crit of
// (1 - F) times the reflected term with F = 1. E_1 (GGX's F = 1 albedo by fixed_rule_dfg.h's rule
// with DielectricExitE1RuleOptions) against adaptive quadrature and against the glass walk's own
// reflected term at F = 1; the complement against the direct form (E_T's sums the same, E_R within
// the rule's bound of each other) and its cost. The rule against adaptive quadrature over the exit
// side: tests/integrate_dielectric_rule*.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/quantities.h"
#include "baker/models/roughness.h"

using namespace kiln;

namespace {

const double kMus[] = {0,   1e-9, 1e-6, 1e-4, 1e-3, 0.003, 0.01, 0.03, 0.05, 0.1,   0.15, 0.2,
                       0.3, 0.4,  0.5,  0.6,  0.7,  0.8,   0.9,  0.95, 0.99, 0.999, 1};
const double kRoughness[] = {0,    1 / 1521.0, 0.01, 0.03, 0.05, 0.08, 0.1, 0.15, 0.2,  0.25, 0.3,
                             0.35, 0.4,        0.45, 0.5,  0.6,  0.7,  0.8, 0.9,  0.95, 1};

/// E_1 by the complement's rule at (mu, alpha).
double E1(double mu, double alpha, long long* evals = nullptr) {
  const std::array<double, 2> ab = FixedRuleGGXDFG(mu, alpha, DielectricExitE1RuleOptions(), evals);
  return ab[0] + ab[1];
}

}  // namespace

TEST_CASE("the exit complement's E_1 rule is within 5e-8 of adaptive quadrature",
          "[dielectric][glass-rule]") {
  // Measured 3.8e-8 at worst (483 points); the tables' rule bound is 7e-7, to which E_1's error
  // adds.
  double worst = 0;
  long long evals = 0;
  int n = 0;
  for (double r : kRoughness)
    for (double mu : kMus) {
      ModelParams p;
      p.roughness = r;
      IntegrationOptions io;
      io.tol = 1e-11;
      IntegrationStats st;
      const std::array<double, 2> ref = SplitSumDFG(MakeModel("ggx", p), mu, io, st);
      const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
      const double err = std::abs(E1(mu, alpha, &evals) - (ref[0] + ref[1]));
      INFO("mu " << mu << " r " << r);
      CHECK(err < 5e-8);
      worst = std::max(worst, err);
      ++n;
    }
  std::printf(
      "glass exit E_1 rule: worst %.3g from adaptive over %d points, %.0f evaluations each\n",
      worst, n, static_cast<double>(evals) / n);
}

TEST_CASE("the exit complement's E_1 is the glass walk's reflected term with F = 1",
          "[dielectric][glass-rule]") {
  // At eta' = 1e-9 the walk's F is 1 but at c = 1 (c_crit rounds to 1), where it is 1 - 4e-9:
  // its E_R (adaptive) is E_1 but for that, at most 4e-9 (the mirror at mu = 1). The same Smith
  // form (height-correlated), roughness and view conventions.
  double worst = 0;
  for (double r : {0.0, 0.05, 0.15, 0.35, 0.6, 1.0})
    for (double mu : {0.0, 1e-6, 0.02, 0.3, 0.7, 0.99, 1.0}) {
      const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
      IntegrationOptions io;
      io.tol = 1e-10;
      IntegrationStats st;
      const std::array<double, 2> walk = DielectricAlbedo(mu, alpha, 1e-9, io, st);
      INFO("mu " << mu << " r " << r << " walk " << walk[0]);
      CHECK(std::abs(E1(mu, alpha) - walk[0]) < 5e-8);
      worst = std::max(worst, std::abs(E1(mu, alpha) - walk[0]));
    }
  std::printf("glass exit E_1 rule: worst %.3g from the walk's F = 1 albedo (adaptive)\n", worst);
}

TEST_CASE("the exit complement keeps E_T's sums and E_R within the bound, at under half the cost",
          "[dielectric][glass-rule]") {
  DielectricRuleOptions direct = TunedDielectricRuleOptions();
  REQUIRE(direct.exitTirComplement);  // the bake's rule takes the complement
  direct.exitTirComplement = false;
  long long evalsDirect = 0, evalsComplement = 0;
  double worstR = 0;
  for (double eta : {1 / 3.0, 0.45, 0.6, 0.75, 1 / 1.1, 0.99}) {
    const double muC = std::sqrt((1 - eta) * (1 + eta));
    for (double r : {0.0, 1 / 1521.0, 0.05, 0.2, 0.45, 0.8, 1.0})
      for (double mu :
           {0.0, 1e-6, 1e-4, 0.003, 0.1, 0.4, 0.7, 0.9, 1.0, eta, muC, muC + 1e-4, muC - 0.01}) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        // Below mu = 1e-4 the rule takes the direct form (dielectric_albedo.cpp,
        // kTirComplementMinMu): the same bits; the cost is compared above it.
        const bool grazing = mu < 1e-4;
        long long* countDirect = grazing ? nullptr : &evalsDirect;
        long long* countComplement = grazing ? nullptr : &evalsComplement;
        const std::array<double, 2> d =
            FixedRuleDielectricAlbedo(mu, alpha, eta, direct, countDirect);
        const std::array<double, 2> c = FixedRuleDielectricAlbedo(
            mu, alpha, eta, TunedDielectricRuleOptions(), countComplement);
        INFO("mu " << mu << " r " << r << " eta " << eta);
        if (grazing) CHECK(c[0] == d[0]);
        // The skipped rings and panels added +0 to E_T (kTirMargin): the same terms in the
        // same lanes, at mu_c too (a near-mirror lobe's rings within ulps of c_crit).
        CHECK(c[1] == d[1]);
        CHECK(std::abs(c[0] - d[0]) < kDielectricRuleBound);
        worstR = std::max(worstR, std::abs(c[0] - d[0]));
      }
  }
  std::printf(
      "glass exit complement: %lld evaluations against %lld direct (mu >= 1e-4); E_R moved %.3g\n",
      evalsComplement, evalsDirect, worstR);
  CHECK(evalsComplement < evalsDirect / 2);
}
