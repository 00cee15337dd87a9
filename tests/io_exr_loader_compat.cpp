// Specification: every committed table in luts/ opens in OpenEXR's RGBA interface
// (Imf::RgbaInputFile, the reader of most image tools and engine importers) with the values kiln's
// own loader reads, in the same row order: a 1-channel table as grey (R = G = B = Y), a 2-channel
// one as (c0, c1, 0, 1) (B unused, zeros), 3 and 4 channels as they are; a table of more than 4
// channels (the ltc tables' 6) as two files, part 1 channels 0-3 as R, G, B, A and part 2
// channels 4-5 as R, G (and B = 0). Each file is of layout kLayoutVersion.
#include <catch2/catch.hpp>

#include <Imath/half.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <dirent.h>

#include <algorithm>
#include <string>
#include <vector>

#include "exr_rgba.h"
#include "kiln/exr_loader.h"

using kiln::test::ReadRgba;

namespace {

std::string lutsDir() { return std::string(KILN_SOURCE_DIR) + "/luts"; }

std::vector<std::string> exrFiles() {
  std::vector<std::string> out;
  if (DIR* d = opendir(lutsDir().c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".exr") == 0) out.push_back(n);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The int attribute `name` of the file's header, or `fallback` when absent.
int intAttribute(const std::string& path, const char* name, int fallback) {
  Imf::InputFile in(path.c_str());
  const auto* a = in.header().findTypedAttribute<Imf::IntAttribute>(name);
  return a != nullptr ? a->value() : fallback;
}


}  // namespace

TEST_CASE("every committed luts/*.exr reads through RgbaInputFile as kiln's loader reads it",
          "[io][exr][luts][compat]") {
  const std::vector<std::string> files = exrFiles();
  REQUIRE(files.size() >= 70);
  int parts = 0;
  for (const std::string& file : files) {
    INFO(file);
    const std::string path = lutsDir() + "/" + file;
    CHECK(intAttribute(path, "kiln.layout", 1) == kiln::kLayoutVersion);
    const kiln::Table table = kiln::loadTable(path);  // the whole table, also from a part
    const int part = intAttribute(path, "kiln.part", 0);
    const std::size_t nc = table.channels.size();
    // The storage channels this file holds: all of them, or its part's.
    const std::size_t first = part > 0 ? std::size_t(part - 1) * 4 : 0;
    const std::size_t count = part > 0 ? std::min<std::size_t>(4, nc - first) : nc;
    REQUIRE(count <= 4);
    parts += part > 0;

    int width = 0, height = 0;
    const std::vector<Imf::Rgba> px = ReadRgba(path, width, height);
    REQUIRE(width == table.imageWidth());
    REQUIRE(height == table.imageHeight());
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < px.size(); ++i) {
      // What the RGBA interface shows of each stored channel (half, rounded to nearest).
      float want[4] = {0.0f, 0.0f, 0.0f, 1.0f};
      for (std::size_t c = 0; c < count; ++c) want[c] = float(half(table.data[i * nc + first + c]));
      if (count == 1) want[1] = want[2] = want[0];  // Y: grey
      const float got[4] = {float(px[i].r), float(px[i].g), float(px[i].b), float(px[i].a)};
      for (int c = 0; c < 4; ++c) mismatches += got[c] != want[c];
    }
    CHECK(mismatches == 0);
  }
  CHECK(parts >= 2);  // the ltc tables are pairs
}
