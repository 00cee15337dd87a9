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
#include <cmath>
#include <vector>

#include "baker/math/quadrature.h"

namespace kiln {

/// Gauss-Legendre nodes per panel of FixedCosineAverage.
constexpr int kCosineAverageNodes = 8;

/// The error the average rules add to that of the E they average, declared for every catalogue
/// average (tests/integrate_fixed_rule_average.cpp holds each to adaptive quadrature at 1e-10).
constexpr double kCosineAverageBound = 1e-8;

/// The layer FixedCosineAverageAngle is given for the diffuse models: their E(mu) bends near
/// mu = 0 on no scale finer than this (panels 0, 0.1, 0.4, pi/2 in asin(mu): within 1e-9 of
/// adaptive quadrature at 1e-10 for every catalogue diffuse model, the tests print each).
constexpr double kMinAngleLayer = 0.1;

/// Gauss-Legendre nodes per panel of the lookup-error search's form of the averages (the same
/// panels; tests/lookup_search_reference.cpp holds it within kSearchRuleBound of the bake's).
constexpr int kSearchAverageNodes = 6;

/// One node of a cosine-average rule: E_avg = sum over the nodes of weight e(mu), the weight
/// including the factor 2 mu (and the angle form's dmu/dx).
struct CosineAverageNode {
  double mu, weight;
};

/// The nodes of the rule above, in ascending mu, with weights that include the factor 2 mu:
/// E_avg = sum of weight e(mu). `layer` is the width of e's layer at mu = 0 (alpha for a
/// microfacet albedo); `nodes` per panel. `kink` (in (0, 1)) adds a panel boundary there;
/// `kinkLayer` > 0 grades panels on both sides of it as at mu = 0 (boundaries at kink -+ b,
/// b = clamp(kinkLayer, 1e-4, 1e-2) 4^k inside (0, 1)): a kink smoothed over a width ~kinkLayer
/// (unity-brdf2's E at mu = sqrt(0.1), over ~alpha).
inline std::vector<CosineAverageNode> CosineAverageNodeList(double layer,
                                                            int nodes = kCosineAverageNodes,
                                                            double kink = -1,
                                                            double kinkLayer = 0) {
  const GaussRule01& rule = CachedGaussLegendre01(nodes);
  std::vector<double> breaks = {0};
  for (double b = std::clamp(layer, 1e-4, 1e-2); b < 1; b *= 4) breaks.push_back(b);
  breaks.push_back(1);
  if (kink > 0 && kink < 1) {  // a panel boundary at e's kink (charlie-smith's mu = 1/2)
    breaks.push_back(kink);
    if (kinkLayer > 0)
      for (double b = std::clamp(kinkLayer, 1e-4, 1e-2); kink - b > 0 || kink + b < 1; b *= 4) {
        if (kink - b > 0) breaks.push_back(kink - b);
        if (kink + b < 1) breaks.push_back(kink + b);
      }
    std::sort(breaks.begin(), breaks.end());
  }
  std::vector<CosineAverageNode> out;
  out.reserve((breaks.size() - 1) * rule.x.size());
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double a = breaks[k], h = breaks[k + 1] - breaks[k];
    for (int i = 0; i < nodes; ++i) {
      double mu = a + h * rule.x[i];
      out.push_back({mu, 2 * rule.w[i] * h * mu});
    }
  }
  return out;
}

/// The nodes of the angle form (FixedCosineAverageAngle) in ascending mu: mu = sin(x) over
/// geometric panels in x from `layer` (clamped to [1e-4, 0.1]) up to pi/2, weight
/// 2 w h mu cos(x) (w, h: the Gauss weight and the panel's width in x); `nodes` per panel.
inline std::vector<CosineAverageNode> CosineAverageAngleNodeList(double layer,
                                                                 int nodes = kCosineAverageNodes) {
  const GaussRule01& rule = CachedGaussLegendre01(nodes);
  std::vector<double> breaks = {0};
  for (double b = std::clamp(layer, 1e-4, 0.1); b < HalfPi; b *= 4) breaks.push_back(b);
  breaks.push_back(HalfPi);
  std::vector<CosineAverageNode> out;
  out.reserve((breaks.size() - 1) * rule.x.size());
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double a = breaks[k], h = breaks[k + 1] - breaks[k];
    for (int i = 0; i < nodes; ++i) {
      double x = a + h * rule.x[i], mu = std::sin(x);
      out.push_back({mu, 2 * rule.w[i] * h * mu * std::cos(x)});
    }
  }
  return out;
}

