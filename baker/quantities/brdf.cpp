// brdf: a model's BRDF itself (no cosine) at a fixed roughness params["roughness"], one or two
// channels (f, or f_rho and f_rho2 for a model with a rho^2 term), in one of the stored forms of
// kiln/stored.h, chosen by the axis names:
// - (mu_l, mu_o, phi) or (mu_l, mu_o, cos_phi): f itself (the first is the form of files before
//   issue #12; gotanda-ggx-brdf takes the second);
// - (mu_max, mu_ratio, cos_phi), a reciprocal model only: f * mu_max with
//   mu_max = max(mu_l, mu_o), mu_ratio = min(mu_l, mu_o) / mu_max (oren-nayar-brdf).
// Why: every catalogue model here is piecewise linear in cos(phi) with its only kink at
// cos(phi) = 0 (Oren-Nayar's cos(phi) C2 and 1 - |cos(phi)|, Gotanda's back-scattering branch of
// B_p), so a cos_phi axis of 3 nodes {-1, 0, 1} interpolates it exactly and the texels go to the
// mu axes. Oren-Nayar has a kink on the diagonal theta_l = theta_o (alpha = max, beta = min),
// which the symmetric axes put on the edge mu_ratio = 1, and tan(beta) = sin(beta) / mu_max grows
// without bound at the horizon, which the factor mu_max removes.
#include <stdexcept>

#include "baker/quantities/common.h"
#include "kiln/stored.h"

namespace kiln {
namespace {
using namespace quantity_detail;

/// The stored form of a brdf spec's axes (kiln/stored.h).
StoredForm FormOf(const std::vector<AxisSpec>& axes) {
  return storedFormOf("brdf", axes.empty() ? "" : axes[0].name, axes.size() > 2 ? axes[2].name : "",
                      "");
}

TableSpec MakeSpec(const std::string& model, std::vector<AxisSpec> axes) {
  std::string name = model + "-" + QuantityName(Quantity::Brdf);
  if (FormOf(axes) == StoredForm::BrdfSymmetric) {
    if (HasRho2(model))
      return Shell(Quantity::Brdf, name, model, {"g_rho", "g_rho2"},
                   {"g_rho = f_rho max(mu_l, mu_o): the BRDF's rho^1 part (no cosine) times the "
                    "larger cosine",
                    "g_rho2 = f_rho2 max(mu_l, mu_o): f = (rho g_rho + rho^2 g_rho2) / mu_max"},
                   std::move(axes));
    return Shell(Quantity::Brdf, name, model, {"g"},
                 {"g = f max(mu_l, mu_o): the BRDF at rho = 1 (no cosine) times the larger cosine"},
                 std::move(axes));
  }
  if (HasRho2(model))
    return Shell(Quantity::Brdf, name, model, {"f_rho", "f_rho2"},
                 {"BRDF (no cosine), rho^1 part", "rho^2 part: f = rho f_rho + rho^2 f_rho2"},
                 std::move(axes));
  return Shell(Quantity::Brdf, name, model, {"f"}, {"BRDF value at rho = 1, cosine excluded"},
               std::move(axes));
}

/// A reciprocal model (oren-nayar) on the symmetric axes: mu_max from 0.02 (tan(beta) is
/// unbounded as both directions reach the horizon), mu_ratio over [0, 1] (the other direction
/// anywhere down to the horizon). A non-reciprocal one (gotanda-ggx) on (mu_l, mu_o) over [0, 1]
/// (its f is bounded). The angle warp puts nodes uniform in the angle near mu = 1, where
/// sin(theta) = sqrt(1 - mu^2) has a square-root point. Each 104 x 104 x 3 = 32448 texels, no
/// more than the 32^3 before (docs/catalogue.md gives the measured lookup errors).
std::vector<AxisSpec> DefaultAxes(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (m && m->reciprocal)
    return {{"mu_max", 0.02, 1, 104, Warp::Angle},
            {"mu_ratio", 0, 1, 104, Warp::Angle},
            {"cos_phi", -1, 1, 3, Warp::Linear}};
  return {{"mu_l", 0, 1, 104, Warp::Angle},
          {"mu_o", 0, 1, 104, Warp::Angle},
          {"cos_phi", -1, 1, 3, Warp::Linear}};
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

/// The stored channels at table coordinates x: the physical point (mu_l, mu_o, phi) from the
/// axes (kiln/stored.h), f there, times mu_max in the symmetric form.
std::vector<double> Evaluate(const TableSpec& spec, const double* x, double,
                             IntegrationStats& stats) {
  ++stats.evals;
  StoredForm form = FormOf(spec.axes);
  double mu_l = x[0], mu_o = x[1], phi = x[2], scale = 1;
  if (form == StoredForm::BrdfSymmetric) {
    if (const ModelInfo* m = FindModel(spec.model); m && !m->reciprocal)
      throw std::invalid_argument("brdf: axes (mu_max, mu_ratio, ...) need a reciprocal model, '" +
                                  spec.model + "' is not");
    mu_l = x[0];
    mu_o = x[0] * x[1];
    scale = x[0];
  }
  if (form != StoredForm::Plain) phi = std::acos(Clamp(x[2], -1.0, 1.0));
  AnyModel m = ModelAt(spec.model, Param(spec, "roughness", 0.5));
  std::vector<double> v =
      RhoChannels(spec, EvaluateParts(m, ViewDirection(mu_o), DirectionFromMuPhi(mu_l, phi)));
  for (double& c : v) c *= scale;
  return v;
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
