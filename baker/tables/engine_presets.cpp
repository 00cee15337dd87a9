// Engine presets: one descriptor per engine (docs/engines.md measures each against the engine's
// own table where one can be had).
#include "baker/tables/engine_presets.h"

#include <algorithm>
#include <stdexcept>

#include "baker/models/registry.h"
#include "baker/tables/catalogue.h"

namespace kiln {
namespace {

EnginePreset FilamentPreset() {
  EnginePreset p;
  p.name = "filament";
  p.engine = "Filament";
  p.source =
      "google/filament libs/ibl/src/CubemapIBL.cpp (CubemapIBL::DFG, DFV_Multiscatter, "
      "DFV_Charlie_Uniform), made by cmgen --ibl-dfg-multiscatter --ibl-dfg-cloth into "
      "generated/data/dfg.inc, loaded by filament/src/DFG.cpp as RGB16F";
  p.tables = {{"ggx-dfg", DfgLayout::FilamentCloth, "DFG_LUT"}};
  p.muTexels = p.roughnessTexels = 128;  // FILAMENT_DFG_LUT_SIZE (filament/src/DFG.h)
  p.format = OutputFormat::Ktx2;
  p.moduleExtension = ".inc";
  p.note =
      "textureLod(light_iblDFG, vec2(NoV, perceptualRoughness), 0.0): R, G = mix weights of F0, "
      "B = cloth DFG; rows in GL order (row 0 = roughness 0.5/128), no --flip-y";
  return p;
}

EnginePreset GltfViewerPreset() {
  EnginePreset p;
  p.name = "gltf-viewer";
  p.engine = "glTF Sample Viewer";
  p.source =
      "KhronosGroup/glTF-Sample-Viewer assets/images/lut_ggx.png, lut_charlie.png, "
      "lut_sheen_E.png, sampled by source/Renderer/shaders/ibl.glsl (texture(u_GGXLUT, "
      "vec2(NdotV, perceptualRoughness)).rg, texture(u_CharlieLUT, vec2(NdotV, "
      "sheenRoughness)).b)";
  PresetTable ggx{"ggx-dfg", DfgLayout::Kiln, "lut_ggx"};
  ggx.pngChannels = {0, 1};  // texture(u_GGXLUT, ...).rg
  PresetTable charlie{"charlie-dfg", DfgLayout::Kiln, "lut_charlie"};
  charlie.pngChannels = {2};  // texture(u_CharlieLUT, ...).b
  PresetTable sheenE{"charlie-smith-albedo", DfgLayout::Kiln, "lut_sheen_E"};
  sheenE.pngChannels = {0};  // texture(u_SheenELUT, ...).r
  p.tables = {ggx, charlie, sheenE};
  p.muTexels = p.roughnessTexels = 128;
  p.format = OutputFormat::Ktx2;
  p.note =
      "u = NdotV, v = roughness; the float files: lut_ggx R, G = scale, bias; lut_charlie and "
      "lut_sheen_E hold their value in R; the 8-bit lut_*.png put it where the viewer reads "
      "(lut_charlie: .b), clamped to [0, 1]";
  return p;
}

EnginePreset ThreePreset() {
  EnginePreset p;
  p.name = "three";
  p.engine = "three.js";
  p.source =
      "mrdoob/three.js src/renderers/shaders/DFGLUTData.js (16 x 16 RG16F: scale, bias; "
      "4096 samples per texel) and examples/jsm/lights/RectAreaLightTexturesLib.js (LTC_MAT_1, "
      "LTC_MAT_2: 64 x 64 RGBA, the published LTC fit)";
  PresetTable ltc{"ltc-ggx", DfgLayout::Kiln, "LTC_MAT_1, LTC_MAT_2"};
  ltc.engineGrid = false;
  ltc.fixedTexels = 64;  // LUT_SIZE of three's lights_physical_pars_fragment
  ltc.exrOnly = true;    // 6 channels
  p.tables = {{"ggx-dfg", DfgLayout::Kiln, "DFG_LUT"}, ltc};
  p.muTexels = p.roughnessTexels = 16;
  p.transposed = true;
  p.format = OutputFormat::Ktx2;
  p.moduleExtension = ".js";
  p.note =
      "DFG: three's texture has u = roughness, v = dotNV: kiln's file keeps u = mu (sample it "
      "with vec2(dotNV, roughness)), the .js has three's order; LTC: 64 x 64 at (roughness, "
      "sqrt(1 - dotNV)) nodes, EXR (6 channels) and .js";
  return p;
}

EnginePreset Ue4Preset() {
  EnginePreset p;
  p.name = "ue4";
  p.engine = "Unreal Engine 4/5";
  p.source =
      "EpicGames UnrealEngine Engine/Shaders/Private/BRDF.ush EnvBRDF (PreIntegratedGF: "
      "Texture2DSampleLevel(PreIntegratedGF, ..., float2(NoV, Roughness), 0).rg)";
  p.tables = {{"ggx-dfg", DfgLayout::Ue4, "PreIntegratedGF"}};
  p.muTexels = 128;
  p.roughnessTexels = 32;
  p.format = OutputFormat::Dds;
  p.note =
      "R = scale, G = bias of F0: SpecularColor * AB.x + saturate(50 * SpecularColor.g) * AB.y";
  return p;
}

EnginePreset BevyPreset() {
  EnginePreset p;
  p.name = "bevy";
  p.engine = "Bevy";
  p.source =
      "bevyengine/bevy crates/bevy_pbr/src/environment_map/dfg.ktx2 (64 x 64 R16G16_SFLOAT: "
      "scale, bias), sampled by F_AB in crates/bevy_pbr/src/render/pbr_lighting.wesl";
  p.tables = {{"ggx-dfg", DfgLayout::Kiln, "dfg.ktx2"}};
  p.muTexels = p.roughnessTexels = 64;  // dfg.ktx2's size
  p.format = OutputFormat::Ktx2;
  p.half = true;  // R16G16_SFLOAT, linearly filtered (Image::from_buffer, ImageSampler::linear)
  p.note =
      "textureSampleLevel(dfg_lut, dfg_lut_sampler, vec2(NdotV, perceptual_roughness), 0.0).rg "
      "= (scale, bias) of F0; row 0 = roughness 0.5/64; half floats";
  return p;
}

std::string Join(const std::vector<std::string>& names, const char* sep) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : sep) + n;
  return out;
}

