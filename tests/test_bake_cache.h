// Bakes shared by the tests of one process: a test that needs a table another test of the same
// run baked with the same spec and options reads that one instead of baking it again.
#pragma once
#include <map>
#include <string>

#include "baker/bake/bake.h"
#include "baker/tables/quantity.h"

namespace kiln::test {

/// BakeTable(spec, opt), baked once per process for each (spec hash, lookup-error measurement,
/// lookup budget): bakes are bit-identical for any thread count (tests/bake_tables.cpp), so the
/// threads do not enter the key. Not thread-safe (Catch2 runs one test at a time).
inline const Table& CachedBake(const TableSpec& spec, const BakeOptions& opt) {
  static std::map<std::string, Table> baked;
  const std::string key = spec.Hash() + (opt.measureLookupError ? "/lookup/" : "/texels/") +
                          std::to_string(opt.lookupBudget);
  auto it = baked.find(key);
  if (it == baked.end()) it = baked.emplace(key, BakeTable(spec, opt)).first;
  return it->second;
}

/// A small spec of kind `q` for `model`: the kind's default axes and warps at `size` nodes each
/// (for an albedo or dfg: mu = 0 and 1, roughness 0, the smooth limit, among the nodes).
inline TableSpec SmallSpec(Quantity q, const std::string& model, int size = 9) {
  const QuantityInfo& info = Describe(q);
  std::vector<AxisSpec> axes = info.defaultAxes(model);
  for (AxisSpec& a : axes) a.size = size;
  return info.makeSpec(model, axes);
}

}  // namespace kiln::test
