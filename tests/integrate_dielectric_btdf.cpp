// The split-sum BTDF pair of the GGX dielectric (baker/integrate/dielectric_btdf.h): T_lobe (the
// lobe's transmittance at F = 0) and T_F (its Fresnel-weighted part), whose difference is the
// transmitted energy E_T of the glass E tables (an independent integration: dielectric_albedo.cpp
// follows the reflected ray too); the smooth limit {1, F(mu)}; and the bake's fixed rule within its
// declared bound of the adaptive reference over the tables' domain, corners included, also by
// the bake's eta columns, which give each eta the bits of the rule at that eta alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

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
  // The bake's path: one eta column per (mu, alpha) over the etas from 1.1 up (the panels fixed
  // at eta = 1.1's), against the same reference.
  std::vector<double> col;
  for (double eta : kEtas)
    if (eta >= kDielectricTableEtaMin) col.push_back(eta);
  double worstColumn = 0;
  for (double mu : kMus)
    for (double alpha : kAlphas) {
      std::vector<std::array<double, 2>> got(col.size());
      FixedRuleDielectricBtdfColumn(mu, alpha, col.data(), static_cast<int>(col.size()),
                                    got.data());
      for (size_t k = 0; k < col.size(); ++k) {
        const std::array<double, 2> ref = Reference(mu, alpha, col[k]);
        for (int c = 0; c < 2; ++c) {
          INFO("column: mu " << mu << " alpha " << alpha << " eta " << col[k] << " channel " << c);
          CHECK(std::abs(got[k][c] - ref[c]) < kDielectricBtdfRuleBound);
          worstColumn = std::max(worstColumn, std::abs(got[k][c] - ref[c]));
        }
      }
    }
  WARN("eta columns: max error " << worstColumn);
}

TEST_CASE("a BTDF eta column gives every eta the bits of the fixed rule at that eta alone",
          "[dielectric-btdf]") {
  // 23 etas (odd: the last lane pair padded) over [1.1, 3], and the bake's 40-node sqrt axis.
  std::vector<double> etas;
  for (int k = 0; k < 23; ++k) etas.push_back(1.1 + 1.9 * std::pow(k / 22.0, 2));
  for (double mu : {0.0, 1e-6, 0.2, 0.7, 1.0})
    for (double alpha : {MinAlpha, 0.09, 1.0}) {
      std::vector<std::array<double, 2>> col(etas.size());
      long long evals = 0;
      FixedRuleDielectricBtdfColumn(mu, alpha, etas.data(), static_cast<int>(etas.size()),
                                    col.data(), &evals);
      CHECK(evals > 0);
      for (size_t k = 0; k < etas.size(); ++k) {
        INFO("mu " << mu << " alpha " << alpha << " eta " << etas[k]);
        long long one = 0;
        const std::array<double, 2> p = FixedRuleDielectricBtdfPair(mu, alpha, etas[k], &one);
        CHECK(std::memcmp(&p, &col[k], sizeof p) == 0);
        CHECK(one == evals);  // every eta of a column walks the same nodes
      }
      // A column of two from its middle: the same bits again (lanes do not mix).
      std::array<double, 2> two[2];
      FixedRuleDielectricBtdfColumn(mu, alpha, etas.data() + 7, 2, two);
      CHECK(std::memcmp(&two[0], &col[7], sizeof two[0]) == 0);
      CHECK(std::memcmp(&two[1], &col[8], sizeof two[1]) == 0);
    }
  // Off the tables' side the column refuses (its panels hold for eta >= 1.1 only).
  const double below[] = {1.05};
  std::array<double, 2> out;
  CHECK_THROWS(FixedRuleDielectricBtdfColumn(0.5, 0.1, below, 1, &out));
}
