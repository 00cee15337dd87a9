// Fixed rules for the microfacet models other than height-correlated GGX, and for GGX with exact
// dielectric Fresnel: the variables of the GGX rule (fixed_rule_dfg.cpp, whose derivation this one
// extends) with the model's own NDF, Smith term and Fresnel factor as smooth weights in them.
//
// Derivation. With l = reflect(o, h), f mu_l dl = D G2 F (o.h) / mu_o dh. Write D = D_ggx r, with
// D_ggx the GGX NDF at the same alpha, and use GGX's visible normals: stretched by 1/alpha, h maps
// to n' = (sin t' cos p, sin t' sin p, cos t') (tan theta_h = alpha tan t'), and
// D_ggx (o.h)^+ / mu_o dh = 2 (o'.n')^+ dn' / (pi (1 + o'_z) G1_ggx(o)), so
//     E_w = 4 / (pi (1 + o'_z)) int_0^pi dp int_0^{t'max(p)} sin t' (o'.n') r g F w dt',
//     g = G2 / G1_ggx(o),
// the horizon cut t'max(p) exact and analytic as in the GGX rule. The NDF ratio r is a function of
// u = tan^2 t' alone, without alpha: the GGX stretch is every model's stretch:
//     Beckmann     D = exp(-tan^2/alpha^2) / (pi alpha^2 cos^4):  r = exp(-u) (1 + u)^2;
//     Blinn-Phong  D = (s + 2)/(2 pi) cos^s, s = 2/alpha^2 - 2:     r = (1 + u)^2 (1 + alpha^2 u)^
//                  (-1/alpha^2 - 1) = ((1 + t^2)^2 / M2)^2 (C^2 / M2)^(1/alpha^2 - 1) below, which
//                  is exp(-u) (1 + u)^2 as alpha -> 0 and 1 at alpha = 1 (D = 1/pi);
// both bounded (by 4/e) and smooth in t'; they only cut the GGX tail short. Heitz & d'Eon 2014's
// Beckmann VNDF would make r = 1 but needs an erf inverse per node; this form needs none.
// g is Smith's term over GGX's G1(o), written without cancellation (mu Lambda finite at mu = 0):
//     height-correlated  g = (mu_o + mu_o Lambda_ggx(o)) / (mu_o + mu_o Lambda(o) + mu_o
//     Lambda(l)), separable          g = (mu_o + mu_o Lambda_ggx(o)) / (mu_o + mu_o Lambda(o))
//     G1(l),
// with the model's Lambda (GGX, or Beckmann's for Beckmann and Blinn-Phong: erfc and exp of
// mu_l / (alpha sin_l)). Both have the masking layer of the GGX rule at mu_l -> 0, at a scale
// ~ min(alpha, mu_o) (height-correlated) or ~ alpha (separable: the pole of G1(l) at
// mu_l = -mu_l Lambda(l) ~ -alpha / 2): the same panels, at the model's scale.
// The exact-Fresnel albedo (F = FrDielectric(o.h, eta), w = 1) adds one scale: F has branch
// points at o.h = +-i eps, eps = sqrt(eta^2 - 1), and is flat beyond. On the visible domain
// o.h >= mu_o / 2 (o.h = mu_o / (2 cos theta_h) on the cut, mu_o at h = n, and it is monotone
// along an azimuth between), so the layer sits near the normal: o.h ~ mu_o + 2 alpha t sin_o cos p
// there, a layer of width (mu_o + eps) / (2 alpha sin_o |cos p|) in t (the panel graded towards
// t = 0 takes it) and, through the azimuths, of width (mu_o + eps) / (2 alpha) in cos p about
// p = pi/2 (the outer grading scale sigma takes the smaller of it and the grazing bend mu_o /
// sin_o, down to kFresnelSigmaFloor). At eta = 1, F = 0 and E = 0 exactly. Everything else (the
// outer sinh grading about p = pi/2, the inner panels: [graded to 0] + plain + [graded to the cut],
// the weights that decide when a structure is worth a panel) is the GGX rule's, with the graded
// panels computed per node (x = expm1(h s) / expm1(h)) instead of tabulated. Two structures are
// new: Beckmann's r is 1e-16 beyond u = 45 (and Blinn-Phong's beyond the u where its log r = -37),
// so the inner range ends there (the essential singularity of exp(-u) at t' = pi/2 is never
// reached); Blinn-Phong's r has a branch point at t' = pi/2 itself (C^(2/alpha^2 - 2)), so its
// tail panel is graded at the cut's distance from it, not alpha. The counts are set per model
// (kTuned below), one set per model, picked by varying each count from a fine rule (24, 24, 10,
// 3, 10, 12) against adaptive quadrature at 1e-10 on the test grids
// (tests/integrate_fixed_rule_microfacet.cpp) and keeping a cheaper set whose worst error there
// stays below 1e-7 (not minimised: a texel costs ~1,000 evaluations, a table a few CPU seconds).
// Nodes are summed in one fixed order, in double arithmetic (GGX's eight at a time where the
// AVX-512F paths run, each lane with the scalar form's operations, no fused multiply-add): the
// rule is deterministic and has the same bits on either path.
#include "baker/integrate/fixed_rule_microfacet.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "baker/integrate/fixed_rule_beckmann_nodes.h"
#include "baker/math/quadrature.h"
#include "baker/models/beckmann_lambda.h"
#include "baker/models/fresnel.h"
#include "baker/models/registry.h"
#include "baker/models/roughness.h"
#include "baker/models/unity.h"
#if defined(__x86_64__) && defined(__GNUC__)
#include "baker/integrate/dielectric_simd.h"
#include "baker/math/fast_exp_log_avx512.h"
#include "baker/integrate/microfacet_node_lanes.h"
#endif

