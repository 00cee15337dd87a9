// False-colour PNG previews, with a minimal dependency-free PNG encoder.
#include "baker/io/png_writer.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "baker/io/atomic_write.h"
#include "baker/io/bitmap_font.h"

namespace kiln {

namespace {
/// gAMA's value for a gamma of 1.0 (the chunk stores 100000 times the encoding gamma).
constexpr std::uint32_t kPngGammaOne = 100000;
}  // namespace

namespace {

/// Gap between channel panels, in pixels, and its grey level.
constexpr int kPanelGap = 4;
constexpr std::uint8_t kGapGrey = 40;
/// A panel is scaled up by an integer factor until its larger side reaches
/// about this many pixels (at most kMaxScale).
constexpr int kTargetPanelSize = 512;
constexpr int kMaxScale = 16;
/// Height in pixels of the single row of a 1D table.
constexpr int kOneDimRowHeight = 32;

void appendBigEndian32(std::string& out, std::uint32_t v) {
  out += static_cast<char>((v >> 24) & 0xFFu);
  out += static_cast<char>((v >> 16) & 0xFFu);
  out += static_cast<char>((v >> 8) & 0xFFu);
  out += static_cast<char>(v & 0xFFu);
}

/// Appends the chunk `type` holding `data`, with its CRC-32 (ISO 3309, as PNG uses: zlib's crc32)
/// of the type and data.
void appendChunk(std::string& png, const char type[4], const std::string& data) {
  appendBigEndian32(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t typeStart = png.size();
  png.append(type, 4);
  png += data;
  const auto* bytes = reinterpret_cast<const Bytef*>(png.data() + typeStart);
  const auto crc =
      ::crc32(::crc32(0L, Z_NULL, 0), bytes, static_cast<uInt>(png.size() - typeStart));
  appendBigEndian32(png, static_cast<std::uint32_t>(crc));
}

/// A zlib stream of `raw` (deflate at level 9, zlib's compress2: deterministic for a given zlib).
std::string zlibStream(const std::vector<std::uint8_t>& raw) {
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string z(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(z.data()), &size, raw.data(),
                static_cast<uLong>(raw.size()), 9) != Z_OK)
    throw std::runtime_error("PNG: zlib could not compress the image");
  z.resize(size);
  return z;
}

}  // namespace

std::string encodePngImage(int width, int height, int bitDepth, int colourType,
                           const std::vector<std::uint8_t>& pixels,
                           const std::vector<std::pair<std::string, std::string>>& text,
                           bool linear) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("PNG image must be at least 1 x 1 pixels");
  int samples = 0;
  if (colourType == 0) samples = 1;
  if (colourType == 2) samples = 3;
  if (colourType == 4) samples = 2;
  if (colourType == 6) samples = 4;
  if (samples == 0 || (bitDepth != 8 && bitDepth != 16))
    throw std::invalid_argument("PNG colour type " + std::to_string(colourType) + " / bit depth " +
                                std::to_string(bitDepth) + " is not written");
  const std::size_t rowBytes =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(samples * bitDepth / 8);
  if (pixels.size() != rowBytes * static_cast<std::size_t>(height))
    throw std::invalid_argument("PNG pixel buffer does not match width x height x sample bytes");
  for (const auto& [keyword, value] : text)
    if (keyword.empty() || keyword.size() > 79 || keyword.find('\0') != std::string::npos ||
        value.find('\0') != std::string::npos)
      throw std::invalid_argument("PNG text keyword '" + keyword + "' is not valid");

  std::vector<std::uint8_t> raw;  // each row: filter type 0 (None), then the pixels
  raw.reserve((rowBytes + 1) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    const auto row =
        pixels.begin() + static_cast<std::ptrdiff_t>(rowBytes * static_cast<std::size_t>(y));
    raw.insert(raw.end(), row, row + static_cast<std::ptrdiff_t>(rowBytes));
  }

  std::string png = "\x89PNG\r\n\x1a\n";
  std::string header;
  appendBigEndian32(header, static_cast<std::uint32_t>(width));
  appendBigEndian32(header, static_cast<std::uint32_t>(height));
  header += static_cast<char>(bitDepth);
  header += static_cast<char>(colourType);
  header += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
  appendChunk(png, "IHDR", header);
  if (linear) {
    std::string cicp;  // BT.709 primaries, linear transfer (8), RGB (matrix 0), full range
    cicp += '\x01';
    cicp += '\x08';
    cicp += '\x00';
    cicp += '\x01';
    appendChunk(png, "cICP", cicp);
    std::string gamma;
    appendBigEndian32(gamma, kPngGammaOne);
    appendChunk(png, "gAMA", gamma);
  }
  for (const auto& [keyword, value] : text) appendChunk(png, "tEXt", keyword + '\0' + value);
  appendChunk(png, "IDAT", zlibStream(raw));
  appendChunk(png, "IEND", std::string());
  return png;
}

