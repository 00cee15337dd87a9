// The glass tables' fixed rule (baker/integrate/dielectric_albedo.cpp) on a held-out grid that
// covers both sides of the interface and every threshold the rule puts panels at: eta in [1/3, 1)
// and (1, 3], eta = 1 exactly and 1 -+ 1e-3 (the Fresnel layer sqrt|eta^2 - 1| = 0.045 at
// grazing microfacets), mu = 0, 1e-6 and 1, the critical cosine mu_c = sqrt(1 - eta^2) and its
// neighbours (the kink of total internal reflection), mu = eta (eta < 1: where the near-vertical
// microfacets leave total internal reflection), GGX alpha from 1e-6 (roughness 1e-3) to 1. Against
// the adaptive reference (at 1000x below the bound): within kDielectricRuleBound on both channels,
// as the bake runs it and by the portable walk (the path of a CPU without AVX-512F, checked here
// on any CPU; tests/integrate_dielectric_simd.cpp holds the two to the same bits), on the grid's
// edges and worst points and a seeded stratified sample of the rest (the dense grid as a [long]
// test). And the identities: E_R + E_T <= 1 (single scattering loses energy), with equality and
// E_R = F(mu) in the smooth limit (alpha -> 0, the rule at alpha = 1e-6 within 1e-4 of it away from
// mu_c), and the loss 1 - E_R - E_T grows with roughness (for mu >= 0.3: at grazing views the
// masking layer mu ~ alpha makes the smoothest lobes lose the most).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/dielectric_simd.h"
#include "baker/models/fresnel.h"
#include "baker/models/roughness.h"
#include "grid_sample.h"

using namespace kiln;

