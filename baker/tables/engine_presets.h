// Engine presets (`kiln bake --preset NAME`): for each engine, the tables it samples in the
// layout, grid, size, orientation and file format its shaders and loaders expect, named after
// the engine source they match (docs/engines.md). One descriptor per preset, in
// engine_presets.cpp.
#pragma once
#include <string>
#include <vector>

#include "baker/io/texture_writers.h"
#include "baker/tables/engine_layout.h"
#include "baker/tables/spec.h"

namespace kiln {

/// One table of a preset: a catalogue table in an engine's channel layout.
struct PresetTable {
  std::string table;                   ///< catalogue name, e.g. "ggx-dfg"
  DfgLayout layout = DfgLayout::Kiln;  ///< its channel layout (dfg tables only)
  std::string engineName;              ///< what the engine calls it, e.g. "DFG_LUT", "lut_ggx"
  /// False: the table keeps its catalogue axes (an LTC table's published node-centred
  /// (roughness, sqrt(1 - mu)) grid, which the engine's shader addresses itself).
  bool engineGrid = true;
  /// > 0: the texels per axis whatever --size says (the engine's shader hard-codes the size).
  int fixedTexels = 0;
  /// True: written as EXR whatever --format says (more than the 4 channels a texture holds).
  bool exrOnly = false;
  /// Non-empty: a catalogue or --only bake also writes the engine's own 8-bit PNG,
  /// `engineName + ".png"` (EnginePng8), table channel k in PNG channel pngChannels[k]
  /// (0 = R, 1 = G, 2 = B): the channel the engine's shader reads.
  std::vector<int> pngChannels = {};
};

/// An engine preset. Every table is baked on the engine grid (texel-centred, uniform in
/// (mu, roughness): ApplyEngineGrid), mu along the image's x (u) and roughness along y (v),
/// unless `transposed`.
struct EnginePreset {
  std::string name;    ///< --preset NAME
  std::string engine;  ///< the engine, e.g. "Filament"
  std::string source;  ///< the engine source file(s) the tables match (repo, path)
  std::vector<PresetTable> tables;
  int muTexels = 128;         ///< texels along mu (the image's width)
  int roughnessTexels = 128;  ///< texels along roughness (the image's height)
  bool flipY = false;         ///< the engine's row 0 is roughness 1 (ApplyFlipY)
  /// The engine's texture has roughness along u and mu along v (three.js's DFGLUTData.js):
  /// only the engine-native writers (a JS module) transpose; the texture formats keep kiln's
  /// order and the docs say to swap the coordinates.
  bool transposed = false;
  OutputFormat format = OutputFormat::Exr;  ///< the default --format of the preset
  /// Store half floats in the EXR, KTX2 and DDS files, as if --half were given (the engine's
  /// texture is 16-bit float and its sampler filters it linearly: Bevy's R16G16_SFLOAT; a
  /// 32-bit float texture is not filterable in WebGPU without an optional feature).
  bool half = false;
  /// The engine's own source file written beside each table (catalogue and --only bakes):
  /// ".inc" (Filament's dfg.inc, FilamentIncText), ".js" (a three.js module, ThreeModuleText)
  /// or "" (none).
  std::string moduleExtension;
  std::string note;  ///< one line: how the engine samples the table
};

/// Every preset, in the order `kiln bake --preset help` lists them.
const std::vector<EnginePreset>& EnginePresets();

/// The preset named `name`; throws std::invalid_argument ("unknown --preset 'x' (filament,
/// ...; --preset help lists them)") for any other name.
const EnginePreset& FindEnginePreset(const std::string& name);

/// The text of `kiln bake --preset help`: one block per preset (name, engine, source, tables,
/// size, orientation, format).
std::string EnginePresetHelp();

/// The specs of `preset`'s tables: each catalogue table with its mu and roughness axes at the
/// preset's sizes (both `size` when size > 0), its layout, the engine grid and the preset's
/// orientation (ApplyEngineOptions); a table with engineGrid false keeps its catalogue axes at
/// fixedTexels (or `size`, or its own) nodes each. With a non-empty `only`, just the preset's
/// tables named there (catalogue names); throws std::invalid_argument for a name that is not one of
/// them.
std::vector<TableSpec> PresetSpecs(const EnginePreset& preset, int size,
                                   const std::vector<std::string>& only = {});

/// A scene's planned table in the preset's form: the mu and roughness axes widened to the
/// engine's [0, 1] (a sheen table's roughness from its floor), at `size` nodes when > 0 (else
/// the preset's sizes), the preset's layout where a preset table of the same catalogue name has
/// one, the engine grid and orientation. Tables without (mu, roughness) axes are left as
/// planned. Returns true when it changed the spec.
/// The preset's entry for the spec named `specName` (a PresetSpecs result), or nullptr.
const PresetTable* PresetTableOf(const EnginePreset& preset, const std::string& specName);

bool ApplyPresetToPlanned(const EnginePreset& preset, int size, TableSpec& spec);

/// The same for `kiln bake --scene` with --layout/--grid/--flip-y and no preset: widens the
/// axes before ApplyEngineGrid when options.engineGrid (the table then takes its kind's own
/// name, e.g. ggx-dfg-engine, not the planned range's), applies the layout to microfacet dfg
/// tables only, and leaves tables without (mu, roughness) axes on kiln's grid. On the engine
/// grid the mu and roughness axes get `muTexels` and `roughnessTexels` nodes (each <= 0: the
/// kind's default size, QuantityInfo::defaultAxes), not the planned ones (which fit the
/// narrowed ranges).
void ApplyEngineOptionsToPlanned(TableSpec& spec, const EngineOptions& options, int muTexels = 0,
                                 int roughnessTexels = 0);

}  // namespace kiln
