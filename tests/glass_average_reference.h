// The nested adaptive reference of the glass averages (ggx-dielectric-albedo-{r,t}-avg and their
// -exit sides) as the texel check takes it: the tolerance split evenly between the quadrature
// over mu and E(mu), E's share graded by the mu rule's weight, and one integration a point for
// both channels (E_R and E_T come from one walk), kept for the process.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <string>
#include <vector>

#include "baker/integrate/dielectric_albedo_avg.h"
#include "baker/models/roughness.h"
#include "baker/quantities/common.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"
#include "point_memo.h"

namespace kiln::test {

/// The share of a glass average's tolerance given to E(mu), graded by the weight 2 mu of the
/// quadrature over mu (NestedAverageTolerance::gradedByWeight): the nested integration costs
/// 1.3x (exit side) to 1.7x (entering) fewer evaluations than EvaluateSpec's tol / 10 everywhere,
/// for the same nominal bound.
constexpr double kGlassAverageInnerTolShare = 0.5;

/// Whether `q` is one of the four glass averages GlassAverageReference takes.
inline bool IsGlassAverage(Quantity q) {
  return q == Quantity::DielectricAlbedoRAvg || q == Quantity::DielectricAlbedoTAvg ||
         q == Quantity::DielectricAlbedoRExitAvg || q == Quantity::DielectricAlbedoTExitAvg;
}

/// {E_avg_R, E_avg_T} at GGX alpha and eta to `tol` (DielectricAlbedoAverage, the tolerance split
/// as kGlassAverageInnerTolShare says), integrated once a process for each (alpha, eta, tol);
/// `evals` (optional) is charged with the evaluations of an integration this call ran.
inline std::array<double, 2> NestedGlassAverage(double alpha, double eta, double tol,
                                                long long* evals = nullptr) {
  static PointMemo<3> memo;
  return memo.Get({alpha, eta, tol}, [&] {
    NestedAverageTolerance split;
    split.outer = (1 - kGlassAverageInnerTolShare) * tol;
    split.inner = kGlassAverageInnerTolShare * tol;
    split.gradedByWeight = true;
    IntegrationStats stats;
    const std::array<double, 2> e = DielectricAlbedoAverage(alpha, eta, split, stats);
    if (evals) *evals += stats.evals;
    return e;
  });
}

/// EvaluateSpec(spec, x, tol) of a glass average (IsGlassAverage) over roughness and eta, by
/// NestedGlassAverage: the r and t kinds at one point share one integration. Roughness 0 (the
/// smooth interface's closed form) is EvaluateSpec's.
inline std::vector<double> GlassAverageReference(const TableSpec& spec, const double* x, double tol,
                                                 long long* evals = nullptr) {
  REQUIRE(IsGlassAverage(spec.quantity));
  REQUIRE(spec.axes.size() == 2);
  REQUIRE(spec.axes[0].name == "roughness");
  REQUIRE(spec.axes[1].name == "eta");
  if (x[0] == 0) {
    IntegrationStats st;
    return EvaluateSpec(spec, x, tol, st);
  }
  const bool transmit = spec.quantity == Quantity::DielectricAlbedoTAvg ||
                        spec.quantity == Quantity::DielectricAlbedoTExitAvg;
  const double alpha = std::max(AlphaFromPerceptual(x[0]), MinAlpha);
  return {NestedGlassAverage(alpha, x[1], tol, evals)[transmit ? 1 : 0]};
}

}  // namespace kiln::test
