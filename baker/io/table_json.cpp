#include "baker/io/table_json.h"

namespace kiln {

nlohmann::ordered_json AxesJson(const std::vector<TableAxis>& axes) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const TableAxis& a : axes) {
    out.push_back({{"name", a.name},
                   {"lo", a.axis.lo},
                   {"hi", a.axis.hi},
                   {"size", a.axis.size},
                   {"warp", warpName(a.axis.warp)}});
    // A constant split point of a root4-layer-split axis (absent: the critical cosine).
    if (a.axis.hasConstantSplit()) out.back()["split"] = a.axis.split;
  }
  return out;
}

void AppendTableDescription(nlohmann::ordered_json& j, const Table& t) {
  j["model"] = t.model;
  j["quantity"] = t.quantity;
  j["channels"] = t.channels;
  j["channel_meanings"] = t.channelMeanings;
  j["axes"] = AxesJson(t.axes);
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
