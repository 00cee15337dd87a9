// unity-nhxroughness-native: Unity's unity_NHxRoughness texture at Unity's own resolution and
// layout (issue #16), T(x, r) = UnityNHxRoughnessTexel (baker/models/unity.h) baked exactly at
// its texel centres, x = (R.L)^4 and r perceptual roughness, both linear. Unity's generator
// (GeneratedTextures.cpp) is not public and no source we could search states the texture's size:
// assumed 64 x 64, texel-centred (centres at (i + 0.5) / 64), as a node-centred kiln table over
// [0.5 / 64, 63.5 / 64]^2, the square a GPU with clamp-to-edge interpolates; outside it the
// lookup clamps, as the GPU does. On request only: its lookup error is that of Unity's texture,
// far above the catalogue's 1e-3 (the lobe of r < 0.316 lives within x in [0.998, 1], inside the
// last texel), which is the finding (docs/models.md "unity-nhxroughness"); unity-nhxroughness is
// the same T within 1e-3.
#include "baker/models/unity.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::UnityNHxRoughnessNative, QuantityName(Quantity::UnityNHxRoughnessNative),
               "none", {"T"},
               {"T = min(1, (n + 2) / (2 pi^2) x^(n/4) / 16), n = UnitySpecPower(r) / 4: Unity's "
                "unity_NHxRoughness texel at x = (R.L)^4, perceptual roughness r"},
               std::move(axes));
}

/// 64 x 64 texel centres (an assumption: see above).
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  constexpr double lo = 0.5 / 64, hi = 63.5 / 64;
  return {{"x", lo, hi, 64, Warp::Linear}, {"r", lo, hi, 64, Warp::Linear}};
}

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", DefaultAxes(""))};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  return {UnityNHxRoughnessTexel(x[0], x[1])};
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

}  // namespace

const QuantityInfo& UnityNHxRoughnessNativeQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::UnityNHxRoughnessNative;
    q.name = "unity-nhxroughness-native";
    q.description = "Unity's BRDF3 lobe texture at Unity's 64 x 64 texel centres (assumed)";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.inDefaultCatalogue = false;
    q.evaluate = Evaluate;
    q.method = Method;
    return q;
  }();
  return info;
}

}  // namespace kiln