/// sum over i of nodes[i].weight values[i], channel by channel, added in the nodes' order (the
/// bits of the rules below for values[i] = e(nodes[i].mu), however the values were computed);
/// the result has as many channels as the longest value.
inline std::vector<double> SumCosineAverage(const std::vector<CosineAverageNode>& nodes,
                                            const std::vector<std::vector<double>>& values) {
  std::vector<double> sum;
  for (size_t i = 0; i < nodes.size() && i < values.size(); ++i) {
    const std::vector<double>& v = values[i];
    if (sum.size() < v.size()) sum.resize(v.size(), 0.0);
    for (size_t c = 0; c < v.size(); ++c) sum[c] += nodes[i].weight * v[c];
  }
  return sum;
}

/// Calls visit(mu, weight) at every node of CosineAverageNodeList(layer, nodes, kink,
/// kinkLayer), in its order.
template <class V>
void FixedCosineAverageNodes(double layer, V&& visit, int nodes = kCosineAverageNodes,
                             double kink = -1, double kinkLayer = 0) {
  for (const CosineAverageNode& n : CosineAverageNodeList(layer, nodes, kink, kinkLayer))
    visit(n.mu, n.weight);
}

/// 2 integral_0^1 e(mu) mu dmu by the fixed rule above; `layer` is the width of e's layer at
/// mu = 0 (alpha for a microfacet albedo). e is called at kCosineAverageNodes nodes per panel,
/// in ascending mu, the same nodes for the same layer (deterministic).
template <class E>
double FixedCosineAverage(E&& e, double layer) {
  double sum = 0;
  FixedCosineAverageNodes(layer, [&](double mu, double weight) { sum += weight * e(mu); });
  return sum;
}

/// The channel-valued form of FixedCosineAverage: e(mu) -> std::vector<double> (the same size at
/// every node), averaged channel by channel with the same nodes and weights; `kink` (when in
/// (0, 1)) adds a panel boundary there.
template <class E>
std::vector<double> FixedCosineAverageChannels(E&& e, double layer, int nodes = kCosineAverageNodes,
                                               double kink = -1, double kinkLayer = 0) {
  std::vector<double> sum;
  auto one = [&](double mu, double weight) {
    std::vector<double> v = e(mu);
    sum.resize(v.size(), 0.0);
    for (size_t c = 0; c < v.size(); ++c) sum[c] += weight * v[c];
  };
  FixedCosineAverageNodes(layer, one, nodes, kink, kinkLayer);
  return sum;
}

/// The angle form, for albedos that are smooth in theta_o but not in mu at mu = 1 (the diffuse
/// models with kinks at theta_l = theta_o: Oren-Nayar's E has sin(theta_o) = sqrt(1 - mu^2)
/// terms). With mu = sin(x), E_avg = 2 int_0^{pi/2} E(sin x) sin x cos x dx: analytic at
/// x = pi/2, and near x = 0 (mu ~ x) the same layer as in mu, so the same geometric panels in
/// x, from `layer` (clamped to [1e-4, 0.1]) up to pi/2 (CosineAverageAngleNodeList). e is called
/// in ascending mu.
template <class E>
std::vector<double> FixedCosineAverageAngle(E&& e, double layer, int nodes = kCosineAverageNodes) {
  std::vector<double> sum;
  for (const CosineAverageNode& n : CosineAverageAngleNodeList(layer, nodes)) {
    std::vector<double> v = e(n.mu);
    sum.resize(v.size(), 0.0);
    for (size_t c = 0; c < v.size(); ++c) sum[c] += n.weight * v[c];
  }
  return sum;
}

}  // namespace kiln
