// The committed tables' texels against the bake's own evaluation, for the tests that hold a
// faster form of a rule to the same bits.
#pragma once
#include <cstring>
#include <string>
#include <vector>

#include "baker/tables/spec.h"
#include "committed_luts.h"
#include "kiln/exr_loader.h"

namespace kiln::test {

/// How many texels of every `stride`-th node of the committed table `name` (luts/NAME.exr, one
/// part) differ, as float32 bits, from the table's rule evaluated there as the bake evaluates it
/// (NodeEvaluationPoint, EvaluateSpec). A stride prime to the axes' sizes visits every row and
/// column. -1 when the file's texel count does not match its spec.
inline int TexelsDifferingFromRule(const std::string& name, size_t stride) {
  const Table t = loadTable(LutsDir() + "/" + name + ".exr");
  const TableSpec spec = SpecFromTable(t);
  const size_t n = spec.TexelCount(), nc = spec.channels.size();
  if (t.data.size() != n * nc) return -1;
  int differing = 0;
  for (size_t i = 0; i < n; i += stride) {
    double x[3];
    NodeEvaluationPoint(spec, i, x);
    IntegrationStats st;
    const std::vector<double> v = EvaluateSpec(spec, x, st);
    for (size_t c = 0; c < nc; ++c) {
      const float f = static_cast<float>(v[c]);
      differing += std::memcmp(&f, &t.data[i * nc + c], sizeof f) != 0;
    }
  }
  return differing;
}

}  // namespace kiln::test
