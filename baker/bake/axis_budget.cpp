// Per-axis linear-interpolation error budget of a table (axis_budget.h).
#include "baker/bake/axis_budget.h"

#include <algorithm>
#include <cmath>

namespace kiln {

std::array<double, 3> NodeCoordinates(const LutView& view, const std::array<int, 3>& node) {
  std::array<double, 3> x = {0, 0, 0};
  auto t = [&](int d) {
    const int n = view.size(d);
    return n > 1 ? static_cast<double>(node[d]) / (n - 1) : 0.0;
  };
  for (int d = 1; d < view.dims; ++d) x[d] = view.axis[d].unwarped(t(d));
  x[0] = view.axis[0].unwarped(t(0), view.layerScaleAt(x.data()), view.splitAt(x.data()));
  return x;
}

std::vector<AxisBudget> AxisErrorBudget(const LutView& view) {
  std::vector<AxisBudget> out;
  if (!view.valid()) return out;
  const int n[3] = {view.size(0), view.size(1), view.size(2)};
  for (int c = 0; c < view.channels; ++c)
    for (int d = 0; d < view.dims; ++d) {
      AxisBudget b;
      b.channel = c;
      b.axis = d;
      b.profile.assign(static_cast<size_t>(n[d]), 0.0);
      if (n[d] >= 3)
        for (int i2 = 0; i2 < n[2]; ++i2)
          for (int i1 = 0; i1 < n[1]; ++i1)
            for (int i0 = 0; i0 < n[0]; ++i0) {
              std::array<int, 3> i = {i0, i1, i2};
              if (i[d] == 0 || i[d] == n[d] - 1) continue;
              std::array<int, 3> lo = i, hi = i;
              --lo[d];
              ++hi[d];
              const double e = std::abs(static_cast<double>(view.at(lo[0], lo[1], lo[2], c)) -
                                        2.0 * view.at(i0, i1, i2, c) +
                                        static_cast<double>(view.at(hi[0], hi[1], hi[2], c))) /
                               8.0;
              double& p = b.profile[static_cast<size_t>(i[d])];
              p = std::max(p, e);
              if (e > b.max) {
                b.max = e;
                b.node = i;
              }
            }
      b.where = NodeCoordinates(view, b.node);
      out.push_back(std::move(b));
    }
  return out;
}

}  // namespace kiln
