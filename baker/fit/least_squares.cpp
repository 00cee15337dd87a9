#include "baker/fit/least_squares.h"

#include <cmath>
#include <stdexcept>

namespace kiln {

namespace {
/// Relative size below which a diagonal entry of R counts as a dependent column.
constexpr double kRankTolerance = 1e-13;
}  // namespace

std::vector<double> SolveLeastSquares(std::vector<double> a, std::vector<double> b, int rows,
                                      int cols) {
  if (rows < cols) throw std::invalid_argument("least squares: fewer rows than columns");
  auto at = [&](int i, int j) -> double& { return a[static_cast<size_t>(i) * cols + j]; };
  std::vector<double> diag(cols, 0.0), v(rows);
  for (int k = 0; k < cols; ++k) {
    double norm = 0;
    for (int i = k; i < rows; ++i) norm += at(i, k) * at(i, k);
    norm = std::sqrt(norm);
    if (norm == 0) continue;
    const double alpha = at(k, k) > 0 ? -norm : norm;
    for (int i = k; i < rows; ++i) v[i] = at(i, k);
    v[k] -= alpha;
    double vv = 0;
    for (int i = k; i < rows; ++i) vv += v[i] * v[i];
    if (vv == 0) continue;
    // Reflect the remaining columns and b: x -= 2 v (v.x) / (v.v).
    for (int j = k; j < cols; ++j) {
      double d = 0;
      for (int i = k; i < rows; ++i) d += v[i] * at(i, j);
      const double f = 2 * d / vv;
      for (int i = k; i < rows; ++i) at(i, j) -= f * v[i];
    }
    double d = 0;
    for (int i = k; i < rows; ++i) d += v[i] * b[i];
    const double f = 2 * d / vv;
    for (int i = k; i < rows; ++i) b[i] -= f * v[i];
    diag[k] = at(k, k);
  }
  double largest = 0;
  for (double r : diag) largest = std::max(largest, std::fabs(r));
  std::vector<double> x(cols, 0.0);
  for (int k = cols - 1; k >= 0; --k) {
    if (std::fabs(diag[k]) <= kRankTolerance * largest) continue;
    double s = b[k];
    for (int j = k + 1; j < cols; ++j) s -= at(k, j) * x[j];
    x[k] = s / diag[k];
  }
  return x;
}

}  // namespace kiln
