// baker/io/engine_png_writer.h: a table as the 8-bit PNG an engine loads its LUT from (the glTF
// Sample Viewer's assets/images/lut_*.png), each table channel in the PNG channel the engine's
// shader reads (docs/engines.md "gltf-viewer").
#pragma once
#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// An 8-bit RGB PNG of a 2-axis table (axis 0 = the image's x): table channel k goes to PNG
/// channel rgbChannels[k] (0 = R, 1 = G, 2 = B), the PNG channels no table channel names hold 0.
/// Each value is clamped to [0, 1] (NaN to 0) and rounded to the nearest of the 256 levels
/// (at most 1/510 off inside [0, 1]). Row j of the table (axis-1 node j) is the PNG's j-th row
/// from the top: kiln's row order, unflipped. When `clipped` is given it receives the number of
/// values above 1 that were clamped. Throws std::invalid_argument naming the table when it has
/// not 2 axes, rgbChannels does not name one PNG channel per table channel, or a placement is
/// outside 0..2 or repeated.
std::string EnginePng8(const Table& table, const std::vector<int>& rgbChannels,
                       long long* clipped = nullptr);

}  // namespace kiln
