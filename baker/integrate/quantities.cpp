#include "baker/integrate/quantities.h"

#include <stdexcept>

namespace kiln {
namespace {

template <class M>
constexpr bool IsSpecular() {
  return std::decay_t<M>::kDomain == IntegrationDomain::HalfVector;
}

/// The view cosine model m is integrated at: a user's lobe (baker/custom/) at mu_o = 0 is taken
/// in the limit from above, at its horizonMu (its f may hold 0 / 0 there).
template <class M>
double ViewCosine(const M& m, double mu_o) {
  if constexpr (std::is_base_of_v<CustomModelBase, std::decay_t<M>>)
    return std::max(mu_o, m.horizonMu);
  return mu_o;
}

/// 2 integral_0^1 g(mu) mu dmu for a channel-valued g. E(mu) bends fastest near mu = 0
/// (mu ln mu for the microfacet albedos), so the first panels are graded towards 0.
template <int N, class G>
Channels<N> CosineWeightedAverage(G&& g, double tol) {
  const double breaks[] = {0, 0.01, 0.1, 0.4, 1};
  auto integrand = [&](double mu) { return (2 * mu) * g(mu); };
  return IntegrateAdaptive<N>(integrand, breaks, 5, tol);
}

/// The light cosines where a light-space model's f bends (its LightMuKinks), none for a model
/// without that method.
template <class M>
auto LightMuKinksOf(const M& m, double mu_o, int) -> decltype(m.LightMuKinks(mu_o)) {
  return m.LightMuKinks(mu_o);
}
template <class M>
std::vector<double> LightMuKinksOf(const M&, double, long) {
  return {};
}
template <class M>
std::vector<double> LightMuKinksOf(const M& m, double mu_o) {
  return LightMuKinksOf(m, mu_o, 0);
}

/// The bends in phi_l of a light-space model's f on each circle theta_l (its LightPhiKinks), none
/// for a model without that method.
template <class M>
auto LightPhiKinksOf(const M& m, double mu_o, int)
    -> decltype(m.LightPhiKinks(mu_o, 0.0, 0.0, nullptr), LightPhiKinkFn()) {
  return [&m, mu_o](double sinT, double cosT, double* cosPhi) {
    return m.LightPhiKinks(mu_o, sinT, cosT, cosPhi);
  };
}
template <class M>
LightPhiKinkFn LightPhiKinksOf(const M&, double, long) {
  return {};
}

}  // namespace

RhoParts DirectionalAlbedo(const AnyModel& model, double mu_o, const IntegrationOptions& opt,
                           IntegrationStats& stats) {
  mu_o = Clamp(mu_o, 0.0, 1.0);
  return std::visit(
      [&](const auto& m) -> RhoParts {
        mu_o = ViewCosine(m, mu_o);
        if constexpr (IsSpecular<decltype(m)>()) {
          auto w = [](const HalfSample&, double rho) { return Channels<1>{rho}; };
          return {IntegrateHalfVector<1>(m, mu_o, w, opt, stats)[0], 0};
        } else {
          auto g = [&](Vec3 wo, Vec3 wi) {
            RhoParts p = m.Parts(wo, wi);
            return Channels<2>{p.lin, p.quad};
          };
          Channels<2> r = IntegrateLightSpace<2>(mu_o, g, opt, stats, LightMuKinksOf(m, mu_o),
                                                 LightPhiKinksOf(m, mu_o, 0));
          return {r[0], r[1]};
        }
      },
      model);
}

RhoParts AverageAlbedo(const AnyModel& model, const IntegrationOptions& opt,
                       IntegrationStats& stats) {
  IntegrationOptions inner = opt;
  inner.tol = opt.tol / 10;
  auto g = [&](double mu) {
    RhoParts p = DirectionalAlbedo(model, mu, inner, stats);
    return Channels<2>{p.lin, p.quad};
  };
  Channels<2> r = CosineWeightedAverage<2>(g, opt.tol / 2);
  return {r[0], r[1]};
}

std::array<double, 2> SplitSumDFG(const AnyModel& model, double mu_o, const IntegrationOptions& opt,
                                  IntegrationStats& stats) {
  mu_o = Clamp(mu_o, 0.0, 1.0);
  return std::visit(
      [&](const auto& m) -> std::array<double, 2> {
        mu_o = ViewCosine(m, mu_o);
        if constexpr (IsSpecular<decltype(m)>()) {
          auto unit = m;
          unit.fresnel = Fresnel{};
          auto w = [](const HalfSample& s, double rho) {
            double w5 = Pow5(1 - s.oh);
            return Channels<2>{rho * (1 - w5), rho * w5};
          };
          return IntegrateHalfVector<2>(unit, mu_o, w, opt, stats);
        } else {
          throw std::invalid_argument("dfg: the split sum needs a specular model");
        }
      },
      model);
}

std::array<double, 2> AverageSplitSumDFG(const AnyModel& model, const IntegrationOptions& opt,
                                         IntegrationStats& stats) {
  IntegrationOptions inner = opt;
  inner.tol = opt.tol / 10;
  auto g = [&](double mu) { return SplitSumDFG(model, mu, inner, stats); };
  return CosineWeightedAverage<2>(g, opt.tol / 2);
}

double FresnelAverage(const Fresnel& fresnel, const IntegrationOptions& opt,
                      IntegrationStats& stats) {
  // F bends at the critical angle (total internal reflection, eta < 1): a panel boundary there.
  double breaks[3] = {0, 1, 1};
  int n = 2;
  if ((fresnel.kind == Fresnel::Kind::Dielectric || fresnel.kind == Fresnel::Kind::Conductor) &&
      fresnel.eta < 1) {
    breaks[1] = SafeSqrt(1 - Sqr(fresnel.eta));
    n = 3;
  }
  auto integrand = [&](double mu) {
    ++stats.evals;
    return Channels<1>{2 * mu * fresnel(mu)};
  };
  double err = 0;
  double r = IntegrateAdaptive<1>(integrand, breaks, n, opt.tol, opt.maxPanels, &err)[0];
  stats.errorEstimate = err;
  return r;
}

}  // namespace kiln
