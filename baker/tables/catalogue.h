// The default catalogue: every table an engine or renderer wants from kiln's models, with the
// sizes and warps chosen so that the lookup error stays small (docs/catalogue.md).
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

struct CatalogueOptions {
  int size = 0;                ///< 0: each table's default; otherwise every axis gets this size
  double brdfRoughness = 0.5;  ///< roughness of the full-BRDF tables (*-brdf)
};

/// Every table of the default catalogue, in a fixed order (quantity by quantity, in registry
/// order; each quantity's descriptor lists its entries).
std::vector<TableSpec> DefaultCatalogue(const CatalogueOptions& opt = {});

/// The tables kiln bakes only on request (`--only`, a scene): kinds with
/// QuantityInfo::inDefaultCatalogue false, in registry order.
std::vector<TableSpec> OnRequestTables(const CatalogueOptions& opt = {});

/// The catalogue entry with this name, in the default catalogue or on request; throws
/// std::invalid_argument naming the unknown table.
TableSpec CatalogueTable(const std::string& name, const CatalogueOptions& opt = {});

/// The models the catalogue bakes its per-model tables for (quantity descriptors iterate them).
const std::vector<std::string>& CatalogueMicrofacetModels();
const std::vector<std::string>& CatalogueDiffuseModels();
/// The sheen models whose default axes are chosen here (docs/models.md "Sheen tables").
const std::vector<std::string>& CatalogueSheenModels();

/// Whether a sheen table (`M-dfg`, `M-albedo`, `M-albedo-avg` of a CatalogueSheenModels model)
/// is in the default catalogue; the others are on request. All nine are: charlie-smith's three
/// and charlie-albedo-avg joined once charlie-smith's own node counts, the Charlie pair's
/// average panels and the albedo's shared lookup-error search brought them within the sheen
/// tables' share of the catalogue's time (docs/catalogue.md).
bool SheenTableInDefaultCatalogue(const std::string& name);

/// The catalogue's default axes (size and warp chosen per model; quantity descriptors choose
/// the rest, baker/quantities/).
/// The roughness axis of a model's tables: sqrt for microfacet models, linear for the others, a
/// 2-node constant axis for a model without roughness. Throws for an unknown model.
AxisSpec DefaultRoughnessAxis(const std::string& model);
/// The mu axis of a diffuse albedo table (sqrt, or angle for the models smooth in theta_o).
AxisSpec DiffuseMuAxis(const std::string& model);
/// The eta axis of the dielectric tables: [1, 3], 24 nodes, sqrt (dense near 1).
AxisSpec DefaultEtaAxis();

}  // namespace kiln
