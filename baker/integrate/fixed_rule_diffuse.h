// A fixed (non-adaptive) rule for the directional albedo of the diffuse models,
//     E(mu_o) = integral_{H^2} f(o, l) mu_l dl   (rho = 1, split in its rho^1 and rho^2 parts),
// in light space (theta_l, phi), the same variables as the adaptive reference
// (integrate/hemisphere.h, IntegrateLightSpace): a small tensor Gauss-Legendre rule on panels
// placed where the integrands bend. Derivation and measured accuracy: fixed_rule_diffuse.cpp.
#pragma once

#include "baker/models/registry.h"

namespace kiln {

/// Node counts of the diffuse fixed rule (tests vary them to show convergence and failure).
struct DiffuseRuleOptions {
  int thetaNodes = 8;  ///< Gauss-Legendre nodes in theta_l per panel
  int phiNodes = 8;    ///< Gauss-Legendre nodes in phi per panel
};

/// E(mu_o) of a light-space (diffuse) model at rho = 1, split as E = rho lin + rho^2 quad, by the
/// fixed rule; mu_o is clamped to [0, 1]. The same nodes for the same (model, mu_o): deterministic.
/// evals (optional) accumulates the integrand evaluations. Throws std::invalid_argument for a
/// specular (half-vector) model.
RhoParts FixedRuleDiffuseAlbedo(const AnyModel& model, double mu_o,
                                const DiffuseRuleOptions& opt = {}, long long* evals = nullptr);

/// True for the models whose panels the rule grades towards theta_o and phi = pi at the grazing
/// scale (Hammon, full Oren-Nayar: poles just outside the hemisphere; fixed_rule_diffuse.cpp).
bool DiffuseRuleGradesGrazing(const AnyModel& model);

/// The absolute error the diffuse rule is declared to, for every catalogue diffuse model over
/// mu in [0, 1] and its whole roughness range (tests/integrate_fixed_rule_diffuse.cpp holds it
/// to adaptive quadrature at 1e-10; the measured worst is printed there).
constexpr double kDiffuseRuleBound = 1e-7;

/// The lookup-error search's node counts (a verification-grade reference, issue #13): 6 x 4 per
/// panel (theta_l x phi), within 6.6e-7 of the bake's rule (burley at mu = 0, r = 1) for every
/// catalogue diffuse model at 0.375 of its evaluations (tests/lookup_search_reference.cpp; the
/// search adds kSearchRuleBound, fixed_rule_microfacet.h, to what it finds).
constexpr DiffuseRuleOptions kSearchDiffuseRuleOptions = {6, 4};

/// The bake rule's evaluations per search-rule evaluation, at most (8 x 8 against 6 x 4 nodes
/// per panel: 64 / 24 = 2.67): the search charges each of its evaluations this many.
constexpr double kSearchDiffuseCharge = 2.6;

}  // namespace kiln
