// A fixed (non-adaptive) rule for the directional albedo of the sheen lobes (models/sheen.h:
// charlie, charlie-smith, ashikhmin-velvet), which is also their cloth DFG,
//     E(mu_o) = integral_{H^2} f(o, l) mu_l dl   (F = 1, no sheen colour),
// a tensor Gauss-Legendre rule in logarithmic variables t = ln(mu_l + c), s = ln(pi - phi + c')
// that make the integrand's layers at the horizon and at l = -o smooth, with panel boundaries at
// its kinks. Derivation and measured accuracy: fixed_rule_sheen.cpp.
#pragma once

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

/// The bake rule's evaluations per search-rule evaluation, rounded down from the measured 1.22
/// (charlie-smith) to 1.27 so that the charge never overstates the saving
/// (tests/tables_sheen_catalogue.cpp).
constexpr double kSearchSheenCharge = 1.2;

}  // namespace kiln
