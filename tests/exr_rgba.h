// An EXR read as any RGBA reader reads it: OpenEXR's RgbaInputFile.
#pragma once
#include <OpenEXR/ImfRgbaFile.h>

#include <string>
#include <vector>

namespace kiln::test {

/// The whole image through OpenEXR's RgbaInputFile, row by row from the first row of the file.
inline std::vector<Imf::Rgba> ReadRgba(const std::string& path, int& width, int& height) {
  Imf::RgbaInputFile in(path.c_str());
  const Imath::Box2i w = in.dataWindow();
  width = w.max.x - w.min.x + 1;
  height = w.max.y - w.min.y + 1;
  std::vector<Imf::Rgba> pixels(std::size_t(width) * std::size_t(height));
  in.setFrameBuffer(pixels.data() - w.min.x - w.min.y * width, 1, std::size_t(width));
  in.readPixels(w.min.y, w.max.y);
  return pixels;
}

}  // namespace kiln::test
