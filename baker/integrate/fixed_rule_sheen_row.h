// One row of the sheen fixed rule (fixed_rule_sheen.cpp): at a light cosine mu_l, the sum over
// the azimuth nodes psi_j of ws_j D(h_j) V, D the Charlie or velvet NDF (models/sheen.h) with the
// inline exp and log (math/fast_exp_log.h), eight nodes per AVX-512F instruction where those paths
// run (dielectric_simd::Enabled()), then four per AVX2 instruction where the CPU has it.
// The lanes give the scalar form's bits (tests/integrate_fixed_rule_sheen_row.cpp).
#pragma once
#include <cstddef>

namespace kiln {

/// The NDF of a sheen row: Charlie's (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi) or the
/// velvet's (1 + 4 exp(-cot^2(theta_h) / alpha^2) / sin^4(theta_h)) / (pi (1 + 4 alpha^2)).
struct SheenRowNdf {
  bool velvet = false;
  double alpha = 0.25;
};

/// The NDF from sin^2(theta_h), as CharlieD and VelvetD compute it with ExpFast and LogFast in
/// place of std::exp and std::log (0 where exp underflows, as std::exp).
double SheenNdf(const SheenRowNdf& ndf, double sin2h);

/// What one row needs: the view wo = (woX, 0, woZ), the light's sine and cosine, the row's
/// visibility V, and the azimuth nodes' -cos(psi_j), sin(psi_j) and weights ws_j (n of them).
struct SheenRow {
  double woX = 0, woZ = 1, sinT = 0, muL = 1, v = 0;
  const double *cosPhi = nullptr, *sinPhi = nullptr, *ws = nullptr;
  size_t n = 0;
};

/// sum_j ws_j (D(h_j) V) over the row, added in the order of j (0 where h is undefined); D from
/// sin^2(theta_h) = |(wo + wi)_xy|^2 / |wo + wi|^2 clamped to [0, 1], wi = (sinT cosPhi_j,
/// sinT sinPhi_j, muL), as HalfSin2 (models/sheen.h).
double SheenRowSum(const SheenRowNdf& ndf, const SheenRow& row);

/// SheenRowSum of two rows that share their azimuth nodes (the same n, cosPhi, sinPhi and ws),
/// into *sumA and *sumB: the same bits, the two rows' additions interleaved on the AVX-512F path
/// (two independent chains of additions where one row's would be the loop's limit).
void SheenRowSum2(const SheenRowNdf& ndf, const SheenRow& a, const SheenRow& b, double* sumA,
                  double* sumB);

/// The same one node at a time in scalar arithmetic (the lanes' reference).
double SheenRowSumScalar(const SheenRowNdf& ndf, const SheenRow& row);

}  // namespace kiln
