// The two sums of the LTC fit's objective (ltc_fit.cpp, FitLtc): the LTC's density at the lobe's
// fixed points and at its own cosine points, eight points at a time where the AVX-512F paths run
// (dielectric_simd::Enabled()), then four where the CPU has AVX2, then two (SSE2 lanes where the
// compiler has them, x86-64 always). Each point's term is the same IEEE arithmetic as one point
// at a time (add, mul, div, sqrt correctly rounded in every lane, no fused multiply-add: the file
// is compiled with -ffp-contract=off), and the terms are summed in one fixed order on every path:
// point k into the partial sum k % 4, the four partial sums added as (s0 + s1) + (s2 + s3) (four
// independent additions per step rather than one chain through every point). The lanes give the
// scalar loops' bits (tests/integrate_ltc_objective.cpp holds them to those loops).
#pragma once
#include <cstddef>

#include "baker/math/constants.h"

namespace kiln {

struct LtcMatrix;

/// The partial sums of the objective's sums: point k is added to partial sum k % kLtcSumLanes.
constexpr size_t kLtcSumLanes = 4;

/// 1 / pi as the fit computes it (the quotient, which need not be InvPi's last bit).
constexpr double kLtcInvPi = 1 / Pi;

/// sum_k pc[k] (max(q_k.z, 0) |det M^-1| / pi) / |q_k|^4, q_k = M^-1 (px[k], py[k], pz[k]), the
/// terms added in the order above: the cross term 2 int f D of the p = 2 objective (M^-1 keeps y
/// apart: q = (i0 x + i2 z, i4 y, i6 x + i8 z)).
double LtcCrossSum(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                   const double* pc, size_t n);

/// sum_j d_j (p = 2) or d_j^2 (p = 3), d_j = c_j.z |det M^-1| / pi |M c_j|^3 at the cosine
/// directions c_j = (cx[j], cy[j], cz[j]), added in the order above: the LTC's own expectation of
/// D^(p-1) (M keeps y apart: M c = (m0 x + m2 z, m4 y, m6 x + m8 z)).
double LtcOwnSum(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                 size_t n, int p);

/// The same sums one point at a time: the reference the lanes are held to.
double LtcCrossSumScalar(const LtcMatrix& ltc, const double* px, const double* py, const double* pz,
                         const double* pc, size_t n);
double LtcOwnSumScalar(const LtcMatrix& ltc, const double* cx, const double* cy, const double* cz,
                       size_t n, int p);

}  // namespace kiln
