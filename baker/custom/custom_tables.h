// The tables a custom model (baker/custom/) has: <id>-albedo, <id>-albedo-avg and, for a
// specular lobe, <id>-dfg, on their kinds' default axes, baked by adaptive quadrature only.
#pragma once
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

/// The tables of every custom model loaded in this process (before any size override).
std::vector<TableSpec> CustomModelTables();

}  // namespace kiln
