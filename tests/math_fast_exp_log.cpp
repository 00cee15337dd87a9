// ExpFast and Log1pNonNegative (baker/math/fast_exp_log.h), the fixed rules' inline exp and log1p,
// against long double expl and log1pl over their whole domains: exp on [-700, 700] (its table
// path; std::exp beyond), log1p from 1e-30 to 1e30, both ends and the special points included.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "baker/math/fast_exp_log.h"
#include "baker/math/fast_exp_log_avx2.h"
#include "baker/math/fast_exp_log_avx512.h"

using namespace kiln;

namespace {

/// |value - ref| in units of the last place of ref rounded to double.
double Ulps(double value, long double ref) {
  const double r = std::abs(static_cast<double>(ref));
  const double ulp = std::nextafter(r, INFINITY) - r;
  return static_cast<double>(std::abs(static_cast<long double>(value) - ref)) / ulp;
}

}  // namespace

TEST_CASE("ExpFast is within 2 ulp of exp on [-700, 700]", "[math][fast-exp-log]") {
  std::mt19937_64 rng(0x32E1);
  std::uniform_real_distribution<double> wide(-kExpFastMaxAbs, kExpFastMaxAbs), small(-50, 1);
  double worst = 0, worstX = 0;
  auto check = [&](double x) {
    const double u = Ulps(ExpFast(x), std::exp(static_cast<long double>(x)));
    if (u > worst) worst = u, worstX = x;
  };
  for (int i = 0; i < 400000; ++i) check(i % 2 ? wide(rng) : small(rng));
  // The ends, zero, and points where the table index wraps (multiples of ln 2 / 64).
  for (double x : {-kExpFastMaxAbs, kExpFastMaxAbs, 0.0, -0.0, 1e-300, -1e-300, 1e-17, -1e-17})
    check(x);
  for (int k = -64 * 1000; k <= 64 * 1000; k += 37)
    for (double d : {-1e-13, 0.0, 1e-13}) check(k * (std::log(2.0) / 64) + d);
  INFO("worst " << worst << " ulp at x = " << worstX);
  CHECK(worst <= 2);
  CHECK(ExpFast(0) == 1);
  // Outside the table's domain: std::exp's values, NaN to NaN.
  CHECK(ExpFast(-746) == 0);
  CHECK(ExpFast(-1e300) == 0);
  CHECK(ExpFast(-745) == std::exp(-745.0));
  CHECK(ExpFast(-720) == std::exp(-720.0));
  CHECK(std::isinf(ExpFast(710)));
  CHECK(std::isnan(ExpFast(NAN)));
}

TEST_CASE("Log1pNonNegative is within 6 ulp of log1p from 1e-30 to 1e30", "[math][fast-exp-log]") {
  std::mt19937_64 rng(0x32E2);
  std::uniform_real_distribution<double> lg(std::log(1e-30), std::log(1e30));
  double worst = 0, worstY = 0;
  auto check = [&](double y) {
    const double u = Ulps(Log1pNonNegative(y), std::log1p(static_cast<long double>(y)));
    if (u > worst) worst = u, worstY = y;
  };
  for (int i = 0; i < 400000; ++i) check(std::exp(lg(rng)));
  // Around the switch at 3/4, where 1 + y first rounds away from 1, and the ends.
  for (double y : {0.75, std::nextafter(0.75, 0.0), 1.1e-16, 2.2e-16, 3.3e-16, 1e-30, 1e30, 1.0})
    check(y);
  INFO("worst " << worst << " ulp at y = " << worstY);
  CHECK(worst <= 6);
  CHECK(Log1pNonNegative(0) == 0);
  CHECK(Log1pNonNegative(1e-20) == 1e-20);
}

