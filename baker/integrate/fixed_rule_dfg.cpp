// Fixed-rule split-sum DFG of GGX: the visible-normal form of the integral (Heitz 2018, "Sampling
// the GGX Distribution of Visible Normals", JCGT 7(4); Heitz 2014 for the Smith terms) with the
// horizon cut taken exactly, integrated by Gauss-Legendre panels whose placement and grading come
// from the integrand's analytic structure, not from error estimates.
//
// Derivation. With l = reflect(o, h) and dl = 4 (o.h) dh, f mu_l dl = D G2 (o.h) / mu_o dh. The
// visible-normal density is D_o(h) = G1(o) (o.h)^+ D(h) / mu_o, so
//     E_w = integral f w mu_l dl = integral_{mu_l > 0} D_o(h) [G2 / G1(o)] w(o.h) dh.
// Stretch by alpha (x, y scaled by 1/alpha): o' = (alpha sin_o, 0, mu_o) / L,
// L = sqrt(alpha^2 sin_o^2 + mu_o^2), and h maps to the unit normal n' = (sin t' cos p,
// sin t' sin p, cos t') (t' = theta'_h, p = phi_h, unchanged). D_o is uniform over the projected
// area of the stretched hemisphere, pi (1 + o'_z) / 2, i.e. D_o dh = 2 (o'.n')^+ dn' / (pi (1 +
// o'_z)):
//     E_w = 4 / (pi (1 + o'_z)) int_0^pi dp int_0^{t'max(p)} sin t' (o'.n') g w dt',
// the 2 from the mirror symmetry p -> -p, g = G2 / G1(o) = 1 / (1 + Lambda_l / (1 + Lambda_o)) in
// [0, 1]. No lobe is left in (t', p): alpha = 1e-12 is as smooth as alpha = 1.
// The horizon cut is exact and analytic in p: with h at (theta, p), mu_l = R cos(2 theta - beta),
// R = sqrt(mu_o^2 + X^2), X = sin_o cos p, beta = atan2(X, mu_o), so mu_l > 0 iff
// theta < theta_max = pi/4 + beta/2, tan theta_max = (R + X) / mu_o = mu_o / (R - X), and
// tan t'max = tan theta_max / alpha. The azimuths p and pi - p (X and -X) share R, and their
// tan theta_max are reciprocal. Swapping the usual order (p outer, t' inner) removes the d^(3/2)
// points where the cut starts and ends in theta: t'max(p) is smooth.
// What is left is near-singular, at three known scales:
//  1. Grazing views: beta(p) bends within cos p ~ sigma = mu_o / sin_o of p = pi/2 (R has branch
//     points at cos p = +-i sigma). The outer rule maps each half p in [0, pi/2], [pi/2, pi] by
//     p = pi/2 -+ sigma sinh(y), y in [0, Y], Y = asinh(pi / (2 sigma)) (sigma at least 0.03: the
//     bend scale below that carries too little weight to matter, measured), Gauss in y. The
//     branch points then sit near y = +-i pi/2 at the end y = 0, so the rule converges at a rate
//     set by pi / Y: it takes outerNodes (0.3 + 0.7 Y / Y(0.03)) nodes per half (outerNodes at
//     grazing, 4 at mu = 1). Y is rounded up to a multiple of 1/32 (sigma down, grading a little
//     stronger), so the rules (|cos p| and weights) are tabulated per level, once.
//  2. The GGX tail: in t' the whole of theta in [~10 alpha, pi/2] sits within ~10 alpha of
//     t' = pi/2 (tan theta = alpha tan t'), where |n| = sqrt(alpha^2 sin^2 + cos^2) has branch
//     points t' = pi/2 +- i atanh(alpha). Where that matters, the last quarter of the inner range
//     is a panel graded towards t'max by log(t'max - t' + e), e = (pi/2 - t'max) + alpha (in
//     t = tan(t'/2) units).
//  3. Masking of l: as mu_l -> 0, g = mu_l (mu_o + mu_o L_o) / (mu_l (...) + mu_o mu_l Lambda_l)
//     has a pole at mu_l = -s, s = mu_o alpha / (mu_o + 2 mu_o Lambda_o) ~ min(alpha, mu_o), and
//     branch points at mu_l = +-i alpha: at the cut at scale e2 = s / |dmu_l/dt'|, which the panel
//     graded towards t'max takes instead when it is the finer one; and, when the opposite
//     azimuth's cut is close to the normal (mu_o << alpha), near t' = 0 at that cut's distance,
//     which a panel over the first half, graded towards 0, takes.
// Two variants share the panels and the kernel (kSeparable, kFresnel below):
//  - Separable Smith (ggx-separable), G2 = G1(o) G1(l): g = G2 / G1(o) = G1(l) = 2 / (1 +
//    sqrt(1 + alpha^2 tan^2 theta_l)) = 2 N1 / (N1 + Q) in the variables below (mu_l = N1 / M2,
//    sin_l^2 = P / M2^2, Q = sqrt(N1^2 + alpha^2 P)), in [0, 1]. Scale 3 becomes: as mu_l -> 0,
//    g ~ 2 mu_l (sqrt(mu_l^2 + alpha^2) - mu_l) / alpha^2 has no pole (there is no (1 +
//    Lambda_o) to cancel against Lambda_l) but branch points at mu_l = +-i alpha: a layer at the
//    cut of width ~ alpha in mu_l whatever mu_o, so s = alpha / 2 (the generic rule's, graded a
//    little finer than the branch points' distance) replaces min(alpha, mu_o). It does not
//    vanish at mu_o = 0 (the correlated g is 1 there): the same panel then grades towards the
//    cut on the front side.
//  - Exact dielectric Fresnel (ggx-fresnel-albedo): w = FrDielectric(o.h, eta) and no B channel.
//    F is a function of c = o.h alone: with eta cos_t = sqrt(c^2 + eta^2 - 1), its only
//    singularities are the branch points c = +-i sqrt(eta^2 - 1), at distance >= 0.83 from the
//    visible range c in [0, 1] for eta >= 1.3 (kFresnelKernelEtaMin): F is smooth on every panel,
//    and the panels of the DFG rule take it with somewhat more outer and bulk nodes
//    (kFresnelBands). Per texel of the tables (integrand_evaluations over texels in
//    luts/manifest.json): ggx-fresnel-albedo 500, ggx-separable 397, against 1,179 and 937 with
//    fixed_rule_microfacet.cpp's rules (git show d25a442~1:luts/manifest.json), whose Fresnel
//    layer panels remain what eta -> 1 needs).
//    F <= 1 and g <= 1 keep the light-azimuth weights of below valid for both variants.
// So an azimuth has at most three panels: [graded to 0] + plain + [graded to the cut]. Every
// node evaluates the whole integrand, g included: one set of nodes for the bulk and the masking
// deficit. A graded panel of length len at scale e takes gradedNodes (deficitNodes towards 0)
// + nodesPerEFold per e-fold of log(1 + len / e); that range is rounded up to a multiple of 0.5
// e-folds (e down), so the graded rules are tabulated per level too: a node costs no exp or log.
// Azimuths of negligible weight W (the bound pi/4 pref w_p t^2 (4/3 |o'_x cos p| t + 2 o'_z) of
// their share, t at the cut) take one plain panel: lightNodes when W < 1e-4, 4 when W < 1e-6.
// Structures whose weight (density at the end times their width) is below 1e-9 are not graded
// for: there the plain panel's error is bounded by that weight. The counts themselves
// (outerNodes, bulkNodes, ...) are set per band of alpha by the bake (kTunedBands below).
// The inner variable is t = tan(t'/2): sin t', cos t' are rational in t, and with S = 2t,
// C = 1 - t^2, q = 1 + t^2, M2 = alpha^2 S^2 + C^2 (|h|^2 times M2 / q^2):
//     mu_l = N1 / M2,  N1 = 2 sin_o alpha S C cos p + mu_o (C^2 - alpha^2 S^2),
//     o.h = (sin_o alpha S cos p + mu_o C) / sqrt(M2),  sin t' (o'.n') dt' = 2 S (o'_x S cos p
//     + o'_z C) / q^3 dt,  g = Ng / (Ng + mu_o alpha^2 P),  P = M2^2 - N1^2,
//     Ng = 2 mu_o (1 + Lambda_o) N1 (sqrt(N1^2 + alpha^2 P) + N1),
// Lambda written without cancellation, so mu_o = 0, mu_o = 1 and alpha = MinAlpha are exact
// limits: an evaluation costs two square roots and one division. Inner counts are multiples of
// 4 and all panels of a texel go through one kernel that evaluates 4 nodes at a time (AVX2 when
// the CPU has it, else SSE2, else portable code), each lane summing its nodes in order, the
// lanes then added as (0 + 2) + (1 + 3): the three kernels agree to the last bit (the variants
// too: tests/integrate_fixed_rule_kernels.cpp forces each path, FixedRuleOptions::simd). The
// Fresnel variant evaluates F as (eta^2 - 1)^2 / 2 (B^2 + X^2 A^2) / (A^2 B^2), A = (c + eta
// cos_t)^2, B = (eta^2 c + eta cos_t)^2, X = (eta^2 + 1) c^2 - 1 (FrDielectric's cancellation-free
// r_perp, r_parl over one division): one more square root and division per node.
#include "baker/integrate/fixed_rule_dfg.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <mutex>
#include <vector>
#if defined(__GNUC__) && defined(__x86_64__)
#define KILN_FIXED_RULE_X86 1
#include <immintrin.h>
#endif

