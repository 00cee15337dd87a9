// The entering glass columns by Fresnel moments (baker/integrate/dielectric_fresnel_moments.h,
// dielectric_albedo.cpp "Columns"): the Chebyshev series of F within its declared bound of
// FrDielectric over the entering side's domain (c in [0, 1], eta in [1.1, 3]), which bounds how far
// E_R by moments moves from the rule applied to F itself; and the column's {E_R, E_T} (E_R by the
// moments, E_T = T_lobe - T_F from the BTDF pair's column) within kDielectricRuleBound of the
// adaptive reference at the entering side's corners and middle, on both the AVX-512F and the
// portable path.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_fresnel_moments.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/models/fresnel.h"
#include "baker/models/roughness.h"

using namespace kiln;

TEST_CASE("Fresnel's Chebyshev series is within its bound of F on the entering side",
          "[dielectric][glass-rule]") {
  // 1,901 etas over [1.1, 3] (ends included) by 2,001 cosines over [0, 1] and 60 more within
  // 1e-2 of c = 0, where the series is worst (the branch points at c = +-i sqrt(eta^2 - 1)).
  double worst = 0, worstC = 0, worstEta = 0;
  for (int ie = 0; ie <= 1900; ++ie) {
    const double eta = ie == 1900 ? 3.0 : kDielectricTableEtaMin + 1.9 * ie / 1900;
    const dielectric_moments::Coefficients co = dielectric_moments::FresnelChebyshev(eta);
    auto check = [&](double c) {
      const double err = std::abs(dielectric_moments::EvaluateSeries(co, c) - FrDielectric(c, eta));
      if (err > worst) worst = err, worstC = c, worstEta = eta;
    };
    for (int ic = 0; ic <= 2000; ++ic) check(ic / 2000.0);
    for (int ic = 0; ic < 60; ++ic) check(1e-2 * std::pow(10.0, -ic / 6.0));
  }
  std::printf("Fresnel series, degree %d: worst |F - F_N| %.3g at c = %.3g, eta = %.4g\n",
              dielectric_moments::kDegree, worst, worstC, worstEta);
  CHECK(worst <= dielectric_moments::kFitBound);
}

TEST_CASE("a lower degree leaves the Fresnel series' bound: the check can fail",
          "[dielectric][glass-rule]") {
  // The same series truncated 6 terms early (degree 20) at eta 3, where the fit is worst.
  dielectric_moments::Coefficients co = dielectric_moments::FresnelChebyshev(3.0);
  for (int k = dielectric_moments::kDegree - 5; k <= dielectric_moments::kDegree; ++k) co.a[k] = 0;
  double worst = 0;
  for (int ic = 0; ic <= 2000; ++ic) {
    const double c = ic / 2000.0;
    worst =
        std::max(worst, std::abs(dielectric_moments::EvaluateSeries(co, c) - FrDielectric(c, 3.0)));
  }
  CHECK(worst > dielectric_moments::kFitBound);
}

TEST_CASE("the entering columns by moments hold {E_R, E_T} within the rule's bound of adaptive",
          "[dielectric][glass-rule]") {
  const double etas[] = {1.1, 1.5, 3.0};
  const bool had = dielectric_simd::Enabled();
  double worst = 0;
  for (bool simd : {true, false}) {
    dielectric_simd::SetEnabled(simd);
    for (double mu : {0.0, 2e-3, 0.5, 1.0})
      for (double r : {0.02, 0.3, 1.0}) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        std::array<double, 2> col[3];
        FixedRuleDielectricAlbedoColumn(mu, alpha, etas, 3, TunedDielectricRuleOptions(), col);
        for (int e = 0; e < 3; ++e) {
          IntegrationOptions opt;
          opt.tol = kDielectricRuleBound / 1000;
          opt.maxPanels = 2000;
          IntegrationStats stats;
          const std::array<double, 2> ref = DielectricAlbedo(mu, alpha, etas[e], opt, stats);
          for (int ch = 0; ch < 2; ++ch) {
            INFO("mu " << mu << " r " << r << " eta " << etas[e] << " channel " << ch << " simd "
                       << simd << ": " << col[e][ch] << " against " << ref[ch]);
            CHECK(std::abs(col[e][ch] - ref[ch]) < kDielectricRuleBound);
            worst = std::max(worst, std::abs(col[e][ch] - ref[ch]));
          }
        }
      }
  }
  dielectric_simd::SetEnabled(had);
  std::printf("entering columns by moments: worst %.3g from adaptive over 72 values\n", worst);
}
