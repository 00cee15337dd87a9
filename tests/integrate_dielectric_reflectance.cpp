// The exit averages' rule (baker/integrate/dielectric_albedo_avg.cpp): E_R alone on the panels
// of the reflected ray's structures (FixedRuleDielectricReflectance: none at the refracted
// ray's), and E_avg_T by reciprocity from the entering side. On the held-out grid of the exit
// side (eta in [1/3, 1), mu = 0, 1e-6, 1, the critical cosine and its neighbours, mu = eta,
// roughness 1e-3 .. 1) E_R stays within kDielectricRuleBound of the adaptive reference at 1e-10,
// and equals the two-channel rule's E_R to well within it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/models/roughness.h"

using namespace kiln;

TEST_CASE("E_R alone (the exit averages' rule) is within its bound of adaptive quadrature",
          "[dielectric][glass-rule]") {
  double worst = 0;
  std::vector<long long> perPoint;
  for (double eta : {1 / 3.0, 0.5, 0.75, 1 / 1.1}) {
    const double muC = std::sqrt((1 - eta) * (1 + eta));
    std::vector<double> mus = {0.0, 1e-6, 0.03, 0.3, 0.6, 0.88, 1.0, eta};
    for (double d : {0.0, -1e-4, 1e-4, -0.01, 0.01}) mus.push_back(std::clamp(muC + d, 0.0, 1.0));
    for (double mu : mus)
      for (double r : {1e-3, 0.05, 0.2, 0.45, 0.8, 1.0}) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        long long e = 0;
        const double f =
            FixedRuleDielectricReflectance(mu, alpha, eta, TunedDielectricRuleOptions(), &e);
        IntegrationOptions opt;
        opt.tol = 1e-10;
        opt.maxPanels = 2000;
        IntegrationStats st;
        const double a = DielectricAlbedo(mu, alpha, eta, opt, st)[0];
        perPoint.push_back(e);
        INFO("mu " << mu << " r " << r << " eta " << eta);
        CHECK(std::abs(f - a) < kDielectricRuleBound);
        worst = std::max(worst, std::abs(f - a));
      }
  }
  std::sort(perPoint.begin(), perPoint.end());
  std::printf("glass E_R rule, exit side: worst %.3g over %zu points; evaluations median %lld\n",
              worst, perPoint.size(), perPoint[perPoint.size() / 2]);
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