#include "baker/math/quadrature.h"
#include "baker/models/roughness.h"

namespace kiln {
namespace {

constexpr int kMaxNodes = 64;
/// Nodes the kernel evaluates at once; inner panels have a multiple of this.
constexpr int kLanes = 4;
/// Grading is skipped for structures of weight below this (see the file comment).
constexpr double kNegligible = 1e-9;
/// Azimuths of weight below these take lightNodes, or kTinyNodes, plain nodes.
constexpr double kLightWeight = 1e-4, kTinyWeight = 1e-6;
constexpr int kTinyNodes = 4;
/// Floor of the outer grading scale about p = pi/2.
constexpr double kSigmaFloor = 0.03;
/// Share of the outer nodes kept at the mildest grading (Y -> 0).
constexpr double kOuterBase = 0.3;
/// Fraction of [0, t_max] given to the panel graded towards t_max.
constexpr double kTailPanel = 0.25;
/// A structure is graded for when its scale is below this fraction of the graded panel.
constexpr double kGradeBelow = 0.25;
/// Inner gradings are rounded up to a multiple of this many e-folds, up to kLevels levels.
constexpr double kLevelStep = 0.5;
constexpr int kLevels = 96;
/// The outer Y = asinh(pi / (2 sigma)) is rounded up to a multiple of this (Y <= 4.65).
constexpr double kOuterStep = 1.0 / 32;
constexpr int kOuterLevels = 160;

/// n rounded up to a multiple of kLanes, within [kLanes, kMaxNodes].
inline int Lanes(int n) {
  return std::min(kMaxNodes, (std::max(n, 1) + kLanes - 1) / kLanes * kLanes);
}

/// A rule on [0, 1] (nodes x, weights w).
struct GaussRule {
  double x[kMaxNodes] = {}, w[kMaxNodes] = {};
  int n = 0;
};

/// Gauss-Legendre rules with 1..kMaxNodes nodes (Newton on P_n), built once.
const GaussRule& Gauss(int n) {
  static const std::vector<GaussRule> rules = [] {
    std::vector<GaussRule> r(kMaxNodes + 1);
    for (int n = 1; n <= kMaxNodes; ++n) {
      r[n].n = n;
      std::vector<double> x, w;
      GaussLegendre01(n, x, w);
      std::copy(x.begin(), x.end(), r[n].x);
      std::copy(w.begin(), w.end(), r[n].w);
    }
    return r;
  }();
  return rules[std::min(std::max(n, 1), kMaxNodes)];
}

/// Graded inner rules on [0, 1], x the distance from the graded end: level k grades over
/// h = k kLevelStep e-folds, x = expm1(h s) / expm1(h), with Lanes(base + ceil(perEFold h))
/// Gauss nodes in s.
struct GradedRules {
  int base = 0;
  double perEFold = 0;
  std::vector<GaussRule> level;
};

std::unique_ptr<const GradedRules> MakeGraded(int base, double perEFold) {
  auto r = std::make_unique<GradedRules>();
  r->base = base;
  r->perEFold = perEFold;
  r->level.resize(kLevels);
  for (int k = 0; k < kLevels; ++k) {
    const double h = k * kLevelStep, em = std::expm1(h);
    const GaussRule& g = Gauss(Lanes(base + static_cast<int>(std::ceil(perEFold * h - 1e-9))));
    GaussRule& o = r->level[k];
    o.n = g.n;
    for (int i = 0; i < g.n; ++i) {
      o.x[i] = k == 0 ? g.x[i] : std::expm1(h * g.x[i]) / em;
      o.w[i] = k == 0 ? g.w[i] : h * g.w[i] * std::exp(h * g.x[i]) / em;
    }
  }
  return r;
}

/// The graded rules for (base, perEFold), built on first use and kept.
const GradedRules& Graded(int base, double perEFold) {
  thread_local const GradedRules* recent[8] = {};  // most recent first
  for (const GradedRules* r : recent)
    if (r && r->base == base && r->perEFold == perEFold) return *r;
  static std::mutex mutex;
  static std::vector<std::unique_ptr<const GradedRules>> all;
  const GradedRules* found = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& r : all)
      if (r->base == base && r->perEFold == perEFold) found = r.get();
    if (!found) {
      all.push_back(MakeGraded(base, perEFold));
      found = all.back().get();
    }
  }
  std::copy_backward(recent, recent + 7, recent + 8);
  recent[0] = found;
  return *found;
}

