// baker/io/engine_module_writer.h: a table as the source file an engine compiles its LUT from:
// Filament's dfg.inc (the uint16_t half-float array filament/src/DFG.cpp includes as DFG_LUT)
// and a three.js ES module of the shape of src/renderers/shaders/DFGLUTData.js (a Uint16Array
// DATA of RG halves and getDFGLUT() returning the DataTexture). `kiln bake --preset filament`
// and `--preset three` write them beside the texture file (docs/engines.md).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// The texels of a 2-axis table (axis 0 = the image's x) as IEEE half floats (round to nearest
/// even), channel fastest, in image order: row j holds axis-1 node j, unless `transpose`, which
/// puts axis 1 along x (row i = axis-0 node i). Throws std::invalid_argument naming the table
/// when it has not 2 axes or a value does not fit in half precision.
std::vector<uint16_t> HalfTexels(const Table& table, bool transpose);

/// Filament's generated/data/dfg.inc: a comment naming the table and the kiln command, then the
/// half floats of HalfTexels(table, false) as "0x%04x, " (4 texels a line), to be included
/// inside `const uint16_t DFG_LUT[] = { ... };` (filament/src/DFG.cpp). Throws as HalfTexels.
std::string FilamentIncText(const Table& table);

/// A three.js ES module with DFGLUTData.js's exported shape: `const DATA = new Uint16Array([...])`
/// of HalfTexels(table, true) (u = roughness, v = mu, three's order), and `export function
/// getDFGLUT()` returning a DataTexture(DATA, width, height, RGFormat, HalfFloatType) with linear
/// filtering and clamp-to-edge wrapping, named 'DFG_LUT', imported from 'three'. Needs a
/// 2-channel table; throws std::invalid_argument naming the table otherwise (or as HalfTexels).
std::string ThreeModuleText(const Table& table);

/// A three.js ES module with RectAreaLightTexturesLib.js's exported shape from an ltc table
/// (channels minv_a, minv_b, minv_c, minv_d, norm, fresnel over (roughness, sqrt_one_minus_mu),
/// roughness along x): `LTC_MAT_1` = (minv_a, minv_b, minv_c, minv_d) and `LTC_MAT_2` = (norm,
/// fresnel, 0, 0) per texel as float arrays (%.9g; three's shader reads LTC_MAT_2's x and y
/// only), and `RectAreaLightTexturesLib.init()` building LTC_FLOAT_1/2 and LTC_HALF_1/2 as
/// width x height RGBA DataTextures (linear magnification, nearest minification, clamp to
/// edge), imported from 'three'. Throws std::invalid_argument naming the table when its channels
/// are not those.
std::string ThreeLtcModuleText(const Table& table);

/// FilamentIncText for ".inc"; for ".js" ThreeLtcModuleText of an ltc table, else
/// ThreeModuleText; throws std::invalid_argument for any other extension.
std::string EngineModuleText(const Table& table, const std::string& extension);

}  // namespace kiln
