// Engine source files of a table: Filament's dfg.inc and a three.js DFGLUTData-shaped module.
#include "baker/io/engine_module_writer.h"

#include "baker/io/half_float.h"

#include <Imath/half.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace kiln {
namespace {

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

namespace {

/// The ltc channels ThreeLtcModuleText reads, in their order.
const std::vector<std::string> kLtcChannels = {"minv_a", "minv_b", "minv_c",
                                               "minv_d", "norm",   "fresnel"};
/// Floats per line of the generated LTC arrays.
constexpr int kFloatsPerLine = 16;

/// `count` RGBA texels as a JS array literal: texel t's channel k is value(t, k).
template <typename Value>
std::string FloatArray(const char* name, size_t count, Value value) {
  std::string out = std::string("\t\tconst ") + name + " = [\n";
  char buf[32];
  for (size_t i = 0; i < count * 4; ++i) {
    if (i % kFloatsPerLine == 0) out += "\t\t\t";
    std::snprintf(buf, sizeof buf, "%.9g,", double(value(i / 4, i % 4)));
    out += buf;
    out += (i % kFloatsPerLine == kFloatsPerLine - 1) ? "\n" : " ";
  }
  return out + "\n\t\t];\n\n";
}

/// The DataTexture lines of one LTC texture of RectAreaLightTexturesLib.
std::string LtcTextures(int n, const std::string& w, const std::string& h) {
  const std::string i = std::to_string(n);
  const std::string args = ", " + w + ", " + h +
                           ", RGBAFormat, TYPE, UVMapping, ClampToEdgeWrapping, "
                           "ClampToEdgeWrapping, LinearFilter, NearestFilter, 1 );\n";
  std::string floatArgs = args, halfArgs = args;
  floatArgs.replace(floatArgs.find("TYPE"), 4, "FloatType");
  halfArgs.replace(halfArgs.find("TYPE"), 4, "HalfFloatType");
  return "\t\tconst ltc_half_" + i + " = new Uint16Array( LTC_MAT_" + i +
         ".length );\n"
         "\t\tLTC_MAT_" +
         i + ".forEach( ( x, index ) => { ltc_half_" + i +
         "[ index ] = DataUtils.toHalfFloat( x ); } );\n"
         "\t\tthis.LTC_FLOAT_" +
         i + " = new DataTexture( new Float32Array( LTC_MAT_" + i + " )" + floatArgs +
         "\t\tthis.LTC_HALF_" + i + " = new DataTexture( ltc_half_" + i + halfArgs +
         "\t\tthis.LTC_FLOAT_" + i + ".needsUpdate = true;\n\t\tthis.LTC_HALF_" + i +
         ".needsUpdate = true;\n\n";
}

}  // namespace

std::string ThreeLtcModuleText(const Table& table) {
  if (table.channels != kLtcChannels || table.dims() != 2)
    throw std::invalid_argument("table '" + table.name +
                                "' is not an ltc table (minv_a..d, norm, fresnel over 2 axes)");
  const size_t nx = table.axes[0].axis.size, ny = table.axes[1].axis.size;
  const std::string w = std::to_string(nx), h = std::to_string(ny);
  const size_t nc = kLtcChannels.size();
  auto mat1 = [&](size_t t, size_t k) { return table.data[t * nc + k]; };
  auto mat2 = [&](size_t t, size_t k) { return k < 2 ? table.data[t * nc + 4 + k] : 0.0f; };
  std::string out =
      "/**\n"
      " * LTC tables for three.js's RectAreaLight, the shape of\n"
      " * examples/jsm/lights/RectAreaLightTexturesLib.js, made by kiln bake --preset three\n"
      " * (" +
      table.generator + ", table " + table.name + ": " + w + " x " + h +
      " texels, u = roughness, v = sqrt(1 - dotNV), at the nodes).\n"
      " */\n\n"
      "import { ClampToEdgeWrapping, DataTexture, DataUtils, FloatType, HalfFloatType, "
      "LinearFilter, NearestFilter, RGBAFormat, UVMapping } from 'three';\n\n"
      "class RectAreaLightTexturesLib {\n\n\tstatic init() {\n\n";
  out += FloatArray("LTC_MAT_1", nx * ny, mat1);
  out += FloatArray("LTC_MAT_2", nx * ny, mat2);
  out += LtcTextures(1, w, h) + LtcTextures(2, w, h);
  out +=
      "\t\treturn this;\n\n\t}\n\n}\n\n"
      "RectAreaLightTexturesLib.LTC_HALF_1 = null;\nRectAreaLightTexturesLib.LTC_HALF_2 = null;\n"
      "RectAreaLightTexturesLib.LTC_FLOAT_1 = null;\nRectAreaLightTexturesLib.LTC_FLOAT_2 = "
      "null;\n\n"
      "export { RectAreaLightTexturesLib };\n";
  return out;
}

std::string EngineModuleText(const Table& table, const std::string& extension) {
  if (extension == ".inc") return FilamentIncText(table);
  if (extension == ".js")
    return table.quantity == "ltc" ? ThreeLtcModuleText(table) : ThreeModuleText(table);
  throw std::invalid_argument("no engine source file of extension '" + extension + "'");
}

}  // namespace kiln