/// Outer rules with n Gauss nodes per half: level k has Y = k kOuterStep (at least one step),
/// sigma = (pi / 2) / sinh(Y), x = |cos p| = sin(sigma sinh(Y s)), w = dp. Built on first use.
const std::vector<GaussRule>& OuterRules(int n) {
  static std::atomic<const std::vector<GaussRule>*> rules[kMaxNodes + 1] = {};
  static std::mutex mutex;
  n = std::min(std::max(n, 1), kMaxNodes);
  if (const std::vector<GaussRule>* r = rules[n].load(std::memory_order_acquire)) return *r;
  std::lock_guard<std::mutex> lock(mutex);
  if (const std::vector<GaussRule>* r = rules[n].load(std::memory_order_relaxed)) return *r;
  auto r = new std::vector<GaussRule>(kOuterLevels);  // kept for the process lifetime
  const GaussRule& g = Gauss(n);
  for (int k = 0; k < kOuterLevels; ++k) {
    const double Y = std::max(k, 1) * kOuterStep, sigma = Pi / 2 / std::sinh(Y);
    GaussRule& o = (*r)[k];
    o.n = g.n;
    for (int i = 0; i < g.n; ++i) {
      const double y = Y * g.x[i];
      o.x[i] = std::sin(sigma * std::sinh(y));
      o.w[i] = g.w[i] * Y * sigma * std::cosh(y);
    }
  }
  rules[n].store(r, std::memory_order_release);
  return *r;
}