bool HasMuAndRoughness(const TableSpec& spec) {
  bool mu = false, r = false;
  for (const AxisSpec& a : spec.axes) {
    mu = mu || a.name == "mu";
    r = r || a.name == "roughness";
  }
  return mu && r;
}

/// Sets the mu and roughness axes to `muN` and `rN` nodes; with `widen`, also to the engine's
/// [0, 1] (a sheen table's axes from its model's floors, as its catalogue entry starts).
void SizeEngineAxes(TableSpec& spec, int muN, int rN, bool widen) {
  for (AxisSpec& a : spec.axes) {
    if (a.name != "mu" && a.name != "roughness") continue;
    a.size = a.name == "mu" ? muN : rN;
    if (!widen) continue;
    a.hi = 1;
    a.lo = 0;
    if (!IsSheen(spec.model)) continue;
    if (a.name == "roughness") a.lo = kSheenTableMinRoughness;
    if (a.name == "mu") a.lo = DiffuseMuAxis(spec.model).lo;  // charlie-smith's kCharlieSmithMinMu
  }
}

}  // namespace

const std::vector<EnginePreset>& EnginePresets() {
  static const std::vector<EnginePreset> presets = {FilamentPreset(), GltfViewerPreset(),
                                                    ThreePreset(), Ue4Preset(), BevyPreset()};
  return presets;
}

const EnginePreset& FindEnginePreset(const std::string& name) {
  std::vector<std::string> names;
  for (const EnginePreset& p : EnginePresets()) {
    if (p.name == name) return p;
    names.push_back(p.name);
  }
  throw std::invalid_argument("unknown --preset '" + name + "' (" + Join(names, ", ") +
                              "; --preset help lists them)");
}

std::string EnginePresetHelp() {
  std::string out;
  for (const EnginePreset& p : EnginePresets()) {
    std::vector<std::string> tables;
    for (const PresetTable& t : p.tables) {
      std::string fixed = t.fixedTexels > 0 ? std::to_string(t.fixedTexels) : "";
      tables.push_back(
          t.table + " -> " + t.engineName +
          (t.engineGrid ? ""
                        : " (" + fixed + " x " + fixed + " nodes" + (t.exrOnly ? ", exr)" : ")")));
    }
    out += p.name + ": " + p.engine + "\n";
    out += "  matches:  " + p.source + "\n";
    out += "  tables:   " + Join(tables, ", ") + "\n";
    out += "  size:     " + std::to_string(p.muTexels) + " (mu) x " +
           std::to_string(p.roughnessTexels) + " (roughness), texel-centred" +
           (p.flipY ? ", rows flipped" : ", row 0 = the smallest roughness") + "\n";
    std::vector<std::string> pngs;
    for (const PresetTable& t : p.tables)
      if (!t.pngChannels.empty()) pngs.push_back(t.engineName + ".png");
    out += std::string("  format:   ") + FormatName(p.format) + " (default; --format changes it)" +
           (p.half ? ", half floats" : "") +
           (p.moduleExtension.empty() ? "" : ", and NAME" + p.moduleExtension) +
           (pngs.empty() ? "" : ", and 8-bit " + Join(pngs, ", ")) + "\n";
    out += "  sampling: " + p.note + "\n";
  }
  return out;
}

