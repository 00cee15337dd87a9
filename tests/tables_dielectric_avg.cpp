// The rough dielectric's averages (integrate/dielectric_albedo_avg.h, quantities
// dielectric_albedo_avg.cpp): at roughness 0 they are the smooth interface's hemispherical F_avg
// and 1 - F_avg (fresnel-dielectric-avg's integral), the fixed rule agrees with adaptive
// quadrature, and transmission is reciprocal: with E_T in importance form,
//     E_avg_T(exit, 1 / eta) = E_avg_T(enter, eta) / eta^2
// (Walter eq. 21 / n_o^2 is symmetric in wo, wi; the 1/eta^2 of the importance form of the
// exit side converts one into the other).
#include <catch2/catch.hpp>

#include <cstring>

#include "baker/bake/bake.h"
#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/quantities.h"
#include "baker/models/fresnel.h"
#include "baker/tables/catalogue.h"

using namespace kiln;

TEST_CASE("dielectric averages at roughness 0: F_avg and 1 - F_avg of either side",
          "[dielectric][avg]") {
  for (double eta : {1.1, 1.5, 2.4, 3.0, 1 / 1.1, 1 / 1.5, 1 / 3.0}) {
    IntegrationOptions opt;
    opt.tol = 1e-12;
    IntegrationStats st;
    const double F = FresnelAverage(Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0}, opt, st);
    const std::array<double, 2> s = SmoothDielectricAlbedoAverage(eta);
    INFO("eta " << eta);
    CHECK(s[0] == Approx(F).margin(1e-9));
    CHECK(s[1] == Approx(1 - F).margin(1e-9));
    // And the rough rule meets it as alpha -> 0 (the GGX layer at mu = 0 is 1e-4 wide here).
    const std::array<double, 2> r = FixedRuleDielectricAlbedoAverage(1e-8, eta);
    CHECK(r[0] == Approx(s[0]).margin(1e-5));
    CHECK(r[1] == Approx(s[1]).margin(1e-5));
  }
}

TEST_CASE("dielectric averages: reciprocity of transmission, E_avg_T(1/eta) = E_avg_T(eta)/eta^2",
          "[dielectric][avg]") {
  for (double alpha : {1e-3, 0.09, 0.6})
    for (double eta : {1.1, 1.5, 3.0}) {
      const double in = FixedRuleDielectricAlbedoAverage(alpha, eta)[1];
      const double out = FixedRuleDielectricAlbedoAverage(alpha, 1 / eta)[1];
      INFO("alpha " << alpha << " eta " << eta);
      CHECK(out == Approx(in / (eta * eta)).margin(2e-6));
    }
}

namespace {

/// The adaptive reference's tolerance: the quadrature over mu to 5e-8, E(mu) to 1e-8 / (2 mu)
/// (graded by the average's weight, so E_avg moves by 1e-8 at most): 6e-8 in all, so a rule held
/// within its bound, 9e-7, of this reference is within 1e-6 of the exact average. (The rule and
/// the reference differ by a few 1e-9 here, as with a reference to 1e-8, which is slower.)
constexpr NestedAverageTolerance kReferenceTol = {5e-8, 1e-8, true};

/// The fixed rule against adaptive quadrature (kReferenceTol) at roughness `alpha` and the four
/// eta of the check: (alpha, eta) = (1, 0.7939) and (0.3, 1/1.1) are where E_T has its point at
/// mu = eta and E_R its sqrt(1 - mu) end; without panels there the rule was 1.8e-5 and 1e-6 off.
/// One test per alpha (each point is an integral of integrals, seconds of one core).
void CheckAverageRuleAgainstAdaptive(double alpha) {
  for (double eta : {1.5, 1 / 1.5, 0.7939, 1 / 1.1}) {
    IntegrationStats st;
    const std::array<double, 2> ad = DielectricAlbedoAverage(alpha, eta, kReferenceTol, st);
    const std::array<double, 2> fx = FixedRuleDielectricAlbedoAverage(alpha, eta);
    INFO("alpha " << alpha << " eta " << eta);
    CHECK(fx[0] == Approx(ad[0]).margin(kDielectricRuleBound + kDielectricAverageBound));
    CHECK(fx[1] == Approx(ad[1]).margin(kDielectricRuleBound + kDielectricAverageBound));
    // Single scattering loses energy: E_avg_R + E_avg_T <= 1.
    CHECK(fx[0] + fx[1] <= 1 + 1e-9);
  }
}

}  // namespace

TEST_CASE("dielectric averages: the fixed rule within 1e-6 of adaptive quadrature, alpha = 1e-4",
          "[dielectric][avg]") {
  CheckAverageRuleAgainstAdaptive(1e-4);
}
TEST_CASE("dielectric averages: the fixed rule within 1e-6 of adaptive quadrature, alpha = 0.25",
          "[dielectric][avg]") {
  CheckAverageRuleAgainstAdaptive(0.25);
}
TEST_CASE("dielectric averages: the fixed rule within 1e-6 of adaptive quadrature, alpha = 0.3",
          "[dielectric][avg]") {
  CheckAverageRuleAgainstAdaptive(0.3);
}
TEST_CASE("dielectric averages: the fixed rule within 1e-6 of adaptive quadrature, alpha = 1",
          "[dielectric][avg]") {
  CheckAverageRuleAgainstAdaptive(1.0);
}

TEST_CASE("the dielectric average tables bake the same values with 1 and 2 threads",
          "[dielectric][avg]") {
  CatalogueOptions copt;
  copt.size = 3;
  TableSpec spec = CatalogueTable("ggx-dielectric-albedo-t-exit-avg", copt);
  BakeOptions one, two;
  one.threads = 1;
  two.threads = 2;
  one.measureLookupError = two.measureLookupError = false;
  Table a = BakeTable(spec, one), b = BakeTable(spec, two);
  REQUIRE(a.data.size() == b.data.size());
  CHECK(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(a.data[0])) == 0);
}
