// blinn-phong-normalization: normalised Blinn-Phong's exact factor and the (s + 2.04) / (8 pi)
// approximation, over the exponent s -> exact, approx.
#include "baker/models/specular.h"
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// Of blinn-phong-normalized: `model` is ignored.
TableSpec MakeSpec(const std::string&, std::vector<AxisSpec> axes) {
  return Shell(Quantity::BlinnPhongNormalization, QuantityName(Quantity::BlinnPhongNormalization),
               "blinn-phong-normalized", {"exact", "approx"},
               {"(s + 2) / (4 pi (2 - 2^(-s/2)))", "(s + 2.04) / (8 pi)"}, std::move(axes));
}

std::vector<AxisSpec> DefaultAxes(const std::string&) { return {{"s", 1, 10000, 1024, Warp::Log}}; }

std::vector<TableSpec> Catalogue(const CatalogueOptions&) {
  return {MakeSpec("", DefaultAxes(""))};
}

std::vector<double> Evaluate(const TableSpec&, const double* x, double, IntegrationStats& stats) {
  ++stats.evals;
  return {NormalizedBlinnPhong::Normalization(x[0]),
          NormalizedBlinnPhong::NormalizationApprox(x[0])};
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
