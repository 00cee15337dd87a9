// exp and log1p for the fixed rules' inner loops: inline, branch-light, plain double arithmetic
// in a fixed order (deterministic, no libm call), within 2 ulp of exp and 6 ulp of log1p on
// their stated domains (tests/math_fast_exp.cpp measures both against long double).
// ExpFast: exp(x) = 2^e 2^(j/64) exp(r), k = 64 e + j = round(64 x / ln 2), |r| <= ln 2 / 128,
// exp(r) - 1 by its Taylor polynomial to r^5 (truncation below 4e-17 relative), 2^(j/64) from a
// table of the correctly rounded values (fast_exp.cpp).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace kiln {

/// 2^(j / 64), j = 0..63, correctly rounded (fast_exp.cpp).
extern const double kExp2Sixtyfourths[64];

/// The domain of ExpFast's table path; outside it ExpFast returns std::exp(x).
constexpr double kExpFastMaxAbs = 700;

/// exp(x) within 2 ulp for |x| <= kExpFastMaxAbs (std::exp(x) beyond, NaN to NaN).
inline double ExpFast(double x) {
  if (!(std::abs(x) <= kExpFastMaxAbs)) return std::exp(x);
  constexpr double kInvLn2N = 92.332482616893658;  // 64 / ln 2
  constexpr double kShift = 6755399441055744.0;    // 1.5 * 2^52: rounds to an integer
  // ln 2 / 64 in two parts: the first with 31 significant bits (kd * hi exact for |kd| < 2^17).
  constexpr double kLn2NHi = 0.01083042468962958, kLn2NLo = 6.619564634077006e-12;
  const double kd = (x * kInvLn2N + kShift) - kShift;
  const double r = (x - kd * kLn2NHi) - kd * kLn2NLo;
  const long long k = static_cast<long long>(kd);
  const int j = static_cast<int>(k & 63);
  const long long e = (k - j) / 64;
  const double r2 = r * r;
  const double p = r + r2 * (0.5 + r * (1.0 / 6) + r2 * (1.0 / 24 + r * (1.0 / 120)));
  const double t = kExp2Sixtyfourths[j];
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return (t + t * p) * scale;
}

/// log(1 + y) for y >= 0 within 6 ulp: log(u) y / (u - 1), u = 1 + y, below y = 3/4 (Goldberg
/// 1991, Theorem 4: the rounding of u cancels), log(u) from there, y where u rounds to 1.
inline double Log1pNonNegative(double y) {
  const double u = 1 + y;
  if (u == 1) return y;
  const double l = std::log(u);
  return y < 0.75 ? l * (y / (u - 1)) : l;
}

}  // namespace kiln
