// The Beckmann-family nodes of the microfacet fixed rule (integrate/fixed_rule_beckmann_nodes.h):
// the SSE2, AVX2 and AVX-512F lanes give the scalar form's bits, and both are within 1e-12 relative
// of the straightforward integrand (std::exp, std::log1p, Lambda's erfc form, a division per
// quotient), over views from the normal to grazing, roughness from 1e-6 to 1, both signs of the
// azimuth and nodes from t = 0 to the horizon t = 1 (where the integrand vanishes or is cut).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/fixed_rule_beckmann_nodes.h"
#include "baker/math/constants.h"

using namespace kiln;

namespace {

/// mu Lambda of GGX and Beckmann as fixed_rule_microfacet.cpp's Context takes them (erfc form).
double MuLambdaGGX(double mu, double sin, double a) {
  const double a2s2 = a * a * sin * sin, den = 2 * (std::sqrt(mu * mu + a2s2) + mu);
  return den > 0 ? a2s2 / den : 0;
}
double MuLambdaBeckmannErfc(double mu, double sin, double a) {
  if (!(sin > 0)) return 0;
  const double x = mu / (a * sin);
  if (!(x < 27)) return 0;
  return std::max(0.0, (a * sin * std::exp(-x * x) * InvSqrtPi - mu * std::erfc(x)) / 2);
}

/// The view constants as MakeContext derives them.
BeckmannNodeView ViewOf(double mu, double alpha, bool blinn, bool separable) {
  BeckmannNodeView v;
  v.a = alpha;
  v.mu = mu;
  v.st = std::sqrt(std::max(0.0, 1 - mu * mu));
  const double L = std::sqrt(alpha * alpha * v.st * v.st + mu * mu);
  v.ozs = mu / L;
  v.oxs = alpha * v.st / L;
  v.gNum = mu + MuLambdaGGX(mu, v.st, alpha);
  v.gDenO = mu + MuLambdaBeckmannErfc(mu, v.st, alpha);
  v.gRatio = v.gNum / v.gDenO;
  v.blinnK = 1 / (alpha * alpha) - 1;
  v.blinnPhong = blinn;
  v.separable = separable;
  return v;
}

/// The integrand at one node, straightforwardly (fixed_rule_microfacet.cpp's derivation):
/// mu_l and sin_l by division, r by std::exp and std::log1p, g by Smith's form with Lambda(l)
/// in the erfc form.
std::array<double, 2> Straightforward(const BeckmannNodeView& v, double c, double t, double w) {
  const double a = v.a, mu = v.mu;
  const double C = 1 - t * t, q = 1 + t * t, S = 2 * t, aS = a * S, M2 = aS * aS + C * C;
  const double N1 = 2 * v.st * aS * C * c + mu * (C * C - aS * aS);
  if (!(N1 > 0)) return {0, 0};
  const double muL = N1 / M2, sinL = std::sqrt((M2 - N1) * (M2 + N1)) / M2;
  double r;
  if (!v.blinnPhong) {
    const double u = C * C > 0 ? S * S / (C * C) : INFINITY;
    r = std::exp(-u) * (1 + u) * (1 + u);
  } else {
    const double qm = q * q / M2;
    r = qm * qm * std::exp(-v.blinnK * std::log1p(aS * aS / (C * C)));
  }
  const double lambdaL = MuLambdaBeckmannErfc(muL, sinL, a) / muL;
  const double g =
      v.separable ? v.gNum / v.gDenO / (1 + lambdaL) : v.gNum / (v.gDenO + mu * lambdaL);
  const double val = w * t * (2 * v.oxs * c * t + v.ozs * C) / (q * q * q) * r * g;
  const double oh = (v.st * aS * c + mu * C) / std::sqrt(M2);
  return {val, val * std::pow(1 - oh, 5)};
}

}  // namespace

TEST_CASE(
    "Beckmann-family nodes: the SIMD lanes give the scalar form's bits, both the "
    "straightforward integrand's value to 1e-12 relative",
    "[integrate][fixed-rule][beckmann-nodes]") {
  std::mt19937_64 rng(0x32B2);
  std::uniform_real_distribution<double> u01(0, 1);
  double worst = 0;
  int nodes = 0;
  for (double mu : {0.0, 1e-9, 1e-4, 0.01, 0.2, 0.5, 0.9, 1.0})
    for (double alpha : {1e-6, 1e-3, 0.02, 0.1, 0.3, 0.6, 0.95, 1.0})
      for (int model = 0; model < 4; ++model) {
        const BeckmannNodeView v = ViewOf(mu, alpha, model >= 2, model % 2 == 1);
        for (double c : {-1.0, -0.6, -1e-3, 0.0, 0.3, 0.999, 1.0}) {
          // 33 nodes (an odd count: the last takes the scalar form): t from 0 to 1, ends included.
          std::vector<double> t(33), w(33);
          for (int i = 0; i < 33; ++i) {
            t[i] = i == 0 ? 0 : i == 32 ? 1 : i < 8 ? 1 - std::pow(u01(rng), 4) : u01(rng);
            w[i] = 0.01 + u01(rng);
          }
          INFO("mu " << mu << " alpha " << alpha << " model " << model << " c " << c);
          // Every path (AVX-512F on and off) and every mix of lanes: 33 = 4 x 8 + 1,
          // 31 = 3 x 8 + 4 + 2 + 1, 14 = 8 + 4 + 2 nodes.
          for (bool avx512 : {true, false})
            for (int n : {33, 31, 14}) {
              dielectric_simd::SetEnabled(avx512);
              double v1 = 0, b1 = 0, v2 = 0, b2 = 0;
              AddBeckmannNodes(v, c, t.data(), w.data(), n, v1, b1);
              AddBeckmannNodesScalar(v, c, t.data(), w.data(), n, v2, b2);
              INFO("AVX-512F " << avx512 << " nodes " << n);
              CHECK(v1 == v2);
              CHECK(b1 == b2);
            }
          dielectric_simd::SetEnabled(true);
          for (int i = 0; i < 33; ++i) {
            double vs = 0, bs = 0;
            AddBeckmannNodesScalar(v, c, &t[i], &w[i], 1, vs, bs);
            const std::array<double, 2> ref = Straightforward(v, c, t[i], w[i]);
            // B = V (1 - o.h)^5 is held to V's scale: 1 - o.h cancels near o.h = 1.
            for (int ch = 0; ch < 2; ++ch) {
              const double got = ch == 0 ? vs : bs, bound = 1e-12 * std::abs(ref[0]) + 1e-300;
              const double err = std::abs(got - ref[ch]);
              if (std::abs(ref[0]) > 1e-290) worst = std::max(worst, err / std::abs(ref[0]));
              INFO("t " << t[i] << " channel " << ch << " " << got << " vs " << ref[ch]);
              CHECK(err <= bound);
            }
            ++nodes;
          }
        }
      }
  WARN("worst difference from the straightforward integrand, relative to V, " << worst << " over "
                                                                              << nodes << " nodes");
  CHECK(nodes > 10000);
}