namespace kiln {
namespace {

constexpr int kMaxNodes = 64;
/// Grading is skipped for structures of weight below this (fixed_rule_dfg.cpp).
constexpr double kNegligible = 1e-9;
/// Azimuths of weight below these take lightNodes, or kTinyNodes, plain nodes.
constexpr double kLightWeight = 1e-4, kTinyWeight = 1e-6;
constexpr int kTinyNodes = 4;
/// Floor of the outer grading scale about p = pi/2 (geometry), and of the Fresnel layer's.
constexpr double kSigmaFloor = 0.03, kFresnelSigmaFloor = 1e-3;
/// Share of the outer nodes kept at the mildest grading.
constexpr double kOuterBase = 0.3;
/// Fraction of [0, t_max] given to the panel graded towards t_max.
constexpr double kTailPanel = 0.25;
/// A structure is graded for when its scale is below this fraction of the graded panel.
constexpr double kGradeBelow = 0.25;
/// unity-brdf1: Unity_SafeNormalize clamps |l + o|^2 = 4 (o.h)^2 at 0.001, below this o.h.
constexpr double kUnitySafeOh = 0.015811388300841896;
/// Bound of r g over GGX's (r <= 4/e, g <= sqrt(pi)): scales the weights that pick light azimuths.
constexpr double kWeightBound = 3;

/// Gauss-Legendre rules on [0, 1] with 1..kMaxNodes nodes (clamped), built once.
const GaussRule01& Gauss(int n) { return CachedGaussLegendre01(std::min(n, kMaxNodes)); }

/// mu Lambda(mu) of GGX, sin = sqrt(1 - mu^2) given, without cancellation (alpha / 2 at mu = 0).
inline double MuLambdaGGX(double mu, double sin, double a) {
  double a2s2 = a * a * sin * sin, den = 2 * (std::sqrt(mu * mu + a2s2) + mu);
  return den > 0 ? a2s2 / den : 0;
}

/// What one evaluation needs: the view, the model, the Fresnel index.
struct Context {
  FixedRuleModel model;
  double mu, st, a, oxs, ozs;
  double gNum;            ///< mu + mu Lambda_ggx(o)
  double gDenO;           ///< mu + mu Lambda(o) (the model's)
  BeckmannNodeView view;  ///< the same for AddBeckmannNodes (Beckmann, Blinn-Phong)
  double blinnK;          ///< 1 / alpha^2 - 1 (Blinn-Phong)
  double tCap;            ///< t beyond which r < 1e-16 (1: none)
  double eta = 0;         ///< > 0: the albedo with FrDielectric(o.h, eta)
  double unityA = 0;      ///< UnityBRDF1: Unity's a = max(r^2, 0.002) (a is alpha_q)
  double sumV = 0, sumB = 0;
  long long count = 0;
};

/// unity-brdf1 at an inner node (see Add): r = D_unity / D_ggx(alpha_q) and
/// g = G2_unity / G1_ggx(o; alpha_q) with G2_unity = 4 mu_o mu_l V_unity, so
///     r = a^2 aq^2 q^4 / ((C^2 a^2 + aq^2 S^2)^2 + 1e-7 M2^2)   (cos^2 theta_h = C^2 / M2),
///     g = 2 mu_l (mu_o + mu_o Lambda_ggx(o)) / (2 mu_l mu_o (1 - a) + a (mu_l + mu_o) + 1e-5),
/// both bounded and smooth; where |l + o|^2 = 4 (o.h)^2 < 0.001, Unity_SafeNormalize scales
/// n.h by 2 (o.h) / sqrt(0.001) (D then uses that n.h; l.h only enters F, here 1).
void AddUnity(Context& k, double t, double C, double S, double q, double M2, double muL,
              double weight, double c) {
  const double a = k.unityA, aq = k.a, mu = k.mu;
  const double oh = (k.st * aq * S * c + mu * C) / std::sqrt(M2);
  double r;
  if (4 * oh * oh < 0.001) {
    // D at the scaled n.h: cos^2 theta_h' = (4 oh^2 / 0.001) C^2 / M2.
    const double cos2 = 4 * oh * oh / 0.001 * C * C / M2, d = cos2 * (a * a - 1) + 1;
    const double dggx = M2 * M2 / (Pi * aq * aq * q * q * q * q);
    r = a * a / (Pi * (d * d + 1e-7)) / dggx;
  } else {
    const double x = C * C * a * a + aq * aq * S * S;
    r = a * a * aq * aq * q * q * q * q / (x * x + 1e-7 * M2 * M2);
  }
  const double g = 2 * muL * k.gNum / (2 * muL * mu * (1 - a) + a * (muL + mu) + 1e-5);
  const double val = weight * t * (2 * k.oxs * c * t + k.ozs * C) / (q * q * q) * r * g;
  const double w = 1 - oh, w2 = w * w;
  k.sumV += val;
  k.sumB += val * (w2 * w2 * w);
}

/// unity-brdf2 at an inner node (see Add): f = D_u / (4 max(0.1, l.h^2) (a + 0.5)) with
/// D_u = a^2 / (pi d^2), d = n.h^2 (a^2 - 1) + 1.00001, so G2 = 4 mu_o mu_l V is
/// mu_o mu_l / (max(0.1, l.h^2) (a + 0.5)) and, at alpha_q = max(a, sqrt(1e-5)),
///     r = a^2 aq^2 q^4 / (1e-5 M2 + aq^2 S^2 + a^2 C^2)^2,
///     g = mu_l (mu_o + mu_o Lambda_ggx(o)) / (max(0.1, (o.h)^2) (a + 0.5))
/// (l.h = o.h for a reflection). g is linear in mu_l: no masking layer. Where 4 (o.h)^2 < 0.001,
/// Unity_SafeNormalize scales n.h and l.h by 2 (o.h) / sqrt(0.001): l.h^2 is then below 0.1 (the
/// max holds it) and D reads the scaled n.h, as in unity-brdf1.
void AddUnity2(Context& k, double t, double C, double S, double q, double M2, double muL,
               double weight, double c) {
  const double a = k.unityA, aq = k.a, mu = k.mu;
  const double oh = (k.st * aq * S * c + mu * C) / std::sqrt(M2);
  double r;
  if (4 * oh * oh < 0.001) {
    const double cos2 = 4 * oh * oh / 0.001 * C * C / M2,
                 d = cos2 * (a * a - 1) + kUnityBRDF2GgxOne;
    const double dggx = M2 * M2 / (Pi * aq * aq * q * q * q * q);
    r = a * a / (Pi * d * d) / dggx;
  } else {
    const double x = 1e-5 * M2 + aq * aq * S * S + a * a * C * C;
    r = a * a * aq * aq * q * q * q * q / (x * x);
  }
  const double g = muL * k.gNum / (std::max(0.1, oh * oh) * (a + 0.5));
  const double val = weight * t * (2 * k.oxs * c * t + k.ozs * C) / (q * q * q) * r * g;
  const double w = 1 - oh, w2 = w * w;
  k.sumV += val;
  k.sumB += val * (w2 * w2 * w);
}

/// Adds weight times the integrand at inner node t of the azimuth with cos p = c: GGX (the
/// general rule's ggx-separable and exact-Fresnel albedo) and the Unity models; Beckmann and
/// Blinn-Phong take AddBeckmannNodes (fixed_rule_beckmann_nodes.h) a panel at a time.
inline void Add(Context& k, double c, double t, double weight) {
  const double a = k.a, mu = k.mu;
  const double t2 = t * t, C = 1 - t2, q = 1 + t2, S = 2 * t, aS = a * S;
  const double C2 = C * C, M2 = aS * aS + C2;
  const double N1 = 2 * k.st * aS * C * c + mu * (C2 - aS * aS);  // mu_l M2
  if (!(N1 > 0)) return;
  if (k.model.ndf == FixedRuleNdf::UnityBRDF1) {
    AddUnity(k, t, C, S, q, M2, N1 / M2, weight, c);
    return;
  }
  if (k.model.ndf == FixedRuleNdf::UnityBRDF2) {
    AddUnity2(k, t, C, S, q, M2, N1 / M2, weight, c);
    return;
  }
  const double invM2 = 1 / M2;
  const double muL = N1 * invM2, sinL = std::sqrt((M2 - N1) * (M2 + N1)) * invM2;
  const double muLambdaL = MuLambdaGGX(muL, sinL, a);
  const double g = k.model.separable ? k.gNum / k.gDenO * (muL / (muL + muLambdaL))
                                     : k.gNum / (k.gDenO + mu * (muLambdaL / muL));
  const double val = weight * t * (2 * k.oxs * c * t + k.ozs * C) / (q * q * q) * g;
  const double oh = (k.st * aS * c + mu * C) * std::sqrt(invM2);
  if (k.eta > 0) {
    k.sumV += val * FrDielectric(oh, k.eta);
  } else {
    const double w = 1 - oh, w2 = w * w;
    k.sumV += val;
    k.sumB += val * (w2 * w2 * w);
  }
}

#if defined(__x86_64__) && defined(__GNUC__)

/// FrDielectric(oh, eta) (models/fresnel.h) in eight lanes: its operations in its order, the
/// clamp and min as MAXPD / MINPD with its operand order, its branches as blends.
KILN_AVX512F_INLINE inline __m512d FrDielectric8(__m512d oh, double eta) {
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
  __m512d x = _mm512_maskz_min_pd(0xFF, _mm512_maskz_max_pd(0xFF, oh, _mm512_set1_pd(-1)), one);
  const __mmask8 neg = _mm512_cmp_pd_mask(x, zero, _CMP_LT_OQ);
  const __m512d e = _mm512_mask_blend_pd(neg, _mm512_set1_pd(eta), _mm512_set1_pd(1 / eta));
  x = _mm512_mask_blend_pd(neg, x, _mm512_sub_pd(zero, x));  // x < 0 there: exactly -x
  const __m512d eta2m1 = _mm512_mul_pd(_mm512_sub_pd(e, one), _mm512_add_pd(e, one));
  const __m512d e2 = _mm512_mul_pd(e, e), x2 = _mm512_mul_pd(x, x);
  const __m512d cos2t = _mm512_div_pd(_mm512_add_pd(x2, eta2m1), e2);
  const __mmask8 tir = _mm512_cmp_pd_mask(cos2t, zero, _CMP_LE_OQ);
  const __m512d cost = _mm512_maskz_sqrt_pd(0xFF, cos2t);
  const __m512d s1 = _mm512_add_pd(x, _mm512_mul_pd(e, cost));
  const __m512d s2 = _mm512_add_pd(_mm512_mul_pd(e, x), cost);
  // (-eta2m1 / s1^2: the sign of a zero numerator does not survive the square below)
  const __m512d rPerp = _mm512_div_pd(_mm512_sub_pd(zero, eta2m1), _mm512_mul_pd(s1, s1));
  const __m512d rParl = _mm512_div_pd(
      _mm512_mul_pd(eta2m1, _mm512_sub_pd(_mm512_mul_pd(_mm512_add_pd(e2, one), x2), one)),
      _mm512_mul_pd(e2, _mm512_mul_pd(s2, s2)));
  const __m512d r = _mm512_div_pd(
      _mm512_add_pd(_mm512_mul_pd(rParl, rParl), _mm512_mul_pd(rPerp, rPerp)), _mm512_set1_pd(2));
  return _mm512_mask_blend_pd(tir, _mm512_maskz_min_pd(0xFF, r, one), one);
}

/// Add's GGX form (not the Unity models) eight nodes at a time, where dielectric_simd::Enabled():
/// each lane does Add's operations in its order (MuLambdaGGX's branch as a mask), the lanes'
/// terms are added in node order, the last block masked: Add's bits.
KILN_AVX512F void AddGgxNodesAvx512(Context& k, double c, const double* t, const double* weight,
                                    int n) {
  // (the sums in registers: through the context they would be stored and reloaded each node)
  double sumV = k.sumV, sumB = k.sumB;
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1), two = _mm512_set1_pd(2);
  const __m512d a = _mm512_set1_pd(k.a), aa = _mm512_set1_pd(k.a * k.a);
  const __m512d mu = _mm512_set1_pd(k.mu), cc = _mm512_set1_pd(c);
  const __m512d twoSt = _mm512_set1_pd(2 * k.st), st = _mm512_set1_pd(k.st);
  const __m512d twoOxsC = _mm512_set1_pd(2 * k.oxs * c), ozs = _mm512_set1_pd(k.ozs);
  const __m512d gNum = _mm512_set1_pd(k.gNum), gDenO = _mm512_set1_pd(k.gDenO);
  const __m512d gRatio = _mm512_set1_pd(k.gNum / k.gDenO);
  for (int i = 0; i < n; i += 8) {
    // The last block's lanes beyond n load 0 and add nothing (`in`).
    const __mmask8 in = n - i >= 8 ? 0xFF : static_cast<__mmask8>((1u << (n - i)) - 1);
    const microfacet_lanes::NodeBlock8 nb =
        microfacet_lanes::LoadNodeBlock8(t + i, in, a, mu, twoSt, cc);
    const __m512d tt = nb.tt, C = nb.C, q = nb.q, aS = nb.aS, M2 = nb.M2, N1 = nb.N1;
    const __mmask8 add = in & _mm512_cmp_pd_mask(N1, zero, _CMP_GT_OQ);
    if (add == 0) continue;
    const __m512d invM2 = _mm512_div_pd(one, M2);
    const __m512d muL = _mm512_mul_pd(N1, invM2);
    const __m512d sinL = _mm512_mul_pd(
        _mm512_maskz_sqrt_pd(0xFF, _mm512_mul_pd(_mm512_sub_pd(M2, N1), _mm512_add_pd(M2, N1))),
        invM2);
    // MuLambdaGGX(muL, sinL, a)
    const __m512d a2s2 = _mm512_mul_pd(_mm512_mul_pd(aa, sinL), sinL);
    const __m512d den = _mm512_mul_pd(
        two, _mm512_add_pd(_mm512_maskz_sqrt_pd(0xFF, _mm512_add_pd(_mm512_mul_pd(muL, muL), a2s2)),
                           muL));
    const __m512d muLambdaL =
        _mm512_maskz_div_pd(_mm512_cmp_pd_mask(den, zero, _CMP_GT_OQ), a2s2, den);
    const __m512d g =
        k.model.separable
            ? _mm512_mul_pd(gRatio, _mm512_div_pd(muL, _mm512_add_pd(muL, muLambdaL)))
            : _mm512_div_pd(gNum,
                            _mm512_add_pd(gDenO, _mm512_mul_pd(mu, _mm512_div_pd(muLambdaL, muL))));
    const __m512d shape =
        _mm512_mul_pd(_mm512_mul_pd(_mm512_maskz_loadu_pd(in, weight + i), tt),
                      _mm512_add_pd(_mm512_mul_pd(twoOxsC, tt), _mm512_mul_pd(ozs, C)));
    const __m512d q3 = _mm512_mul_pd(_mm512_mul_pd(q, q), q);
    const __m512d val = _mm512_mul_pd(_mm512_div_pd(shape, q3), g);
    const __m512d oh =
        _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_mul_pd(st, aS), cc), _mm512_mul_pd(mu, C)),
                      _mm512_maskz_sqrt_pd(0xFF, invM2));
    alignas(64) double vv[8], bv[8];
    if (k.eta > 0) {
      _mm512_store_pd(vv, _mm512_mul_pd(val, FrDielectric8(oh, k.eta)));
      for (int l = 0; l < 8; ++l)
        if (add & (1 << l)) sumV += vv[l];
      continue;
    }
    const __m512d w = _mm512_sub_pd(one, oh), w2 = _mm512_mul_pd(w, w);
    _mm512_store_pd(vv, val);
    _mm512_store_pd(bv, _mm512_mul_pd(val, _mm512_mul_pd(_mm512_mul_pd(w2, w2), w)));
    for (int l = 0; l < 8; ++l)
      if (add & (1 << l)) {
        sumV += vv[l];
        sumB += bv[l];
      }
  }
  k.sumV = sumV;
  k.sumB = sumB;
}

