// The rough dielectric's hemispherical reflectance through one kernel per roughness.
//
// Over the visible microfacet normals (models/dielectric_bsdf.h: GGX, height-correlated Smith,
// exact Fresnel; Walter et al. 2007) the hemispherical average of E_R,
//     E_avg_R = 2 int_0^1 E_R(mu) mu dmu
//             = (1 / pi) int D(m) int c F(c) G2(o, i) [mu_o > 0] [mu_i > 0] [c > 0] do dm,
// (i = 2 c m - o, c = o.m) depends on eta only through F(c). For a fixed m, o parametrised by
// c = o.m and its azimuth psi about m (do = dc dpsi) gives
//     E_avg_R(alpha, eta) = int_0^1 F(c, eta) c K_alpha(c) dc,
//     K_alpha(c) = (1 / pi) int D(m) int_0^{2 pi} G2(o, i) [mu_o > 0] [mu_i > 0] dpsi dm,
// K independent of eta (K -> 2 as alpha -> 0: E_avg_R -> F_avg). So one kernel per roughness
// serves every eta of a table row (derivation and rule in dielectric_kernel.cpp).
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "baker/integrate/hemisphere.h"

namespace kiln {

/// K_alpha(c) for c in [0, 1], GGX alpha > 0 (at least MinAlpha), by adaptive quadrature to tol
/// (absolute): the reference. stats.evals accumulates the evaluations.
double DielectricReflectanceKernel(double c, double alpha, double tol, IntegrationStats& stats);

/// K_alpha(c) by the fixed rule (deterministic). evals (optional) accumulates the evaluations.
double FixedRuleDielectricReflectanceKernel(double c, double alpha, long long* evals = nullptr);

/// K_alpha at the fixed nodes of one roughness, from which ExitAverageR integrates any eta:
/// the geometric panels of the grazing layer c in [0, cSplit] (where F = 1 on the exit side)
/// integrated once, and K on [cSplit, 1] as a polynomial in t = sqrt(1 - c) through its values
/// at Chebyshev points (dielectric_kernel.cpp, "The rule").
struct DielectricReflectanceKernelRow {
  double alpha = 0;
  double lowIntegral = 0;             ///< int_0^cSplit c K(c) dc
  std::vector<double> t, k, weights;  ///< interpolation nodes in t, K there, barycentric weights
  long long evals = 0;                ///< the kernel's evaluations
  /// K at c in [cSplit, 1] by barycentric interpolation.
  double At(double c) const;
};

/// The kernel row of GGX alpha by the fixed rule: its nodes on the calling oneTBB arena's threads,
/// summed in their order (deterministic: the same bits for any thread count).
DielectricReflectanceKernelRow MakeDielectricReflectanceKernelRow(double alpha);

/// The same row through a memo by the bits of alpha (thread-safe; a thread asking for a row
/// another is integrating waits for it): the exit table's roughness row and the lookup-error
/// search's points of one roughness (its probes share their offsets across cells) share one
/// kernel. A remembered row is the row computed (the same bits).
std::shared_ptr<const DielectricReflectanceKernelRow> CachedDielectricReflectanceKernelRow(
    double alpha);

/// E_avg_R at (alpha, eta') on the exit side (eta' <= 1 / kDielectricTableEtaMin, >= 1/3) by the
/// kernel route: the bake's rule of ggx-dielectric-albedo-r-exit-avg. evals (optional) is
/// charged the row's evaluations (what the point costs alone).
double KernelDielectricExitAverageR(double alpha, double eta, long long* evals = nullptr);

/// The declared distance of the kernel route from the adaptive reference (tests hold it there):
/// the E rule's and the mu rule's bounds together, as the route it replaced declared.
constexpr double kDielectricKernelBound = 9e-7;

/// E_avg_R at eta' in [1 / 3, 1 / kDielectricTableEtaMin] (the exit side, where F = 1 below the
/// critical cosine c_crit = sqrt(1 - eta'^2)) from a kernel row: lowIntegral, then F c K over
/// [cSplit, 1] on panels graded in sqrt|c - c_crit| on both sides of c_crit and in sqrt(1 - c)
/// towards 1. Deterministic.
double DielectricExitAverageRFromKernel(const DielectricReflectanceKernelRow& row, double eta);

/// Where the kernel's grazing panels end: below the smallest critical cosine of the exit tables
/// (sqrt(1 - 1 / 1.1^2) = 0.417).
constexpr double kDielectricKernelSplit = 0.4;

}  // namespace kiln
