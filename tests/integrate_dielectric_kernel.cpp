// The exit side's E_avg_R by one kernel per roughness (integrate/dielectric_kernel.h):
// E_avg_R(alpha, eta') = int_0^1 F(c, eta') c K_alpha(c) dc with K_alpha independent of eta'.
// The kernel's fixed rule stays within 3e-7 of its adaptive reference on a grid of (c, roughness);
// its interpolant on [0.4, 1] within 1e-7 of the rule between the nodes; the route agrees with
// the mu rule over E_R walks (the route it replaced, itself held to adaptive quadrature) and
// with adaptive quadrature of the average on held-out points, within kDielectricKernelBound;
// and a roughness row of the exit table's 24 eta' costs under a tenth of the mu rule's
// evaluations. A kernel row and an entering average column, whose nodes run on the arena's
// threads, have the bits and counts of one thread's for any thread count.
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/dielectric_kernel.h"
#include "baker/models/roughness.h"

using namespace kiln;

namespace {

double AlphaOf(double r) { return std::max(AlphaFromPerceptual(r), MinAlpha); }

}  // namespace

TEST_CASE("the reflectance kernel's fixed rule is within 3e-7 of adaptive quadrature",
          "[dielectric][glass-rule]") {
  double worst = 0;
  for (double r : {0.02, 0.1, 0.3, 0.6, 1.0})
    for (double c : {1e-4, 0.003, 0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.9999, 1.0}) {
      IntegrationStats st;
      const double a = DielectricReflectanceKernel(c, AlphaOf(r), 1e-10, st);
      const double f = FixedRuleDielectricReflectanceKernel(c, AlphaOf(r));
      INFO("c " << c << " r " << r);
      CHECK(std::abs(f - a) < 3e-7);
      worst = std::max(worst, std::abs(f - a));
    }
  std::printf("glass reflectance kernel: worst %.3g from adaptive\n", worst);
  // The smooth limit: K -> 2 (E_avg_R -> F_avg) away from grazing.
  CHECK(FixedRuleDielectricReflectanceKernel(0.5, 1e-6) == Approx(2).margin(1e-9));
}

TEST_CASE("the reflectance kernel's interpolant holds the rule between its nodes",
          "[dielectric][glass-rule]") {
  for (double r : {0.05, 0.45, 1.0}) {
    const DielectricReflectanceKernelRow row = MakeDielectricReflectanceKernelRow(AlphaOf(r));
    for (double c = kDielectricKernelSplit; c <= 1; c += 0.0173) {
      INFO("c " << c << " r " << r);
      CHECK(std::abs(row.At(c) - FixedRuleDielectricReflectanceKernel(c, AlphaOf(r))) < 1e-7);
    }
  }
}

TEST_CASE("the kernel route's E_avg_R agrees with the mu rule over E_R walks",
          "[dielectric][glass-rule]") {
  // Held out: roughness from the smooth corner to 1, eta' from 1/3 to 1/1.1 with the crossing of
  // mu_c and mu = eta' (1/sqrt 2).
  double worst = 0;
  for (double r : {0.004, 0.05, 0.263, 0.5, 0.77, 1.0})
    for (double eta : {1 / 3.0, 0.384, 0.55, 1 / std::sqrt(2.0), 0.8, 0.9, 1 / 1.1}) {
      const double k = KernelDielectricExitAverageR(AlphaOf(r), eta);
      const double m = FixedRuleDielectricExitAverageR(AlphaOf(r), eta, kDielectricAverageNodes,
                                                       static_cast<long long*>(nullptr));
      INFO("r " << r << " eta " << eta);
      CHECK(std::abs(k - m) < kDielectricKernelBound);
      worst = std::max(worst, std::abs(k - m));
    }
  std::printf("glass E_avg_R exit, kernel against mu rule: worst %.3g\n", worst);
}