/// Natural log to about 1e-4 (enough to pick a level): binary exponent plus a short series.
inline double RoughLog(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  bits = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1023) << 52);
  double m;
  std::memcpy(&m, &bits, sizeof m);                // x = m 2^e, m in [1, 2)
  const double z = (m - 1) / (m + 1), z2 = z * z;  // log m = 2 atanh(z)
  return e * 0.69314718055994531 + 2 * z * (1 + z2 * (1.0 / 3 + z2 * (0.2 + z2 / 7)));
}

/// Level of a panel of length len graded at scale e (at least the grading it asks for).
inline int Level(double len, double e) {
  const double h = RoughLog(1 + len / e) + 1e-3;
  return std::min(kLevels - 1, static_cast<int>(std::ceil(h / kLevelStep)));
}

/// mu Lambda(mu) of GGX without cancellation (alpha / 2 at mu = 0).
inline double MuLambda(double mu, double a) {
  double s2 = std::max(0.0, 1 - mu * mu), a2 = a * a;
  double den = 2 * (std::sqrt(mu * mu + a2 * s2) + mu);
  return den > 0 ? a2 * s2 / den : 0;
}

/// Constants of the inner integrand (file comment, with S = 2t folded in).
struct Integrand {
  double a2x, a2, mu, ozs, g1, muA2;
  double e2m1, eta2, eta2p1, fScale;  ///< Fresnel: eta^2 - 1, eta^2, eta^2 + 1, (eta^2 - 1)^2 / 2
};

/// The integrands of the kernel: (A + B, B) with height-correlated Smith, the same with separable
/// Smith, and the exact-Fresnel albedo (height-correlated).
enum Mode { kCorrelated = 0, kSeparable = 1, kFresnel = 2 };

/// A panel of the inner rule: nodes t = t0 + h x_i, weights wh w_i (wh includes the azimuth's).
struct Panel {
  const GaussRule* rule;
  double t0, h, wh;
};

/// One azimuth: its constants of the integrand and its panels [firstPanel, endPanel).
struct Azimuth {
  double kMl, kOh, kOn;
  int firstPanel, endPanel;
};

/// Four doubles, for the portable kernel.
struct Quad {
  double v[4];
};
inline Quad operator+(const Quad& a, const Quad& b) {
  return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}};
}
inline Quad operator-(const Quad& a, const Quad& b) {
  return {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2], a.v[3] - b.v[3]}};
}
inline Quad operator*(const Quad& a, const Quad& b) {
  return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}};
}
inline Quad operator/(const Quad& a, const Quad& b) {
  return {{a.v[0] / b.v[0], a.v[1] / b.v[1], a.v[2] / b.v[2], a.v[3] / b.v[3]}};
}
inline Quad Splat(double x, const Quad&) { return {{x, x, x, x}}; }
inline Quad Load(const double* p, const Quad&) { return {{p[0], p[1], p[2], p[3]}}; }
inline Quad Sqrt(const Quad& a) {
  return {{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])}};
}
inline Quad Max(const Quad& a, const Quad& b) {  // as maxpd
  return {{a.v[0] > b.v[0] ? a.v[0] : b.v[0], a.v[1] > b.v[1] ? a.v[1] : b.v[1],
           a.v[2] > b.v[2] ? a.v[2] : b.v[2], a.v[3] > b.v[3] ? a.v[3] : b.v[3]}};
}
inline Quad Min(const Quad& a, const Quad& b) {  // as minpd
  return {{a.v[0] < b.v[0] ? a.v[0] : b.v[0], a.v[1] < b.v[1] ? a.v[1] : b.v[1],
           a.v[2] < b.v[2] ? a.v[2] : b.v[2], a.v[3] < b.v[3] ? a.v[3] : b.v[3]}};
}
inline double Reduce(const Quad& a) { return (a.v[0] + a.v[2]) + (a.v[1] + a.v[3]); }

