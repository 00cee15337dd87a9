// baker/io/bitmap_font.h: a 5 x 7 pixel bitmap font for the labels of kiln's PNG previews
// (axes, ranges, colour bars): digits, Latin letters and the punctuation numbers and axis names
// need. No dependency, no global state.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace kiln {

/// Pixels one character advances: 5 columns of glyph and 1 of space, times `scale`.
constexpr int kGlyphAdvance = 6;
/// Pixel rows of a line of text: 7 rows of glyph and 2 of space, times `scale`.
constexpr int kGlyphLineHeight = 9;

/// The width in pixels of `text` drawn at `scale` (kGlyphAdvance per character).
int TextWidth(const std::string& text, int scale = 1);

/// Draws `text` into an 8-bit RGB image (`width` x `height`, rows top to bottom) with its top-left
/// corner at (x, y), each glyph pixel a `scale` x `scale` block of `rgb`. Pixels outside the image
/// are skipped; a character without a glyph is drawn as a box.
void DrawText(std::vector<std::uint8_t>& image, int width, int height, int x, int y,
              const std::string& text, const std::uint8_t rgb[3], int scale = 1);

}  // namespace kiln
