// charlie-smith's f with its view's Lambda given (CharlieSmithSheen::FGivenLambdaO, kept by the
// LTC fit's lobe): the bits of f, so the ltc tables keep theirs.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "baker/integrate/ltc_fit.h"
#include "baker/math/constants.h"
#include "baker/math/splitmix.h"
#include "baker/models/sheen.h"
#include "float_bits.h"

using namespace kiln;

TEST_CASE("charlie-smith's f with its view's Lambda given has the bits of f", "[sheen][ltc]") {
  uint64_t state = 0xC4A7;
  int nonzero = 0;
  for (double alpha : {0.045 * 0.045, 0.01, 0.09, 0.3, 0.6, 1.0})
    for (double muO : {0.0, 1e-4, 7.96e-4, 0.02, 0.3, 0.5, 0.49999999, 0.8, 1.0}) {
      const CharlieSmithSheen m{alpha};
      const Vec3 wo = ViewDirection(muO);
      const double lambdaO = CharlieSheenLambda(muO, alpha);
      for (int k = 0; k < 200; ++k) {
        // Directions over the whole sphere (below the horizon too).
        const double z = 2 * SplitMixUniform(state) - 1, phi = 2 * Pi * SplitMixUniform(state);
        const double s = std::sqrt(std::max(0.0, 1 - z * z));
        const Vec3 wi{s * std::cos(phi), s * std::sin(phi), z};
        const double f = m.f(wo, wi);
        REQUIRE(test::Bits(m.FGivenLambdaO(wo, wi, lambdaO)) == test::Bits(f));
        nonzero += f > 0;
      }
    }
  CHECK(nonzero > 1000);
}

TEST_CASE("A charlie-smith LTC lobe evaluates f mu_l as the registry's model does",
          "[sheen][ltc]") {
  uint64_t state = 0x5EE7;
  for (double r : {0.045, 0.2, 0.7, 1.0})
    for (double mu : {LtcFitMu(0.0), 0.1, 0.6, 1.0}) {
      const LtcLobe lobe("charlie-smith", r, mu);
      ModelParams p;
      p.roughness = r;
      const AnyModel model = MakeModel("charlie-smith", p);
      for (int k = 0; k < 100; ++k) {
        const double z = SplitMixUniform(state), phi = 2 * Pi * SplitMixUniform(state);
        const double s = std::sqrt(1 - z * z);
        const Vec3 wi{s * std::cos(phi), s * std::sin(phi), z};
        const double expect = Evaluate(model, lobe.wo(), wi) * wi.z;
        REQUIRE(test::Bits(lobe.Eval(wi)) == test::Bits(wi.z > 0 ? expect : 0.0));
      }
    }
}

TEST_CASE("charlie-smith's 1 / V with its view's Lambda given has the bits of InverseV",
          "[sheen]") {
  // (ClampSwitches scans mu_l with Lambda(mu_o) computed once.)
  for (double alpha : {0.045 * 0.045, 0.09, 0.6, 1.0})
    for (double muO : {1e-4, 0.02, 0.5, 0.9, 1.0}) {
      const CharlieSmithSheen m{alpha};
      const double lambdaO = CharlieSheenLambda(muO, alpha);
      for (double muL = 1e-12; muL <= 1; muL *= 1.7)
        REQUIRE(test::Bits(m.InverseVGiven(muO, muL, lambdaO)) == test::Bits(m.InverseV(muO, muL)));
    }
}
