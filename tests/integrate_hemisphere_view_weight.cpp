// The half-vector references' per-view weights (a model's HalfWeightAtView, its view's constants
// computed once) against the per-sample HalfWeight they replace: the same bits, sample by sample
// and integral by integral, on a grid of models, views and roughnesses.
#include <catch2/catch.hpp>
#include <cstring>
#include <type_traits>
#include <vector>

#include "baker/integrate/hemisphere.h"
#include "baker/models/registry.h"
#include "builtin_models.h"

using namespace kiln;

namespace {

/// Model m seen through its per-sample HalfWeight only (no HalfWeightAtView): the integrator's
/// path before the per-view weights.
template <class M>
struct PerSampleWeight {
  static constexpr IntegrationDomain kDomain = IntegrationDomain::HalfVector;
  const M* m;
  PolarParam FromV(double v) const { return m->FromV(v); }
  double VFromTheta(double theta) const { return m->VFromTheta(theta); }
  double HalfWeight(const HalfSample& s) const { return m->HalfWeight(s); }
  double MaskingScale() const { return m->MaskingScale(); }
  int PhiKinks(double mu_o, double sinTheta_o, PolarParam h, double* cosPhi) const {
    return m->PhiKinks(mu_o, sinTheta_o, h, cosPhi);
  }
  int ThetaKinks(double theta_o, double* theta) const { return m->ThetaKinks(theta_o, theta); }
};

template <class M, class = void>
struct HasViewWeight : std::false_type {};
template <class M>
struct HasViewWeight<M, std::void_t<decltype(std::declval<const M&>().HalfWeightAtView(0.0))>>
    : std::true_type {};

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The views of the grid: the horizon, a grazing view, an oblique one and the normal.
const double kViews[] = {0.0, 1e-6, 0.3, 1.0};

/// Fresnel factors the microfacet models are checked with: none, Schlick, a dielectric with and
/// without total internal reflection, a conductor.
std::vector<Fresnel> Fresnels() {
  std::vector<Fresnel> out(5);
  out[1].kind = Fresnel::Kind::Schlick;
  out[1].f0 = 0.04;
  out[2].kind = Fresnel::Kind::Dielectric;
  out[2].eta = 1.5;
  out[3].kind = Fresnel::Kind::Dielectric;
  out[3].eta = 0.7;
  out[4].kind = Fresnel::Kind::Conductor;
  out[4].eta = 0.2;
  out[4].k = 3.1;
  return out;
}

/// Checks model m's per-view weight against HalfWeight on a grid of half vectors at every view,
/// then (integrals) the albedo and split-sum integrals of both paths at tolerance tol: the same
/// bits, the same evaluations (the paths differ in the weight alone, at any tolerance).
template <class M>
void CheckSameBits(const M& m, bool integrals = true, double tol = 1e-6) {
  for (double mu : kViews) {
    INFO("mu_o = " << mu);
    const auto w = m.HalfWeightAtView(mu);
    HalfSample s;
    s.wo = ViewDirection(mu);
    s.mu_o = mu;
    for (double v : {1.0, 0.9, 0.5, 0.1, 1e-3, 1e-8}) {
      PolarParam h = m.FromV(v);
      for (double phi : {0.0, 0.3, 1.2, 2.0, 3.0}) {
        s.wm = SphericalDirectionHalfTurn(h.sinTheta, h.cosTheta, phi);
        s.oh = Dot(s.wo, s.wm);
        s.cosTheta_h = h.cosTheta;
        s.mu_l = 2 * s.oh * h.cosTheta - mu;
        s.wi = Reflect(s.wo, s.wm);
        if (!(s.mu_l > 0) || !(s.oh > 0)) continue;
        INFO("v = " << v << ", phi = " << phi);
        CHECK(SameBits(w(s), m.HalfWeight(s)));
      }
    }
    if (!integrals) continue;
    IntegrationOptions opt;
    opt.tol = tol;
    const PerSampleWeight<M> old{&m};
    auto albedo = [](const HalfSample&, double rho) { return Channels<1>{rho}; };
    auto dfg = [](const HalfSample& hs, double rho) {
      double w5 = Pow5(1 - hs.oh);
      return Channels<2>{rho * (1 - w5), rho * w5};
    };
    IntegrationStats a, b, c, d;
    const double e = IntegrateHalfVector<1>(m, mu, albedo, opt, a)[0];
    const double eOld = IntegrateHalfVector<1>(old, mu, albedo, opt, b)[0];
    CHECK(SameBits(e, eOld));
    CHECK(a.evals == b.evals);
    const Channels<2> f = IntegrateHalfVector<2>(m, mu, dfg, opt, c);
    const Channels<2> fOld = IntegrateHalfVector<2>(old, mu, dfg, opt, d);
    CHECK(SameBits(f[0], fOld[0]));
    CHECK(SameBits(f[1], fOld[1]));
    CHECK(c.evals == d.evals);
  }
}

}  // namespace

TEST_CASE(
    "The half-vector references' per-view weights give HalfWeight's bits and the same integrals "
    "(every built-in specular model, mu 0 to 1, roughness 0 to 1)",
    "[integrate][hemisphere]") {
  int checked = 0;
  for (const ModelInfo& info : test::BuiltInModels()) {
    if (!info.specular()) continue;
    for (double r : {0.0, 0.02, 0.3, 1.0}) {
      ModelParams p;
      p.roughness = r;
      AnyModel model = MakeModel(info.id, p);
      std::visit(
          [&](const auto& m) {
            using M = std::decay_t<decltype(m)>;
            if constexpr (HasViewWeight<M>::value) {
              INFO(info.id << " r = " << r);
              CheckSameBits(m);
              ++checked;
            }
          },
          model);
    }
  }
  CHECK(checked > 0);
}

TEST_CASE(
    "The microfacet models' per-view weights give HalfWeight's bits and the same integrals for "
    "every NDF, Smith form and Fresnel factor",
    "[integrate][hemisphere]") {
  // Every weight on the whole grid; the integrals (the costly part) at the sharpest lobe without
  // a Fresnel factor and at a broad one with total internal reflection's.
  const std::vector<Fresnel> fresnels = Fresnels();
  for (size_t f = 0; f < fresnels.size(); ++f)
    for (SmithForm form : {SmithForm::HeightCorrelated, SmithForm::Separable, SmithForm::VCavity})
      for (double alpha : {1e-4, 0.05, 0.5, 1.0}) {
        INFO("fresnel kind " << static_cast<int>(fresnels[f].kind) << ", form "
                             << static_cast<int>(form) << ", alpha = " << alpha);
        const bool integrals = (f == 0 && alpha == 1e-4) || (f == 3 && alpha == 0.5);
        MicrofacetBRDF<GGXDistribution> ggx{{alpha}, form, fresnels[f]};
        MicrofacetBRDF<BeckmannDistribution> beckmann{{alpha}, form, fresnels[f]};
        MicrofacetBRDF<BlinnPhongDistribution> blinn{{alpha}, form, fresnels[f]};
        CheckSameBits(ggx, integrals);
        CheckSameBits(beckmann, integrals);
        CheckSameBits(blinn, integrals);
      }
  NormalizedBlinnPhong phong;
  phong.s = 60;
  phong.rs = 0.8;
  phong.fresnel = Fresnels()[1];
  CheckSameBits(phong);
}
