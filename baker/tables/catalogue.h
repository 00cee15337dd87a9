// The default catalogue: every table an engine or renderer wants from kiln's models, with the
// sizes and warps chosen so that the lookup error stays small (README "The catalogue").
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

struct CatalogueOptions {
  int size = 0;              ///< 0: each table's default; otherwise every axis gets this size
  double brdfRoughness = 0.5;  ///< roughness of the full-BRDF tables (*-brdf)
};

/// Every table of the default catalogue, in a fixed order.
std::vector<TableSpec> DefaultCatalogue(const CatalogueOptions& opt = {});

/// The catalogue entry with this name; throws std::invalid_argument naming the unknown table.
TableSpec CatalogueTable(const std::string& name, const CatalogueOptions& opt = {});

/// Builders the scene planner shares with the catalogue (one table kind each). The axis ranges
/// default to the catalogue's; a planner narrows them.
TableSpec DfgSpec(const std::string& model, AxisSpec mu, AxisSpec roughness);
TableSpec AlbedoSpec(const std::string& model, AxisSpec mu, AxisSpec roughness);
TableSpec AlbedoAvgSpec(const std::string& model, AxisSpec roughness);
TableSpec FresnelAlbedoSpec(AxisSpec mu, AxisSpec roughness, AxisSpec eta);
TableSpec FresnelAlbedoAvgSpec(AxisSpec roughness, AxisSpec eta);
TableSpec FresnelDielectricSpec(AxisSpec mu, AxisSpec eta);
TableSpec FresnelDielectricAvgSpec(AxisSpec eta);
TableSpec FresnelConductorSpec(AxisSpec mu, AxisSpec n, AxisSpec k);
TableSpec BlinnPhongNormalizationSpec(AxisSpec s);
TableSpec BrdfSpec(const std::string& model, double roughness, AxisSpec mu_l, AxisSpec mu_o,
                   AxisSpec phi);

/// The catalogue's default axes (size and warp chosen per table kind).
AxisSpec DefaultMuAxis(const std::string& quantity);
AxisSpec DefaultRoughnessAxis(const std::string& model);
AxisSpec DiffuseMuAxis(const std::string& model);
AxisSpec DefaultEtaAxis();

}  // namespace kiln
