// The microfacet fixed rule skips Beckmann's Lambda(l) (an exp and psi) where
// x = mu_l / (alpha sin_l) >= 6 (fixed_rule_beckmann_nodes.cpp, kBeckmannLambdaNegligibleX):
// there it vanishes in the sums it enters, so the rule's bits, and the committed tables, are
// unchanged.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "baker/models/microfacet.h"
#include "baker/tables/spec.h"
#include "committed_texels.h"

using namespace kiln;

TEST_CASE("Beckmann's Lambda beyond x = 6 vanishes in the masking sums of the fixed rule",
          "[integrate][fixed-rule][lambda-skip]") {
  // g = gNum / (mu_o + mu_o Lambda(o) + mu_o Lambda(l)) height-correlated and
  // gNum / (mu_o + mu_o Lambda(o)) mu_l / (mu_l + mu_l Lambda(l)) separable: the Lambda(l) term
  // must round away in both, for every view, roughness and light with x >= 6.
  int checked = 0;
  for (double alpha : {1e-4, 1e-3, 0.01, 0.05, 0.1, 0.3, 0.6, 1.0}) {
    const BeckmannDistribution d{alpha};
    for (double muO : {0.0, 1e-6, 1e-3, 0.05, 0.3, 0.7, 1.0}) {
      const double gDenO = muO + d.MuLambda(muO);
      for (double x = 6; x <= 27; x += 0.0625) {
        // mu_l / sin_l = alpha x: mu_l = alpha x / sqrt(1 + alpha^2 x^2).
        const double ax = alpha * x, muL = ax / std::sqrt(1 + ax * ax);
        const double muLambdaL = d.MuLambda(muL);
        INFO("alpha " << alpha << " mu_o " << muO << " x " << x);
        CHECK(gDenO + muO * (muLambdaL / muL) == gDenO);
        CHECK(muL + muLambdaL == muL);
        ++checked;
      }
    }
  }
  CHECK(checked > 10000);
}

TEST_CASE("The Beckmann and Blinn-Phong fixed rules give the committed texels",
          "[integrate][fixed-rule][lambda-skip]") {
  // Every 13th node of the catalogue's tables (all rows and columns visited), as the bake
  // evaluates it, against the float32 texel in luts/.
  for (const char* name : {"beckmann-dfg", "beckmann-separable-dfg", "blinn-phong-dfg"}) {
    INFO(name);
    CHECK(test::TexelsDifferingFromRule(name, 13) == 0);
  }
}
