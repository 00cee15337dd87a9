// A fixed rule for the albedo of a cosine lobe about the mirror direction (Lafortune's Phong
// lobe, models/lafortune.h; issue #16). Derivation: fixed_rule_lobe.cpp.
#pragma once

namespace kiln {

/// E(mu) of f = (n + 2) / (2 pi) max(0, m.l)^n (m the mirror direction of o, f = 0 below the
/// horizon), cosine mu_l included, rs = 1, at view cosine mu in [0, 1] (clamped) and n > 0. At
/// n = 0 it returns the limit n -> 0+ (the half-space m.l > 0), not Lafortune's Lambertian
/// n = 0 (0^0 = 1 on the whole hemisphere, E = 1). Deterministic; evals (optional) accumulates
/// the integrand evaluations.
double FixedRuleMirrorLobeAlbedo(double mu, double n, long long* evals = nullptr);

/// E(mu) of unity-brdf3's specular lobe (models/unity.h, rs = 1), cosine mu_l included:
/// f = min(16, c |m.l|^n) / pi with c = (n + 2) / (2 pi^2), n = UnitySpecPower(r) / 4 (Unity's
/// unity_NHxRoughness texel, saturating at 1, times LUT_RANGE = 16). The lobe about the mirror
/// direction m and its twin about -m ((R.L)^4 is even) in one integral over the lobe angle, the
/// azimuth in closed form, with a panel boundary at the clamp's kink (docs/models.md). mu in
/// [0, 1] (clamped), n >= 0. Deterministic; evals (optional) accumulates the evaluations.
double FixedRuleUnityBRDF3Albedo(double mu, double n, long long* evals = nullptr);

/// The absolute error FixedRuleMirrorLobeAlbedo and FixedRuleUnityBRDF3Albedo is declared to
/// (tests/integrate_fixed_rule_ unity.cpp holds it against adaptive quadrature at 1e-10).
constexpr double kMirrorLobeRuleBound = 6e-7;

}  // namespace kiln
