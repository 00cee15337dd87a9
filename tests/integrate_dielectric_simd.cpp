// The glass walks' AVX-512F paths (baker/integrate/dielectric_simd*): where the CPU has AVX-512F
// the fixed rule's eta columns and the exit side's per-point walk run eight lanes at a time; the
// tables must not depend on it. Each path must give the portable path's bits, at the points the
// bake and the lookup-error search evaluate (columns of 1 .. 40 etas of the E pair and of the BTDF
// pair, the exit side's E pair and E_R alone, the averages), at the corners of the domain (mu 0
// and 1, roughness near 0 and 1, eta at both ends of both sides) and at the exit side's thresholds
// (mu_c and its neighbours, mu = eta). The exit walk fuses multiply-adds and sums in eight lanes
// on both paths (std::fma on the portable one, by the CPU's FMA instructions or by libm), so it too
// must match bit for bit, all three ways.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/integrate/dielectric_simd.h"
#include "dielectric_simd_paths.h"
#include "baker/models/roughness.h"

using namespace kiln;
using kiln::test::BothPaths;

namespace {

/// Runs f by the AVX-512F paths, by the portable exit ring with the CPU's FMA instructions and by
/// it with libm's std::fma, and restores the defaults; returns the three results.
template <class F>
auto ExitPaths(F&& f) {
  auto [avx, fmaInstr] = BothPaths(f);
  dielectric_simd::SetEnabled(false);
  dielectric_simd::SetPortableFmaInstructions(false);
  auto libm = f();
  dielectric_simd::SetPortableFmaInstructions(true);
  dielectric_simd::SetEnabled(true);
  return std::make_tuple(avx, fmaInstr, libm);
}

template <class T>
bool SameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

const double kMus[] = {0.0, 1e-6, 0.013, 0.2, 0.5, 0.77, 0.999, 1.0};
const double kRoughness[] = {1.0 / (39 * 39), 0.05, 0.3, 0.7, 1.0};

/// Turns the AVX-512F paths on (a warning where the CPU has none: the comparisons then hold the
/// portable path to itself) and returns the tuned rule's options.
DielectricRuleOptions FastPathsOn() {
  dielectric_simd::SetEnabled(true);
  if (!dielectric_simd::Enabled())
    WARN(
        "no AVX-512F on this CPU: both runs take the portable path (the test compares it with "
        "itself)");
  return TunedDielectricRuleOptions();
}

}  // namespace

TEST_CASE("the AVX-512F glass walks give the portable walks' bits", "[dielectric][glass-rule]") {
  const DielectricRuleOptions opt = FastPathsOn();
  int compared = 0;
  SECTION("entering columns of 1, 2, 7, 8, 9, 16 and 40 etas") {
    std::vector<double> etas;
    for (int k = 0; k < 40; ++k) etas.push_back(1.1 + 1.9 * (k / 39.0) * (k / 39.0));
    for (int n : {1, 2, 7, 8, 9, 16, 40})
      for (double mu : kMus)
        for (double r : kRoughness) {
          const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
          const int first = n == 40 ? 0 : (40 - n) / 2;
          auto run = [&] {
            std::vector<std::array<double, 2>> col(n);
            long long evals = 0;
            FixedRuleDielectricAlbedoColumn(mu, alpha, etas.data() + first, n, opt, col.data(),
                                            &evals);
            return std::make_pair(col, evals);
          };
          const auto [on, off] = BothPaths(run);
          INFO("n " << n << " mu " << mu << " r " << r);
          CHECK(on.second == off.second);
          for (int e = 0; e < n; ++e) CHECK(SameBits(on.first[e], off.first[e]));
          ++compared;
        }
  }
  SECTION("the BTDF pair's columns of 1, 2, 7, 8, 9 and 40 etas") {
    std::vector<double> etas;
    for (int k = 0; k < 40; ++k) etas.push_back(1.1 + 1.9 * (k / 39.0) * (k / 39.0));
    for (int n : {1, 2, 7, 8, 9, 40})
      for (double mu : kMus)
        for (double r : kRoughness) {
          const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
          const int first = n == 40 ? 0 : (40 - n) / 2;
          auto run = [&] {
            std::vector<std::array<double, 2>> col(n);
            long long evals = 0;
            FixedRuleDielectricBtdfColumn(mu, alpha, etas.data() + first, n,
                                          TunedDielectricBtdfRuleOptions(), col.data(), &evals);
            return std::make_pair(col, evals);
          };
          const auto [on, off] = BothPaths(run);
          INFO("n " << n << " mu " << mu << " r " << r);
          CHECK(on.second == off.second);
          for (int e = 0; e < n; ++e) CHECK(SameBits(on.first[e], off.first[e]));
          ++compared;
        }
  }
  SECTION("the averages, both sides") {
    for (double eta : {1.0 / 3, 0.75, 1.0 / 1.1, 1.1, 1.7, 3.0})
      for (double r : {0.05, 0.5, 1.0}) {
        const double alpha = AlphaFromPerceptual(r);
        auto avg = [&] { return FixedRuleDielectricAlbedoAverage(alpha, eta, 6, nullptr); };
        const auto [on, off] = BothPaths(avg);
        INFO("eta " << eta << " r " << r);
        CHECK(SameBits(on, off));
        ++compared;
      }
  }
  CHECK(compared > 0);
}

TEST_CASE("the AVX-512F exit walk gives the portable exit walk's bits",
          "[dielectric][glass-rule]") {
  const DielectricRuleOptions opt = FastPathsOn();
  int compared = 0;
  // The exit side's E pair and E_R alone, and the entering side below 1.1 (the same walk), at the
  // corners and at the exit side's thresholds: mu_c and its neighbours, mu = eta.
  for (double eta : {1.0 / 3, 0.5, 0.62, 0.9, 1.0 / 1.1, 0.999, 1.0001, 1.05}) {
    std::vector<double> mus(std::begin(kMus), std::end(kMus));
    if (eta < 1) {
      const double muC = std::sqrt((1 - eta) * (1 + eta));
      for (double d : {0.0, -1e-4, 1e-4, 0.01}) mus.push_back(std::min(1.0, muC + d));
      mus.push_back(eta);
    }
    for (double mu : mus)
      for (double r : kRoughness) {
        const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
        auto pair = [&] {
          long long evals = 0;
          return std::make_pair(FixedRuleDielectricAlbedo(mu, alpha, eta, opt, &evals), evals);
        };
        const auto [on, off, libm] = ExitPaths(pair);
        auto reflect = [&] { return FixedRuleDielectricReflectance(mu, alpha, eta, opt); };
        const auto [ron, roff, rlibm] = ExitPaths(reflect);
        INFO("eta " << eta << " mu " << mu << " r " << r << ": E_R " << on.first[0] << " "
                    << off.first[0] << ", E_T " << on.first[1] << " " << off.first[1]
                    << ", E_R alone " << ron << " " << roff);
        CHECK(on.second == off.second);
        CHECK(SameBits(on.first[0], off.first[0]));
        CHECK(SameBits(on.first[1], off.first[1]));
        CHECK(SameBits(ron, roff));
        CHECK(SameBits(libm.first, off.first));
        CHECK(SameBits(rlibm, roff));
        ++compared;
      }
  }
  CHECK(compared == 470);
}