#ifdef KILN_FIXED_RULE_X86
/// Four doubles in two SSE2 registers (lanes 0, 1 | 2, 3).
struct Pair {
  __m128d lo, hi;
};
inline Pair operator+(Pair a, Pair b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Pair operator-(Pair a, Pair b) { return {a.lo - b.lo, a.hi - b.hi}; }
inline Pair operator*(Pair a, Pair b) { return {a.lo * b.lo, a.hi * b.hi}; }
inline Pair operator/(Pair a, Pair b) { return {a.lo / b.lo, a.hi / b.hi}; }
inline Pair Splat(double x, Pair) { return {_mm_set1_pd(x), _mm_set1_pd(x)}; }
inline Pair Load(const double* p, Pair) { return {_mm_loadu_pd(p), _mm_loadu_pd(p + 2)}; }
inline Pair Sqrt(Pair a) { return {_mm_sqrt_pd(a.lo), _mm_sqrt_pd(a.hi)}; }
inline Pair Max(Pair a, Pair b) { return {_mm_max_pd(a.lo, b.lo), _mm_max_pd(a.hi, b.hi)}; }
inline Pair Min(Pair a, Pair b) { return {_mm_min_pd(a.lo, b.lo), _mm_min_pd(a.hi, b.hi)}; }
inline double Reduce(Pair a) { return (a.lo[0] + a.hi[0]) + (a.lo[1] + a.hi[1]); }
#pragma GCC push_options
#pragma GCC target("avx2")
inline __m256d Splat(double x, __m256d) { return _mm256_set1_pd(x); }
inline __m256d Load(const double* p, __m256d) { return _mm256_loadu_pd(p); }
inline __m256d Sqrt(__m256d a) { return _mm256_sqrt_pd(a); }
inline __m256d Max(__m256d a, __m256d b) { return _mm256_max_pd(a, b); }
inline __m256d Min(__m256d a, __m256d b) { return _mm256_min_pd(a, b); }
inline double Reduce(__m256d a) { return (a[0] + a[2]) + (a[1] + a[3]); }
#pragma GCC pop_options
#endif

// V is a 256-bit vector only inside the AVX2 kernel, where Kernel is always inlined.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
/// Sums the integrand of `M` times weight over all panels of all azimuths, 4 nodes at a time:
/// (A + B, B) for kCorrelated and kSeparable, (E, 0) for kFresnel.
template <class V, int M>
__attribute__((always_inline)) inline void Kernel(const Integrand& k, const Azimuth* az, int nAz,
                                                  const Panel* panels, double& sumV, double& sumB) {
  const V z{};
  const V one = Splat(1.0, z), zero = Splat(0.0, z), tiny = Splat(1e-300, z);
  const V a2x = Splat(k.a2x, z), a2 = Splat(k.a2, z), mu = Splat(k.mu, z), ozs = Splat(k.ozs, z);
  const V g1 = Splat(k.g1, z), muA2 = Splat(k.muA2, z), two = Splat(2.0, z);
  const V e2m1 = Splat(k.e2m1, z), eta2 = Splat(k.eta2, z), eta2p1 = Splat(k.eta2p1, z);
  const V fScale = Splat(k.fScale, z);
  V sv = zero, sb = zero;
  for (int j = 0; j < nAz; ++j) {
    const V kMl = Splat(az[j].kMl, z), kOh = Splat(az[j].kOh, z), kOn = Splat(az[j].kOn, z);
    for (int p = az[j].firstPanel; p < az[j].endPanel; ++p) {
      const GaussRule& g = *panels[p].rule;
      const V t0 = Splat(panels[p].t0, z), h = Splat(panels[p].h, z), wh = Splat(panels[p].wh, z);
      for (int i = 0; i < g.n; i += kLanes) {
        const V t = t0 + h * Load(g.x + i, z), wt = wh * Load(g.w + i, z);
        const V t2 = t * t, C = one - t2, q = one + t2;
        const V aS = a2x * t, aS2 = aS * aS, C2 = C * C, M2 = aS2 + C2;
        const V N1 = Max(zero, kMl * t * C + mu * (C2 - aS2));  // mu_l M2
        const V P = (M2 - N1) * (M2 + N1);
        const V Q = Sqrt(N1 * N1 + a2 * P);
        V Ng, Dg;  // g = Ng / Dg
        if constexpr (M == kSeparable) {
          Ng = two * N1;  // G1(l) = 2 N1 / (N1 + Q)
          Dg = (N1 + Q) + tiny;
        } else {
          Ng = g1 * N1 * (Q + N1);
          Dg = Ng + (muA2 * P + tiny);  // tiny: g = 0 / tiny at the cut when mu = 0
        }
        const V sM = Sqrt(M2), qD = q * q * q * Dg, r = one / (sM * qD);
        const V oh = (kOh * t + mu * C) * qD * r;  // o.h
        const V val = (t * (kOn * t + ozs * C)) * (Ng * wt) * sM * r;
        if constexpr (M == kFresnel) {
          // FrDielectric(o.h, eta) with eta cos_t = sqrt(c^2 + eta^2 - 1) (no total internal
          // reflection for eta > 1), r_perp = -(eta^2 - 1) / A, r_parl = (eta^2 - 1) X / B,
          // A = (c + eta cos_t)^2, B = (eta^2 c + eta cos_t)^2, X = (eta^2 + 1) c^2 - 1.
          const V c2 = oh * oh, etaCt = Sqrt(c2 + e2m1);
          const V sa = oh + etaCt, sb2 = eta2 * oh + etaCt;
          const V A = sa * sa, B = sb2 * sb2, X = eta2p1 * c2 - one;
          const V A2 = A * A, B2 = B * B;
          const V F = Min(one, fScale * (B2 + X * X * A2) / (A2 * B2));
          sv = sv + val * F;
        } else {
          const V w = one - oh;  // 1 - o.h
          const V w2 = w * w;
          sv = sv + val;
          sb = sb + val * (w2 * w2 * w);
        }
      }
    }
  }
  sumV = Reduce(sv);
  sumB = Reduce(sb);
}
#pragma GCC diagnostic pop

#ifdef KILN_FIXED_RULE_X86
template <int M>
__attribute__((target("avx2"))) void KernelAVX2(const Integrand& k, const Azimuth* az, int nAz,
                                                const Panel* panels, double& sumV, double& sumB) {
  Kernel<__m256d, M>(k, az, nAz, panels, sumV, sumB);
}
#endif

/// The kernel of `M` on the SIMD path `path` (Widest: the widest the CPU runs; all give the same
/// bits; a path the CPU or the build lacks falls back to the widest).
template <int M>
void SumOf(SimdPath path, const Integrand& k, const Azimuth* az, int nAz, const Panel* panels,
           double& sumV, double& sumB) {
  if (!SimdPathAvailable(path)) path = SimdPath::Widest;
#ifdef KILN_FIXED_RULE_X86
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (path == SimdPath::AVX2 || (path == SimdPath::Widest && avx2))
    KernelAVX2<M>(k, az, nAz, panels, sumV, sumB);
  else if (path == SimdPath::Portable)
    Kernel<Quad, M>(k, az, nAz, panels, sumV, sumB);
  else
    Kernel<Pair, M>(k, az, nAz, panels, sumV, sumB);
#else
  Kernel<Quad, M>(k, az, nAz, panels, sumV, sumB);
#endif
}

void Sum(int mode, SimdPath path, const Integrand& k, const Azimuth* az, int nAz,
         const Panel* panels, double& sumV, double& sumB) {
  if (mode == kSeparable)
    SumOf<kSeparable>(path, k, az, nAz, panels, sumV, sumB);
  else if (mode == kFresnel)
    SumOf<kFresnel>(path, k, az, nAz, panels, sumV, sumB);
  else
    SumOf<kCorrelated>(path, k, az, nAz, panels, sumV, sumB);
}

/// The bake's node counts by band of alpha (alpha below; outer, bulk, graded, per e-fold,
/// deficit; lightNodes stays 6). Tuned greedily, band by band, on the 128 x 128 catalogue grid
/// against adaptive quadrature at 1e-11: each band takes the fewest evaluations that keep its
/// worst error at or below the uniform rule's (FixedRuleOptions' defaults) worst, 2.9e-7. Small
/// alpha needs fewer bulk nodes (its lobe sits in the graded panels); the last band keeps the
/// uniform rule's outer and bulk counts (the grid's worst texel, mu = 0.094, r = 0.91, is there).
/// Mean evaluations per texel of that grid: 448 uniform, 363 tuned; 4000 off-grid points (mu and
/// r random, a quarter in the mu ~ alpha layer) stay within 2.9e-7 too.
struct TunedBand {
  double alphaBelow;
  int outer, bulk, graded;
  double perEFold;
  int deficit;
};
constexpr TunedBand kTunedBands[] = {{0.004, 11, 7, 4, 1.3, 4},
                                     {0.02, 11, 7, 4, 1.4, 4},
                                     {0.06, 10, 7, 5, 1.4, 4},
                                     {0.16, 12, 8, 5, 1.2, 4},
                                     {INFINITY, 12, 9, 4, 1.4, 4}};
/// ggx-separable's (separable Smith, the masking scale alpha / 2) and the exact-Fresnel albedo's
/// (eta >= kFresnelKernelEtaMin), tuned the same way against adaptive quadrature at 1e-10 on the
/// grids of tests/integrate_fixed_rule_kernels.cpp (worst 4e-8 separable, 7e-8 Fresnel there).
constexpr TunedBand kSeparableBands[] = {{0.004, 12, 8, 5, 1.6, 5},
                                         {0.02, 12, 8, 5, 1.6, 5},
                                         {0.06, 12, 8, 5, 1.6, 5},
                                         {0.16, 12, 8, 5, 1.6, 5},
                                         {INFINITY, 14, 7, 5, 1.4, 5}};
constexpr TunedBand kFresnelBands[] = {{0.004, 14, 8, 5, 1.6, 4},
                                       {0.02, 12, 8, 5, 1.6, 5},
                                       {0.06, 16, 8, 5, 1.6, 5},
                                       {0.16, 16, 8, 5, 1.6, 5},
                                       {INFINITY, 14, 9, 5, 1.6, 5}};
/// The lookup-error search's form of kFresnelBands, one set for every band: measured against it on
/// a 49 x 41 (mu, r) grid (mu = 0, 1e-9, 1; r = 0, 1) x 10 eta in [1.3, 3]: worst 1.3e-6
/// (kSearchRuleBound 2e-6), 0.50 of its evaluations.
constexpr TunedBand kSearchFresnelBands[] = {{INFINITY, 9, 5, 4, 1.2, 4}};

}  // namespace

