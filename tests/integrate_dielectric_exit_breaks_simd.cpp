// The exit walk's inner breaks eight rings at once (dielectric_simd::PhiBreaks8, the AVX-512F
// path) against the scalar breaks the portable path computes ring by ring
// (dielectric_exit_breaks::PhiBreaks): the same boundaries, bit for bit, and the same count, for
// every ring of a view (lanes 1 .. 8 of a call), on views of both sides of the exit range (eta'
// 1/3 .. 0.999, mu 0 .. 1, roughness 1/39^2 .. 1) and at the rings where the scalar code takes
// its special branches: sin_m = 0 (the whole circle), nothing visible (an empty ring) and the
// refracted layer cut at its most thresholds; with and without the reflected ray's thresholds
// below c_crit (ExitBreakConsts::cDrop, the exit walk's complement form).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "baker/integrate/dielectric_exit_breaks.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/models/microfacet.h"

using namespace kiln;

namespace {

/// The members dielectric_exit_breaks' PhiBreaks and ConstsOf read (dielectric_albedo.cpp's
/// View, MakeView's formulas).
struct TestView {
  double mu, st, eta, eta2m1, cCrit;
  int ncs = 2;
  double cs[2];
  GGXDistribution dist;
  double maskingRatio = 4;
  bool reflectOnly = false;
};

TestView ViewOf(double mu, double roughness, double eta) {
  TestView v;
  v.mu = mu;
  v.st = std::sqrt(std::max(0.0, (1 - mu) * (1 + mu)));
  v.eta = eta;
  v.eta2m1 = (eta - 1) * (eta + 1);
  v.cCrit = std::sqrt(-v.eta2m1);
  v.cs[0] = std::sqrt(std::abs(v.eta2m1));
  v.cs[1] = 4 * v.cs[0];
  v.dist.alpha = std::max(roughness * roughness, 1e-7);
  return v;
}

/// What the rings checked reached: how many, and those that took the special branches.
struct Coverage {
  long rings = 0, wholeCircle = 0, empty = 0, most = 0;  ///< most: the largest count
  long dropped = 0;                                      ///< rings that lost a boundary to k.cDrop
};

/// PhiBreaks8 on rings h[0 .. m-1] with the view's thresholds k against the scalar PhiBreaks of
/// each, bit for bit.
void CheckRings(const TestView& v, const dielectric_exit_breaks::ExitBreakConsts& k,
                const PolarParam* h, int m, Coverage* cov) {
  const dielectric_simd::ExitPhiView pv{v.mu,      v.st,        v.cCrit,      v.eta2m1,
                                        v.eta < 1, v.ncs,       k.nReflected, k.nRefracted,
                                        v.cs,      k.reflected, k.refracted,  k.cDrop};
  double cosM[8] = {}, sinM[8] = {};
  for (int l = 0; l < m; ++l) {
    cosM[l] = h[l].cosTheta;
    sinM[l] = h[l].sinTheta;
  }
  double phis[8][dielectric_simd::kMaxRingPhis];
  int np[8];
  dielectric_simd::PhiBreaks8(pv, cosM, sinM, m, phis, np);
  for (int l = 0; l < m; ++l) {
    double scalar[dielectric_simd::kMaxRingPhis];
    const int n = dielectric_exit_breaks::PhiBreaks(v, k, h[l], scalar);
    INFO("mu " << v.mu << " alpha " << v.dist.alpha << " eta " << v.eta << " cos_m "
               << h[l].cosTheta << " lane " << l << " of " << m);
    REQUIRE(np[l] == n);
    CHECK(std::memcmp(phis[l], scalar, sizeof(double) * n) == 0);
    ++cov->rings;
    cov->wholeCircle += !(v.st * h[l].sinTheta > 0) && n == 2;
    cov->empty += n == 0;
    cov->most = std::max(cov->most, static_cast<long>(n));
    dielectric_exit_breaks::ExitBreakConsts all = k;
    all.cDrop = -INFINITY;
    cov->dropped += dielectric_exit_breaks::PhiBreaks(v, all, h[l], scalar) > n;
  }
}

}  // namespace

TEST_CASE("the eight-ring inner breaks of the exit walk give the scalar breaks' bits",
          "[dielectric][glass-rule]") {
  if (!dielectric_simd::Enabled()) {
    WARN("no AVX-512F on this CPU: PhiBreaks8 is not run (the portable path never calls it)");
    return;
  }
  Coverage cov;
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> unit(0, 1);
  const double etas[] = {1.0 / 3, 0.5, 1 / 1.5, 0.9, 0.999};
  const double mus[] = {0.0, 1e-6, 0.01, 0.3, 0.745, 0.9, 0.999, 1.0};
  const double roughness[] = {1.0 / (39 * 39), 0.02, 0.2, 0.6, 1.0};
  for (double eta : etas)
    for (double mu : mus)
      for (double r : roughness) {
        const TestView v = ViewOf(mu, r, eta);
        // Rings from v = 1 (sin_m = 0) down to the GGX tail, and a seeded sample; every lane count.
        PolarParam h[64];
        int n = 0;
        for (double vv : {1.0, 1 - 1e-12, 0.5, 1e-3, 1e-9}) h[n++] = v.dist.FromV(vv);
        while (n < 36) h[n++] = v.dist.FromV(unit(rng));
        // Every threshold, and without the reflected ray's below c_crit - 1e-13 (the exit walk's
        // complement form, dielectric_albedo.cpp's kTirMargin).
        dielectric_exit_breaks::ExitBreakConsts k = dielectric_exit_breaks::ConstsOf(v);
        for (int m = 1, at = 0; at + m <= n; at += m, m = m % 8 + 1)
          CheckRings(v, k, h + at, m, &cov);
        k.cDrop = v.cCrit - 1e-13;
        for (int m = 1, at = 0; at + m <= n; at += m, m = m % 8 + 1)
          CheckRings(v, k, h + at, m, &cov);
      }
  // Layers longer than a view's (the same code path, more thresholds): the refracted layer runs
  // into the limit of kMaxThresholds thresholds a ring.
  const TestView v = ViewOf(0.5, 0.3, 0.9);
  dielectric_exit_breaks::ExitBreakConsts k;
  k.nReflected = 16;
  for (int i = 0; i < k.nReflected; ++i) k.reflected[i] = 0.01 * (i + 1);
  k.nRefracted = dielectric_exit_breaks::kMaxLayer;
  for (int i = 0; i < k.nRefracted; ++i) k.refracted[i] = 0.1 + 0.0125 * i;
  PolarParam h[40];
  for (int i = 0; i < 40; ++i) h[i] = v.dist.FromV(0.02 + 0.96 * i / 39);
  const long before = cov.most;
  cov.most = 0;
  for (int at = 0; at < 40; at += 8) CheckRings(v, k, h + at, 8, &cov);
  k.cDrop = v.cCrit - 1e-13;  // dropped thresholds still count towards the limit
  for (int at = 0; at < 40; at += 8) CheckRings(v, k, h + at, 8, &cov);
  const long crafted = cov.most;
  cov.most = before;
  INFO("rings " << cov.rings << ", whole circle " << cov.wholeCircle << ", empty " << cov.empty
                << ", most breaks " << cov.most << ", dropped " << cov.dropped);
  CHECK(cov.dropped > 0);
  CHECK(cov.wholeCircle > 0);
  CHECK(cov.empty > 0);
  CHECK(cov.most >= 16);
  INFO("crafted layers: most breaks " << crafted);
  CHECK(crafted >= 2 + dielectric_exit_breaks::kMaxThresholds - 2);
}
