// Specification of `kiln bake --preset filament` against Filament's own generated DFG table
// (tests/engines/filament_dfg_lut.csv: Filament v1.19.0's generated/data/dfg.inc, 64 x 64,
// origin and licence in tests/engines/README.md; docs/engines.md "filament"). Filament's cmgen
// writes row j at roughness (j + 1.5) / N, one texel above the centre (j + 0.5) / N its shader
// samples and kiln bakes: kiln's row j + 1 is Filament's row j.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include "baker/bake/bake.h"
#include "baker/tables/engine_presets.h"

namespace {

/// The size of Filament v1.19.0's dfg.inc (later versions: 128).
constexpr int kFilamentSize = 64;
/// Filament's texels are Monte Carlo estimates (1024 samples; the cloth channel 4096) stored as
/// halves: kiln's next row lies within this of them (measured 0.0041 in R, 0.0126 in G at the
/// grazing column, 0.0073 in the cloth channel: docs/engines.md "filament").
constexpr double kFilamentTolerance = 0.015;
/// Filament's rows below this hold the cloth channel at a roughness under the shaders' 0.045
/// clamp (r = 1.5/64 and 2.5/64), where kiln's sheen table holds the clamped value.
constexpr int kFirstClampedClothRow = 2;

using Texel = std::array<double, 3>;

/// tests/engines/filament_dfg_lut.csv: (row, col) -> (R, G, B) = (B, A + B, cloth DFG).
std::map<std::pair<int, int>, Texel> FilamentReference() {
  std::ifstream in(std::string(KILN_SOURCE_DIR) + "/tests/engines/filament_dfg_lut.csv");
  std::map<std::pair<int, int>, Texel> ref;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;
    int row = 0, col = 0;
    Texel v{};
    REQUIRE(std::sscanf(line.c_str(), "%d,%d,%lf,%lf,%lf", &row, &col, &v[0], &v[1], &v[2]) == 5);
    ref[{row, col}] = v;
  }
  REQUIRE(ref.size() == 19 * 19);
  return ref;
}

/// The largest |kiln - filament| in channel `c` over Filament's texels (row, col) below the last
/// row, reading kiln's texel (row + rowShift, col); with `flip`, kiln's rows reversed. Rows
/// below `firstRow` are left out.
double MaxFilamentDifference(const kiln::Table& t, const std::map<std::pair<int, int>, Texel>& ref,
                             int c, int rowShift, bool flip = false, int firstRow = 0) {
  double worst = 0;
  for (const auto& [key, v] : ref) {
    const int row = key.first, col = key.second;
    if (row < firstRow || row + rowShift >= kFilamentSize) continue;
    const int kilnRow = flip ? kFilamentSize - 1 - (row + rowShift) : row + rowShift;
    const double kilnValue = t.data[(size_t(kilnRow) * kFilamentSize + size_t(col)) * 3 + c];
    worst = std::max(worst, std::fabs(kilnValue - v[c]));
  }
  return worst;
}

}  // namespace

TEST_CASE("preset filament at 64 x 64: kiln's row j + 1 is Filament v1.19.0's dfg.inc row j",
          "[engine-presets][filament]") {
  const kiln::EnginePreset& filament = kiln::FindEnginePreset("filament");
  const std::vector<kiln::TableSpec> specs = kiln::PresetSpecs(filament, kFilamentSize);
  REQUIRE(specs.size() == 1);
  kiln::BakeOptions opt;
  opt.threads = 2;
  opt.measureLookupError = false;
  const kiln::Table t = kiln::BakeTable(specs[0], opt);
  REQUIRE(t.channels.size() == 3);
  const auto ref = FilamentReference();

  // Filament's row j holds roughness (j + 1.5) / 64: kiln's row j + 1.
  CHECK(MaxFilamentDifference(t, ref, 0, 1) < kFilamentTolerance);
  CHECK(MaxFilamentDifference(t, ref, 1, 1) < kFilamentTolerance);
  CHECK(MaxFilamentDifference(t, ref, 2, 1, false, kFirstClampedClothRow) < kFilamentTolerance);
  // At the texel centres the shader samples (kiln's row j) Filament's table is one texel off:
  // measured 0.054 in R, 0.046 in G, 0.94 in the cloth channel.
  CHECK(MaxFilamentDifference(t, ref, 0, 0) > 0.04);
  CHECK(MaxFilamentDifference(t, ref, 2, 0, false, kFirstClampedClothRow) > 0.5);
  // Reversed rows or another channel order are far off.
  CHECK(MaxFilamentDifference(t, ref, 1, 1, true) > 0.3);
  kiln::Table swapped = t;
  for (size_t i = 0; i < swapped.data.size(); i += 3)
    std::swap(swapped.data[i], swapped.data[i + 1]);
  CHECK(MaxFilamentDifference(swapped, ref, 0, 1) > 0.3);
}