#endif

/// Adds the n nodes (t[i], weight[i]) of the azimuth with cos p = c, in order: Beckmann and
/// Blinn-Phong by AddBeckmannNodes, GGX eight at a time where the AVX-512F paths run (the same
/// bits), else one at a time (Add).
inline void AddNodes(Context& k, double c, const double* t, const double* weight, int n) {
  k.count += n;
  if (k.model.ndf == FixedRuleNdf::Beckmann || k.model.ndf == FixedRuleNdf::BlinnPhong) {
    AddBeckmannNodes(k.view, c, t, weight, n, k.sumV, k.sumB);
    return;
  }
#if defined(__x86_64__) && defined(__GNUC__)
  if (k.model.ndf == FixedRuleNdf::GGX && dielectric_simd::Enabled()) {
    AddGgxNodesAvx512(k, c, t, weight, n);
    return;
  }
#endif
  for (int i = 0; i < n; ++i) Add(k, c, t[i], weight[i]);
}

/// A plain Gauss panel of n nodes over t in [t0, t0 + len].
inline void PlainPanel(Context& k, double c, double pw, double t0, double len, int n) {
  const GaussRule01& g = Gauss(n);
  const int m = static_cast<int>(g.x.size());
  double t[kMaxNodes], w[kMaxNodes];
  for (int i = 0; i < m; ++i) {
    t[i] = t0 + len * g.x[i];
    w[i] = pw * len * g.w[i];
  }
  AddNodes(k, c, t, w, m);
}

