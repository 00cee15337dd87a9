// A fixed (non-adaptive) rule for the directional albedo of the sheen lobes (models/sheen.h:
// charlie, charlie-smith, ashikhmin-velvet), which is also their cloth DFG,
//     E(mu_o) = integral_{H^2} f(o, l) mu_l dl   (F = 1, no sheen colour),
// a tensor Gauss-Legendre rule in logarithmic variables t = ln(mu_l + c), s = ln(pi - phi + c')
// that make the integrand's layers at the horizon and at l = -o smooth, with panel boundaries at
// its kinks. Derivation and measured accuracy: fixed_rule_sheen.cpp.
#pragma once

#include <string>

#include "baker/models/registry.h"

namespace kiln {

/// Node counts and panel lengths of the sheen fixed rule (tests vary them to show convergence
/// and failure).
struct SheenRuleOptions {
  int tNodes = 12;       ///< Gauss-Legendre nodes per panel in t = ln(mu_l + c)
  int sNodes = 8;        ///< Gauss-Legendre nodes per panel in s = ln(pi - phi + c)
  double tPanel = 4;     ///< the longest panel in t
  double sPanel = 4;     ///< the longest panel in s
  int mirrorPanels = 3;  ///< geometric panels (ratio 4) towards mu_l = mu_o from both sides
  int psiPanels = 2;     ///< geometric panels (ratio 4) towards pi - phi = 0
  /// The mirror grading (mirrorPanels) only where alpha exceeds this: the mirror singularity
  /// |theta_h|^(1/alpha) is smooth enough for the plain panels at 1/alpha < 1/this.
  double mirrorMinAlpha = 0;
  /// When > 0, a panel boundary at mu_l = lobeBreak * r (r = sqrt(alpha)), the scale of the
  /// lobe's layer at the horizon (item 3 of the derivation).
  double lobeBreak = 0;
};

/// True for the sheen models (CharlieSheen, CharlieSmithSheen, AshikhminVelvet).
bool IsSheenModel(const AnyModel& model);

/// E(mu_o) of a sheen model (F = 1, cosine included) by the fixed rule; mu_o is clamped to
/// [0, 1]. The same nodes for the same (model, mu_o): deterministic. evals (optional)
/// accumulates the integrand evaluations. Throws std::invalid_argument for a model that is not a
/// sheen lobe.
double FixedRuleSheenAlbedo(const AnyModel& model, double mu_o, const SheenRuleOptions& opt = {},
                            long long* evals = nullptr);

/// The absolute error the sheen rule is declared to, over mu in [0, 1] and each model's table
/// domain (r in [0.045, 1]; tests/integrate_fixed_rule_sheen.cpp holds it to adaptive
/// quadrature at 1e-10 and prints the measured worst).
constexpr double kSheenRuleBound = 5e-7;

/// The lookup-error search's node counts (a verification-grade reference, issue #13): 10 x 6 per
/// panel (t x s), the same panels with one more towards psi = 0 (psiPanels 3); within 7.7e-7 of
/// the bake's rule over the three models' table domains (61 root4 mu x 31 log r, mu = 0 and r =
/// 0.045 included) at 1/1.27 of its evaluations (measured in the commit that set them).
constexpr SheenRuleOptions kSearchSheenRuleOptions = {10, 6, 4, 4, 3, 3};

/// charlie-smith's bake rule (fixed_rule_sheen.cpp, "charlie-smith's nodes"): 12 x 6 nodes per
/// panel, the mirror grading only for alpha > 0.3, a boundary at mu_l = r / 2; within 5e-7 of
/// adaptive quadrature at every node of its tables, at 0.47 of the shared rule's evaluations.
constexpr SheenRuleOptions kCharlieSmithRuleOptions = {12, 6, 4, 4, 3, 2, 0.3, 0.5};

/// charlie-smith's lookup-error search rule: the same panels at 8 x 6 nodes per panel, within
/// kSearchRuleBound of kCharlieSmithRuleOptions (tests/lookup_search_reference.cpp).
constexpr SheenRuleOptions kCharlieSmithSearchRuleOptions = {8, 6, 4, 4, 3, 2, 0.3, 0.5};

/// charlie-smith's bake-rule evaluations per search-rule evaluation: the same panels and nodes
/// in s, 12 / 8 nodes per panel in t, so exactly 1.5 at every point
/// (tests/tables_sheen_catalogue.cpp, tests/integrate_fixed_rule_charlie_smith.cpp).
constexpr double kCharlieSmithSearchCharge = 1.5;

/// The options of the bake rule (search = false) or the search's rule (search = true) for a
/// sheen model id ("charlie-smith" takes its own; the others the shared defaults).
SheenRuleOptions SheenRuleOptionsFor(const std::string& model, bool search);
/// The same for a sheen model's node counts as its descriptor names them (ModelInfo::sheenRule).
SheenRuleOptions SheenRuleOptionsFor(SheenRule rule, bool search);

/// The bake rule's evaluations per search-rule evaluation, rounded down from the measured 1.22
/// (charlie-smith) to 1.27 so that the charge never overstates the saving
/// (tests/tables_sheen_catalogue.cpp).
constexpr double kSearchSheenCharge = 1.2;

}  // namespace kiln
