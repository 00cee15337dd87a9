// The scene commands of the kiln command line (see docs/scene.md). `kiln bake --scene` calls
// BakeScene (baker/scene/bake_scene.h).
#pragma once
#include <CLI/CLI.hpp>

namespace kiln::cli {

/// kiln plan SCENE [--out DIR] [--size N] [--check] [--json]: prints the tables a glTF 2.0 asset
/// (.gltf, .glb) or a kiln scene manifest needs, why, their ranges and sizes, whether DIR
/// (default luts/) holds them up to date, and what needs no table (--json: as one JSON object,
/// FormatPlanJson). With --check, exits 1 after the report when a table is missing or stale. A
/// bad scene file is an error naming the file and the JSON pointer (exit 1); warnings go to
/// stderr.
void RegisterPlan(CLI::App& app);

}  // namespace kiln::cli