/// A panel of length len from the end `end` (t = end + dir x, dir = +-1), graded towards `end`
/// at scale e: x = len expm1(h s) / expm1(h), h = log(1 + len / e), with base + perEFold h Gauss
/// nodes in s.
inline void GradedPanel(Context& k, double c, double pw, double end, double dir, double len,
                        double e, int base, double perEFold) {
  const double h = std::log1p(len / e), em = std::expm1(h);
  const GaussRule01& g = Gauss(base + static_cast<int>(std::ceil(perEFold * h - 1e-9)));
  const int m = static_cast<int>(g.x.size());
  double t[kMaxNodes], w[kMaxNodes];
  for (int i = 0; i < m; ++i) {
    const double x = len * std::expm1(h * g.x[i]) / em;
    t[i] = end + dir * x;
    w[i] = pw * len * h * g.w[i] * std::exp(h * g.x[i]) / em;
  }
  AddNodes(k, c, t, w, m);
}

/// A segment [t0, t1] of an azimuth graded towards its left end at scale eL and its right end at
/// eR (INFINITY: no grading): both, halves graded each way; one, graded where the scale is below
/// kGradeBelow of the segment (that half graded, the other n plain nodes); none, n plain nodes.
void Segment(Context& k, double c, double pw, double t0, double t1, double eL, double eR, int n,
             const MicrofacetRuleOptions& opt) {
  const double len = t1 - t0;
  if (!(len > 0)) return;
  const bool gl = eL < kGradeBelow * len, gr = eR < kGradeBelow * len;
  if (gl && gr) {
    GradedPanel(k, c, pw, t0, 1, len / 2, eL, opt.gradedNodes, opt.nodesPerEFold);
    GradedPanel(k, c, pw, t1, -1, len - len / 2, eR, opt.gradedNodes, opt.nodesPerEFold);
  } else if (gl) {
    GradedPanel(k, c, pw, t0, 1, len / 2, eL, opt.gradedNodes, opt.nodesPerEFold);
    PlainPanel(k, c, pw, t0 + len / 2, len - len / 2, n);
  } else if (gr) {
    PlainPanel(k, c, pw, t0, len - len / 2, n);
    GradedPanel(k, c, pw, t1, -1, len / 2, eR, opt.gradedNodes, opt.nodesPerEFold);
  } else {
    PlainPanel(k, c, pw, t0, len, n);
  }
}

/// unity-brdf2's kink levels of o.h: Unity_SafeNormalize's sqrt(0.001) / 2 and max(0.1, l.h^2)'s
/// sqrt(0.1).
constexpr double kUnity2Levels[2] = {kUnitySafeOh, kUnityBRDF2LhKink};

/// o.h along the azimuth with cos p = c. The stretch is isotropic, so the azimuth is h's own and
/// o.h = mu cos(theta) + s_o c sin(theta) = A cos(theta - theta0), A = sqrt(mu^2 + s_o^2 c^2),
/// theta0 = atan2(s_o c, mu), theta the polar angle of h (tan theta = alpha tan t', t = tan(t'/2)).
/// It rises to A at theta0 and falls after: a level L < A is crossed at theta0 -+ acos(L / A).
/// Writes the crossings inside (0, t1) in t, increasing, and whether o.h rises through each.
int Unity2Crossings(const Context& k, double c, double t1, double level, double* t, bool* rising) {
  const double A = std::sqrt(k.mu * k.mu + k.st * k.st * c * c);
  if (!(A > level)) return 0;
  const double th0 = std::atan2(k.st * c, k.mu), d = std::acos(level / A);
  int n = 0;
  for (int i = 0; i < 2; ++i) {
    const double th = i == 0 ? th0 - d : th0 + d;
    if (!(th > 0 && th < Pi / 2)) continue;
    const double tq = std::tan(std::atan(std::tan(th) / k.a) / 2);
    if (tq > 0 && tq < t1) {
      t[n] = tq;
      rising[n] = i == 0;
      ++n;
    }
  }
  return n;
}

