#include "baker/scene/axis_narrowing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace kiln {
namespace {

std::vector<double> Nodes(const AxisSpec& a) {
  std::vector<double> x(static_cast<size_t>(std::max(1, a.size)));
  Axis axis = a.ToAxis();
  for (int i = 0; i < a.size; ++i) x[static_cast<size_t>(i)] = axis.node(i);
  return x;
}

/// Width of the cell of nodes `x` containing v (the end cells beyond the ends).
double CellWidth(const std::vector<double>& x, double v) {
  if (x.size() < 2) return 0;
  size_t i = std::upper_bound(x.begin(), x.end(), v) - x.begin();
  i = std::clamp<size_t>(i, 1, x.size() - 1);
  return x[i] - x[i - 1];
}

/// True when no cell of `a` is wider than the cell of `full` (nodes `ref`) at its centre.
bool AsFine(const AxisSpec& a, const std::vector<double>& ref) {
  std::vector<double> x = Nodes(a);
  for (size_t j = 0; j + 1 < x.size(); ++j)
    if (x[j + 1] - x[j] > CellWidth(ref, 0.5 * (x[j] + x[j + 1])) * (1 + 1e-9)) return false;
  return true;
}

}  // namespace

AxisSpec NarrowAxis(const AxisSpec& full, double lo, double hi) {
  if (lo == full.lo && hi == full.hi) return full;
  std::vector<double> ref = Nodes(full);
  int cap = 4 * std::max(2, full.size) + 1;
  AxisSpec best = full;
  best.lo = lo;
  best.hi = hi;
  best.size = cap;
  best.warp = Warp::Linear;
  best.split = std::numeric_limits<double>::quiet_NaN();
  for (Warp warp : {full.warp, Warp::Linear}) {
    if (warp == Warp::Log && lo <= 0) continue;
    // A constant split point outside the narrowed range: the warp cannot keep it.
    if (warp == Warp::Root4LayerSplit && std::isfinite(full.split) &&
        !(lo < full.split && full.split < hi))
      continue;
    AxisSpec a = full;
    a.lo = lo;
    a.hi = hi;
    a.warp = warp;
    if (warp != Warp::Root4LayerSplit) a.split = std::numeric_limits<double>::quiet_NaN();
    for (a.size = 2; a.size < best.size; ++a.size)
      if (AsFine(a, ref)) {
        best = a;
        break;
      }
  }
  return best;
}

AxisSpec SliceAxis(const AxisSpec& full, double v) {
  std::vector<double> x = Nodes(full);
  double w = CellWidth(x, v);
  if (!(w > 0)) w = full.hi - full.lo;
  AxisSpec a = full;
  a.size = 2;
  a.warp = Warp::Linear;
  a.split = std::numeric_limits<double>::quiet_NaN();
  if (v < full.lo) {
    a.lo = v, a.hi = v + w;
  } else if (v >= full.hi) {
    a.lo = v - w, a.hi = v;
  } else {
    a.lo = v;
    a.hi = *std::upper_bound(x.begin(), x.end(), v);
  }
  return a;
}

}  // namespace kiln
