// The built-in BRDF models, without the run-time ones a test of the same process registered (a
// user's lobe, baker/custom/): the tests that walk "every model" check kiln's own models, and
// their verdicts must not depend on which tests ran before them in one process.
#pragma once
#include <functional>
#include <vector>

#include "baker/models/registry.h"

namespace kiln::test {

/// AllModels() without the run-time models (ModelInfo::codeHash set: a user's lobe), in order.
inline std::vector<std::reference_wrapper<const ModelInfo>> BuiltInModels() {
  std::vector<std::reference_wrapper<const ModelInfo>> out;
  for (const ModelInfo& m : AllModels())
    if (m.codeHash.empty()) out.push_back(std::cref(m));
  return out;
}

}  // namespace kiln::test