/// unity-brdf2's azimuth [0, t1]: panel boundaries where o.h crosses its kink levels
/// (Unity2Crossings); the SafeNormalize kink's inner side (o.h below it: D's scaled peak sits on
/// the kink) graded towards it at unity-brdf1's scale, with max(a^2, 1e-5) for D's width in
/// n.h^2; eEnd at t1.
void UnityBRDF2Azimuth(Context& k, double c, double pw, double t1, double eEnd,
                       const MicrofacetRuleOptions& opt) {
  const double a = k.a, st = k.st, mu = k.mu;
  auto ohAt = [&](double t) {
    const double C = 1 - t * t, aS = a * 2 * t;
    return (st * aS * c + mu * C) / std::sqrt(aS * aS + C * C);
  };
  struct B {
    double t, eBefore, eAfter;
  } bs[4];
  int m = 0;
  for (int li = 0; li < 2; ++li) {
    double tc[2];
    bool up[2];
    const int n = Unity2Crossings(k, c, t1, kUnity2Levels[li], tc, up);
    for (int i = 0; i < n; ++i) {
      double eK = INFINITY;
      if (li == 0) {
        const double dt = 1e-7 * t1,
                     slope = std::abs(ohAt(tc[i] + dt) - ohAt(tc[i] - dt)) / (2 * dt);
        const double ua = k.unityA * k.unityA;
        eK = std::max(std::max(ua, 1e-5) * kUnitySafeOh / (2 * std::max(slope, 1e-300)), 1e-12);
      }
      // Rising through the level: the inside (below it) is before the crossing.
      bs[m++] = {tc[i], up[i] ? eK : INFINITY, up[i] ? INFINITY : eK};
    }
  }
  for (int i = 1; i < m; ++i)  // insertion sort by t (at most 4)
    for (int j = i; j > 0 && bs[j].t < bs[j - 1].t; --j) std::swap(bs[j], bs[j - 1]);
  const int n = opt.bulkNodes + opt.gradedNodes;
  double t0 = 0, eL = INFINITY;
  for (int i = 0; i < m; ++i) {
    Segment(k, c, pw, t0, bs[i].t, eL, bs[i].eBefore, n, opt);
    t0 = bs[i].t;
    eL = bs[i].eAfter;
  }
  Segment(k, c, pw, t0, t1, eL, eEnd, n, opt);
}

/// t at the cut of the azimuth with cos p = +-cx (side 0: +, 1: -), as Rule2 computes it.
double CutT(const Context& k, double cx, int side) {
  const double mu = k.mu, X = k.st * cx, R = std::sqrt(mu * mu + X * X), RX = R + X;
  if (side == 1 && mu == 0) return 0;
  // (side 0 at mu = 0: iT = 0 on every azimuth, also at cx = 0 where Rule2 puts no node)
  const double iT =
      side == 0 ? (mu > 0 ? mu * (1 / RX) : 0) : std::min(RX * (mu > 0 ? 1 / mu : 0), 1e150);
  const double iu = k.a * iT;
  return 1 / (iu + std::sqrt(iu * iu + 1));
}

/// unity-brdf2's outer breakpoints in y (cx = sin(sigma sinh y)) over [0, Y]: where o.h at the
/// cut crosses one of its kink levels sqrt(0.1), sqrt(0.001) / 2 on either side, by bisection
/// (o.h at the cut taken monotone in y), sorted, with 0 and Y.
std::vector<double> UnityBRDF2OuterBreaks(const Context& k, double sigma, double Y) {
  const double* levels = kUnity2Levels;
  auto ohCut = [&](double y, int side) {
    const double cx = std::sin(sigma * std::sinh(y)), c = side == 0 ? cx : -cx;
    const double t = CutT(k, cx, side), C = 1 - t * t, aS = k.a * 2 * t;
    return (k.st * aS * c + k.mu * C) / std::sqrt(aS * aS + C * C);
  };
  std::vector<double> out = {0.0, Y};
  // Where a level is tangent to an azimuth (A = level: the two crossings meet), cx =
  // sqrt(level^2 - mu^2) / s_o.
  for (int li = 0; li < 2; ++li) {
    const double level = levels[li];
    if (!(level > k.mu && k.st > 0)) continue;
    const double cx = std::sqrt((level - k.mu) * (level + k.mu)) / k.st;
    if (cx < 1) {
      const double y = std::asinh(std::asin(cx) / sigma);
      if (y > 1e-9 * Y && y < Y * (1 - 1e-9)) out.push_back(y);
    }
  }
  for (int side = 0; side < 2; ++side)
    for (int li = 0; li < 2; ++li) {
      const double level = levels[li];
      const double f0 = ohCut(0, side) - level, f1 = ohCut(Y, side) - level;
      if (!((f0 < 0) != (f1 < 0))) continue;
      double lo = 0, hi = Y;
      for (int i = 0; i < 60; ++i) {
        const double m = (lo + hi) / 2;
        ((ohCut(m, side) - level < 0) == (f0 < 0) ? lo : hi) = m;
      }
      const double yb = (lo + hi) / 2;
      if (yb > 1e-9 * Y && yb < Y * (1 - 1e-9)) out.push_back(yb);
    }
  std::sort(out.begin(), out.end());
  return out;
}

/// The scales of one view that place Rule2's nodes: the masking pole's distance sMask below the
/// horizon, the factor weightScale of the weights that pick light azimuths, the outer map's
/// width sigma and the Fresnel layer eps = sqrt(eta^2 - 1) (0: no Fresnel).
struct RuleScales {
  double sMask = 0, weightScale = 1, sigma = 0, eps = 0;
};

/// Rule2's RuleScales for the view and model of `k`.
RuleScales ScalesOf(const Context& k) {
  const double mu = k.mu, st = k.st, a = k.a;
  RuleScales s;
  // Masking pole of g at mu_l = -sMask: ~ min(alpha, mu) height-correlated, ~ alpha separable.
  const double muLo = k.gDenO - mu;
  s.sMask = k.model.separable ? a / 2 : (mu > 0 ? mu * a / (mu + 2 * muLo) : 0);
  // unity-brdf1: V's pole in mu_l at -(a mu + 1e-5) / (2 mu (1 - a) + a).
  if (k.model.ndf == FixedRuleNdf::UnityBRDF1)
    s.sMask = (k.unityA * mu + 1e-5) / (2 * mu * (1 - k.unityA) + k.unityA);
  // unity-brdf2: g is linear in mu_l (no masking pole), and up to 1 / (0.1 (a + 0.5)) times
  // GGX's: the weights that pick light azimuths scale by it.
  if (k.model.ndf == FixedRuleNdf::UnityBRDF2) {
    s.sMask = 0;
    s.weightScale = 1 / (0.1 * (k.unityA + 0.5));
  }
  s.sigma = std::min(1e3, std::max(st > 0 ? mu / st : 1e3, kSigmaFloor));
  if (k.eta > 0) {
    s.eps = std::sqrt((k.eta - 1) * (k.eta + 1));
    s.sigma = std::min(s.sigma, std::max((mu + s.eps) / (2 * a), kFresnelSigmaFloor));
  }
  return s;
}