namespace {

/// The options of the band of `bands` that holds alpha.
template <size_t N>
FixedRuleOptions BandOptions(const TunedBand (&bands)[N], double alpha) {
  const double a = std::max(alpha, MinAlpha);
  const TunedBand* b = bands;
  while (b + 1 < std::end(bands) && !(a < b->alphaBelow)) ++b;  // NaN: the last band
  FixedRuleOptions o;
  o.outerNodes = b->outer;
  o.bulkNodes = b->bulk;
  o.gradedNodes = b->graded;
  o.nodesPerEFold = b->perEFold;
  o.deficitNodes = b->deficit;
  return o;
}

}  // namespace

FixedRuleOptions TunedFixedRuleOptions(double alpha) { return BandOptions(kTunedBands, alpha); }

FixedRuleOptions TunedSeparableRuleOptions(double alpha) {
  return BandOptions(kSeparableBands, alpha);
}

FixedRuleOptions TunedFresnelKernelOptions(double alpha) {
  return BandOptions(kFresnelBands, alpha);
}

FixedRuleOptions SearchFresnelKernelOptions(double alpha) {
  return BandOptions(kSearchFresnelBands, alpha);
}

std::array<double, 2> FixedRuleGGXDFG(double mu, double alpha, long long* evals) {
  return FixedRuleGGXDFG(mu, alpha, TunedFixedRuleOptions(alpha), evals);
}

