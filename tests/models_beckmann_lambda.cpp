// Beckmann's Smith Lambda in its one-exp form (models/beckmann_lambda.h: psi(x) = 1/sqrt(pi) -
// x erfcx(x) as piecewise polynomials) against the straightforward erfc form evaluated in long
// double, over the whole range of the polynomials (both ends and every piece boundary included)
// and over views from the normal to grazing at roughness 1e-6 to 1.
#include <catch2/catch.hpp>

#include <cmath>

#include "baker/models/beckmann_lambda.h"
#include "baker/models/microfacet.h"

using namespace kiln;

namespace {

/// psi(x) = (exp(-x^2) / sqrt(pi) - x erfc(x)) exp(x^2), in long double (64-bit mantissa on
/// x86-64: the cancellation at x = 6, a factor 73, stays below 1e-17 relative).
long double PsiReference(long double x) {
  const long double invSqrtPi = 0.564189583547756286948079451560772586L;
  return (std::exp(-x * x) * invSqrtPi - x * std::erfc(x)) * std::exp(x * x);
}

/// mu Lambda(mu) = (alpha sin exp(-x^2) / sqrt(pi) - mu erfc(x)) / 2 at x = mu / (alpha sin)
/// rounded to double as BeckmannMuLambda rounds it (exp(-x^2) turns x's rounding into 2 x^2
/// times as much relative error, the same for both forms: compared at the same x), in long
/// double.
long double MuLambdaReference(double mu, double sin, double alpha) {
  const long double invSqrtPi = 0.564189583547756286948079451560772586L;
  const double as = alpha * sin, x = mu / as;
  const long double xl = x, asl = as;
  return (asl * std::exp(-xl * xl) * invSqrtPi - asl * xl * std::erfc(xl)) / 2;
}

}  // namespace

TEST_CASE("psi's polynomials are within 6e-16 relative of 1/sqrt(pi) - x erfcx(x) on [0, 6]",
          "[models][beckmann-lambda]") {
  double worst = 0, worstX = 0;
  const int n = 60000;
  for (int i = 0; i <= n; ++i) {
    const double x = kBeckmannPsiMaxX * i / n;  // every piece boundary (multiples of 1/4) too
    for (double xi : {x, std::nextafter(x, 0.0), std::nextafter(x, 7.0)}) {
      if (xi < 0 || xi > kBeckmannPsiMaxX) continue;
      const long double ref = PsiReference(xi);
      const double rel = static_cast<double>(std::abs((BeckmannPsi(xi) - ref) / ref));
      if (rel > worst) worst = rel, worstX = xi;
    }
  }
  INFO("worst relative error " << worst << " at x = " << worstX);
  CHECK(worst < 6e-16);
  CHECK(BeckmannPsi(0) == Approx(InvSqrtPi).epsilon(1e-16));
}

TEST_CASE("Beckmann's mu Lambda in the one-exp form matches the erfc form to 1e-15 + x^2 ulp",
          "[models][beckmann-lambda]") {
  double worst = 0;
  int checked = 0;
  for (double alpha : {1e-6, 1e-3, 0.01, 0.05, 0.2, 0.5, 0.8, 1.0}) {
    for (int i = 0; i <= 4000; ++i) {
      // mu from 0 (the horizon) to 1, dense near both ends.
      const double u = i / 4000.0, mu = u * u * (3 - 2 * u);
      const double sin = std::sqrt(std::max(0.0, 1 - mu * mu));
      const double fast = BeckmannMuLambda(mu, sin, alpha);
      if (!(sin > 0)) {
        CHECK(fast == 0);
        continue;
      }
      const double x = mu / (alpha * sin);
      if (x >= 27) {
        CHECK(fast == 0);  // exp(-x^2) underflows
        continue;
      }
      const long double ref = MuLambdaReference(mu, sin, alpha);
      INFO("alpha " << alpha << " mu " << mu << " x " << x);
      if (x <= kBeckmannPsiMaxX) {
        const double rel = static_cast<double>(std::abs((fast - ref) / ref));
        worst = std::max(worst, rel);
        // x^2 rounded to double carries x^2 2^-53 absolute into exp(-x^2), as in any double form.
        CHECK(rel < 1e-15 + 0x1p-52 * x * x);
        ++checked;
      } else {
        // Beyond the polynomials the erfc form: Lambda < 1.1e-17, far below what it is added to.
        CHECK(std::abs(fast - ref) <= 1.1e-17 * mu + 1e-300);
      }
    }
  }
  WARN("worst relative difference " << worst << " over " << checked << " points with x <= 6");
  CHECK(checked > 10000);
  // At the horizon (mu = 0, x = 0): alpha / (2 sqrt(pi)).
  CHECK(BeckmannMuLambda(0, 1, 0.3) == Approx(0.3 * InvSqrtPi / 2).epsilon(1e-15));
}

TEST_CASE("Beckmann's mu Lambda in the one-exp form agrees with BeckmannDistribution's",
          "[models][beckmann-lambda]") {
  // The distribution's erfc form in double: equal to within its own rounding where the two
  // terms do not cancel much (x <= 2).
  for (double alpha : {0.05, 0.3, 1.0})
    for (double mu : {0.0, 0.01, 0.1, 0.3, 0.6}) {
      const double sin = std::sqrt(1 - mu * mu);
      if (mu / (alpha * sin) > 2) continue;
      CHECK(BeckmannMuLambda(mu, sin, alpha) ==
            Approx(BeckmannDistribution{alpha}.MuLambda(mu)).epsilon(1e-14));
    }
}

#if defined(__SSE2__)
TEST_CASE("BeckmannPsi2 gives BeckmannPsi's bits in each lane", "[models][beckmann-lambda]") {
  int differ = 0;
  for (int i = 0; i <= 24000; ++i) {
    const double x0 = kBeckmannPsiMaxX * i / 24000,
                 x1 = kBeckmannPsiMaxX * ((i * 7919) % 24001) / 24000;
    alignas(16) double out[2];
    _mm_store_pd(out, BeckmannPsi2(_mm_set_pd(x1, x0)));
    differ += out[0] != BeckmannPsi(x0) || out[1] != BeckmannPsi(x1);
  }
  CHECK(differ == 0);
}
#endif
