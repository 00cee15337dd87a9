// The registry: tables/quantity_list.inc's kinds, each described by its own file.
#include <stdexcept>

#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"

namespace kiln {

#define KILN_QUANTITY(id) const QuantityInfo& id##Quantity();
#include "baker/tables/quantity_list.inc"
#undef KILN_QUANTITY

const std::vector<const QuantityInfo*>& AllQuantities() {
  static const std::vector<const QuantityInfo*> all = [] {
    std::vector<const QuantityInfo*> v = {
#define KILN_QUANTITY(id) &id##Quantity(),
#include "baker/tables/quantity_list.inc"
#undef KILN_QUANTITY
    };
    // Describe() indexes by the enum: each descriptor must carry its own id, in list order.
    for (size_t i = 0; i < v.size(); ++i)
      if (static_cast<size_t>(v[i]->id) != i)
        throw std::logic_error(std::string("quantity registry: '") + v[i]->name + "' out of order");
    return v;
  }();
  return all;
}

const QuantityInfo& Describe(Quantity q) { return *AllQuantities().at(static_cast<size_t>(q)); }

const QuantityInfo* FindQuantity(std::string_view name) {
  for (const QuantityInfo* q : AllQuantities())
    if (name == q->name) return q;
  return nullptr;
}

std::string TableName(Quantity q, const std::string& model) {
  const QuantityInfo& info = Describe(q);
  return info.makeSpec(model, info.defaultAxes(model)).name;
}

}  // namespace kiln
