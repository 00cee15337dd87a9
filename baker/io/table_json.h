// A table's description as JSON fields, the same in manifest.json and in the kiln.json metadata
// of the KTX2 and PNG16 files.
#pragma once
#include <nlohmann/json.hpp>

#include "kiln/table.h"

namespace kiln {

/// The axes as a JSON array, each {name, lo, hi, size, warp} (warp by name): as the manifest,
/// kiln.json, `kiln inspect --json` and `kiln plan --json` write them.
nlohmann::ordered_json AxesJson(const std::vector<TableAxis>& axes);

/// Appends to `j`, in this order: model, quantity, channels, channel_meanings, axes (name, lo,
/// hi, size, warp each), params, method, tolerance, bake_error and lookup_error (max, rms,
/// filter, where): what a table says about itself, as its kiln.* attributes do.
void AppendTableDescription(nlohmann::ordered_json& j, const Table& t);

}  // namespace kiln