TEST_CASE("the kernel route's E_avg_R is within its bound of adaptive quadrature",
          "[dielectric][glass-rule]") {
  for (const auto& p : {std::array<double, 2>{0.263, 0.384}, std::array<double, 2>{0.77, 0.62}}) {
    IntegrationStats st;
    const double a = DielectricAlbedoAverage(AlphaOf(p[0]), p[1], 1e-8, st)[0];
    INFO("r " << p[0] << " eta " << p[1]);
    CHECK(std::abs(KernelDielectricExitAverageR(AlphaOf(p[0]), p[1]) - a) < kDielectricKernelBound);
  }
}

TEST_CASE("a kernel row gives every eta' the same bits, remembered or not, and costs little",
          "[dielectric][glass-rule]") {
  const double alpha = AlphaOf(0.37);
  const DielectricReflectanceKernelRow row = MakeDielectricReflectanceKernelRow(alpha);
  long long kernelEvals = 0, muEvals = 0;
  for (int e = 0; e < 24; ++e) {
    const double eta = 1 / 3.0 + (1 / 1.1 - 1 / 3.0) * e / 23;
    const double direct = DielectricExitAverageRFromKernel(row, eta);
    long long evals = 0;
    const double cached = KernelDielectricExitAverageR(alpha, eta, &evals);
    CHECK(std::memcmp(&direct, &cached, sizeof direct) == 0);
    CHECK(evals == row.evals);  // a point alone costs the row
    if (e % 8 == 0) FixedRuleDielectricExitAverageR(alpha, eta, kDielectricAverageNodes, &muEvals);
  }
  kernelEvals = row.evals;
  // A row of 24 eta' by the mu rule walks 24 points (3 sampled here, times 8).
  CHECK(static_cast<double>(kernelEvals) < 0.1 * 8 * static_cast<double>(muEvals));
  std::printf("glass E_avg_R exit: kernel row %lld evaluations, mu rule ~%lld for 24 eta'\n",
              kernelEvals, 8 * muEvals);
}

TEST_CASE("a kernel row and an average column have one thread's bits on any thread count",
          "[dielectric][glass-rule][threads]") {
  const double alpha = AlphaOf(0.43);
  const double etas[3] = {1.1, 1.52, 2.9};
  auto row = [&](int threads) {
    tbb::task_arena arena(threads);
    DielectricReflectanceKernelRow r;
    arena.execute([&] { r = MakeDielectricReflectanceKernelRow(alpha); });
    return r;
  };
  auto column = [&](int threads, long long* evals) {
    tbb::task_arena arena(threads);
    std::array<std::array<double, 2>, 3> out{};
    arena.execute([&] {
      FixedRuleDielectricAlbedoAverageColumn(alpha, etas, 3, kDielectricAverageNodes, out.data(),
                                             evals);
    });
    return out;
  };
  const DielectricReflectanceKernelRow one = row(1);
  long long oneEvals = 0;
  const std::array<std::array<double, 2>, 3> oneColumn = column(1, &oneEvals);
  REQUIRE(one.evals > 0);
  REQUIRE(oneEvals > 0);
  for (int threads : {2, 4}) {
    INFO(threads << " threads");
    const DielectricReflectanceKernelRow r = row(threads);
    CHECK(r.evals == one.evals);
    CHECK(std::memcmp(&r.lowIntegral, &one.lowIntegral, sizeof r.lowIntegral) == 0);
    REQUIRE(r.k.size() == one.k.size());
    CHECK(std::memcmp(r.k.data(), one.k.data(), r.k.size() * sizeof(double)) == 0);
    CHECK(std::memcmp(r.t.data(), one.t.data(), r.t.size() * sizeof(double)) == 0);
    long long evals = 0;
    const std::array<std::array<double, 2>, 3> c = column(threads, &evals);
    CHECK(evals == oneEvals);
    CHECK(std::memcmp(c.data(), oneColumn.data(), sizeof c) == 0);
  }
}