#if defined(__SSE2__)
TEST_CASE("ExpFast2 gives ExpFast's bits in each lane", "[math][fast-exp-log]") {
  std::mt19937_64 rng(0x32E3);
  std::uniform_real_distribution<double> wide(-kExpFastMaxAbs, kExpFastMaxAbs), small(-40, 1);
  int differ = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x0 = i % 2 ? wide(rng) : small(rng), x1 = i % 3 ? small(rng) : wide(rng);
    alignas(16) double out[2];
    _mm_store_pd(out, ExpFast2(_mm_set_pd(x1, x0)));
    differ += out[0] != ExpFast(x0) || out[1] != ExpFast(x1);
  }
  for (double x : {-kExpFastMaxAbs, kExpFastMaxAbs, 0.0}) {
    alignas(16) double out[2];
    _mm_store_pd(out, ExpFast2(_mm_set1_pd(x)));
    differ += out[0] != ExpFast(x) || out[1] != ExpFast(x);
  }
  CHECK(differ == 0);
}

TEST_CASE("LogFast2 and Log1pNonNegative2 give their scalar forms' bits in each lane",
          "[math][fast-exp-log]") {
  std::mt19937_64 rng(0x32E5);
  std::uniform_real_distribution<double> lg(-700, 700), small(-40, 2);
  int differ = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x0 = std::exp(lg(rng)), x1 = i % 2 ? 1 + std::exp(small(rng)) : x0 * 3;
    const double y0 = std::exp(small(rng)), y1 = i % 5 ? std::exp(lg(rng)) : 0.75;
    alignas(16) double lx[2], ly[2];
    _mm_store_pd(lx, LogFast2(_mm_set_pd(x1, x0)));
    _mm_store_pd(ly, Log1pNonNegative2(_mm_set_pd(y1, y0)));
    differ += lx[0] != LogFast(x0) || lx[1] != LogFast(x1);
    differ += ly[0] != Log1pNonNegative(y0) || ly[1] != Log1pNonNegative(y1);
  }
  alignas(16) double ends[2];
  _mm_store_pd(ends, Log1pNonNegative2(_mm_set_pd(1e-300, 0.0)));
  differ += ends[0] != 0 || ends[1] != 1e-300;
  CHECK(differ == 0);
}
#endif

TEST_CASE(
    "LogFast is within 2 ulp or 3e-16 absolute of log over the normal doubles, 2 ulp just above 1",
    "[math][fast-exp-log]") {
  std::mt19937_64 rng(0x32E4);
  std::uniform_real_distribution<double> lg(-708, 709), near1(0.9, 1.1);
  double worstUlp = 0;
  auto check = [&](double x) {
    const long double ref = std::log(static_cast<long double>(x));
    const double v = LogFast(x);
    if (ref != 0) worstUlp = std::max(worstUlp, Ulps(v, ref));
  };
  for (int i = 0; i < 400000; ++i) check(i % 2 ? std::exp(lg(rng)) : near1(rng));
  for (double x : {2.2250738585072014e-308, 1.7976931348623157e308, 1.0, 2.0, 0.5,
                   std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), std::nextafter(2.0, 0.0)})
    check(x);
  INFO("worst " << worstUlp << " ulp");
  CHECK(worstUlp <= 2);
  CHECK(LogFast(1) == 0);
  // Near 1 on both sides (r exact, e ln 2 and log 2 cancelling exactly below 1): relative
  // accuracy, what log1p's form needs.
  double worstNear1 = 0;
  for (int i = 1; i <= 100000; ++i)
    for (double x :
         {1 + i * (1.0 / 64) / 100001, 1 - i * (1.0 / 64) / 100001,
          1 + std::ldexp(static_cast<double>(i), -60), 1 - std::ldexp(static_cast<double>(i), -61)})
      worstNear1 = std::max(worstNear1, Ulps(LogFast(x), std::log(static_cast<long double>(x))));
  INFO("worst " << worstNear1 << " ulp on (1 - 1/64, 1 + 1/64)");
  CHECK(worstNear1 <= 2);
  // Outside the normal range: std::log's values.
  CHECK(LogFast(0) == -INFINITY);
  CHECK(std::isnan(LogFast(-1)));
  CHECK(LogFast(4.9e-324) == std::log(4.9e-324));
}

