// The LTC fit's objective sums in lanes (integrate/ltc_objective.h): the same bits as one point at
// a time in the sums' one order (four partial sums), on every path.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "baker/integrate/dielectric_simd.h"
#include "baker/integrate/ltc_fit.h"
#include "baker/integrate/ltc_objective.h"
#include "baker/math/constants.h"
#include "baker/math/splitmix.h"
#include "float_bits.h"

using namespace kiln;

namespace {

/// Points on the sphere (either hemisphere), with weights of either sign.
struct Points {
  std::vector<double> x, y, z, w;
};

Points RandomPoints(size_t n, uint64_t seed) {
  uint64_t state = seed;
  Points p;
  for (size_t i = 0; i < n; ++i) {
    const double zc = 2 * SplitMixUniform(state) - 1, phi = 2 * Pi * SplitMixUniform(state);
    const double s = std::sqrt(std::max(0.0, 1 - zc * zc));
    p.x.push_back(s * std::cos(phi));
    p.y.push_back(s * std::sin(phi));
    p.z.push_back(zc);
    p.w.push_back(SplitMixUniform(state) - 0.25);
  }
  return p;
}

/// LTCs over the fit's range: widths from 1e-4 to 10, skews, frames tilted to grazing.
std::vector<LtcMatrix> Matrices() {
  std::vector<LtcMatrix> out;
  for (double m11 : {1e-4, 0.01, 0.3, 1.0, 10.0})
    for (double m22 : {2e-4, 0.5, 3.0})
      for (double m13 : {-0.7, 0.0, 0.4})
        for (double tilt : {0.0, 0.8, 1.55}) {
          LtcFrameParams f;
          f.m11 = m11;
          f.m22 = m22;
          f.m13 = m13;
          f.z = Vec3{std::sin(tilt), 0, std::cos(tilt)};
          out.push_back(LtcMatrix::From(f));
        }
  return out;
}

}  // namespace

TEST_CASE("The LTC objective's sums in lanes give the bits of one point at a time",
          "[integrate][ltc][ltc-objective]") {
  int checked = 0;
  for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(3), size_t(64), size_t(255), size_t(256),
                   size_t(30)}) {
    const Points p = RandomPoints(n, 17 + n);
    for (const LtcMatrix& m : Matrices()) {
      const double crossRef =
          LtcCrossSumScalar(m, p.x.data(), p.y.data(), p.z.data(), p.w.data(), n);
      for (bool avx512 : {true, false}) {  // the AVX-512F lanes on and off
        dielectric_simd::SetEnabled(avx512);
        const double cross = LtcCrossSum(m, p.x.data(), p.y.data(), p.z.data(), p.w.data(), n);
        REQUIRE(test::Bits(cross) == test::Bits(crossRef));
        for (int power : {2, 3}) {
          const double own = LtcOwnSum(m, p.x.data(), p.y.data(), p.z.data(), n, power);
          const double ownRef = LtcOwnSumScalar(m, p.x.data(), p.y.data(), p.z.data(), n, power);
          REQUIRE(test::Bits(own) == test::Bits(ownRef));
        }
      }
      dielectric_simd::SetEnabled(true);
      ++checked;
    }
  }
  CHECK(checked == 8 * 135);
}

TEST_CASE(
    "The LTC objective's cross sum treats a point below the LTC's horizon and a point at "
    "its origin as one point at a time does",
    "[integrate][ltc][ltc-objective]") {
  // q.z < 0 adds 0 (max(q.z, 0)); q = 0 gives 0 / 0, a NaN the scalar loop carries too.
  LtcFrameParams f;
  const LtcMatrix m = LtcMatrix::From(f);
  const std::vector<double> x = {0.0, 0.3, 0.0, 0.0}, y = {0.0, 0.1, 0.0, 0.2},
                            z = {-1.0, -0.2, 0.0, 0.9}, w = {1.0, 2.0, 3.0, 4.0};
  const double twoBelow = LtcCrossSum(m, x.data(), y.data(), z.data(), w.data(), 2);
  CHECK(test::Bits(twoBelow) == test::Bits(0.0));
  const double withOrigin = LtcCrossSum(m, x.data(), y.data(), z.data(), w.data(), 4);
  const double withOriginRef = LtcCrossSumScalar(m, x.data(), y.data(), z.data(), w.data(), 4);
  CHECK(std::isnan(withOrigin));
  CHECK(std::isnan(withOriginRef));
}

TEST_CASE("The LTC objective's sums add point k into partial sum k % 4, then (s0 + s1) + (s2 + s3)",
          "[integrate][ltc][ltc-objective]") {
  // Four independent partial sums instead of one chain of additions through all points: the
  // fit's objective is add-latency bound otherwise. Each point's term is a one-point sum.
  int differsFromChain = 0;
  for (size_t n : {size_t(5), size_t(64), size_t(256)}) {
    const Points p = RandomPoints(n, 91 + n);
    for (const LtcMatrix& m : Matrices()) {
      double part[4] = {0, 0, 0, 0}, chain = 0;
      double ownPart[4] = {0, 0, 0, 0};
      for (size_t k = 0; k < n; ++k) {
        const double term = LtcCrossSumScalar(m, &p.x[k], &p.y[k], &p.z[k], &p.w[k], 1);
        part[k % 4] += term;
        chain += term;
        ownPart[k % 4] += LtcOwnSumScalar(m, &p.x[k], &p.y[k], &p.z[k], 1, 2);
      }
      const double expect = (part[0] + part[1]) + (part[2] + part[3]);
      const double ownExpect = (ownPart[0] + ownPart[1]) + (ownPart[2] + ownPart[3]);
      const double cross = LtcCrossSum(m, p.x.data(), p.y.data(), p.z.data(), p.w.data(), n);
      REQUIRE(test::Bits(cross) == test::Bits(expect));
      REQUIRE(test::Bits(LtcOwnSum(m, p.x.data(), p.y.data(), p.z.data(), n, 2)) ==
              test::Bits(ownExpect));
      differsFromChain += test::Bits(expect) != test::Bits(chain);
    }
  }
  CHECK(differsFromChain > 0);  // the data tell the two orders apart
}
