#include "baker/io/table_json.h"

namespace kiln {

void AppendTableDescription(nlohmann::ordered_json& j, const Table& t) {
  j["model"] = t.model;
  j["quantity"] = t.quantity;
  j["channels"] = t.channels;
  j["channel_meanings"] = t.channelMeanings;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const TableAxis& a : t.axes)
    axes.push_back({{"name", a.name},
                    {"lo", a.axis.lo},
                    {"hi", a.axis.hi},
                    {"size", a.axis.size},
                    {"warp", warpName(a.axis.warp)}});
  j["axes"] = axes;
  j["params"] = t.params;
  j["method"] = t.method;
  j["tolerance"] = t.tolerance;
  j["bake_error"] = t.bakeError;
  j["lookup_error"] = {{"max", t.lookupError.max},
                       {"rms", t.lookupError.rms},
                       {"filter", t.lookupError.filter},
                       {"where", t.lookupError.where}};
}

}  // namespace kiln
