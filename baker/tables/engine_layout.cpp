// Engine layouts of a table spec: DFG channel layouts, the engine grid, flipped rows.
#include "baker/tables/engine_layout.h"

#include <algorithm>
#include <stdexcept>

namespace kiln {
namespace {

constexpr const char* kFilamentChannels[2] = {"B", "A_plus_B"};

bool HasFilamentChannels(const TableSpec& spec) {
  return spec.channels.size() == 2 && spec.channels[0] == kFilamentChannels[0] &&
         spec.channels[1] == kFilamentChannels[1];
}

}  // namespace

DfgLayout ParseDfgLayout(const std::string& text) {
  if (text == "kiln") return DfgLayout::Kiln;
  if (text == "ue4") return DfgLayout::Ue4;
  if (text == "filament") return DfgLayout::Filament;
  throw std::invalid_argument("unknown --layout '" + text + "' (kiln, ue4 or filament)");
}

void ApplyDfgLayout(TableSpec& spec, DfgLayout layout) {
  if (layout == DfgLayout::Kiln) return;
  if (spec.quantity != Quantity::Dfg)
    throw std::invalid_argument(std::string("--layout ") +
                                (layout == DfgLayout::Ue4 ? "ue4" : "filament") +
                                " applies to dfg tables; '" + spec.name + "' is " +
                                QuantityName(spec.quantity) + " (pick dfg tables with --only)");
  if (layout == DfgLayout::Ue4) return;  // (scale, bias) in (R, G): kiln's own order
  // Filament (libs/ibl/src/CubemapIBL.cpp, DFV_Multiscatter, used by cmgen --ibl-dfg and the
  // engine's built-in DFG LUT): DFV.x = integral of Fc V ... = B, DFV.y = integral of V ... =
  // A + B, and the shader reconstructs E = mix(DFV.x, DFV.y, f0) = (1 - f0) B + f0 (A + B).
  spec.channels = {kFilamentChannels[0], kFilamentChannels[1]};
  spec.meanings = {"Filament DFG.x = B = integral f/F (1 - o.h)^5 mu_l dl",
                   "Filament DFG.y = A + B = integral f/F mu_l dl, E = mix(x, y, F0)"};
  spec.name += "-filament";
}

std::vector<double> DfgLayoutValues(const TableSpec& spec, double a, double b) {
  if (HasFilamentChannels(spec)) return {b, a + b};
  return {a, b};
}

void ApplyEngineGrid(TableSpec& spec) {
  bool mu = false, roughness = false;
  for (AxisSpec& a : spec.axes) {
    if (a.name != "mu" && a.name != "roughness") continue;
    if (a.lo != 0 || a.hi != 1)
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

bool FlipsY(const Table& table) {
  for (const std::string& kv : splitList(table.params, ';'))
    if (kv == "flip_y=1") return true;
  return false;
}

}  // namespace kiln
