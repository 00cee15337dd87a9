// The sheen fixed rule's rows (integrate/fixed_rule_sheen_row.h): the AVX2 and AVX-512F lanes give
// the scalar form's bits, and the scalar form is within 1e-12 relative of the model's own terms
// (CharlieD, VelvetD and HalfSin2 of models/sheen.h, std::exp and std::log) at every node: views
// from the normal to grazing, roughness from the tables' 0.045 to 1, lights from the horizon to the
// normal, azimuths over [0, pi] with the mirror (psi = 0) and the back (psi = pi) included.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/fixed_rule_sheen_row.h"
#include "baker/models/sheen.h"

using namespace kiln;

namespace {

/// The row's node j as the models compute it: ws_j (D(h) V), 0 where h is undefined.
double ModelTerm(const SheenRowNdf& ndf, const SheenRow& r, size_t j) {
  bool ok;
  const Vec3 wo{r.woX, 0, r.woZ}, wi{r.sinT * r.cosPhi[j], r.sinT * r.sinPhi[j], r.muL};
  const double s2 = HalfSin2(wo, wi, &ok);
  const double d = ndf.velvet ? VelvetD(ndf.alpha, s2) : CharlieD(ndf.alpha, s2);
  return r.ws[j] * (ok ? d * r.v : 0);
}

}  // namespace

TEST_CASE(
    "Sheen rows: the SIMD lanes give the scalar form's bits, the scalar form the model's "
    "terms to 1e-12 relative",
    "[integrate][fixed-rule][sheen-row]") {
  std::mt19937_64 rng(0x32C1);
  std::uniform_real_distribution<double> u01(0, 1);
  double worst = 0;
  int rows = 0;
  for (bool velvet : {false, true})
    for (double r : {0.045, 0.06, 0.1, 0.3, 0.6, 1.0})
      for (double muO : {0.0, 1e-6, 0.01, 0.3, 0.8, 1.0})
        for (double muL : {0.0, 1e-7, 0.02, 0.4, muO, 0.97, 1.0}) {
          const SheenRowNdf ndf{velvet, r * r};
          // 37 azimuths (an odd count: the last ones take the scalar form), psi = 0 and pi in.
          const size_t n = 37;
          std::vector<double> cosPhi(n), sinPhi(n), ws(n);
          for (size_t j = 0; j < n; ++j) {
            const double psi = j == 0 ? 0 : j == 1 ? Pi : Pi * std::pow(u01(rng), 3);
            cosPhi[j] = -std::cos(psi);
            sinPhi[j] = std::sin(psi);
            ws[j] = 0.01 + u01(rng);
          }
          const SheenRow row{std::sqrt(1 - muO * muO),
                             muO,
                             std::sqrt(1 - muL * muL),
                             muL,
                             0.25 + muL,
                             cosPhi.data(),
                             sinPhi.data(),
                             ws.data(),
                             n};
          INFO("velvet " << velvet << " r " << r << " mu_o " << muO << " mu_l " << muL);
          // Every path (AVX-512F on and off) and every mix of lanes: 37 = 4 x 8 + 4 + 1 and
          // 30 = 3 x 8 + 4 + 2 nodes.
          for (bool avx512 : {true, false})
            for (size_t count : {n, size_t(30)}) {
              dielectric_simd::SetEnabled(avx512);
              SheenRow part = row;
              part.n = count;
              INFO("AVX-512F " << avx512 << " nodes " << count);
              CHECK(SheenRowSum(ndf, part) == SheenRowSumScalar(ndf, part));
              // Two rows sharing the azimuth nodes (SheenRowSum2): each its own bits.
              SheenRow other = part;
              other.muL = 0.5 * (muL + 0.3);
              other.sinT = std::sqrt(1 - other.muL * other.muL);
              other.v = 0.25 + other.muL;
              double a = -1, b = -1;
              SheenRowSum2(ndf, part, other, &a, &b);
              CHECK(a == SheenRowSumScalar(ndf, part));
              CHECK(b == SheenRowSumScalar(ndf, other));
            }
          dielectric_simd::SetEnabled(true);
          for (size_t j = 0; j < n; ++j) {
            SheenRow one = row;
            one.cosPhi += j;
            one.sinPhi += j;
            one.ws += j;
            one.n = 1;
            const double got = SheenRowSumScalar(ndf, one), ref = ModelTerm(ndf, row, j);
            const double err = std::abs(got - ref);
            if (std::abs(ref) > 1e-290) worst = std::max(worst, err / std::abs(ref));
            CHECK(err <= 1e-12 * std::abs(ref) + 1e-300);
          }
          ++rows;
        }
  WARN("worst relative difference from the models' terms " << worst << " over " << rows << " rows");
}
