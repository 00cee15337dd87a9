// The LTC grid fit's own measurement of the overlap form of its L1 error
// (LtcFitOptions::overlapNorm, baker/integrate/ltc_fit.h): the fit's lobe samples reused, the same
// bits as a separate LtcOverlapError at the stored (float) coefficients.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "baker/integrate/ltc_fit.h"

using namespace kiln;

namespace {

constexpr double kAlphaFloor = 1e-5;

/// The lobe FitLtcGrid fits at (r, mu).
LtcLobe GridLobe(const char* model, double r, double mu) {
  return LtcLobe(model, std::max(r, std::sqrt(kAlphaFloor)), LtcFitMu(mu));
}

/// A stand-in for the lobe's exact norm: any positive value per texel serves the comparison.
double TestNorm(size_t ir, size_t im) { return 0.5 + 0.01 * double(ir) + 0.003 * double(im); }

}  // namespace

TEST_CASE("The grid fit's overlap error is LtcOverlapError at the stored coefficients, bit for bit",
          "[ltc]") {
  const std::vector<double> rs = {0.1, 0.4, 0.8}, mus = {1, 0.7, 0.3, 0.05};
  LtcFitOptions opt;
  opt.retryMisses = true;
  opt.overlapNorm = TestNorm;
  for (const char* model : {"charlie-smith", "ggx"}) {
    const std::vector<LtcTexel> fit = FitLtcGrid(model, rs, mus, kAlphaFloor, 2, opt);
    REQUIRE(fit.size() == rs.size() * mus.size());
    for (size_t im = 0; im < mus.size(); ++im)
      for (size_t ir = 0; ir < rs.size(); ++ir) {
        const LtcTexel& t = fit[ir + rs.size() * im];
        const double stored[4] = {float(t.minv[0]), float(t.minv[1]), float(t.minv[2]),
                                  float(t.minv[3])};
        const double expect = LtcOverlapError(GridLobe(model, rs[ir], mus[im]), TestNorm(ir, im),
                                              LtcMatrix::FromInverse(stored), opt.errorSamples);
        INFO(model << " r " << rs[ir] << " mu " << mus[im]);
        CHECK(t.l1 == expect);
        CHECK(t.l1 <= 2);  // (>= 0 needs the exact norm)
      }
  }
}

TEST_CASE("A texel whose overlap norm is not positive is left unmeasured", "[ltc]") {
  LtcFitOptions opt;
  opt.overlapNorm = [](size_t ir, size_t) { return ir == 0 ? 0.0 : 1.0; };
  const std::vector<LtcTexel> fit = FitLtcGrid("ggx", {0.3, 0.6}, {1, 0.5}, kAlphaFloor, 1, opt);
  CHECK(fit[0].l1 == -1);
  CHECK(fit[2].l1 == -1);
  CHECK(fit[1].l1 >= 0);
  CHECK(fit[3].l1 >= 0);
}
