// Engine source files of a table: Filament's dfg.inc and a three.js DFGLUTData-shaped module.
#include "baker/io/engine_module_writer.h"

#include <Imath/half.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace kiln {
namespace {

/// The largest finite half float.
constexpr float kHalfMax = 65504.0f;
/// Texels per line of the generated arrays (Filament's cmgen writes 4).
constexpr int kTexelsPerLine = 4;

std::string Hex4(uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%04x", v);
  return buf;
}

/// The half floats as "0x....," lines of kTexelsPerLine texels of `channels` each.
std::string HexLines(const std::vector<uint16_t>& halves, size_t channels, const char* indent) {
  std::string out;
  const size_t perLine = channels * kTexelsPerLine;
  for (size_t i = 0; i < halves.size(); ++i) {
    if (i % perLine == 0) out += indent;
    out += Hex4(halves[i]) + ",";
    out += (i % perLine == perLine - 1 || i + 1 == halves.size()) ? "\n" : " ";
  }
  return out;
}

}  // namespace

std::vector<uint16_t> HalfTexels(const Table& table, bool transpose) {
  if (table.dims() != 2)
    throw std::invalid_argument("table '" + table.name + "' has " + std::to_string(table.dims()) +
                                " axes; an engine LUT has 2");
  const size_t nx = table.axes[0].axis.size, ny = table.axes[1].axis.size;
  const size_t nc = table.channels.size();
  std::vector<uint16_t> out;
  out.reserve(nx * ny * nc);
  const size_t rows = transpose ? nx : ny, cols = transpose ? ny : nx;
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < cols; ++c) {
      const size_t i = transpose ? r : c, j = transpose ? c : r;  // axis-0, axis-1 node
      for (size_t k = 0; k < nc; ++k) {
        const float v = table.data[(j * nx + i) * nc + k];
        if (!(std::fabs(v) <= kHalfMax))
          throw std::invalid_argument("table '" + table.name +
                                      "' has a value that does not fit in half precision");
        out.push_back(Imath::half(v).bits());
      }
    }
  return out;
}

std::string FilamentIncText(const Table& table) {
  const std::vector<uint16_t> halves = HalfTexels(table, false);
  std::string out = "// " + table.name + ": " + std::to_string(table.axes[0].axis.size) + " x " +
                    std::to_string(table.axes[1].axis.size) + " " +
                    std::to_string(table.channels.size()) +
                    "-channel half floats in GL order (row 0 = the first roughness node), made "
                    "by kiln bake --preset filament (" +
                    table.generator + ")\n";
  return out + HexLines(halves, table.channels.size(), "    ");
}

std::string ThreeModuleText(const Table& table) {
  if (table.channels.size() != 2)
    throw std::invalid_argument("table '" + table.name + "' has " +
                                std::to_string(table.channels.size()) +
                                " channels; three.js's DFG LUT is RG (scale, bias)");
  const std::vector<uint16_t> halves = HalfTexels(table, true);
  const std::string width = std::to_string(table.axes[1].axis.size);   // roughness along u
  const std::string height = std::to_string(table.axes[0].axis.size);  // mu along v
  std::string out =
      "/**\n"
      " * DFG LUT for three.js, the shape of src/renderers/shaders/DFGLUTData.js, made by\n"
      " * kiln bake --preset three (" +
      table.generator + ", table " + table.name +
      ").\n"
      " * Resolution: " +
      width + "x" + height +
      " (u = roughness, v = dotNV, texel centres)\n"
      " * Format: RG16F (2 half floats per texel: scale, bias)\n"
      " */\n\n"
      "import { DataTexture, RGFormat, HalfFloatType, LinearFilter, ClampToEdgeWrapping } "
      "from 'three';\n\n"
      "const DATA = new Uint16Array( [\n";
  out += HexLines(halves, 2, "\t");
  out +=
      "] );\n\n"
      "let lut = null;\n\n"
      "export function getDFGLUT() {\n\n"
      "\tif ( lut === null ) {\n\n"
      "\t\tlut = new DataTexture( DATA, " +
      width + ", " + height +
      ", RGFormat, HalfFloatType );\n"
      "\t\tlut.name = 'DFG_LUT';\n"
      "\t\tlut.minFilter = LinearFilter;\n"
      "\t\tlut.magFilter = LinearFilter;\n"
      "\t\tlut.wrapS = ClampToEdgeWrapping;\n"
      "\t\tlut.wrapT = ClampToEdgeWrapping;\n"
      "\t\tlut.generateMipmaps = false;\n"
      "\t\tlut.needsUpdate = true;\n\n"
      "\t}\n\n"
      "\treturn lut;\n\n"
      "}\n";
  return out;
}

std::string EngineModuleText(const Table& table, const std::string& extension) {
  if (extension == ".inc") return FilamentIncText(table);
  if (extension == ".js") return ThreeModuleText(table);
  throw std::invalid_argument("no engine source file of extension '" + extension + "'");
}

}  // namespace kiln