#if defined(__x86_64__)
namespace {

/// f's four lanes at (x0, x1, x2, x3), computed in an AVX2 function (its target attribute).
template <class F>
KILN_AVX2 void Lanes4(F f, const double* x, double* out) {
  _mm256_storeu_pd(out, f(_mm256_loadu_pd(x)));
}
KILN_AVX2 __m256d Exp4(__m256d x) { return ExpFast4(x); }
KILN_AVX2 __m256d Log4(__m256d x) { return LogFast4(x); }
KILN_AVX2 __m256d Log1p4(__m256d x) { return Log1pNonNegative4(x); }

}  // namespace

TEST_CASE("ExpFast4, LogFast4 and Log1pNonNegative4 give their scalar forms' bits in each lane",
          "[math][fast-exp-log]") {
  if (!__builtin_cpu_supports("avx2")) return;  // (no AVX2 path on this CPU)
  std::mt19937_64 rng(0x32E6);
  std::uniform_real_distribution<double> wide(-kExpFastMaxAbs, kExpFastMaxAbs), small(-40, 2);
  int differ = 0;
  for (int i = 0; i < 100000; ++i) {
    double xe[4], xl[4], y[4], oe[4], ol[4], oy[4];
    for (int l = 0; l < 4; ++l) {
      xe[l] = (i + l) % 2 ? wide(rng) : small(rng);
      xl[l] = (i + l) % 3 ? std::exp(wide(rng)) : 1 + std::exp(small(rng)) * (l % 2 ? 1 : -0.01);
      y[l] = (i + l) % 5 ? std::exp(small(rng)) : l * 0.25;
    }
    Lanes4(Exp4, xe, oe);
    Lanes4(Log4, xl, ol);
    Lanes4(Log1p4, y, oy);
    for (int l = 0; l < 4; ++l)
      differ +=
          oe[l] != ExpFast(xe[l]) || ol[l] != LogFast(xl[l]) || oy[l] != Log1pNonNegative(y[l]);
  }
  CHECK(differ == 0);
}

namespace {

/// f's eight lanes at x[0..7], computed in an AVX-512F function (its target attribute).
template <class F>
KILN_AVX512F void Lanes8(F f, const double* x, double* out) {
  _mm512_storeu_pd(out, f(_mm512_loadu_pd(x)));
}
KILN_AVX512F __m512d Exp8(__m512d x) { return ExpFast8(x); }
KILN_AVX512F __m512d Log8(__m512d x) { return LogFast8(x); }
KILN_AVX512F __m512d Log1p8(__m512d x) { return Log1pNonNegative8(x); }

}  // namespace

TEST_CASE("ExpFast8, LogFast8 and Log1pNonNegative8 give their scalar forms' bits in each lane",
          "[math][fast-exp-log]") {
  if (!__builtin_cpu_supports("avx512f")) return;  // (no AVX-512F path on this CPU)
  std::mt19937_64 rng(0x32E8);
  std::uniform_real_distribution<double> wide(-kExpFastMaxAbs, kExpFastMaxAbs), small(-40, 2);
  int differ = 0;
  for (int i = 0; i < 50000; ++i) {
    double xe[8], xl[8], y[8], oe[8], ol[8], oy[8];
    for (int l = 0; l < 8; ++l) {
      xe[l] = (i + l) % 2 ? wide(rng) : small(rng);
      xl[l] = (i + l) % 3 ? std::exp(wide(rng)) : 1 + std::exp(small(rng)) * (l % 2 ? 1 : -0.01);
      y[l] = (i + l) % 5 ? std::exp(small(rng)) : l * 0.25;
    }
    Lanes8(Exp8, xe, oe);
    Lanes8(Log8, xl, ol);
    Lanes8(Log1p8, y, oy);
    for (int l = 0; l < 8; ++l)
      differ +=
          oe[l] != ExpFast(xe[l]) || ol[l] != LogFast(xl[l]) || oy[l] != Log1pNonNegative(y[l]);
  }
  CHECK(differ == 0);
}
#endif
