// The exit averages' rule (baker/integrate/dielectric_albedo_avg.cpp): E_R alone on the panels
// of the reflected ray's structures (FixedRuleDielectricReflectance: none at the refracted
// ray's), and E_avg_T by reciprocity from the entering side. On the held-out grid of the exit
// side (eta in [1/3, 1), mu = 0, 1e-6, 1, the critical cosine and its neighbours, mu = eta,
// roughness 1e-3 .. 1; its edges and worst points whole, a seeded stratified sample of the rest,
// the dense grid as a [long] test) E_R stays within kDielectricRuleBound of the adaptive
// reference at 1000x below the bound, and equals the two-channel rule's E_R to well within it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/models/roughness.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

const double kExitEtas[] = {1 / 3.0, 0.5, 0.75, 1 / 1.1};
const double kExitRoughness[] = {1e-3, 0.05, 0.2, 0.45, 0.8, 1.0};

/// An (eta, mu) row of the exit side's held-out grid; whole: visited at every roughness.
struct ExitRow {
  double eta, mu;
  bool whole;
};

/// The rows, eta slowest: mu = 0, 1e-6, a spread, 1, eta, the critical cosine mu_c and its
/// neighbours. Whole: the ends eta = 1/3 and 1/1.1, and at every eta mu = 0, 1 and mu_c.
std::vector<ExitRow> ExitRows() {
  std::vector<ExitRow> rows;
  for (double eta : kExitEtas) {
    const double muC = std::sqrt((1 - eta) * (1 + eta));
    std::vector<double> mus = {0.0, 1e-6, 0.03, 0.3, 0.6, 0.88, 1.0, eta};
    for (double d : {0.0, -1e-4, 1e-4, -0.01, 0.01}) mus.push_back(std::clamp(muC + d, 0.0, 1.0));
    for (double mu : mus)
      rows.push_back(
          {eta, mu, eta == 1 / 3.0 || eta == 1 / 1.1 || mu == 0 || mu == 1 || mu == muC});
  }
  return rows;
}

/// Where E_R errs most on the dense grid (the [long] test below), as (roughness, row) indices,
/// always visited: next to the critical cosine mu_c of eta = 1/3, mu_c - 1e-4 at roughness 0.45
/// (3.9e-7) and 0.8 (3.1e-7), mu_c at 0.8 (2.5e-7), mu = 0.88 at 0.8 (2.3e-7); and off the whole
/// rows, eta = 0.5 at mu_c - 1e-4, roughness 0.45 (1.8e-7).
const std::vector<test::GridIndex> kExitWorst = {{3, 9}, {4, 9}, {4, 8}, {4, 5}, {3, 22}};

/// E_R's rule within kDielectricRuleBound of the adaptive reference (at 1000x below the bound)
/// at the roughness ends and whole rows, one point of each 3 x 3 block of the rest (seeded), and
/// kExitWorst; block 1: every point.
void CheckExitReflectanceGrid(size_t block) {
  const std::vector<ExitRow> rows = ExitRows();
  std::vector<size_t> whole;
  for (size_t k = 0; k < rows.size(); ++k)
    if (rows[k].whole) whole.push_back(k);
  double worst = 0;
  std::vector<long long> perPoint;
  for (const test::GridIndex& p : test::StratifiedGrid(std::size(kExitRoughness), rows.size(),
                                                       block, 0xE817, {}, whole, kExitWorst)) {
    const double eta = rows[p.j].eta, mu = rows[p.j].mu, r = kExitRoughness[p.i];
    const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
    long long e = 0;
    const double f =
        FixedRuleDielectricReflectance(mu, alpha, eta, TunedDielectricRuleOptions(), &e);
    IntegrationOptions opt;
    opt.tol = kDielectricRuleBound / 1000;
    opt.maxPanels = 2000;
    IntegrationStats st;
    const double a = DielectricAlbedo(mu, alpha, eta, opt, st)[0];
    perPoint.push_back(e);
    INFO("mu " << mu << " r " << r << " eta " << eta);
    CHECK(std::abs(f - a) < kDielectricRuleBound);
    worst = std::max(worst, std::abs(f - a));
  }
  std::sort(perPoint.begin(), perPoint.end());
  std::printf("glass E_R rule, exit side: worst %.3g over %zu points; evaluations median %lld\n",
              worst, perPoint.size(), perPoint[perPoint.size() / 2]);
}

}  // namespace

TEST_CASE("E_R alone (the exit averages' rule) is within its bound of adaptive quadrature",
          "[dielectric][glass-rule]") {
  CheckExitReflectanceGrid(3);
}

TEST_CASE(
    "Dense grid: E_R alone (the exit averages' rule) is within its bound of adaptive quadrature "
    "on all of the exit side's held-out grid (long: run by hand)",
    "[dielectric][glass-rule][long]") {
  CheckExitReflectanceGrid(1);
}

TEST_CASE("the exit averages' E_avg_T is eta^2 times the entering side's at 1 / eta",
          "[dielectric][glass-rule]") {
  for (double alpha : {1e-3, 0.09, 0.6})
    for (double eta : {1 / 3.0, 0.6, 1 / 1.2}) {
      const std::array<double, 2> out = FixedRuleDielectricAlbedoAverage(alpha, eta);
      const std::array<double, 2> in = FixedRuleDielectricAlbedoAverage(alpha, 1 / eta);
      INFO("alpha " << alpha << " eta " << eta);
      CHECK(out[1] == eta * eta * in[1]);
      // and E_avg_R by its own rule: single scattering loses energy.
      CHECK(out[0] + out[1] <= 1 + 1e-9);
      CHECK(out[0] > 0);
    }
}
