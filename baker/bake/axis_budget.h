// The per-axis budget of a table's linear-interpolation error, read from its node values alone:
// along each axis, h^2 f'' / 8 in warped coordinates (the second difference of the stored values
// over three neighbouring nodes, divided by 8), the estimate CellErrorEstimates sums over the
// axes. `kiln inspect --axes` prints it: which axis spends a table's error, and where, so that a
// layout (node counts, warps, stored form) can be weighed without baking it (docs/models.md,
// ggx-dielectric: the glass layouts).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "kiln/lut.h"

namespace kiln {

/// One channel's budget along one axis.
struct AxisBudget {
  int channel = 0;
  int axis = 0;
  /// max over the interior nodes of |f(i-1) - 2 f(i) + f(i+1)| / 8 along `axis` (stored values:
  /// a residual stored form's residual), the estimated linear-interpolation error at the middle
  /// of a cell from this axis alone; 0 for an axis of fewer than 3 nodes.
  double max = 0;
  std::array<int, 3> node = {0, 0, 0};      ///< the node indices where max is (unused axes 0)
  std::array<double, 3> where = {0, 0, 0};  ///< that node's coordinates (axis units)
  /// Per node of `axis`: the max of the same estimate over the other axes (0 at the ends).
  std::vector<double> profile;
};

/// The coordinates (axis units) of node (i0, i1, i2) of `view`: axis 1 and 2 by their own warps,
/// axis 0 at the layer scale and split point those give (LutView::layerScaleAt, splitAt).
std::array<double, 3> NodeCoordinates(const LutView& view, const std::array<int, 3>& node);

/// The budget of every channel along every axis of `view` (channel-major, then axis).
std::vector<AxisBudget> AxisErrorBudget(const LutView& view);

}  // namespace kiln
