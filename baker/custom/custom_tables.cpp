#include "baker/custom/custom_tables.h"

#include "baker/custom/custom_registry.h"

namespace kiln {

std::vector<TableSpec> CustomModelTables() {
  std::vector<TableSpec> out;
  for (const std::string& id : CustomModelIds()) {
    const ModelInfo* info = FindModel(id);
    std::vector<Quantity> kinds = {Quantity::Albedo, Quantity::AlbedoAvg};
    if (info->specular()) kinds.push_back(Quantity::Dfg);
    for (Quantity k : kinds) {
      const QuantityInfo& q = Describe(k);
      out.push_back(q.makeSpec(id, q.defaultAxes(id)));
    }
  }
  return out;
}

}  // namespace kiln