/// Rule2's outer nodes in y (the azimuth is p = pi/2 - sigma sinh(y) folded, y in [0, Y]) and
/// their weights in y: one Gauss panel over [0, Y]; unity-brdf2 splits it where a kink of its
/// o.h levels meets the cut (UnityBRDF2OuterBreaks): there the inner integral is not smooth in
/// the azimuth.
void OuterNodes(const Context& k, const MicrofacetRuleOptions& opt, double sigma,
                std::vector<double>& ys, std::vector<double>& wys) {
  static const double kYRef = std::asinh(Pi / (2 * kSigmaFloor));
  const double Y = std::asinh(Pi / (2 * sigma));
  const int nOuter = std::min(
      kMaxNodes, static_cast<int>(std::ceil(
                     opt.outerNodes * (kOuterBase + (1 - kOuterBase) * std::min(Y, kYRef) / kYRef) +
                     opt.outerNodes * std::max(0.0, Y - kYRef) / kYRef - 1e-9)));
  const GaussRule01& go = Gauss(nOuter);
  std::vector<double> breaks = {0.0, Y};
  if (k.model.ndf == FixedRuleNdf::UnityBRDF2) breaks = UnityBRDF2OuterBreaks(k, sigma, Y);
  for (size_t b = 0; b + 1 < breaks.size(); ++b)
    for (size_t io = 0; io < go.x.size(); ++io) {
      if (breaks.size() == 2) {
        ys.push_back(Y * go.x[io]);
        wys.push_back(go.w[io] * Y);
      } else {
        const double len = breaks[b + 1] - breaks[b];
        ys.push_back(breaks[b] + len * go.x[io]);
        wys.push_back(go.w[io] * len);
      }
    }
}

/// Both sides of one outer node's cut (0: cos p > 0, 1: cos p < 0): t at the cut (tm), dt/dt'
/// there (d), the masking scale e2 at the cut and, for the opposite side, e0
/// (fixed_rule_dfg.cpp).
struct CutSides {
  double tm[2], d[2], e2[2], e0[2];
};

/// The CutSides of the outer node whose azimuth has |cos p| = cx.
CutSides SidesOf(const Context& k, double sMask, double cx) {
  const double mu = k.mu, a = k.a, a2 = a * a;
  const double invMu = mu > 0 ? 1 / mu : 0;
  const double X = k.st * cx, R = std::sqrt(mu * mu + X * X), RX = R + X;
  const double iT[2] = {mu * (1 / RX), std::min(RX * invMu, 1e150)};
  CutSides s;
  for (int side = 0; side < 2; ++side) {
    const double iu = a * iT[side], m = 1 + a2 * iT[side] * iT[side];
    const double t1 = 1 / (iu + std::sqrt(iu * iu + 1));
    const double u = sMask * a * (1 + iT[side] * iT[side]) / (2 * R * m);  // e2 / (dt/dt')
    s.tm[side] = side == 1 && mu == 0 ? 0 : t1;
    s.d[side] = (1 + t1 * t1) / 2;
    s.e2[side] = u * s.d[side];
    s.e0[side] = t1 + u / 2;
  }
  return s;
}

/// unity-brdf1's panels of one azimuth (c = cos p, weight pw) over [0, t1] when its
/// Unity_SafeNormalize kink, where o.h = sqrt(0.001) / 2, lies inside (o.h runs monotonically
/// from mu at t = 0 to the cut): a panel boundary there, each side graded towards its own
/// structure (eStart at 0, eEnd at t1). Returns false, adding nothing, when the kink is not
/// inside.
bool UnityBRDF1KinkPanels(Context& k, const MicrofacetRuleOptions& opt, double c, double pw,
                          double t1, double eStart, double eEnd) {
  const double mu = k.mu, st = k.st, a = k.a;
  auto ohAt = [&](double t) {
    const double C = 1 - t * t, aS = a * 2 * t;
    return (st * aS * c + mu * C) / std::sqrt(aS * aS + C * C);
  };
  const double f0 = ohAt(0) - kUnitySafeOh, f1 = ohAt(t1) - kUnitySafeOh;
  if (!((f0 < 0) != (f1 < 0) && f0 != 0 && f1 != 0)) return false;
  double lo = 0, hi = t1;
  for (int i = 0; i < 60; ++i) {
    const double m = (lo + hi) / 2;
    ((ohAt(m) - kUnitySafeOh < 0) == (f0 < 0) ? lo : hi) = m;
  }
  const double tk = (lo + hi) / 2;
  const int n = opt.bulkNodes + opt.gradedNodes;
  // Inside (o.h < sqrt(0.001) / 2) D reads n.h scaled by o.h / (sqrt(0.001) / 2): its
  // peak sits on the kink and falls off within w = max(a^2, sqrt(1e-7)) in n.h^2, a
  // layer of width w h0 / (2 |d(o.h)/dt|) in t on the inside of tk.
  const double dt = 1e-7 * t1, slope = std::abs(ohAt(tk + dt) - ohAt(tk - dt)) / (2 * dt);
  const double ua = k.unityA * k.unityA;
  const double eK = std::max(
      std::max(ua, 3.1622776601683794e-4) * kUnitySafeOh / (2 * std::max(slope, 1e-300)), 1e-12);
  const bool insideLow = f0 < 0;  // [0, tk] is inside
  // [0, tk]
  if (insideLow) {
    const double half = tk / 2;
    if (eStart < half / 8)
      GradedPanel(k, c, pw, 0, 1, half, eStart, opt.deficitNodes, opt.nodesPerEFold);
    else
      PlainPanel(k, c, pw, 0, half, n);
    GradedPanel(k, c, pw, tk, -1, tk - half, eK, opt.gradedNodes, opt.nodesPerEFold);
  } else if (eStart < tk / 8) {
    GradedPanel(k, c, pw, 0, 1, tk, eStart, opt.deficitNodes, opt.nodesPerEFold);
  } else {
    PlainPanel(k, c, pw, 0, tk, n);
  }
  // [tk, t1]
  const double rest = t1 - tk;
  if (!insideLow) {
    const double half = rest / 2;
    GradedPanel(k, c, pw, tk, 1, half, eK, opt.gradedNodes, opt.nodesPerEFold);
    if (eEnd < kGradeBelow * half)
      GradedPanel(k, c, pw, t1, -1, rest - half, eEnd, opt.gradedNodes, opt.nodesPerEFold);
    else
      PlainPanel(k, c, pw, tk + half, rest - half, n);
  } else if (eEnd < kGradeBelow * rest) {
    GradedPanel(k, c, pw, t1, -1, rest, eEnd, opt.gradedNodes, opt.nodesPerEFold);
  } else {
    PlainPanel(k, c, pw, tk, rest, n);
  }
  return true;
}