namespace {

/// The rule for the kernel's integrand `mode` (eta: the Fresnel index of kFresnel): the panels
/// of the file comment, then one kernel call. Returns (A, B) (kFresnel: (E, 0)).
std::array<double, 2> Rule(int mode, double mu, double alpha, double eta,
                           const FixedRuleOptions& opt, long long* evals) {
  mu = std::min(1.0, std::max(0.0, mu));
  const double a = std::max(alpha, MinAlpha), a2 = a * a;
  const double st = std::sqrt(std::max(0.0, 1 - mu * mu));
  const double L = std::sqrt(a2 * st * st + mu * mu);
  const double ozs = mu / L, oxs = a * st / L;  // stretched view o'
  const double pref = 16 / (Pi * (1 + ozs));    // 4 / (pi (1 + o'_z)) times the kernel's 1/4
  const double muLo = MuLambda(mu, a);
  // Scale 3 (file comment): the pole of g at mu_l = -sMask (height-correlated), or G1(l)'s branch
  // points at mu_l = +-i alpha (separable), graded for at alpha / 2.
  const double sMask = mode == kSeparable ? a / 2 : mu > 0 ? mu * a / (mu + 2 * muLo) : 0;
  const double sigma = std::min(1e3, std::max(st > 0 ? mu / st : 1e3, kSigmaFloor));
  const int outerLevel = std::min(
      kOuterLevels - 1, static_cast<int>(std::ceil(std::asinh(Pi / (2 * sigma)) / kOuterStep)));
  static const double kYFloor = std::asinh(Pi / (2 * kSigmaFloor));
  const double outerShare = kOuterBase + (1 - kOuterBase) * outerLevel * kOuterStep / kYFloor;
  const int nOuter =
      std::min(opt.outerNodes, static_cast<int>(std::ceil(opt.outerNodes * outerShare - 1e-9)));
  const GaussRule& go = OuterRules(nOuter)[outerLevel];
  const GaussRule& gBulk = Gauss(Lanes(opt.bulkNodes));
  const GaussRule& gWhole = Gauss(Lanes(opt.bulkNodes + opt.gradedNodes));
  const GaussRule& gMiddle = Gauss(Lanes(opt.deficitNodes));
  const GaussRule& gLight = Gauss(Lanes(opt.lightNodes));
  const GaussRule& gTiny = Gauss(kTinyNodes);
  const GradedRules& toEnd = Graded(opt.gradedNodes, opt.nodesPerEFold);
  const GradedRules& toStart = Graded(opt.deficitNodes, opt.nodesPerEFold);
  Integrand k;
  k.a2x = 2 * a;
  k.a2 = a2;
  k.mu = mu;
  k.ozs = ozs;
  k.g1 = 2 * (mu + muLo);
  k.muA2 = mu * a2;
  k.e2m1 = mode == kFresnel ? (eta - 1) * (eta + 1) : 0;
  k.eta2 = eta * eta;
  k.eta2p1 = k.eta2 + 1;
  k.fScale = k.e2m1 * k.e2m1 / 2;
  const double invMu = mu > 0 ? 1 / mu : 0;

  // Per outer node, both sides (0: cos p > 0, 1: cos p < 0): t at the cut, dt/dt' there, the
  // masking scale e2 at the cut and, for the opposite side, e0 = t + e2 / (2 dt/dt').
  double tm[2][kMaxNodes], dtdtp[2][kMaxNodes], e2[2][kMaxNodes], e0[2][kMaxNodes];
  for (int io = 0; io < go.n; ++io) {
    const double X = st * go.x[io], R = std::sqrt(mu * mu + X * X), RX = R + X;
    // 1 / tan(theta_max): front mu / (R + X), back (R + X) / mu (nothing survives at mu = 0).
    // (capped: beyond 1e150 the back cut is at t = 0 to working precision).
    const double iT[2] = {mu * (1 / RX), std::min(RX * invMu, 1e150)};
    double s[2], m[2];
    for (int side = 0; side < 2; ++side) {
      const double iu = a * iT[side];
      s[side] = iu + std::sqrt(iu * iu + 1);  // 1 / t at the cut
      m[side] = 1 + a2 * iT[side] * iT[side];
    }
    // e2 = sMask / |dmu_l/dt'| dt/dt', |dmu_l/dt'| = 2 R (alpha^2 + T^2) / (alpha (1 + T^2)).
    const double invS = 1 / (s[0] * s[1]), invM = sMask * a / (2 * R * m[0] * m[1]);
    for (int side = 0; side < 2; ++side) {
      const double t1 = s[1 - side] * invS, d = (1 + t1 * t1) / 2;
      const double u = invM * m[1 - side] * (1 + iT[side] * iT[side]);  // e2 / (dt/dt')
      tm[side][io] = side == 1 && mu == 0 ? 0 : t1;
      dtdtp[side][io] = d;
      e2[side][io] = u * d;
      e0[side][io] = t1 + u / 2;
    }
  }

  // Panels of every azimuth.
  Azimuth az[2 * kMaxNodes];
  Panel panels[6 * kMaxNodes];
  int nAz = 0, np = 0;
  long long count = 0;
  for (int io = 0; io < go.n; ++io) {
    for (int side = 0; side < 2; ++side) {
      const double t1 = tm[side][io];
      if (!(t1 > 0)) continue;
      const double c = side == 0 ? go.x[io] : -go.x[io], pw = go.w[io];
      Azimuth& A = az[nAz++];
      A.kMl = 4 * st * a * c;
      A.kOh = 2 * st * a * c;
      A.kOn = 2 * oxs * c;
      A.firstPanel = np;
      const double weight = pref / 4 * pw * t1 * t1 * (4.0 / 3 * std::abs(A.kOn) * t1 + 2 * ozs);
      if (weight < kTinyWeight) {
        panels[np++] = {&gTiny, 0, t1, pw * t1};
      } else if (weight < kLightWeight) {
        panels[np++] = {&gLight, 0, t1, pw * t1};
      } else {
        // o'.n' (1 + t^2) at the cut; a structure of width e there weighs onMax e / (dt/dt').
        const double onMaxQ = oxs * 2 * t1 * c + ozs * (1 - t1 * t1);
        const double floorW = kNegligible * dtdtp[side][io] * (1 + t1 * t1);
        const double eTail = (1 - t1) + a, len = kTailPanel * t1, e2s = e2[side][io];
        double eEnd = INFINITY;
        if (onMaxQ * eTail > floorW && eTail < kGradeBelow * len) eEnd = eTail;
        if (sMask > 0 && e2s < kGradeBelow * len && onMaxQ * e2s > floorW)
          eEnd = std::min(eEnd, e2s);
        double split = 0;
        const double eStart = e0[1 - side][io];
        if (sMask > 0 && tm[1 - side][io] > 0 && eStart < t1 / 8 &&
            eStart * eStart * ozs > kNegligible) {
          split = t1 / 2;
          panels[np++] = {&toStart.level[Level(split, eStart)], 0, split, pw * split};
        }
        if (eEnd < INFINITY) {
          const double mid = t1 - len - split;
          panels[np++] = {split > 0 ? &gMiddle : &gBulk, split, mid, pw * mid};
          panels[np++] = {&toEnd.level[Level(len, eEnd)], t1, -len, pw * len};
        } else {
          panels[np++] = {split > 0 ? &gBulk : &gWhole, split, t1 - split, pw * (t1 - split)};
        }
      }
      A.endPanel = np;
      for (int p = A.firstPanel; p < np; ++p) count += panels[p].rule->n;
    }
  }
  double sumV, sumB;
  Sum(mode, opt.simd, k, az, nAz, panels, sumV, sumB);
  if (evals) *evals += count;
  if (mode == kFresnel) return {pref * sumV, 0};
  return {pref * (sumV - sumB), pref * sumB};
}

}  // namespace