std::string encodePngRgb8(int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (width >= 1 && height >= 1 &&
      rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
    throw std::invalid_argument("PNG pixel buffer does not match width x height x 3");
  return encodePngImage(width, height, 8, 2, rgb, {});
}

void viridis(double t, std::uint8_t rgb[3]) {
  if (!(t > 0.0)) t = 0.0;
  if (t > 1.0) t = 1.0;
  // Polynomial fit of matplotlib's viridis (Matt Zucker, public domain).
  static constexpr double c[7][3] = {{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                     {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                     {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                     {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                     {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                     {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                     {-5.435455855934631, 4.645852612178535, 26.3124352495832}};
  for (int k = 0; k < 3; ++k) {
    double v = c[6][k];
    for (int p = 5; p >= 0; --p) v = v * t + c[p][k];
    v = std::min(1.0, std::max(0.0, v));
    rgb[k] = static_cast<std::uint8_t>(std::lround(v * 255.0));
  }
}

namespace {

constexpr int kMargin = 6;      ///< around the preview, pixels
constexpr int kLabelGap = 3;    ///< between an image and its labels
constexpr int kBarHeight = 10;  ///< the colour bar's height
constexpr int kColumnGap = 16;  ///< between two channels' panels
constexpr std::uint8_t kInk[3] = {230, 230, 230};

std::string Short(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// The labels of one axis: "lo", "hi", "name (warp, nodes)" and its two parts.
struct AxisLabels {
  std::string lo, hi, name, bare, detail;
};

AxisLabels LabelsOf(const TableAxis& a) {
  std::string detail =
      "(" + std::string(warpName(a.axis.warp)) + ", " + std::to_string(a.axis.size) + ")";
  return {Short(a.axis.lo), Short(a.axis.hi), a.name + " " + detail, a.name, detail};
}

/// The channel's [min, max] over the table.
std::pair<float, float> RangeOf(const Table& table, int c) {
  const int channels = static_cast<int>(table.channels.size());
  float lo = table.data[static_cast<std::size_t>(c)], hi = lo;
  for (std::size_t k = static_cast<std::size_t>(c); k < table.data.size();
       k += static_cast<std::size_t>(channels)) {
    lo = std::min(lo, table.data[k]);
    hi = std::max(hi, table.data[k]);
  }
  return {lo, hi};
}

std::string TitleOf(const Table& table, int c) {
  const std::vector<std::string> rgba = {"R", "G", "B", "A"};
  return (c < 4 ? rgba[static_cast<std::size_t>(c)] + " = " : std::string()) +
         table.channels[static_cast<std::size_t>(c)];
}

}  // namespace

PreviewLayout FalseColourLayout(const Table& table) {
  PreviewLayout l;
  const int columns = table.imageWidth(), rows = table.imageHeight();
  const int channels = static_cast<int>(table.channels.size());
  l.scale = std::max(1, std::min(kMaxScale, kTargetPanelSize / std::max(columns, rows)));
  l.rowHeight = table.dims() == 1 ? std::max(l.scale, kOneDimRowHeight) : l.scale;
  l.imageWidth = columns * l.scale;
  l.imageHeight = rows * l.rowHeight;
  // Left of each image: axis 1's labels (top: lo, bottom: hi, middle: its name).
  int left = 0;
  if (table.dims() >= 2) {
    AxisLabels y = LabelsOf(table.axes[1]);
    left = std::max({TextWidth(y.lo), TextWidth(y.hi), TextWidth(y.bare), TextWidth(y.detail)}) +
           kLabelGap;
  }
  AxisLabels x = LabelsOf(table.axes[0]);
  int panel = std::max(l.imageWidth, TextWidth(x.name));
  for (int c = 0; c < channels; ++c) {
    auto [lo, hi] = RangeOf(table, c);
    panel = std::max({panel, TextWidth(TitleOf(table, c)),
                      TextWidth(Short(lo)) + TextWidth(Short(hi)) + kGlyphAdvance});
  }
  if (table.dims() == 3) {
    AxisLabels z = LabelsOf(table.axes[2]);
    panel = std::max(panel, TextWidth("slices: " + z.name + " " + z.lo + ".." + z.hi));
  }
  l.imageTop = kMargin + kGlyphLineHeight;
  for (int c = 0; c < channels; ++c)
    l.imageLeft.push_back(kMargin + c * (left + panel + kColumnGap) + left);
  l.width = 2 * kMargin + channels * (left + panel) + (channels - 1) * kColumnGap;
  const int lines = table.dims() == 3 ? 3 : 2;  // x ticks, x name [, slices]
  l.barTop = l.imageTop + l.imageHeight + kLabelGap + lines * kGlyphLineHeight;
  l.barHeight = kBarHeight;
  l.height = l.barTop + kBarHeight + kLabelGap + kGlyphLineHeight + kMargin;
  return l;
}

void writeFalseColourPng(const std::string& path, const Table& table) {
  std::string problem;
  if (!validateTable(table, problem))
    throw std::runtime_error("kiln: cannot write '" + path + "': invalid table: " + problem);
  const PreviewLayout l = FalseColourLayout(table);
  const int columns = table.imageWidth();
  const int rows = table.imageHeight();
  const int channels = static_cast<int>(table.channels.size());
  const int width = l.width, height = l.height;
  std::vector<std::uint8_t> rgb(
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, kGapGrey);
  auto put = [&](int px, int py, const std::uint8_t colour[3]) {
    std::uint8_t* pixel =
        &rgb[(static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px)) * 3];
    pixel[0] = colour[0];
    pixel[1] = colour[1];
    pixel[2] = colour[2];
  };
  auto text = [&](int x, int y, const std::string& s) {
    DrawText(rgb, width, height, x, y, s, kInk);
  };
  const AxisLabels x = LabelsOf(table.axes[0]);
  for (int c = 0; c < channels; ++c) {
    auto [lo, hi] = RangeOf(table, c);
    const double range = static_cast<double>(hi) - static_cast<double>(lo);
    const int left = l.imageLeft[static_cast<std::size_t>(c)], top = l.imageTop;
    for (int row = 0; row < rows; ++row) {
      for (int col = 0; col < columns; ++col) {
        const float v = table.data[(static_cast<std::size_t>(row) * columns + col) * channels + c];
        const double t = range > 0.0 ? (static_cast<double>(v) - lo) / range : 0.5;
        std::uint8_t colour[3];
        viridis(t, colour);
        for (int py = row * l.rowHeight; py < (row + 1) * l.rowHeight; ++py)
          for (int px = col * l.scale; px < (col + 1) * l.scale; ++px)
            put(left + px, top + py, colour);
      }
    }
    // Title, axis 0 below the image (lo at the left, hi at the right, then its name), axis 1 at
    // the left (lo at the top: row 0 is its first node), the slices of a 3D table.
    text(left, kMargin, TitleOf(table, c));
    int y = top + l.imageHeight + kLabelGap;
    text(left, y, x.lo);
    text(left + l.imageWidth - TextWidth(x.hi), y, x.hi);
    text(left, y + kGlyphLineHeight, x.name + " ->");
    if (table.dims() >= 2) {
      const AxisLabels a1 = LabelsOf(table.axes[1]);
      const int x1 = left - kLabelGap;
      const int sliceHeight = table.size(1) * l.rowHeight;
      text(x1 - TextWidth(a1.lo), top, a1.lo);
      text(x1 - TextWidth(a1.hi), top + sliceHeight - 7, a1.hi);
      text(x1 - TextWidth(a1.bare), top + sliceHeight / 2 - kGlyphLineHeight, a1.bare);
      text(x1 - TextWidth(a1.detail), top + sliceHeight / 2, a1.detail);
    }
    if (table.dims() == 3) {
      const AxisLabels z = LabelsOf(table.axes[2]);
      text(left, y + 2 * kGlyphLineHeight, "slices: " + z.name + " " + z.lo + ".." + z.hi);
    }
    // The colour bar: viridis from the channel's min (left) to its max (right), labelled.
    for (int px = 0; px < l.imageWidth; ++px) {
      std::uint8_t colour[3];
      viridis(l.imageWidth > 1 ? static_cast<double>(px) / (l.imageWidth - 1) : 0.5, colour);
      for (int py = 0; py < l.barHeight; ++py) put(left + px, l.barTop + py, colour);
    }
    const int yr = l.barTop + l.barHeight + kLabelGap;
    text(left, yr, Short(lo));
    text(left + l.imageWidth - TextWidth(Short(hi)), yr, Short(hi));
  }
  const std::string png = encodePngRgb8(width, height, rgb);
  writeAtomically(path, [&](const std::string& temporaryPath) { writeBytes(temporaryPath, png); });
}

}  // namespace kiln