/// The inner panels of one side of one outer node (|cos p| = cx, weight pw in y, prefactor
/// pref): plain panels where the azimuth's weight is small, else panels graded towards the
/// structures at t = 0 (the opposite side's masking, the Fresnel layer) and at the cut (GGX's
/// tail, Fresnel in the tail, the masking pole).
void SidePanels(Context& k, const MicrofacetRuleOptions& opt, const RuleScales& s,
                const CutSides& cut, int side, double cx, double pw, double pref) {
  const double mu = k.mu, st = k.st, a = k.a;
  const double t1 = std::min(cut.tm[side], k.tCap);
  const bool capped = t1 < cut.tm[side];  // the cut and its structures lie beyond the NDF's end
  if (!(t1 > 0)) return;
  const double c = side == 0 ? cx : -cx, kOn = 2 * k.oxs * c;
  const double weight = s.weightScale * kWeightBound * pref / 4 * pw * t1 * t1 *
                        (4.0 / 3 * std::abs(kOn) * t1 + 2 * k.ozs);
  if (weight < kTinyWeight) {
    PlainPanel(k, c, pw, 0, t1, kTinyNodes);
    return;
  }
  if (weight < kLightWeight) {
    PlainPanel(k, c, pw, 0, t1, opt.lightNodes);
    return;
  }
  const double onMaxQ = k.oxs * 2 * t1 * c + k.ozs * (1 - t1 * t1);
  const double floorW = kNegligible * cut.d[side] * (1 + t1 * t1);
  // GGX's tail: branch points at t = 1 +- i alpha; Blinn-Phong's r has C^(2/alpha^2 - 2), a
  // branch point at t = 1 itself (the cut's distance from it, down to 1e-5).
  const double eTail = k.model.ndf == FixedRuleNdf::BlinnPhong && k.blinnK > 0 && !capped
                           ? std::max(1 - t1, 1e-5)
                           : (1 - t1) + a,
               len = kTailPanel * t1;
  double eEnd = INFINITY;
  if (onMaxQ * eTail > floorW && eTail < kGradeBelow * len) eEnd = eTail;
  // Fresnel in the GGX tail: o.h ~ mu + 2 alpha sin_o |cos p| / C there, which crosses the
  // layer o.h ~ eps at C ~ alpha / eps (a 1/C decay of 1 - F beyond it).
  const double eFT = (1 - t1) + a * (1 + 2 * st * std::abs(c) / std::max(s.eps, 1e-300));
  if (k.eta > 0 && onMaxQ * eFT > floorW && eFT < kGradeBelow * len) eEnd = std::min(eEnd, eFT);
  if (!capped && s.sMask > 0 && cut.e2[side] < kGradeBelow * len && onMaxQ * cut.e2[side] > floorW)
    eEnd = std::min(eEnd, cut.e2[side]);
  if (k.model.ndf == FixedRuleNdf::UnityBRDF2) {
    UnityBRDF2Azimuth(k, c, pw, t1, eEnd, opt);
    return;
  }
  double eStart = INFINITY;
  const double eMask = cut.e0[1 - side];
  if (s.sMask > 0 && cut.tm[1 - side] > 0 && eMask < t1 / 8 && eMask * eMask * k.ozs > kNegligible)
    eStart = eMask;
  if (k.eta > 0 && st > 0 && cx > 0) {
    const double eF = (mu + s.eps) / (2 * a * st * cx);
    if (eF < t1 / 8) eStart = std::min(eStart, eF);
  }
  if (k.model.ndf == FixedRuleNdf::UnityBRDF1 && mu < 2 * kUnitySafeOh &&
      UnityBRDF1KinkPanels(k, opt, c, pw, t1, eStart, eEnd))
    return;
  double split = 0;
  if (eStart < INFINITY) {
    split = t1 / 2;
    GradedPanel(k, c, pw, 0, 1, split, eStart, opt.deficitNodes, opt.nodesPerEFold);
  }
  if (eEnd < INFINITY) {
    const double mid = t1 - len - split;
    PlainPanel(k, c, pw, split, mid, split > 0 ? opt.deficitNodes : opt.bulkNodes);
    GradedPanel(k, c, pw, t1, -1, len, eEnd, opt.gradedNodes, opt.nodesPerEFold);
  } else {
    PlainPanel(k, c, pw, split, t1 - split,
               split > 0 ? opt.bulkNodes : opt.bulkNodes + opt.gradedNodes);
  }
}

/// The rule: (sumV, sumB) times the prefactor (Fresnel: sumV is E). The outer nodes
/// (OuterNodes) pick light azimuths, each side of each (SidesOf) gets its inner panels
/// (SidePanels).
std::array<double, 2> Rule2(Context& k, const MicrofacetRuleOptions& opt, long long* evals) {
  const double pref = 16 / (Pi * (1 + k.ozs));
  const RuleScales s = ScalesOf(k);
  std::vector<double> ys, wys;
  OuterNodes(k, opt, s.sigma, ys, wys);
  for (size_t io = 0; io < ys.size(); ++io) {
    const double y = ys[io];
    const double cx = std::sin(s.sigma * std::sinh(y)), pw = wys[io] * s.sigma * std::cosh(y);
    const CutSides cut = SidesOf(k, s.sMask, cx);
    for (int side = 0; side < 2; ++side) SidePanels(k, opt, s, cut, side, cx, pw, pref);
  }
  if (evals) *evals += k.count;
  return {pref * (k.sumV - k.sumB), pref * k.sumB};
}

/// The context of a view and model (eta = 0: the DFG).
/// Blinn-Phong's end of the NDF for alpha a (blinnK = 1 / a^2 - 1): the u = tan^2 t' where
/// log r = 2 log(1 + u) - (1 / a^2 + 1) log(1 + a^2 u) falls to -37, by 60 bisections in log u
/// (INFINITY when it stays above). It depends on a alone: the last a's value is kept per thread
/// (a table's texels of one roughness come one after another), the same bits.
double BlinnPhongEnd(double a, double blinnK) {
  thread_local double lastA = -1, lastEnd = INFINITY;
  if (a == lastA) return lastEnd;
  auto logR = [&](double u) { return 2 * std::log1p(u) - (blinnK + 2) * std::log1p(a * a * u); };
  double uMax = INFINITY;
  if (logR(1e300) < -37) {
    double lo = std::log(1e-3), hi = std::log(1e300);
    for (int i = 0; i < 60; ++i) {
      const double m = (lo + hi) / 2;
      (logR(std::exp(m)) < -37 ? hi : lo) = m;
    }
    uMax = std::exp(hi);
  }
  lastA = a;
  lastEnd = uMax;
  return uMax;
}

Context MakeContext(const FixedRuleModel& model, double mu, double alpha) {
  Context k;
  k.model = model;
  k.mu = std::min(1.0, std::max(0.0, mu));
  k.a = std::max(alpha, MinAlpha);
  if (model.ndf == FixedRuleNdf::UnityBRDF1) {
    k.unityA = std::max(alpha, 0.002);
    k.a = std::max(k.unityA, kUnityBRDF1SamplerAlpha);  // alpha_q: UnityBRDF1::Sampler
  }
  if (model.ndf == FixedRuleNdf::UnityBRDF2) {
    k.unityA = std::max(alpha, 0.0);
    k.a = std::max(k.unityA, kUnityBRDF2SamplerAlpha);  // alpha_q: UnityBRDF2::Sampler
  }
  k.st = std::sqrt(std::max(0.0, 1 - k.mu * k.mu));
  const double L = std::sqrt(k.a * k.a * k.st * k.st + k.mu * k.mu);
  k.ozs = k.mu / L;
  k.oxs = k.a * k.st / L;
  k.gNum = k.mu + MuLambdaGGX(k.mu, k.st, k.a);
  k.gDenO = k.mu + (model.ndf == FixedRuleNdf::GGX ? MuLambdaGGX(k.mu, k.st, k.a)
                                                   : BeckmannMuLambda(k.mu, k.st, k.a));
  k.blinnK = 1 / (k.a * k.a) - 1;
  k.view = {k.a,
            k.mu,
            k.st,
            k.oxs,
            k.ozs,
            k.gNum,
            k.gDenO,
            k.gNum / k.gDenO,
            k.blinnK,
            model.ndf == FixedRuleNdf::BlinnPhong,
            model.separable};
  // The end of the NDF: u = tan^2 t' where log r = -37 (r = exp(-u) (1 + u)^2 for Beckmann; for
  // Blinn-Phong 2 log(1 + u) - (1 / alpha^2 + 1) log(1 + alpha^2 u), by bisection in log u, none
  // when it stays above), then t = tan(t'/2).
  double uMax = INFINITY;
  if (model.ndf == FixedRuleNdf::Beckmann) uMax = 45;
  if (model.ndf == FixedRuleNdf::BlinnPhong) uMax = BlinnPhongEnd(k.a, k.blinnK);
  // (no cap beyond u = 1e12: t is within 1e-6 of 1 there, where the tail grading takes over)
  k.tCap = uMax < 1e12 ? std::tan(std::atan(std::sqrt(uMax)) / 2) : 1;
  return k;
}

