// The hemispherical averages of the rough dielectric's energies (models/dielectric_bsdf.h, GGX,
// height-correlated Smith, exact Fresnel; Walter et al. 2007),
//     E_avg_R = 2 integral_0^1 E_R(mu) mu dmu,   E_avg_T = 2 integral_0^1 E_T(mu) mu dmu,
// E_R, E_T as integrate/dielectric_albedo.h gives them (E_T in importance form, without
// 1/eta^2). What a Turquin-style multiple-scattering compensation of glass reads next to E(mu)
// on both sides of the interface.
//
// The rule over mu (derivation in dielectric_albedo_avg.cpp): panels graded from the GGX layer
// at mu = 0 (as integrate/fixed_rule_average.h) and, for eta < 1, graded in s = sqrt|mu - mu_c|
// on both sides of the critical cosine mu_c = sqrt(1 - eta^2), where E follows F's square-root
// kink (softened over ~alpha mu_c): F is analytic in s there; in sqrt|mu - eta| either side of
// mu = eta (eta < 1), where the near-vertical microfacets start to transmit; and in sqrt(1 - mu)
// over the last stretch before mu = 1.
#pragma once
#include <array>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/integrate/hemisphere.h"

namespace kiln {

/// {E_avg_R, E_avg_T} at GGX alpha > 0 and eta in (0, inf) by the fixed rule: E by
/// FixedRuleDielectricAlbedo (the 3D tables' rule) at kDielectricAverageNodes Gauss nodes per mu
/// panel.
/// Deterministic; evals (optional) accumulates integrand evaluations. `channels`: the entering
/// side computes only those (each with the bits it has in both, the others NaN) and charges their
/// evaluations; the other sides compute both.
std::array<double, 2> FixedRuleDielectricAlbedoAverage(
    double alpha, double eta, long long* evals = nullptr,
    DielectricChannels channels = DielectricChannels::Both);
/// The same with `nodes` Gauss nodes per mu panel (tests and experiments; the exit side's E_avg_R
/// takes the kernel route, KernelDielectricExitAverageR, whatever `nodes`).
std::array<double, 2> FixedRuleDielectricAlbedoAverage(double alpha, double eta, int nodes,
                                                       long long* evals);

/// {E_avg_R, E_avg_T} at n etas at once (1 <= n <= kMaxDielectricColumn, every eta >=
/// kDielectricTableEtaMin: the entering side, where the mu panels do not depend on eta), into
/// out: one E column (FixedRuleDielectricAlbedoColumn) per mu node, the nodes on the calling
/// oneTBB arena's threads and summed in their order. Each out[e] has the bits
/// FixedRuleDielectricAlbedoAverage(alpha, etas[e], nodes) gives, for any thread count; evals:
/// one eta's. `channels`: only those are computed (the E columns asked for them alone), each
/// with the bits it has in both; a channel not asked is NaN and charges nothing.
void FixedRuleDielectricAlbedoAverageColumn(double alpha, const double* etas, int n, int nodes,
                                            std::array<double, 2>* out, long long* evals,
                                            DielectricChannels channels = DielectricChannels::Both);
/// The same at kDielectricAverageNodes, remembering recent columns with the channels computed
/// (dielectric_column_memo.h, DielectricChannelMemo): a column asked for a channel its entry
/// lacks computes that channel alone and adds it. A hit charges the evaluations of the channels
/// asked, as computing them would.
void FixedRuleDielectricAlbedoAverageColumn(double alpha, const double* etas, int n,
                                            std::array<double, 2>* out, long long* evals,
                                            DielectricChannels channels = DielectricChannels::Both);

/// Integrates {E_avg_R, E_avg_T} at (alpha, etas[e]) for n entering etas (1 <= n <=
/// kMaxDielectricColumn, every eta >= kDielectricTableEtaMin) as one column and keeps each point
/// in a memo that FixedRuleDielectricAlbedoAverage(alpha, eta, evals) and, at eta = 1 / etas[e],
/// FixedRuleDielectricExitAverageT(alpha, eta, kDielectricAverageNodes, evals) read first: the
/// same bits and evaluations as the point alone (a column gives each eta a column of one's bits),
/// one walk for the n points (the lookup-error searches' points of one roughness,
/// QuantityInfo::prepareSearch). Points the memo holds already (another search's: t-avg after
/// r-avg) are not integrated again. `channels`: the memo's points get those (a point lacking
/// one of them is integrated for the channels it lacks; reading a point charges the
/// evaluations of the channels read). Returns how many etas it integrated. Thread-safe.
int PrepareDielectricAverageColumn(double alpha, const double* etas, int n,
                                   DielectricChannels channels = DielectricChannels::Both);

/// The exit side (1 / eta >= kDielectricTableEtaMin): E_avg_R by the mu rule of E_R alone
/// (FixedRuleDielectricReflectance: no panels at the refracted ray's structures; the bake
/// takes the kernel route instead, dielectric_kernel.h, and the tests hold the two together),
/// and E_avg_T by reciprocity from the entering side, E_avg_T(eta) = eta^2 E_avg_T(1 / eta) (the
/// importance form's transpose, models/dielectric_bsdf.h: fhat_t(wi, wo) = fhat_t(wo, wi) /
/// e^2), the entering column's rule at 1 / eta. FixedRuleDielectricAlbedoAverage gives both there
/// (E_avg_R by KernelDielectricExitAverageR).
double FixedRuleDielectricExitAverageR(double alpha, double eta, int nodes, long long* evals);
double FixedRuleDielectricExitAverageT(double alpha, double eta, int nodes, long long* evals);
/// The exit side's E_avg_R by the mu rule with E_R by the node counts `opt`
/// (FixedRuleDielectricReflectance).
double FixedRuleDielectricExitAverageR(double alpha, double eta, int nodes,
                                       const DielectricRuleOptions& opt, long long* evals);

/// The same averages by adaptive quadrature over mu (Gauss-Kronrod on the same panels) of the
/// adaptive E (DielectricAlbedo to tol / 10): the reference, to about tol (absolute).
std::array<double, 2> DielectricAlbedoAverage(double alpha, double eta, double tol,
                                              IntegrationStats& stats);

/// How DielectricAlbedoAverage splits its tolerance: the quadrature over mu to `outer`, E(mu) to
/// `inner` (absolute); gradedByWeight: E(mu) to inner / (2 mu) instead (at most
/// kMaxGradedInnerTol), whose error moves E_avg = int 2 mu E dmu by at most `inner` all the same.
struct NestedAverageTolerance {
  double outer = 0, inner = 0;
  bool gradedByWeight = false;
};

/// The cap of a graded inner tolerance (NestedAverageTolerance::gradedByWeight) near mu = 0.
constexpr double kMaxGradedInnerTol = 1e-6;

/// DielectricAlbedoAverage with its tolerance split as `tol` says; the form above is
/// {tol / 2, tol / 10, false}, bit for bit. Both forms remember their recent results (by the bits
/// of alpha, eta and the split; thread-safe): the r and t kinds at one point (EvaluateSpec gives
/// one channel each) take one integration, and a remembered one returns the same bits and charges
/// `stats` the evaluations and error estimate it had.
std::array<double, 2> DielectricAlbedoAverage(double alpha, double eta,
                                              const NestedAverageTolerance& tol,
                                              IntegrationStats& stats);

/// The smooth interface (alpha = 0): {F_avg(eta), 1 - F_avg(eta)}, F_avg = 2 int F mu dmu; for
/// eta < 1 from the entering side by reciprocity, 1 - F_avg(eta) = eta^2 (1 - F_avg(1 / eta)).
std::array<double, 2> SmoothDielectricAlbedoAverage(double eta);

/// Gauss nodes per mu panel of the bake's rule.
constexpr int kDielectricAverageNodes = 10;

/// The error the fixed rule adds to that of the E it averages (tests hold it to adaptive).
constexpr double kDielectricAverageBound = 2e-7;

}  // namespace kiln
