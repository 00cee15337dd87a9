// brdf: a model's BRDF itself (no cosine) at a fixed roughness params["roughness"], over
// (mu_l, mu_o, phi) -> f; f_rho, f_rho2 for a model with a rho^2 term.
#include "baker/quantities/common.h"

namespace kiln {
namespace {
using namespace quantity_detail;

TableSpec MakeSpec(const std::string& model, std::vector<AxisSpec> axes) {
  std::string name = model + "-" + QuantityName(Quantity::Brdf);
  if (HasRho2(model))
    return Shell(Quantity::Brdf, name, model, {"f_rho", "f_rho2"},
                 {"BRDF (no cosine), rho^1 part", "rho^2 part: f = rho f_rho + rho^2 f_rho2"},
                 std::move(axes));
  return Shell(Quantity::Brdf, name, model, {"f"}, {"BRDF value at rho = 1, cosine excluded"},
               std::move(axes));
}

/// mu from 0.02: Oren-Nayar's tan(beta) is unbounded as both directions reach the horizon.
std::vector<AxisSpec> DefaultAxes(const std::string&) {
  return {{"mu_l", 0.02, 1, 32, Warp::Sqrt},
          {"mu_o", 0.02, 1, 32, Warp::Sqrt},
          {"phi", 0, Pi, 32, Warp::Linear}};
}

/// The diffuse models whose BRDF has no cheap closed form in a shader, at opt.brdfRoughness.
std::vector<TableSpec> Catalogue(const CatalogueOptions& opt) {
  std::vector<TableSpec> out;
  for (const char* m : {"oren-nayar", "gotanda-ggx"}) {
    TableSpec s = MakeSpec(m, DefaultAxes(m));
    s.params["roughness"] = opt.brdfRoughness;
    out.push_back(s);
  }
  return out;
}

std::vector<double> Evaluate(const TableSpec& spec, const double* x, double,
                             IntegrationStats& stats) {
  ++stats.evals;
  AnyModel m = ModelAt(spec.model, Param(spec, "roughness", 0.5));
  return RhoChannels(spec, EvaluateParts(m, ViewDirection(x[1]), DirectionFromMuPhi(x[0], x[2])));
}

std::string Method(const TableSpec&) { return ClosedFormMethod(); }

}  // namespace

const QuantityInfo& BrdfQuantity() {
  static const QuantityInfo info = [] {
    QuantityInfo q;
    q.id = Quantity::Brdf;
    q.name = "brdf";
    q.description = "the BRDF itself at one roughness, cosine excluded";
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
