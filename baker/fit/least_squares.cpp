#include "baker/fit/least_squares.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kiln {

namespace {
/// Relative size below which a diagonal entry of R counts as a dependent column.
constexpr double kRankTolerance = 1e-13;

/// acc[j] += s * row[j] for j < n. Two lanes a step (the compiler packs them into one vector
/// operation); every lane is its own sum, so the bits are those of the plain loop.
void AddScaled(double* __restrict acc, const double* __restrict row, double s, int n) {
  int j = 0;
  for (; j + 1 < n; j += 2) {
    acc[j] += s * row[j];
    acc[j + 1] += s * row[j + 1];
  }
  if (j < n) acc[j] += s * row[j];
}

/// row[j] -= f[j] * s for j < n, two lanes a step like AddScaled.
void SubtractScaled(double* __restrict row, const double* __restrict f, double s, int n) {
  int j = 0;
  for (; j + 1 < n; j += 2) {
    row[j] -= f[j] * s;
    row[j + 1] -= f[j + 1] * s;
  }
  if (j < n) row[j] -= f[j] * s;
}
}  // namespace

std::vector<double> SolveLeastSquares(std::vector<double> a, std::vector<double> b, int rows,
                                      int cols) {
  return SolveLeastSquaresInPlace(a, b, rows, cols);
}

std::vector<double> SolveLeastSquaresInPlace(std::vector<double>& a, std::vector<double>& b,
                                             int rows, int cols) {
  if (rows < cols) throw std::invalid_argument("least squares: fewer rows than columns");
  auto at = [&](int i, int j) -> double& { return a[static_cast<size_t>(i) * cols + j]; };
  std::vector<double> diag(cols, 0.0), v(rows), dot(cols);
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
    // Reflect the remaining columns and b: x -= 2 v (v.x) / (v.v). Each column's dot product
    // and update run over i in order as one column at a time would (a column's update touches
    // only that column), but row by row: contiguous and vectorisable across the columns.
    std::fill(dot.begin() + k, dot.end(), 0.0);
    for (int i = k; i < rows; ++i) AddScaled(&dot[k], &at(i, k), v[i], cols - k);
    for (int j = k; j < cols; ++j) dot[j] = 2 * dot[j] / vv;
    for (int i = k; i < rows; ++i) SubtractScaled(&at(i, k), &dot[k], v[i], cols - k);
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
