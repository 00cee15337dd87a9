// baker/io/png_writer.h: a false-colour preview of a kiln table.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// Encodes an 8-bit RGB image (rgb holds width * height * 3 bytes, rows top
/// to bottom) as a complete PNG file: IHDR, one IDAT holding the rows (filter
/// None) deflated by zlib at level 9, IEND, each chunk with its CRC-32. Throws
/// std::invalid_argument on a size mismatch or an empty image.
std::string encodePngRgb8(int width, int height, const std::vector<std::uint8_t>& rgb);

/// Encodes an image as a complete PNG file: IHDR (`bitDepth` 8 or 16, `colourType` 0 grey, 2
/// RGB, 4 grey + alpha or 6 RGBA, no interlace), one tEXt chunk per (keyword, text) pair in
/// order (keyword 1..79 bytes; neither may contain a NUL); with `linear`, before them, the chunks
/// saying the samples are linear: cICP (primaries 1 BT.709, transfer 8 linear, matrix 0, full
/// range) and gAMA 100000 (gamma 1.0), and no sRGB or iCCP; one IDAT (rows with filter None,
/// deflated by zlib at level 9), IEND. `pixels` holds the rows top to bottom, samples interleaved,
/// 16-bit samples big-endian (PNG's order). Throws std::invalid_argument on a size mismatch, an
/// empty image, an unsupported depth or type, or a bad keyword.
std::string encodePngImage(int width, int height, int bitDepth, int colourType,
                           const std::vector<std::uint8_t>& pixels,
                           const std::vector<std::pair<std::string, std::string>>& text,
                           bool linear = false);

/// The viridis colour of t in [0, 1] (clamped; NaN maps to 0) as 8-bit RGB,
/// from a degree-6 polynomial fit of matplotlib's viridis.
void viridis(double t, std::uint8_t rgb[3]);

/// Where writeFalseColourPng draws, in pixels: the whole picture, each channel's texel image
/// (all of imageWidth x imageHeight, at (imageLeft[c], imageTop)), each texel a scale x
/// rowHeight block, and the colour bar under each image.
struct PreviewLayout {
  int width = 0, height = 0;
  int imageWidth = 0, imageHeight = 0, imageTop = 0;
  std::vector<int> imageLeft;  ///< one per channel, in storage order
  int scale = 1, rowHeight = 1;
  int barTop = 0, barHeight = 0;
};

/// The layout writeFalseColourPng uses for `table` (valid).
PreviewLayout FalseColourLayout(const Table& table);

/// Writes a false-colour PNG of `table` to `path`: one panel per channel, side by side left to
/// right in storage order on a dark background. Each panel is the table's EXR image (axis 0 to
/// the right, axis 1 downwards, 3D slices stacked downwards), each texel an integer-scaled block
/// (1D tables are drawn 32 pixels tall), coloured with viridis over the channel's own [min, max]
/// (a constant channel is drawn mid-range); labelled with the channel ("R = A"), axis 0's range
/// and name (warp, nodes) under the image, axis 1's at its left (first node at the top), a 3D
/// table's slice axis, and a colour bar under each image with the channel's min and max
/// (bitmap_font.h). Written through a temporary file and a rename; throws std::runtime_error with
/// a one-line message on failure or when the table fails validateTable.
void writeFalseColourPng(const std::string& path, const Table& table);

}  // namespace kiln
