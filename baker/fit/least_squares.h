// Dense linear least squares by Householder QR, in double: the small solver `kiln fit` needs.
#pragma once
#include <vector>

namespace kiln {

/// The x minimising |A x - b|_2 for A of `rows` x `cols` (row-major, rows >= cols), by
/// Householder QR (no normal equations: the Chebyshev design matrices of a fit stay well
/// conditioned this way). A column that QR finds dependent (|R_kk| below 1e-13 of the largest)
/// gets coefficient 0. Deterministic: one thread, a fixed order of operations.
std::vector<double> SolveLeastSquares(std::vector<double> a, std::vector<double> b, int rows,
                                      int cols);

/// SolveLeastSquares working in the caller's `a` and `b` (left holding R and Q^T b): the same
/// bits, without a copy of A per solve when a caller solves many systems of one size.
std::vector<double> SolveLeastSquaresInPlace(std::vector<double>& a, std::vector<double>& b,
                                             int rows, int cols);

}  // namespace kiln