/// The bake's node counts per model (outer, bulk, graded, per e-fold, deficit, light).
struct Tuned {
  FixedRuleNdf ndf;
  bool separable;
  MicrofacetRuleOptions opt;
};
// Beckmann's Lambda has an essential singularity where sin_l = 0 (x = mu_l / (alpha sin_l) -> inf,
// exp(-x^2) flat on the real line only): a cone point at l = n, inside the lobe when alpha ~ 1,
// which takes more inner nodes than GGX's Lambda. The Fresnel layer takes more bulk nodes.
// Beckmann, beckmann-separable and Blinn-Phong were cut from {24, 20, 8, 3, 10, 8} to 0.74-0.76 of
// its evaluations (bulk 14), each still within 1e-7 of adaptive quadrature at 1e-10 on the test
// grid (worst 5.2e-8, 6.3e-8, 5.2e-8; tests/integrate_fixed_rule_microfacet.cpp).
const Tuned kTuned[] = {
    {FixedRuleNdf::GGX, true, {24, 12, 6, 2, 8, 8}},
    {FixedRuleNdf::Beckmann, false, {22, 14, 8, 3, 10, 8}},
    {FixedRuleNdf::Beckmann, true, {24, 14, 7, 3, 9, 8}},
    {FixedRuleNdf::BlinnPhong, false, {22, 14, 8, 3, 10, 8}},
    {FixedRuleNdf::GGX, false, {24, 12, 6, 2, 8, 8}},
    {FixedRuleNdf::UnityBRDF1, false, {32, 16, 8, 2, 8, 8}},
    {FixedRuleNdf::UnityBRDF2, false, {16, 16, 8, 2, 8, 8}},
};
const MicrofacetRuleOptions kTunedFresnel = {24, 16, 8, 2, 8, 8};
// The search's verification-grade counts: fewer outer nodes (16) and, for the Beckmann Lambda's
// cone point, 12 bulk nodes (14 for the exact Fresnel below eta = 1.3); measured against the bake's
// rule on tests/lookup_search_reference.cpp's 49 x 41 (mu, r) grid with mu = 0, 1e-9, r = 0 and 1:
// worst 1.55e-6 (beckmann-separable at r = 1), 0.58 to 0.59 of its evaluations (before the bake
// rules' cut to bulk 14: 1.3e-6, 0.49; exact Fresnel: 4.6e-8, 0.58). ggx-separable's tables take
// the GGX kernel (fixed_rule_dfg.h), their own search reference; its counts here stay for callers
// of this rule.
const MicrofacetRuleOptions kSearchGgxSeparable = {16, 8, 5, 2, 6, 6};
const MicrofacetRuleOptions kSearchOther = {16, 12, 6, 2, 6, 6};
const MicrofacetRuleOptions kSearchFresnel = {16, 14, 6, 2, 6, 6};

}  // namespace

bool FixedRuleModelFor(const ModelInfo& model, FixedRuleModel* out) {
  if (model.rule != RuleFamily::Microfacet) return false;
  FixedRuleNdf ndf = FixedRuleNdf::GGX;
  switch (model.microfacetNdf) {
    case MicrofacetNdf::GGX:
      ndf = FixedRuleNdf::GGX;
      break;
    case MicrofacetNdf::Beckmann:
      ndf = FixedRuleNdf::Beckmann;
      break;
    case MicrofacetNdf::BlinnPhong:
      ndf = FixedRuleNdf::BlinnPhong;
      break;
    case MicrofacetNdf::UnityBRDF1:
      ndf = FixedRuleNdf::UnityBRDF1;
      break;
    case MicrofacetNdf::UnityBRDF2:
      ndf = FixedRuleNdf::UnityBRDF2;
      break;
  }
  if (out) *out = FixedRuleModel{ndf, model.separableSmith};
  return true;
}

bool FixedRuleModelFor(const char* model, FixedRuleModel* out) {
  const ModelInfo* m = FindModel(model);
  return m && FixedRuleModelFor(*m, out);
}

MicrofacetRuleOptions TunedMicrofacetRuleOptions(const FixedRuleModel& model) {
  for (const Tuned& t : kTuned)
    if (t.ndf == model.ndf && t.separable == model.separable) return t.opt;
  return MicrofacetRuleOptions{};
}

MicrofacetRuleOptions TunedFresnelRuleOptions() { return kTunedFresnel; }

MicrofacetRuleOptions SearchMicrofacetRuleOptions(const FixedRuleModel& model) {
  return model.ndf == FixedRuleNdf::GGX ? kSearchGgxSeparable : kSearchOther;
}

MicrofacetRuleOptions SearchFresnelRuleOptions() { return kSearchFresnel; }

double SearchMicrofacetCharge(const FixedRuleModel& model) {
  return model.ndf == FixedRuleNdf::GGX ? 1.7 : 1.65;
}

std::array<double, 2> FixedRuleMicrofacetDFG(const FixedRuleModel& model, double mu, double alpha,
                                             const MicrofacetRuleOptions& opt, long long* evals) {
  Context k = MakeContext(model, mu, alpha);
  return Rule2(k, opt, evals);
}

std::array<double, 2> FixedRuleMicrofacetDFG(const FixedRuleModel& model, double mu, double alpha,
                                             long long* evals) {
  return FixedRuleMicrofacetDFG(model, mu, alpha, TunedMicrofacetRuleOptions(model), evals);
}

double FixedRuleGGXFresnelAlbedo(double mu, double alpha, double eta,
                                 const MicrofacetRuleOptions& opt, long long* evals) {
  if (!(eta > 1)) return 0;  // F = 0 at eta = 1 (FrDielectric); eta < 1 is not this rule's
  Context k = MakeContext(FixedRuleModel{FixedRuleNdf::GGX, false}, mu, alpha);
  k.eta = eta;
  return Rule2(k, opt, evals)[0];
}

double FixedRuleGGXFresnelAlbedo(double mu, double alpha, double eta, long long* evals) {
  return FixedRuleGGXFresnelAlbedo(mu, alpha, eta, TunedFresnelRuleOptions(), evals);
}

}  // namespace kiln
