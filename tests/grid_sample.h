// Stratified, seeded samples of the (x, y) grids the fixed-rule tests compare against adaptive
// quadrature: every point on the grid's edges (its first and last row and column, and the rows
// and columns of the values a test names: kinks, grazing decades), one point drawn from each
// block of the interior, and the points a test names (where the rule's error is known to peak).
// The dense grid is the same call with block 1 (the tests' [long] variants).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "test_util.h"

namespace kiln::test {

/// A point of a grid by its indices: x[i], y[j].
struct GridIndex {
  size_t i = 0, j = 0;
  bool operator==(const GridIndex& o) const { return i == o.i && j == o.j; }
};

/// The values of `all` equal to one of `wanted` (exactly), as indices into `all`.
template <class C>
std::vector<size_t> IndicesOf(const C& all, const std::vector<double>& wanted) {
  std::vector<size_t> out;
  size_t k = 0;
  for (double v : all) {
    if (std::find(wanted.begin(), wanted.end(), v) != wanted.end()) out.push_back(k);
    ++k;
  }
  return out;
}

/// The points of an nx x ny grid to visit, x fastest: every point whose i is 0, nx - 1 or in
/// edgeX, or whose j is 0, ny - 1 or in edgeY; of the other (interior) points, cut into blocks
/// of `block` x `block` consecutive interior indices, one per block, drawn by a generator
/// seeded with `seed`; and the points `always`. block 1 visits every point (the dense grid).
inline std::vector<GridIndex> StratifiedGrid(size_t nx, size_t ny, size_t block, uint64_t seed,
                                             const std::vector<size_t>& edgeX = {},
                                             const std::vector<size_t>& edgeY = {},
                                             const std::vector<GridIndex>& always = {}) {
  auto isEdge = [](size_t k, size_t n, const std::vector<size_t>& named) {
    return k == 0 || k + 1 == n || std::find(named.begin(), named.end(), k) != named.end();
  };
  std::vector<size_t> innerX, innerY;
  for (size_t i = 0; i < nx; ++i)
    if (!isEdge(i, nx, edgeX)) innerX.push_back(i);
  for (size_t j = 0; j < ny; ++j)
    if (!isEdge(j, ny, edgeY)) innerY.push_back(j);
  std::vector<GridIndex> out;
  for (size_t j = 0; j < ny; ++j)
    for (size_t i = 0; i < nx; ++i)
      if (isEdge(i, nx, edgeX) || isEdge(j, ny, edgeY)) out.push_back({i, j});
  Rng rng(seed);
  for (size_t bj = 0; bj < innerY.size(); bj += block)
    for (size_t bi = 0; bi < innerX.size(); bi += block) {
      const size_t wi = std::min(block, innerX.size() - bi),
                   wj = std::min(block, innerY.size() - bj);
      const size_t di = std::min(wi - 1, static_cast<size_t>(rng.Uniform() * wi));
      const size_t dj = std::min(wj - 1, static_cast<size_t>(rng.Uniform() * wj));
      out.push_back({innerX[bi + di], innerY[bj + dj]});
    }
  for (const GridIndex& p : always)
    if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  return out;
}

}  // namespace kiln::test
