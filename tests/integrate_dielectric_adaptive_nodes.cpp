// The glass adaptive references' inner integrand a Gauss-Kronrod panel at a time
// (baker/integrate/dielectric_adaptive_nodes.*): where the CPU has AVX-512F the E pair's and the
// BTDF pair's walks evaluate a panel's 15 azimuth nodes in eight lanes, and every reference
// value, error estimate and evaluation count must keep the scalar walk's bits. Node by node on
// rings across the domain (entering and exit side, grazing and normal views, roughness 1e-4 .. 1,
// azimuths at the critical cosine, the reflected and refracted horizons and the visibility end,
// each with its neighbouring doubles), then whole walks.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "baker/integrate/dielectric_adaptive_nodes.h"
#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/integrate/dielectric_simd.h"
#include "dielectric_simd_paths.h"
#include "baker/math/constants.h"
#include "baker/math/quadrature.h"

using namespace kiln;
using kiln::test::BothPaths;

namespace {

template <class T>
bool SameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

const double kMus[] = {0.0, 1e-6, 0.013, 0.2, 0.5, 0.77, 0.999, 1.0};
const double kAlphas[] = {1e-4, 1e-3, 0.05, 0.3, 0.7, 1.0};
/// Exit side (eta < 1: total internal reflection), near 1 and entering.
const double kEtas[] = {1 / 3.0, 1 / 1.5, 1 / 1.1, 0.999, 1.0001, 1.1, 1.5, 3.0};
/// Microfacet polar angles: the normal, tiny, the bulk and near the horizon.
const double kThetas[] = {0.0, 1e-7, 0.01, 0.3, 0.8, 1.2, 1.5, 1.5707963};

/// The azimuth boundaries of a test ring: a uniform sweep of [0, pi] with both ends, and each
/// threshold of the integrand (c = c0: visibility, the critical cosine, the Fresnel layer, the
/// reflected ray's horizon) with its neighbouring doubles, sorted (panels of zero width too).
std::vector<double> Azimuths(double mu, double eta, PolarParam h) {
  std::vector<double> phis;
  for (int i = 0; i <= 40; ++i) phis.push_back(Pi * i / 40);
  const double st = std::sqrt((1 - mu) * (1 + mu)), A = mu * h.cosTheta, B = st * h.sinTheta;
  const double eps = std::sqrt(std::abs((eta - 1) * (eta + 1)));
  const double c0s[] = {0.0, eta < 1 ? std::sqrt(1 - eta * eta) : 0.0, eps, 4 * eps,
                        h.cosTheta > 0 ? mu / (2 * h.cosTheta) : 0.0};
  for (double c0 : c0s) {
    if (!(B > 0)) break;
    const double cp = (c0 - A) / B;
    if (!(cp > -1 && cp < 1)) continue;
    const double phi = std::acos(cp);
    phis.push_back(std::nextafter(phi, 0.0));
    phis.push_back(phi);
    phis.push_back(std::nextafter(phi, 4.0));
  }
  std::sort(phis.begin(), phis.end());
  return phis;
}

/// The inner variable at every panel boundary k of np (the azimuths themselves: the thresholds
/// and their neighbours) and at the 15 Gauss-Kronrod nodes of every panel [k, k + 1].
std::vector<double> InnerNodes(int np) {
  std::vector<double> ys;
  for (int k = 0; k + 1 < np; ++k) {
    ys.push_back(k);
    double x[15];
    GaussKronrod15Nodes(k, k + 1, x);
    ys.insert(ys.end(), x, x + 15);
  }
  ys.push_back(np - 1);
  return ys;
}

/// Every node of InnerNodes through ring h's boundaries Azimuths, in calls of 1 .. 16 nodes (every
/// lane count); checks each node's bits on both paths.
template <class RingNodes>
void CheckRing(RingNodes ringNodes, double mu, double alpha, double eta, PolarParam h,
               long long* nodes) {
  const std::vector<double> phis = Azimuths(mu, eta, h);
  const int np = static_cast<int>(phis.size());
  const std::vector<double> ys = InnerNodes(np);
  const int total = static_cast<int>(ys.size());
  int start = 0, mismatches = 0;
  std::array<Channels<2>, 16> on, off;
  for (int call = 0; start < total; ++call) {
    const int n = std::min(1 + call % 16, total - start);
    dielectric_simd::SetEnabled(true);
    ringNodes(mu, alpha, eta, h, ys.data() + start, phis.data(), np, n, on.data());
    dielectric_simd::SetEnabled(false);
    ringNodes(mu, alpha, eta, h, ys.data() + start, phis.data(), np, n, off.data());
    dielectric_simd::SetEnabled(true);
    for (int i = 0; i < n; ++i) {
      if (SameBits(on[i], off[i])) continue;
      if (mismatches++ == 0)
        UNSCOPED_INFO("first at y " << ys[start + i] << ": " << on[i][0] << " " << on[i][1]
                                    << " vs " << off[i][0] << " " << off[i][1]);
    }
    start += n;
  }
  *nodes += total;
  INFO("mu " << mu << " alpha " << alpha << " eta " << eta << " cos_m " << h.cosTheta);
  REQUIRE(mismatches == 0);
}

}  // namespace

TEST_CASE("the glass adaptive references' nodes in lanes are the scalar integrand's bits",
          "[glass-adaptive]") {
  long long nodes = 0;
  for (double mu : kMus)
    for (double alpha : kAlphas)
      for (double eta : kEtas)
        for (double theta : kThetas) {
          const PolarParam h{std::sin(theta), std::cos(theta)};
          CheckRing(dielectric_adaptive::AlbedoRingNodes, mu, alpha, eta, h, &nodes);
          if (eta >= 1) CheckRing(dielectric_adaptive::BtdfRingNodes, mu, alpha, eta, h, &nodes);
        }
  CHECK(nodes > 3000000);
}

TEST_CASE("the glass adaptive references keep the scalar walk's values, estimates and counts",
          "[glass-adaptive]") {
  struct Result {
    std::array<double, 2> value;
    double errorEstimate;
    long long evals;
  };
  const double mus[] = {0.0, 0.013, 0.5, 1.0};
  const double alphas[] = {1e-4, 0.3, 1.0};
  const double etas[] = {1 / 1.5, 1 / 1.1, 1.1, 1.5};
  IntegrationOptions opt;
  opt.tol = 1e-8;
  for (double mu : mus)
    for (double alpha : alphas)
      for (double eta : etas) {
        INFO("mu " << mu << " alpha " << alpha << " eta " << eta);
        // The walk `walk` (DielectricAlbedo or DielectricBtdfPair) by both paths: the same bits.
        auto checkWalk = [&](auto walk) {
          const auto [lanes, scalar] = BothPaths([&] {
            IntegrationStats stats;
            const std::array<double, 2> v = walk(mu, alpha, eta, opt, stats);
            return Result{v, stats.errorEstimate, stats.evals};
          });
          CHECK(SameBits(lanes.value, scalar.value));
          CHECK(SameBits(lanes.errorEstimate, scalar.errorEstimate));
          CHECK(lanes.evals == scalar.evals);
        };
        checkWalk(DielectricAlbedo);
        if (eta >= 1) checkWalk(DielectricBtdfPair);
      }
}