std::array<double, 2> FixedRuleGGXDFG(double mu, double alpha, const FixedRuleOptions& opt,
                                      long long* evals) {
  return Rule(kCorrelated, mu, alpha, 0, opt, evals);
}

std::array<double, 2> FixedRuleGGXSeparableDFG(double mu, double alpha, const FixedRuleOptions& opt,
                                               long long* evals) {
  return Rule(kSeparable, mu, alpha, 0, opt, evals);
}

std::array<double, 2> FixedRuleGGXSeparableDFG(double mu, double alpha, long long* evals) {
  return Rule(kSeparable, mu, alpha, 0, TunedSeparableRuleOptions(alpha), evals);
}

double FixedRuleGGXFresnelKernel(double mu, double alpha, double eta, const FixedRuleOptions& opt,
                                 long long* evals) {
  if (!(eta > 1)) return 0;  // F = 0 at eta = 1; eta < 1 is not this rule's
  return Rule(kFresnel, mu, alpha, eta, opt, evals)[0];
}

double FixedRuleGGXFresnelKernel(double mu, double alpha, double eta, long long* evals) {
  return FixedRuleGGXFresnelKernel(mu, alpha, eta, TunedFresnelKernelOptions(alpha), evals);
}

bool SimdPathAvailable(SimdPath path) {
#ifdef KILN_FIXED_RULE_X86
  if (path == SimdPath::AVX2) return __builtin_cpu_supports("avx2");
  return true;
#else
  return path == SimdPath::Widest || path == SimdPath::Portable;
#endif
}

}  // namespace kiln