namespace {

const double kEtas[] = {1 / 3.0, 0.5, 0.75, 0.97, 0.999, 1.0, 1.001, 1.02, 1.25, 1.7, 2.4, 3.0};
const double kRoughness[] = {1e-3, 0.05, 0.2, 0.45, 0.8, 1.0};

/// The mu of the grid at eta: the ends, a spread, and for eta < 1 mu_c, its neighbours and eta.
std::vector<double> MusAt(double eta) {
  std::vector<double> mus = {0.0, 1e-6, 0.03, 0.3, 0.6, 0.88, 1.0};
  if (eta < 1) {
    const double muC = std::sqrt((1 - eta) * (1 + eta));
    for (double d : {0.0, -1e-4, 1e-4, -0.01, 0.01}) mus.push_back(std::clamp(muC + d, 0.0, 1.0));
    mus.push_back(eta);
  }
  return mus;
}

/// The adaptive reference, to 1000x below the bound it checks.
std::array<double, 2> Adaptive(double mu, double alpha, double eta) {
  IntegrationOptions opt;
  opt.tol = kDielectricRuleBound / 1000;
  opt.maxPanels = 2000;
  IntegrationStats stats;
  return DielectricAlbedo(mu, alpha, eta, opt, stats);
}

/// The (eta, mu) rows of the held-out grid, eta slowest, and the roughness its columns.
struct Row {
  double eta, mu;
  bool whole;  // an edge: visited at every roughness
};

/// The rows: (eta, mu) for mu in MusAt(eta). Whole: the ends eta = 1/3 and 3, eta = 1 and
/// 1 -+ 1e-3, and at every eta mu = 0, 1 and the critical cosine mu_c.
std::vector<Row> Rows() {
  std::vector<Row> rows;
  for (double eta : kEtas)
    for (double mu : MusAt(eta)) {
      const bool edgeEta = eta == 1 / 3.0 || eta == 3.0 || std::abs(eta - 1) <= 1e-3;
      const double muC = eta < 1 ? std::sqrt((1 - eta) * (1 + eta)) : -1;
      rows.push_back({eta, mu, edgeEta || mu == 0 || mu == 1 || mu == muC});
    }
  return rows;
}

/// Where the rule errs most on the dense held-out grid (the [long] test below), as (roughness,
/// row) indices, always visited. With the exit side's own node counts: E_R at mu_c + 0.01,
/// roughness 0.45, eta = 0.5 (3.0e-7), at mu = 0.03, roughness 0.8, eta = 1/3 (2.9e-7) and at
/// mu_c - 1e-4, roughness 0.45, eta = 0.5 (2.7e-7); E_R at mu = 1, roughness 0.2, eta = 0.5 was
/// 4.8e-7 with 10 outer nodes in the second class. Before them, all at roughness 0.45 next to
/// the critical cosine mu_c: eta = 0.5 at mu_c + 0.01 (2.7e-7), mu_c - 1e-4 (2.7e-7) and mu_c +
/// 1e-4 (2.5e-7); eta = 0.75, 0.97 and 0.999 at mu_c - 0.01, mu_c - 0.01 and mu_c + 0.01 (2.2e-7,
/// 2.0e-7, 1.9e-7).
const std::vector<test::GridIndex> kHeldOutWorst = {{2, 19}, {4, 2},  {3, 24}, {3, 21},
                                                    {3, 22}, {3, 36}, {3, 49}, {3, 63}};

/// The points the default test visits: the roughness ends and the whole rows at every roughness,
/// one point of each 3 x 3 block of the rest (seeded), and kHeldOutWorst. block 1: dense.
std::vector<test::GridIndex> HeldOutPoints(const std::vector<Row>& rows, size_t block) {
  std::vector<size_t> whole;
  for (size_t k = 0; k < rows.size(); ++k)
    if (rows[k].whole) whole.push_back(k);
  return test::StratifiedGrid(std::size(kRoughness), rows.size(), block, 0x4E1D, {}, whole,
                              kHeldOutWorst);
}

/// The tuned rule by the portable walk (the AVX-512F paths off): what a CPU without AVX-512F
/// bakes, held to Adaptive here on any CPU.
std::array<double, 2> PortableRule(double mu, double alpha, double eta) {
  dielectric_simd::SetEnabled(false);
  const std::array<double, 2> f =
      FixedRuleDielectricAlbedo(mu, alpha, eta, TunedDielectricRuleOptions(), nullptr);
  dielectric_simd::SetEnabled(true);
  return f;
}

/// The tuned rule, as the bake runs it and by the portable walk, within kDielectricRuleBound of
/// Adaptive at HeldOutPoints(block).
void CheckHeldOutGrid(size_t block) {
  double worst = 0;
  std::vector<long long> perPoint;
  const std::vector<Row> rows = Rows();
  for (const test::GridIndex& p : HeldOutPoints(rows, block)) {
    const double eta = rows[p.j].eta, mu = rows[p.j].mu, r = kRoughness[p.i];
    const double alpha = std::max(AlphaFromPerceptual(r), MinAlpha);
    long long e = 0;
    const std::array<double, 2> f =
        FixedRuleDielectricAlbedo(mu, alpha, eta, TunedDielectricRuleOptions(), &e);
    const std::array<double, 2> portable = PortableRule(mu, alpha, eta);
    const std::array<double, 2> a = Adaptive(mu, alpha, eta);
    perPoint.push_back(e);
    for (int c = 0; c < 2; ++c) {
      INFO("mu " << mu << " r " << r << " eta " << eta << " channel " << c << ": fixed " << f[c]
                 << " portable " << portable[c] << " adaptive " << a[c]);
      CHECK(std::abs(f[c] - a[c]) < kDielectricRuleBound);
      CHECK(std::abs(portable[c] - a[c]) < kDielectricRuleBound);
      worst = std::max({worst, std::abs(f[c] - a[c]), std::abs(portable[c] - a[c])});
    }
  }
  std::sort(perPoint.begin(), perPoint.end());
  std::printf(
      "glass rule, held-out grid: worst %.3g over %zu points; evaluations median %lld, "
      "max %lld\n",
      worst, perPoint.size(), perPoint[perPoint.size() / 2], perPoint.back());
}

}  // namespace

TEST_CASE("the glass rule is within its bound of adaptive quadrature on a held-out grid",
          "[dielectric][glass-rule]") {
  CheckHeldOutGrid(3);
}

TEST_CASE(
    "Dense grid: the glass rule is within its bound of adaptive quadrature on all of the "
    "held-out grid (long: run by hand)",
    "[dielectric][glass-rule][long]") {
  CheckHeldOutGrid(1);
}

TEST_CASE("the glass rule holds its bound where a denser grid found its worst point",
          "[dielectric][glass-rule]") {
  // A 2,304-point grid (16 etas 1/3 .. 3, 19 mu, 9 roughness) found the exit rule 6.11e-7 from
  // adaptive here, above the 6e-7 it then declared: the bound is 7e-7 since. The error was the
  // outer rule's over the part under total internal reflection; the bake's E_R is now E_1 minus
  // total internal reflection's complement, which does not walk that part (1e-9 here), and the
  // direct form (F times the reflected term everywhere) keeps the hard point.
  const double mu = 1, alpha = 0.01, eta = 0.62;
  const std::array<double, 2> f = FixedRuleDielectricAlbedo(mu, alpha, eta);
  DielectricRuleOptions directOpt = TunedDielectricRuleOptions();
  directOpt.exitTirComplement = false;
  const std::array<double, 2> d = FixedRuleDielectricAlbedo(mu, alpha, eta, directOpt);
  const std::array<double, 2> a = Adaptive(mu, alpha, eta);
  for (int c = 0; c < 2; ++c) {
    INFO("channel " << c << " fixed " << f[c] << " direct " << d[c] << " adaptive " << a[c]);
    CHECK(std::abs(f[c] - a[c]) < kDielectricRuleBound);
    CHECK(std::abs(d[c] - a[c]) < kDielectricRuleBound);
  }
  CHECK(std::abs(d[0] - a[0]) > 5e-7);  // the direct E_R there is the hard point it was found to be
  CHECK(std::abs(f[0] - a[0]) < 1e-8);  // the complement's is not
}

