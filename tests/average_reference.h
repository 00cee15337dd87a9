// The nested adaptive reference of an average albedo, E_avg = 2 int_0^1 E(mu) mu dmu, with its
// tolerance split between the two levels where it costs least: the tests that hold an average's
// fixed rule to adaptive quadrature take it instead of AverageAlbedo, which spends a tenth of its
// tolerance on every E(mu) (seconds a point for the sheen and diffuse models' 2D light-space E).
#pragma once
#include <catch2/catch.hpp>

#include <vector>

#include "baker/integrate/quantities.h"
#include "baker/math/quadrature.h"
#include "baker/models/registry.h"
#include "baker/quantities/common.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"

namespace kiln::test {

/// The share of an average's tolerance given to its inner E(mu): an error of at most d in every
/// E(mu) moves E_avg by at most d (2 mu dmu integrates to 1 over [0, 1]), the outer quadrature
/// over mu takes the rest. 0.8 costs least of 0.5 to 0.9 over the sheen, diffuse, Ward and Unity
/// averages the tests take, whose E(mu) adaptive quadrature meets far inside its tolerance. Not
/// for a model whose E only just meets it (kajiya-kay at r = 0, at 0.8 and at 0.5): the outer
/// quadrature, at or below the inner tolerance, then chases the inner one's noise (minutes where
/// AverageAlbedo, E at a tenth of the tolerance, takes a fraction of a second).
constexpr double kAverageInnerTolShare = 0.8;

/// kAverageInnerTolShare for a specular model (E by half-vector quadrature): 0.5 costs least of
/// 0.5 to 0.95 over the microfacet averages the tests take.
constexpr double kSpecularAverageInnerTolShare = 0.5;

/// The first panels of the quadrature over mu, graded towards mu = 0 where E(mu) bends fastest
/// (mu ln mu for the microfacet albedos): AverageAlbedo's.
constexpr double kAverageMuBreaks[] = {0, 0.01, 0.1, 0.4, 1};

/// E_avg of `model` (the lin and quad parts, as AverageAlbedo splits them) to `tol` absolute in
/// all: adaptive Gauss-Kronrod over mu to (1 - share) tol of E(mu) by adaptive quadrature
/// (DirectionalAlbedo) to share tol.
inline RhoParts AdaptiveAverageAlbedo(const AnyModel& model, double tol,
                                      double share = kAverageInnerTolShare) {
  IntegrationOptions inner;
  inner.tol = share * tol;
  IntegrationStats stats;
  auto integrand = [&](double mu) {
    const RhoParts e = DirectionalAlbedo(model, mu, inner, stats);
    return Channels<2>{2 * mu * e.lin, 2 * mu * e.quad};
  };
  const Channels<2> avg =
      IntegrateAdaptive<2>(integrand, kAverageMuBreaks,
                           static_cast<int>(std::size(kAverageMuBreaks)), (1 - share) * tol);
  return {avg[0], avg[1]};
}

/// EvaluateSpec(spec, x, tol) of an albedo-avg table over roughness (x[0] = r), its channels
/// from AdaptiveAverageAlbedo (a specular model's at kSpecularAverageInnerTolShare): the
/// adaptive reference of the average tables' fixed rules.
inline std::vector<double> AdaptiveAverageSpec(const TableSpec& spec, const double* x, double tol) {
  REQUIRE(spec.quantity == Quantity::AlbedoAvg);
  REQUIRE(spec.axes.size() == 1);
  REQUIRE(spec.axes[0].name == "roughness");
  // The model and channels as the kind's own evaluation builds them (baker/quantities/common.h).
  const ModelInfo* info = FindModel(spec.model);
  REQUIRE(info != nullptr);
  const double share = info->specular() ? kSpecularAverageInnerTolShare : kAverageInnerTolShare;
  return quantity_detail::RhoChannels(
      spec, AdaptiveAverageAlbedo(quantity_detail::ModelInDomain(spec.model, x[0]), tol, share));
}

}  // namespace kiln::test
