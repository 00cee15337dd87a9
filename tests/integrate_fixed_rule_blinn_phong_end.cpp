// The microfacet fixed rule keeps Blinn-Phong's end of the NDF (a function of alpha alone) from the
// last roughness it was asked for: any order of calls gives every point the same bits.
#include <catch2/catch.hpp>

#include <array>
#include <vector>

#include "baker/integrate/fixed_rule_microfacet.h"
#include "float_bits.h"

using namespace kiln;

TEST_CASE("Blinn-Phong's fixed rule gives the same bits whatever roughness came before",
          "[integrate][fixed-rule][fixed-rule-microfacet]") {
  const FixedRuleModel blinn{FixedRuleNdf::BlinnPhong, false};
  const std::vector<double> alphas = {1e-4, 0.01, 0.05, 0.2, 0.5, 0.9, 1.0};
  const std::vector<double> mus = {0.0, 0.3, 1.0};
  // Each point alone, after a call at another roughness.
  std::vector<std::array<double, 2>> alone;
  for (double a : alphas)
    for (double mu : mus) {
      FixedRuleMicrofacetDFG(blinn, 0.5, a == 0.2 ? 0.5 : 0.2);
      alone.push_back(FixedRuleMicrofacetDFG(blinn, mu, a));
    }
  // Then in runs of one roughness, backwards.
  for (size_t i = alphas.size(); i-- > 0;)
    for (size_t j = 0; j < mus.size(); ++j) {
      const std::array<double, 2> v = FixedRuleMicrofacetDFG(blinn, mus[j], alphas[i]);
      const std::array<double, 2>& w = alone[i * mus.size() + j];
      INFO("alpha " << alphas[i] << " mu " << mus[j]);
      CHECK(test::Bits(v[0]) == test::Bits(w[0]));
      CHECK(test::Bits(v[1]) == test::Bits(w[1]));
    }
}