std::vector<TableSpec> PresetSpecs(const EnginePreset& preset, int size,
                                   const std::vector<std::string>& only) {
  for (const std::string& name : only) {
    bool found = false;
    for (const PresetTable& t : preset.tables) found = found || t.table == name;
    if (!found) {
      std::vector<std::string> names;
      for (const PresetTable& t : preset.tables) names.push_back(t.table);
      throw std::invalid_argument("--only '" + name + "' is not a table of --preset " +
                                  preset.name + " (" + Join(names, ", ") + ")");
    }
  }
  std::vector<TableSpec> specs;
  for (const PresetTable& t : preset.tables) {
    if (!only.empty() && std::find(only.begin(), only.end(), t.table) == only.end()) continue;
    TableSpec spec = CatalogueTable(t.table);
    if (!t.engineGrid) {
      const int n = t.fixedTexels > 0 ? t.fixedTexels : size;
      if (n > 0)
        for (AxisSpec& a : spec.axes) a.size = n;
      specs.push_back(spec);
      continue;
    }
    SizeEngineAxes(spec, size > 0 ? size : preset.muTexels,
                   size > 0 ? size : preset.roughnessTexels, false);
    EngineOptions options;
    options.layout = t.layout;
    options.engineGrid = true;
    options.flipY = preset.flipY;
    ApplyEngineOptions(spec, options);
    specs.push_back(spec);
  }
  return specs;
}

const PresetTable* PresetTableOf(const EnginePreset& preset, const std::string& specName) {
  for (const PresetTable& t : preset.tables)
    if (specName.rfind(t.table, 0) == 0 &&
        (specName.size() == t.table.size() || specName[t.table.size()] == '-'))
      return &t;
  return nullptr;
}

void ApplyEngineOptionsToPlanned(TableSpec& spec, const EngineOptions& options, int muTexels,
                                 int roughnessTexels) {
  if (!HasMuAndRoughness(spec)) return;
  const bool microfacetDfg = spec.quantity == Quantity::Dfg && !IsSheen(spec.model);
  // On the engine grid the table spans the engine's whole (mu, roughness) square, whatever
  // range the scene's materials asked for: it takes its kind's own name (no range suffix).
  if (options.engineGrid) spec.name = TableName(spec.quantity, spec.model);
  if (microfacetDfg) ApplyDfgLayout(spec, options.layout);
  if (options.engineGrid) {
    // The planned sizes fit the scene's narrowed ranges: the whole square takes the given
    // sizes, or the kind's defaults.
    int muN = muTexels, rN = roughnessTexels;
    for (const AxisSpec& a : Describe(spec.quantity).defaultAxes(spec.model)) {
      if (a.name == "mu" && muN <= 0) muN = std::max(a.size, 2);
      if (a.name == "roughness" && rN <= 0) rN = std::max(a.size, 2);
    }
    SizeEngineAxes(spec, muN, rN, true);
    ApplyEngineGrid(spec);
  }
  if (options.flipY) ApplyFlipY(spec);
}

bool ApplyPresetToPlanned(const EnginePreset& preset, int size, TableSpec& spec) {
  if (!HasMuAndRoughness(spec)) return false;
  EngineOptions options;
  options.engineGrid = true;
  options.flipY = preset.flipY;
  const std::string kindName = TableName(spec.quantity, spec.model);
  for (const PresetTable& t : preset.tables)
    if (kindName == t.table) options.layout = t.layout;
  if (spec.quantity == Quantity::Dfg && !IsSheen(spec.model) && options.layout == DfgLayout::Kiln)
    options.layout = preset.tables.front().layout;  // the engine's microfacet dfg layout
  ApplyEngineOptionsToPlanned(spec, options, size > 0 ? size : preset.muTexels,
                              size > 0 ? size : preset.roughnessTexels);
  return true;
}

}  // namespace kiln
