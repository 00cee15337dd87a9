// Engine layouts of a table spec: DFG channel layouts, the engine grid, flipped rows.
#include "baker/tables/engine_layout.h"

#include <algorithm>
#include <stdexcept>

#include "baker/models/registry.h"

namespace kiln {
namespace {

constexpr const char* kFilamentChannels[2] = {"B", "A_plus_B"};
constexpr const char* kFilamentClothChannel = "DFV_Charlie";
/// The sheen model of Filament's cloth channel (CubemapIBL.cpp DFV_Charlie_Uniform: the Charlie
/// NDF with the Neubelt/"Ashikhmin" visibility 1 / (4 (mu_l + mu_o - mu_l mu_o))).
constexpr const char* kFilamentClothModel = "charlie";

const char* LayoutName(DfgLayout layout) {
  switch (layout) {
    case DfgLayout::Kiln:
      return "kiln";
    case DfgLayout::Ue4:
      return "ue4";
    case DfgLayout::Filament:
      return "filament";
    case DfgLayout::FilamentCloth:
      return "filament-cloth";
  }
  return "?";
}

bool HasFilamentChannels(const TableSpec& spec) {
  return spec.channels.size() >= 2 && spec.channels[0] == kFilamentChannels[0] &&
         spec.channels[1] == kFilamentChannels[1];
}

bool IsSheenSpec(const TableSpec& spec) { return IsSheen(spec.model); }

}  // namespace

DfgLayout ParseDfgLayout(const std::string& text) {
  if (text == "kiln") return DfgLayout::Kiln;
  if (text == "ue4") return DfgLayout::Ue4;
  if (text == "filament") return DfgLayout::Filament;
  if (text == "filament-cloth") return DfgLayout::FilamentCloth;
  throw std::invalid_argument("unknown --layout '" + text +
                              "' (kiln, ue4, filament or filament-cloth)");
}

void ApplyDfgLayout(TableSpec& spec, DfgLayout layout) {
  if (layout == DfgLayout::Kiln) return;
  if (spec.quantity != Quantity::Dfg)
    throw std::invalid_argument(std::string("--layout ") + LayoutName(layout) +
                                " applies to dfg tables; '" + spec.name + "' is " +
                                QuantityName(spec.quantity) + " (pick dfg tables with --only)");
  if (IsSheenSpec(spec))
    throw std::invalid_argument(
        std::string("--layout ") + LayoutName(layout) + " applies to microfacet dfg tables; '" +
        spec.name +
        "' is a sheen table of one channel (Filament's cloth DFG is the third channel of "
        "--layout filament-cloth, e.g. --preset filament)");
  if (layout == DfgLayout::Ue4) return;  // (scale, bias) in (R, G): kiln's own order
  // Filament (libs/ibl/src/CubemapIBL.cpp, DFV_Multiscatter, used by cmgen --ibl-dfg and the
  // engine's built-in DFG LUT): DFV.x = integral of Fc V ... = B, DFV.y = integral of V ... =
  // A + B, and the shader reconstructs E = mix(DFV.x, DFV.y, f0) = (1 - f0) B + f0 (A + B).
  spec.channels = {kFilamentChannels[0], kFilamentChannels[1]};
  spec.meanings = {"Filament DFG.x = B = integral f/F (1 - o.h)^5 mu_l dl",
                   "Filament DFG.y = A + B = integral f/F mu_l dl, E = mix(x, y, F0)"};
  if (layout == DfgLayout::Filament) {
    spec.name += "-filament";
    return;
  }
  spec.channels.push_back(kFilamentClothChannel);
  spec.meanings.push_back(
      "Filament DFG.z = DFV_Charlie = integral f mu_l dl of the Charlie sheen (Neubelt "
      "visibility, F = 1) at roughness max(r, sheen_roughness_min)");
  spec.params[kSheenRoughnessMinParam] = kSheenShaderMinRoughness;
  spec.name += "-filament-cloth";
}

double SheenRoughnessFor(const TableSpec& spec, double r) {
  auto it = spec.params.find(kSheenRoughnessMinParam);
  return it == spec.params.end() ? r : std::max(r, it->second);
}

bool HasFilamentClothChannel(const TableSpec& spec) {
  return spec.channels.size() == 3 && HasFilamentChannels(spec) &&
         spec.channels[2] == kFilamentClothChannel;
}

TableSpec FilamentClothSpec(const TableSpec& spec) {
  TableSpec cloth = spec;
  cloth.model = kFilamentClothModel;
  cloth.name = std::string(kFilamentClothModel) + "-" + QuantityName(Quantity::Dfg);
  cloth.channels = {"DFV"};
  cloth.meanings = {spec.meanings.size() > 2 ? spec.meanings[2] : ""};
  cloth.params.erase(kSheenRoughnessMinParam);
  return cloth;
}

std::vector<double> DfgLayoutValues(const TableSpec& spec, double a, double b) {
  if (HasFilamentChannels(spec)) return {b, a + b};
  return {a, b};
}

void ApplyEngineGrid(TableSpec& spec) {
  bool mu = false, roughness = false;
  const bool sheen = IsSheenSpec(spec);
  for (AxisSpec& a : spec.axes) {
    if (a.name != "mu" && a.name != "roughness") continue;
    // A sheen table's axes start at its model's floor (roughness 0.045, charlie-smith's mu
    // 1e-4); on the engine grid they span [0, 1] and the shader's clamp defines the rest.
    const double floor = a.name == "roughness" ? kSheenTableMinRoughness : kCharlieSmithMinMu;
    const bool sheenFloor = sheen && a.lo > 0 && a.lo <= floor;
    if ((a.lo != 0 && !sheenFloor) || a.hi != 1)
      throw std::invalid_argument("--grid engine: table '" + spec.name + "' axis " + a.name +
                                  " spans [" + std::to_string(a.lo) + ", " + std::to_string(a.hi) +
                                  "], not [0, 1]");
    const int n = std::max(a.size, 2);
    a.size = n;
    a.lo = 0.5 / n;
    a.hi = 1.0 - 0.5 / n;
    a.warp = Warp::Linear;
    (a.name == "mu" ? mu : roughness) = true;
  }
  if (!mu || !roughness)
    throw std::invalid_argument("--grid engine needs (mu, roughness) axes; table '" + spec.name +
                                "' has " + (mu ? "no roughness axis" : "no mu axis"));
  if (sheen) spec.params[kSheenRoughnessMinParam] = kSheenShaderMinRoughness;
  spec.name += "-engine";
}

void ApplyFlipY(TableSpec& spec) {
  spec.params["flip_y"] = 1;
  spec.name += "-flipy";
}

void ApplyEngineOptions(TableSpec& spec, const EngineOptions& options) {
  ApplyDfgLayout(spec, options.layout);
  if (options.engineGrid) ApplyEngineGrid(spec);
  if (options.flipY) ApplyFlipY(spec);
}

}  // namespace kiln
