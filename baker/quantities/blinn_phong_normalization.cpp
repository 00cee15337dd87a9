// blinn-phong-normalization: normalised Blinn-Phong's exact factor N(s) and the (s + 2.04) / (8 pi)
// approximation over the exponent s, each stored divided by its linear part (s + 2) / (8 pi)
// (channels exact_ratio, approx_ratio; kiln/stored.h BlinnPhongRatio). The factors grow to 398
// at s = 10^4, where a log axis of 1024 nodes interpolated them to 4e-3 absolute; the ratios lie
// in [1, 1.55] and are smooth in log(s).
#include "baker/models/specular.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Of blinn-phong-normalized: `model` is ignored.
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(
      Quantity::BlinnPhongNormalization, QuantityName(Quantity::BlinnPhongNormalization),
      "blinn-phong-normalized", {"exact_ratio", "approx_ratio"},
      {"2 / (2 - 2^(-s/2)): the exact factor (s + 2) / (4 pi (2 - 2^(-s/2))) over "
       "(s + 2) / (8 pi)",
       "(s + 2.04) / (s + 2): the approximation (s + 2.04) / (8 pi) over (s + 2) / (8 pi)"},
      std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) { return {{"s", 1, 10000, 1024, Warp::Log}}; }

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("", DefaultAxes(""))};
}

/// The channels at s = x[0]: the ratios, or the factors themselves for a file written before
/// issue #12 (channels exact, approx).
std::vector<double> Evaluate(const TableSpec& spec, const double* x, double,
                             IntegrationStats& stats) {
  ++stats.evals;
  const bool ratio = spec.channels.empty() || spec.channels[0] != "exact";
  const double linear = ratio ? (x[0] + 2) / (8 * Pi) : 1;
  return {NormalizedBlinnPhong::Normalization(x[0]) / linear,
          NormalizedBlinnPhong::NormalizationApprox(x[0]) / linear};
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

}  // namespace

const QuantityInfo& BlinnPhongNormalizationQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::BlinnPhongNormalization;
    q.name = "blinn-phong-normalization";
    q.description = "normalised Blinn-Phong's factor, exact and approximated";
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
