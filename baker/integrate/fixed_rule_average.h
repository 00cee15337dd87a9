// A fixed (non-adaptive) rule for the cosine-weighted average over the view angle,
//     E_avg = 2 integral_0^1 E(mu) mu dmu,
// of a directional albedo E(mu) that a fixed rule already gives at any mu (the GGX
// visible-normal rule, fixed_rule_dfg.h): one pass over a few dozen mu nodes, no nested
// adaptive quadrature.
//
// Derivation. A microfacet albedo is smooth in mu except near mu = 0, where it varies on the
// scale of the roughness (a layer in mu / alpha; at alpha ~ 1 it behaves like mu ln mu). The
// rule puts Gauss-Legendre panels on a geometric grid that starts at the layer's scale
// m0 = clamp(alpha, 1e-4, 1e-2) and grows by 4 up to mu = 1, plus the panel [0, m0]: each panel
// then sees a function that is smooth on its own scale, so a fixed node count converges
// geometrically on every panel, at every alpha. The layer is never narrower than 1e-4: below
// that, the cosine weight leaves the panel [0, m0] a share of at most m0^2 = 1e-8 of E_avg, and
// E varies by at most ~0.06 across it. Measured (tests/integrate_fixed_rule.cpp), with the GGX
// rule inside: within 1e-8 of adaptive quadrature at 1e-10 for r in [0, 1], where the inner
// rule's own error (below kFixedRuleBound) is the larger part.
#pragma once
#include <algorithm>
#include <vector>

#include "baker/math/quadrature.h"

namespace kiln {

/// Gauss-Legendre nodes per panel of FixedCosineAverage.
constexpr int kCosineAverageNodes = 8;

/// 2 integral_0^1 e(mu) mu dmu by the fixed rule above; `layer` is the width of e's layer at
/// mu = 0 (alpha for a microfacet albedo). e is called at kCosineAverageNodes nodes per panel,
/// in ascending mu, the same nodes for the same layer (deterministic).
template <class E>
double FixedCosineAverage(E&& e, double layer) {
  static const auto rule = [] {
    std::pair<std::vector<double>, std::vector<double>> r;
    GaussLegendre01(kCosineAverageNodes, r.first, r.second);
    return r;
  }();
  std::vector<double> breaks = {0};
  for (double b = std::clamp(layer, 1e-4, 1e-2); b < 1; b *= 4) breaks.push_back(b);
  breaks.push_back(1);
  double sum = 0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double a = breaks[k], h = breaks[k + 1] - breaks[k];
    for (int i = 0; i < kCosineAverageNodes; ++i) {
      double mu = a + h * rule.first[i];
      sum += rule.second[i] * h * e(mu) * mu;
    }
  }
  return 2 * sum;
}

}  // namespace kiln
