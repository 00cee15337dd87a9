// The adaptive reference of the glass E tables (ggx-dielectric-albedo-{r,t} and their -exit
// sides) as the texel check takes it: EvaluateSpec's integration (DielectricAlbedo, adaptive
// Gauss-Kronrod to tol), which gives E_R and E_T from one walk, run once a point for both kinds
// and kept for the process.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <string>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/models/roughness.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"
#include "kiln/stored.h"
#include "point_memo.h"

namespace kiln::test {

/// The most panels of a level of the reference's integration (quantities/dielectric_albedo.cpp,
/// Evaluate).
constexpr int kGlassAlbedoMaxPanels = 2000;

/// Whether `q` is one of the four glass E kinds GlassAlbedoReference takes.
inline bool IsGlassAlbedo(Quantity q) {
  return q == Quantity::DielectricAlbedoR || q == Quantity::DielectricAlbedoT ||
         q == Quantity::DielectricAlbedoRExit || q == Quantity::DielectricAlbedoTExit;
}

/// {E_R, E_T} at view cosine mu, GGX alpha and eta to `tol` by DielectricAlbedo (EvaluateSpec's
/// options), integrated once a process for each (mu, alpha, eta, tol).
inline std::array<double, 2> SharedGlassAlbedo(double mu, double alpha, double eta, double tol) {
  static PointMemo<4> memo;
  return memo.Get({mu, alpha, eta, tol}, [&] {
    IntegrationOptions opt;
    opt.tol = tol;
    opt.maxPanels = kGlassAlbedoMaxPanels;
    IntegrationStats stats;
    return DielectricAlbedo(mu, alpha, eta, opt, stats);
  });
}

/// EvaluateSpec(spec, x, tol) of a glass E table (IsGlassAlbedo) over (mu, roughness, eta), by
/// SharedGlassAlbedo: the r and t kinds at one point share one integration. The stored channel:
/// E, or E minus the closed form the table's channel names (E_*_residual, E_*_tir_residual).
/// Roughness 0 (the smooth interface's closed form) is EvaluateSpec's.
inline std::vector<double> GlassAlbedoReference(const TableSpec& spec, const double* x,
                                                double tol) {
  REQUIRE(IsGlassAlbedo(spec.quantity));
  REQUIRE(spec.axes.size() == 3);
  REQUIRE(spec.axes[0].name == "mu");
  REQUIRE(spec.axes[1].name == "roughness");
  REQUIRE(spec.axes[2].name == "eta");
  REQUIRE(spec.channels.size() == 1);
  if (x[1] == 0) {
    IntegrationStats st;
    return EvaluateSpec(spec, x, tol, st);
  }
  const bool transmit = spec.quantity == Quantity::DielectricAlbedoT ||
                        spec.quantity == Quantity::DielectricAlbedoTExit;
  const double mu = x[0], r = x[1], eta = x[2];
  double v = SharedGlassAlbedo(mu, std::max(AlphaFromPerceptual(r), MinAlpha), eta, tol)[transmit];
  const std::string& channel = spec.channels[0];
  if (channel == "E_R_residual" || channel == "E_T_residual")
    v -= dielectricAlbedoClosedForm(mu, r, eta, transmit);
  else if (channel == "E_R_tir_residual" || channel == "E_T_tir_residual")
    v -= dielectricExitClosedForm(mu, r, eta, transmit);
  return {v};
}

}  // namespace kiln::test
