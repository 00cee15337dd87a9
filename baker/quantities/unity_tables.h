// The albedo and albedo-avg tables of Unity's, Ward's and Lafortune's models (issue #16): on
// request only (QuantityInfo::onRequest of the albedo kinds), each by a fixed rule held to the
// adaptive integrator. Today unity-brdf1 (integrate/fixed_rule_microfacet.h, FixedRuleNdf::
// UnityBRDF1); the others are listed in docs/models.md with why they have none yet.
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {
struct CatalogueOptions;

/// The models whose albedo tables are baked on request.
const std::vector<std::string>& OnRequestAlbedoModels();

/// The albedo kind's on-request entries: `M-albedo` for M in OnRequestAlbedoModels().
std::vector<TableSpec> OnRequestAlbedoTables(const CatalogueOptions& opt);

/// The albedo-avg kind's on-request entries: `M-albedo-avg`, 64 roughness nodes.
std::vector<TableSpec> OnRequestAlbedoAvgTables(const CatalogueOptions& opt);

}  // namespace kiln
