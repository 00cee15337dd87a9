// Engine layouts of a table spec (issue #14): the DFG channel layouts engines expect
// (--layout kiln|ue4|filament), the texel-centred grid engines sample with
// texture(lut, vec2(NoV, roughness)) (--grid engine) and a flipped row order (--flip-y). Each is
// a change of the spec, so it changes the spec hash (and the table name) of what it bakes.
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

/// The channel layouts of a dfg table.
enum class DfgLayout {
  Kiln,      ///< R = A (scale of F0), G = B (bias): E = F0 A + F90 B
  Ue4,       ///< Unreal's PreIntegratedGF / EnvBRDF: R = scale, G = bias, i.e. kiln's (same bytes)
  Filament,  ///< Filament's multiscatter DFG: R = B, G = A + B; E = mix(R, G, F0)
};

/// Parses "kiln", "ue4" or "filament"; throws std::invalid_argument
/// ("unknown --layout 'x' (kiln, ue4 or filament)") otherwise.
DfgLayout ParseDfgLayout(const std::string& text);

/// Applies `layout` to `spec`. Kiln and Ue4 leave it unchanged (Unreal's EnvBRDF LUT stores
/// (scale, bias) in (R, G), which is kiln's order). Filament renames the channels to
/// {"B", "A_plus_B"} with their meanings and appends "-filament" to the name; EvaluateSpec then
/// returns (B, A + B) (DfgLayoutValues), so the bake, the lookup-error measurement and
/// `kiln verify` all see the Filament values. Throws std::invalid_argument
/// ("--layout filament applies to dfg tables; 'x' is albedo") for a non-kiln layout on a table
/// whose quantity is not dfg.
void ApplyDfgLayout(TableSpec& spec, DfgLayout layout);

/// The channel values of a dfg spec from kiln's (A, B): (A, B), or (B, A + B) when the spec has
/// the Filament channels of ApplyDfgLayout.
std::vector<double> DfgLayoutValues(const TableSpec& spec, double a, double b);

/// Turns the spec's mu and roughness axes (each must span [0, 1]) into the texel-centred grid
/// engines sample: N nodes (the axis's own size, at least 2) over [0.5 / N, 1 - 0.5 / N] with the
/// linear warp, so node i sits at (i + 0.5) / N and kiln's texture coordinate of a value x
/// (Axis::gpuCoord) is x itself: a shader's texture(lut, vec2(NoV, roughness)) reads the table
/// with the plain values, clamped to the edge texels' centres below 0.5 / N and above
/// 1 - 0.5 / N. Other axes are kept. Appends "-engine" to the name. Throws std::invalid_argument
/// naming the table when it has no mu or no roughness axis, or one not spanning [0, 1].
void ApplyEngineGrid(TableSpec& spec);

/// Marks the spec as written with its rows in reverse order within each axis-2 slice (row 0 =
/// the last node of axis 1): params["flip_y"] = 1 (so the spec hash changes) and "-flipy"
/// appended to the name. The texels in memory stay in kiln order; the writers flip (FlipsY).
void ApplyFlipY(TableSpec& spec);

/// What `kiln bake --layout/--grid/--flip-y` asks for.
struct EngineOptions {
  DfgLayout layout = DfgLayout::Kiln;
  bool engineGrid = false;  ///< --grid engine
  bool flipY = false;       ///< --flip-y
};

/// ApplyDfgLayout, then ApplyEngineGrid and ApplyFlipY when asked (so a name reads
/// <table>[-filament][-engine][-flipy]); throws as they do. The defaults change nothing.
void ApplyEngineOptions(TableSpec& spec, const EngineOptions& options);

/// True when `table`'s params carry flip_y=1 (ApplyFlipY).
bool FlipsY(const Table& table);

}  // namespace kiln
