// An 8-bit engine PNG of a table (engine_png_writer.h).
#include "baker/io/engine_png_writer.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "baker/io/png_writer.h"

namespace kiln {
namespace {

/// The channels of the PNG EnginePng8 writes (RGB).
constexpr int kPngChannels = 3;
/// The largest 8-bit level.
constexpr double kMaxLevel = 255.0;

}  // namespace

std::string EnginePng8(const Table& table, const std::vector<int>& rgbChannels,
                       long long* clipped) {
  const std::string what = "engine PNG of table '" + table.name + "': ";
  if (table.dims() != 2) throw std::invalid_argument(what + "needs 2 axes");
  const size_t nc = table.channels.size();
  if (rgbChannels.size() != nc)
    throw std::invalid_argument(what + "needs one PNG channel per table channel (" +
                                std::to_string(nc) + ")");
  bool used[kPngChannels] = {false, false, false};
  for (int c : rgbChannels) {
    if (c < 0 || c >= kPngChannels || used[c])
      throw std::invalid_argument(what + "PNG channel " + std::to_string(c) +
                                  " is outside 0..2 or given twice");
    used[c] = true;
  }
  const int w = table.size(0), h = table.size(1);
  std::vector<std::uint8_t> rgb(size_t(w) * size_t(h) * kPngChannels, 0);
  long long above = 0;
  for (size_t texel = 0; texel < size_t(w) * size_t(h); ++texel)
    for (size_t k = 0; k < nc; ++k) {
      const double v = table.data[texel * nc + k];
      above += v > 1;
      const double level =
          std::isnan(v) ? 0 : std::round(std::fmin(std::fmax(v, 0.0), 1.0) * kMaxLevel);
      rgb[texel * kPngChannels + size_t(rgbChannels[k])] = std::uint8_t(level);
    }
  if (clipped) *clipped = above;
  return encodePngRgb8(w, h, rgb);
}

}  // namespace kiln
