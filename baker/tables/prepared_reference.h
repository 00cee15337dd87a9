// The lookup-error search's reference at many points of one table (SearchReference,
// EvaluateSpec) with what does not depend on the point resolved once.
#pragma once
#include <vector>

#include "baker/tables/spec.h"

namespace kiln {

/// SearchReference and EvaluateSpec(spec, x, stats) of one spec, with what does not depend on
/// the point looked up once (the kind's descriptor, whether the fixed rule applies, whether a
/// sheen table's roughness clamp applies; each a model-name lookup per point otherwise): the
/// same values, stats and exceptions at every point. Keeps a reference to `spec`. Thread-safe.
class PreparedReference {
 public:
  explicit PreparedReference(const TableSpec& spec);
  /// SearchReference(spec, x, stats).
  std::vector<double> Search(const double* x, IntegrationStats& stats) const;
  /// EvaluateSpec(spec, x, stats): the bake's own method.
  std::vector<double> Bake(const double* x, IntegrationStats& stats) const;

 private:
  const TableSpec& spec_;
  const QuantityInfo& q_;
  bool clamp_ = false;  ///< the sheen roughness clamp applies: the general path
  bool fixed_ = false;  ///< UsesFixedRule(spec)
};

}  // namespace kiln
