// What `kiln plan` prints: each planned table with its axes, size, reasons and whether the output
// folder already holds it up to date; then what needs no table, and why.
#pragma once
#include <string>

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

}  // namespace kiln
