// Engine layouts of a table spec (issue #14): the DFG channel layouts engines expect
// (--layout kiln|ue4|filament|filament-cloth), the texel-centred grid engines sample with
// texture(lut, vec2(NoV, roughness)) (--grid engine) and a flipped row order (--flip-y). Each is
// a change of the spec, so it changes the spec hash (and the table name) of what it bakes.
#pragma once
#include <string>
#include <vector>

#include "baker/models/sheen.h"
#include "baker/tables/spec.h"

namespace kiln {

/// The channel layouts of a dfg table.
enum class DfgLayout {
  Kiln,      ///< R = A (scale of F0), G = B (bias): E = F0 A + F90 B
  Ue4,       ///< Unreal's PreIntegratedGF / EnvBRDF: R = scale, G = bias, i.e. kiln's (same bytes)
  Filament,  ///< Filament's multiscatter DFG: R = B, G = A + B; E = mix(R, G, F0)
  /// Filament's whole DFG LUT (cmgen --ibl-dfg-multiscatter --ibl-dfg-cloth): R = B, G = A + B
  /// of GGX and B = DFV_Charlie, the Charlie sheen's cloth DFG (kiln's charlie-dfg) at the same
  /// (mu, roughness), its roughness clamped below to kSheenShaderMinRoughness as Filament's
  /// shaders clamp the cloth and sheen roughness (param sheen_roughness_min).
  FilamentCloth,
};

/// The sheen roughness below which an engine-grid sheen table (and the cloth channel of
/// DfgLayout::FilamentCloth) holds the value at this roughness: Filament clamps its sheen and
/// cloth perceptual roughness to MIN_PERCEPTUAL_ROUGHNESS = 0.045 (docs/models.md "Charlie
/// sheen"), below which kiln's Charlie models are not defined (models/sheen.h).
constexpr double kSheenShaderMinRoughness = kCharlieMinRoughness;

/// The spec param naming that clamp (written to kiln.params, part of the spec hash).
constexpr const char* kSheenRoughnessMinParam = "sheen_roughness_min";

/// The roughness at which a sheen lobe is evaluated for a node at roughness r of `spec`:
/// max(r, params[sheen_roughness_min]) when the spec has that param, else r.
double SheenRoughnessFor(const TableSpec& spec, double r);

/// Parses "kiln", "ue4", "filament" or "filament-cloth"; throws std::invalid_argument
/// ("unknown --layout 'x' (kiln, ue4, filament or filament-cloth)") otherwise.
DfgLayout ParseDfgLayout(const std::string& text);

/// Applies `layout` to `spec`. Kiln and Ue4 leave it unchanged (Unreal's EnvBRDF LUT stores
/// (scale, bias) in (R, G), which is kiln's order). Filament renames the channels to
/// {"B", "A_plus_B"} with their meanings and appends "-filament" to the name; EvaluateSpec then
/// returns (B, A + B) (DfgLayoutValues), so the bake, the lookup-error measurement and
/// `kiln verify` all see the Filament values. Throws std::invalid_argument
/// ("--layout filament applies to dfg tables; 'x' is albedo") for a non-kiln layout on a table
/// whose quantity is not dfg, and for Filament's layouts on a sheen table (one channel: it is
/// the third channel of FilamentCloth, not a (B, A + B) pair). FilamentCloth renames the
/// channels to {"B", "A_plus_B", "DFV_Charlie"}, sets params[sheen_roughness_min] and appends
/// "-filament-cloth"; the dfg kind then adds the cloth value (FilamentClothSpec).
void ApplyDfgLayout(TableSpec& spec, DfgLayout layout);

/// The channel values of a dfg spec from kiln's (A, B): (A, B), or (B, A + B) when the spec has
/// the Filament channels of ApplyDfgLayout.
std::vector<double> DfgLayoutValues(const TableSpec& spec, double a, double b);

/// True when `spec` has the channels of DfgLayout::FilamentCloth.
bool HasFilamentClothChannel(const TableSpec& spec);

/// The Charlie sheen dfg spec whose value is the cloth channel of a FilamentCloth spec (the
/// catalogue's charlie-dfg with the same axes' names): evaluate it at (mu, SheenRoughnessFor(r)).
TableSpec FilamentClothSpec(const TableSpec& spec);

/// Turns the spec's mu and roughness axes (each must span [0, 1]) into the texel-centred grid
/// engines sample: N nodes (the axis's own size, at least 2) over [0.5 / N, 1 - 0.5 / N] with the
/// linear warp, so node i sits at (i + 0.5) / N and kiln's texture coordinate of a value x
/// (Axis::gpuCoord) is x itself: a shader's texture(lut, vec2(NoV, roughness)) reads the table
/// with the plain values, clamped to the edge texels' centres below 0.5 / N and above
/// 1 - 0.5 / N. Other axes are kept. Appends "-engine" to the name. A sheen table's roughness
/// axis (which starts at kSheenTableMinRoughness, where the Charlie models end) and
/// charlie-smith's mu axis (from 1e-4, below every texel centre for N <= 4096) are taken as
/// [0, 1] too: params[sheen_roughness_min] = kSheenShaderMinRoughness says that the nodes below
/// hold the value at that roughness, as the engines' shaders clamp. Throws
/// std::invalid_argument naming the table when it has no mu or no roughness axis, or one not
/// spanning [0, 1] (a sheen table: starting above its own floor).
void ApplyEngineGrid(TableSpec& spec);

/// Marks the spec as written with its rows in reverse order within each axis-2 slice (row 0 =
/// the last node of axis 1): params["flip_y"] = 1 (so the spec hash changes) and "-flipy"
/// appended to the name. The texels in memory stay in kiln order; the writers flip
/// (io/texture_writers.h FlipsY).
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

}  // namespace kiln
