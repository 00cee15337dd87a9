// unity-nhxroughness: the texture Unity's BRDF3_Unity_PBS reads its specular lobe from
// (unity_NHxRoughness, UnityStandardBRDF.cginc; issue #16), T(x, r) = min(1, P) with
//   P = (n + 2) / (2 pi^2) x^(n/4) / 16,  n = PerceptualRoughnessToSpecPower(r) / 4,
// x = (R.L)^4 in [0, 1], r perceptual roughness in [0, 1] (UnityNHxRoughnessTexel in
// baker/models/unity.h; docs/models.md "unity-nhxroughness").
//
// Axes: the lobe exponent, not (x, r). The lobe x^(n/4) = exp(-(n/4) u), u = -ln x, falls from 1
// to 0 over u ~ 4 / n: within x in [0.998, 1] for r < 0.316 (n up to 4999.5 at r <= 0.1), and,
// at r -> 1 (n down to 2.5e-5), only below x ~ 1e-300, beyond any warp of x in double precision
// (at r = 1 the texel jumps from 0 at x = 0 to 0.0063 at the smallest double). In
//   s = ln(n / 4) + ln(u)
// the lobe is exp(-e^s) for every roughness: one curve, neither a layer nor a jump, and P is
// (n + 2) / (32 pi^2) exp(-e^s), linear in n at fixed s. So the table is P over (s, n): s linear
// over [-16, 4] (at s = -16, P is within (n + 2) / (32 pi^2) e^-16 <= 1.8e-6 of its value at
// x = 1, s = -infinity; at s = 4, exp(-e^4) = 2e-24 of the value 0 at x = 0), n linear over
// Unity's own range [UnitySpecPower(1), UnitySpecPower(0)] / 4 with 2 nodes (bilinear is exact in
// n), so r needs no floor: the whole domain [0, 1]^2 maps into the axes. The channel is P before
// Unity's clamp at 1 (a clamped channel would put a kink, e^s = ln((n + 2) / (32 pi^2)), on a
// curve across the cells); the runtime's min(1, P) is 1-Lipschitz, so T keeps P's bound
// (kiln/stored.h StoredForm::UnityLobe: the coordinates from (x, r) and the clamp).
// 768 nodes along s: the linear-interpolation error of 15.8 exp(-e^s) is 15.8 * 0.31 h^2 / 8 at
// h = 20 / 767, below 1e-3 (docs/catalogue.md gives the measured figure).
#include "baker/models/unity.h"
#include "baker/quantities/common.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Model-free: `model` is ignored ("none").
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::UnityNHxRoughness, QuantityName(Quantity::UnityNHxRoughness), "none",
               {"P"},
               {"P = (n + 2) / (2 pi^2) x^(n/4) / 16 at s = ln(n / 4) + ln(-ln x), n = "
                "UnitySpecPower(r) / 4: Unity's unity_NHxRoughness texel before its clamp, "
                "T(x, r) = min(1, P)"},
               std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"s", -16, 4, 768, Warp::Linear},
          {"n", UnitySpecPower(1) / 4, UnitySpecPower(0) / 4, 2, Warp::Linear}};
}

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("none", DefaultAxes(""))};
}

/// P at x = (s, n): the lobe x^(n/4) is exp(-e^s) there.
std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  double n = x[1];
  return {(n + 2) / (2 * Pi * Pi) * std::exp(-std::exp(x[0])) / kUnityNHxRoughnessRange};
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

}  // namespace

const QuantityInfo& UnityNHxRoughnessQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::UnityNHxRoughness;
    q.name = "unity-nhxroughness";
    q.description = "Unity's BRDF3 lobe texture T((R.L)^4, r), on lobe-exponent axes";
    q.makeSpec = MakeSpec;
    q.defaultAxes = DefaultAxes;
    q.catalogue = Catalogue;
    q.evaluate = Evaluate;
    q.method = Method;
    return q;
  }();
  return info;
}

}  // namespace kiln
