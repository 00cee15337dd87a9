// The split-sum BTDF pair of the GGX dielectric (baker/integrate/dielectric_btdf.h): T_lobe (the
// lobe's transmittance at F = 0) and T_F (its Fresnel-weighted part), whose difference is the
// transmitted energy E_T of the glass E tables (an independent integration: dielectric_albedo.cpp
// follows the reflected ray too); the smooth limit {1, F(mu)}; and the bake's fixed rule within its
// declared bound of the adaptive reference over the tables' domain, corners included.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/models/fresnel.h"

using namespace kiln;

namespace {
const double kMus[] = {0.0, 0.003, 0.02, 0.1, 0.35, 0.7, 0.95, 1.0};
const double kAlphas[] = {1e-4, 0.0025, 0.02, 0.1, 0.3, 0.6, 1.0};
const double kEtas[] = {1.0, 1.1, 1.33, 1.5, 2.2, 3.0};

std::array<double, 2> Reference(double mu, double alpha, double eta) {
  IntegrationOptions opt;
  opt.tol = 1e-10;
  opt.maxPanels = 2000;
  IntegrationStats stats;
  return DielectricBtdfPair(mu, alpha, eta, opt, stats);
}
}  // namespace

TEST_CASE("the BTDF pair's difference is the transmitted energy E_T", "[dielectric-btdf]") {
  double worst = 0;
  for (double mu : {0.01, 0.3, 0.8})
    for (double alpha : {0.01, 0.2, 0.8})
      for (double eta : {1.1, 1.5, 3.0}) {
        IntegrationOptions opt;
        opt.tol = 1e-10;
        opt.maxPanels = 2000;
        IntegrationStats stats;
        double et = DielectricAlbedo(mu, alpha, eta, opt, stats)[1];
        std::array<double, 2> p = Reference(mu, alpha, eta);
        INFO("mu " << mu << " alpha " << alpha << " eta " << eta);
        CHECK(std::abs((p[0] - p[1]) - et) < 1e-8);
        // The lobe loses energy to masking only: 0 < T_F < T_lobe <= 1.
        CHECK(p[0] <= 1 + 1e-12);
        CHECK(p[1] > 0);
        CHECK(p[1] < p[0]);
        worst = std::max(worst, std::abs((p[0] - p[1]) - et));
      }
  WARN("max |T_lobe - T_F - E_T| = " << worst);
}

TEST_CASE("the BTDF pair of a smooth interface is {1, F(mu)}, and roughness takes it there",
          "[dielectric-btdf]") {
  for (double mu : {0.2, 0.6, 1.0})
    for (double eta : {1.1, 1.5, 3.0}) {
      std::array<double, 2> s = SmoothDielectricBtdfPair(mu, eta);
      CHECK(s[0] == 1.0);
      CHECK(s[1] == FrDielectric(mu, eta));
      std::array<double, 2> p = Reference(mu, 1e-4, eta);
      INFO("mu " << mu << " eta " << eta);
      CHECK(std::abs(p[0] - 1) < 1e-4);
      CHECK(std::abs(p[1] - s[1]) < 1e-4);
    }
  // eta = 1: no Fresnel, and a nearly smooth lobe transmits all.
  CHECK(Reference(0.5, 1e-4, 1.0)[1] == 0.0);
  CHECK_THROWS(Reference(0.5, 0.1, 0.9));
}

TEST_CASE("the BTDF pair's fixed rule is within its bound of the adaptive reference",
          "[dielectric-btdf]") {
  double worst = 0;
  long long evals = 0;
  int n = 0;
  for (double mu : kMus)
    for (double alpha : kAlphas)
      for (double eta : kEtas) {
        std::array<double, 2> ref = Reference(mu, alpha, eta);
        std::array<double, 2> got = FixedRuleDielectricBtdfPair(mu, alpha, eta, &evals);
        ++n;
        for (int c = 0; c < 2; ++c) {
          INFO("mu " << mu << " alpha " << alpha << " eta " << eta << " channel " << c);
          CHECK(std::abs(got[c] - ref[c]) < kDielectricBtdfRuleBound);
          worst = std::max(worst, std::abs(got[c] - ref[c]));
        }
      }
  WARN("fixed rule: max error " << worst << ", " << evals / n << " evaluations per point");
}