TEST_CASE("the exit rule holds its bound where the cap's edge passes the pole, next to mu_c",
          "[dielectric][glass-rule]") {
  // Just above or below mu_c the edge of the cap c > c_crit passes the pole theta_m = 0 at
  // theta_m = |theta_o - acos c_crit|, and the rings beyond it cut the cap on that scale
  // (dielectric_albedo.cpp, CapPoleBreaks). Without the geometric breaks there the rule was
  // 1.02e-6 from adaptive at the first point, a texel of albedo-r-exit (mu_c + 6.05e-4), and 7.3e-7
  // and 7.7e-7 at the next three with 20 outer nodes; the fifth is mu = mu_c, where the rings'
  // share of the cap grows like sqrt(theta_m).
  struct Point {
    double mu, r, eta;
  };
  const double muC3 = std::sqrt((1 - 1 / 3.0) * (1 + 1 / 3.0));
  for (const Point& p :
       {Point{0.94341443042002082, 0.54801151295384087, 1 / 3.0}, Point{0.886388, 0.4361, 0.464},
        Point{0.8864, 0.44, 0.464}, Point{0.916766, 0.6103, 0.4021}, Point{muC3, 0.61126, 1 / 3.0},
        Point{0.92542607640282459, 0.59898754455104308, 0.3804497593706494}}) {
    const double alpha = std::max(AlphaFromPerceptual(p.r), MinAlpha);
    const std::array<double, 2> a = Adaptive(p.mu, alpha, p.eta);
    const std::array<double, 2> f = FixedRuleDielectricAlbedo(p.mu, alpha, p.eta);
    INFO("mu " << p.mu << " r " << p.r << " eta " << p.eta << " E_R " << f[0] - a[0] << " E_T "
               << f[1] - a[1]);
    CHECK(std::abs(f[0] - a[0]) < kDielectricRuleBound);
    CHECK(std::abs(f[1] - a[1]) < kDielectricRuleBound);
  }
}

TEST_CASE(
    "glass energy: E_R + E_T <= 1, the smooth limit F and 1 - F, the loss grows with "
    "roughness",
    "[dielectric][glass-rule]") {
  for (double eta : kEtas)
    for (double mu : MusAt(eta)) {
      INFO("mu " << mu << " eta " << eta);
      // The smooth interface exactly, and the rule approaching it.
      const std::array<double, 2> s = SmoothDielectricAlbedo(mu, eta);
      CHECK(s[0] == FrDielectric(mu, eta));
      CHECK(s[0] + s[1] == 1.0);
      if (mu >= 0.03) {  // below, the GGX masking layer of width alpha is still there
        // Within 1e-4, or at the kink of total internal reflection (F's infinite slope at mu_c,
        // smoothed over ~alpha in the microfacet cosine) within 20 sqrt(alpha).
        const double muC = eta < 1 ? std::sqrt((1 - eta) * (1 + eta)) : -1;
        const double tol = std::abs(mu - muC) > 5e-3 ? 1e-4 : 2e-2;
        const std::array<double, 2> nearSmooth = FixedRuleDielectricAlbedo(mu, 1e-6, eta);
        CHECK(std::abs(nearSmooth[0] - s[0]) < tol);
        CHECK(std::abs(nearSmooth[1] - s[1]) < tol);
      }
      double lastLoss = -1;
      for (double r : kRoughness) {
        const std::array<double, 2> e =
            FixedRuleDielectricAlbedo(mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta);
        const double loss = 1 - e[0] - e[1];
        INFO("r " << r);
        CHECK(loss >= -kDielectricRuleBound);
        // Away from grazing views (at mu ~ alpha the masking layer of the smoothest lobes loses
        // the most: there the loss first falls with roughness).
        if (mu >= 0.3) CHECK(loss >= lastLoss - 2 * kDielectricRuleBound);
        lastLoss = loss;
      }
    }
}
