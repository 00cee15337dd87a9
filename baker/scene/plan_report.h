// What `kiln plan` prints: each planned table with its axes, size, reasons and whether the output
// folder already holds it up to date; then what needs no table, and why.
#pragma once
#include <string>
#include <vector>

#include "baker/scene/plan.h"

namespace kiln {

/// Whether DIR/<name>.exr holds `spec`: its stored spec hash equals spec.Hash().
enum class TableState { UpToDate, Stale, Missing };

TableState StateOf(const TableSpec& spec, const std::string& dir);

/// "up to date", "stale" (a file with another spec hash, or not a kiln table) or "missing".
const char* StateName(TableState state);

/// One line: "mu 0..1 (64, sqrt) x roughness 0.3..0.6 (20, linear)".
std::string AxesText(const TableSpec& spec);

/// The report `kiln plan` prints for `plan` against output folder `dir`.
std::string FormatPlan(const Plan& plan, const std::string& dir);

/// The state of each table of `plan` in `dir` (StateOf), in plan order.
std::vector<TableState> PlanStates(const Plan& plan, const std::string& dir);

/// What `kiln plan --json` prints: one JSON object (2-space indented, a final newline) with
///   "scene" (path), "format" ("glTF", "glb", "kiln scene"), "materials" (count), "dir",
///   "tables": [{"name", "state" ("up to date" | "stale" | "missing"), "file" (DIR/<name>.exr),
///     "quantity", "model", "channels" [..], "axes" [{"name", "lo", "hi", "size", "warp"}],
///     "params" {name: value} (axes the scene fixed), "texels", "bytes_float32",
///     "scene_uses" {axis: "0.3" | "0.2..0.6" | "whole axis"}, "needed_by" [..], "spec_hash"}],
///   "up_to_date", "stale", "missing" (counts), "notes": [{"kind" ("no table" | "no effect" |
///   "not yet" | "unknown" | "unused"), "topic", "why", "materials" [..]}], "warnings" [..].
std::string FormatPlanJson(const Plan& plan, const std::string& dir);

}  // namespace kiln
