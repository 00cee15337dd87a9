// K_alpha(c) of the rough dielectric's hemispherical reflectance, and E_avg_R from it.
//
// Derivation. For a microfacet normal m at polar angle theta_m (azimuth 0) and a view o at
// c = o.m with azimuth psi about m (s = sqrt(1 - c^2)), the reflected ray is i = 2 c m - o, and
//     mu_o = a - b cos psi,   mu_i = a + b cos psi,   a = c cos_m,  b = s sin_m.
// The integrand of K is symmetric under psi -> -psi and under psi -> pi - psi (o and i swap,
// G2 is symmetric), and mu_i >= a > 0 on psi in [0, pi/2], so with D dm = dv dphi_m / (2 pi
// cos_m) (v = alpha^2 / (alpha^2 + tan^2 theta_m), GGX's complementary CDF of D cos)
//     K_alpha(c) = (4 / pi) int_0^1 dv / cos_m int_psi0^{pi/2} G2(mu_o, mu_i) dpsi,
// psi0 = acos(a / b) where b > a (the view crosses the horizon), else 0. G2 = 1 / (1 + Lambda_o +
// Lambda_i) = mu_o mu_i / (mu_o mu_i + mu_i L(mu_o) + mu_o L(mu_i)), L = mu Lambda (finite at
// mu = 0). Structures: in psi, the masking layers mu_o = m and mu_i = m (m geometric from alpha / 4
// by 4 below 1/4) and the horizon psi0; in theta_m, where the horizon enters the circle (a = b:
// theta_m = pi/2 - theta_c), where the least mu_o on the circle, cos(theta_m + theta_c), crosses
// -+m, where a = c cos_m crosses m (c small), and GGX's tail (tan theta_m = 2 alpha 4^k). Every
// panel is smoothstep-mapped (as dielectric_walk.h: square-root ends and the tail's cos_m^-1 ~
// v^-1/2 become analytic), Gauss-Legendre on each (fixed rule) or Gauss-Kronrod to a tolerance
// (the reference).
//
// The rule. In c, K has the grazing layer (c ~ alpha, where both rays graze) and is smooth above
// it up to c = 1, where it follows theta_c ~ sqrt(2 (1 - c)). So: on [0, cSplit] (cSplit = 0.4,
// below every exit critical cosine, F = 1 there) int c K dc once, by Gauss on geometric panels
// from alpha / 16 by 4; on [cSplit, 1] K through its values at Chebyshev points in t = sqrt(1 - c)
// (a polynomial in t: barycentric interpolation), so that each eta' integrates F c K over its own
// panels, graded in sqrt|c - c_crit| on both sides of the critical cosine (F is 1 below it and
// analytic in sqrt(c - c_crit) above) and in t towards c = 1, with the interpolant's values.
#include "baker/integrate/dielectric_kernel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "baker/integrate/dielectric_walk.h"
#include "baker/math/quadrature.h"
#include "baker/models/fresnel.h"
#include "baker/models/microfacet.h"

namespace kiln {
namespace {

constexpr int kMaxBreaks = 64;
/// Gauss nodes of the fixed rule's panels by class (dielectric_walk.h's NodesOf): an outer
/// (theta_m) panel [v_a, v_b] by its weight bound 2 (v_a - v_b) / cos_m(v_b) (G2 <= 1), an inner
/// (psi) panel by its width in radians, a low c panel [c_a, c_b] by c_b (its share of E_avg_R is
/// below c_b^2).
constexpr int kOuterNodes[4] = {16, 8, 4, 2};
constexpr double kOuterWeight[3] = {1e-2, 1e-4, 1e-6};
constexpr int kInnerNodes[4] = {16, 10, 6, 4};
constexpr double kInnerWidth[3] = {0.5, 0.1, 0.02};
constexpr int kLowNodes[4] = {16, 8, 4, 2};
constexpr double kLowEnd[3] = {0.05, 5e-3, 5e-4};
/// Chebyshev points of the interpolant on [cSplit, 1].
constexpr int kChebyshevPoints = 49;
/// Gauss nodes per panel of the per-eta integral over [cSplit, 1].
constexpr int kEtaNodes = 32;

/// The smoothstep map of [a, b] at u in [0, 1]: the point and its Jacobian.
inline double Smooth(double a, double b, double u, double* jac) {
  *jac = (b - a) * 6 * u * (1 - u);
  return a + (b - a) * u * u * (3 - 2 * u);
}

/// The kernel's problem at one c.
struct KernelView {
  double c, s, thetaC;
  GGXDistribution dist;
  /// G2 of the two rays' cosines (both > 0).
  double G2(double muO, double muI) const {
    const double p = muO * muI;
    return p / (p + muI * dist.MuLambda(muO) + muO * dist.MuLambda(muI));
  }
  /// The masking thresholds m: alpha / 4, times 4, below 1/4.
  int Masking(double* ms) const {
    int n = 0;
    for (double m = dist.alpha / 4; m < 0.25 && n < 12; m *= 4) ms[n++] = m;
    return n;
  }
  /// Outer boundaries in theta_m, ascending from 0 to pi/2.
  int ThetaBreaks(double* th) const {
    int n = 0;
    const double end = Pi / 2;
    auto add = [&](double t) {
      if (t > 0 && t < end && n < kMaxBreaks - 2) th[n++] = t;
    };
    th[n++] = 0;
    add(end - thetaC);
    double ms[12];
    const int nm = Masking(ms);
    for (int k = 0; k < nm; ++k) {
      add(std::acos(ms[k]) - thetaC);
      add(std::acos(-ms[k]) - thetaC);
      if (ms[k] < c) add(std::acos(ms[k] / c));
    }
    for (double tn = 2 * dist.alpha; tn < 64; tn *= 4) add(std::atan(tn));
    th[n++] = end;
    std::sort(th, th + n);
    return n;
  }
  /// Inner boundaries in psi over [psi0, pi/2] at (a, b); returns their count (>= 2).
  int PsiBreaks(double a, double b, double* ps) const {
    int n = 0;
    ps[n++] = b > a ? std::acos(a / b) : 0;
    const double lo = ps[0];
    auto add = [&](double cosPsi) {
      if (cosPsi > -1 && cosPsi < 1) {
        const double p = std::acos(cosPsi);
        if (p > lo && p < Pi / 2) ps[n++] = p;
      }
    };
    double ms[12];
    const int nm = Masking(ms);
    if (b > 0)
      for (int k = 0; k < nm; ++k) {
        add((a - ms[k]) / b);
        add((ms[k] - a) / b);
      }
    ps[n++] = Pi / 2;
    std::sort(ps, ps + n);
    return n;
  }
};

KernelView MakeKernelView(double c, double alpha) {
  KernelView k;
  k.c = std::clamp(c, 0.0, 1.0);
  k.s = std::sqrt(std::max(0.0, (1 - k.c) * (1 + k.c)));
  k.thetaC = std::acos(k.c);
  k.dist.alpha = std::max(alpha, MinAlpha);
  return k;
}

/// (4 / pi) int over the outer panels, each ring's psi integral by `inner`: the fixed rule's
/// walk, with `outer(f, a, b)` integrating f over the smoothstep variable of [a, b] in v.
template <class Outer, class Inner>
double KernelWalk(const KernelView& k, Outer&& outer, Inner&& inner) {
  double th[kMaxBreaks];
  const int nt = k.ThetaBreaks(th);
  double sum = 0;
  for (int i = 0; i + 1 < nt; ++i) {
    const double va = i == 0 ? 1.0 : k.dist.VFromTheta(th[i]), vb = k.dist.VFromTheta(th[i + 1]);
    auto ring = [&](double u) {
      double jac;
      const double v = Smooth(va, vb, u, &jac);
      jac = -jac;
      if (!(v > 0) || !(jac > 0)) return 0.0;
      const PolarParam h = k.dist.FromV(v);
      if (!(h.cosTheta > 0)) return 0.0;
      const double a = k.c * h.cosTheta, b = k.s * h.sinTheta;
      double ps[kMaxBreaks];
      const int np = k.PsiBreaks(a, b, ps);
      auto f = [&](double psi) {
        const double cp = dielectric_walk::CosHalfTurn(psi), muO = a - b * cp, muI = a + b * cp;
        return muO > 0 && muI > 0 ? k.G2(muO, muI) : 0.0;
      };
      return jac / h.cosTheta * inner(f, ps, np);
    };
    const double weight = vb > 0 ? 2 * (va - vb) / std::cos(th[i + 1]) : INFINITY;
    sum += outer(ring, weight);
  }
  return 4 / Pi * sum;
}

/// The fixed rule over panels [ps[j], ps[j+1]] of f, smoothstep-mapped, Gauss nodes by width
/// class; count accumulates the evaluations.
template <class F>
double FixedPanels(F& f, const double* ps, int np, long long& count) {
  double sum = 0;
  for (int j = 0; j + 1 < np; ++j) {
    if (!(ps[j + 1] > ps[j])) continue;
    const GaussRule01& g = CachedGaussLegendre01(
        dielectric_walk::NodesOf(kInnerNodes, kInnerWidth, ps[j + 1] - ps[j]));
    double part = 0;
    for (size_t q = 0; q < g.x.size(); ++q) {
      double jac;
      const double x = Smooth(ps[j], ps[j + 1], g.x[q], &jac);
      ++count;
      part += g.w[q] * jac * f(x);
    }
    sum += part;
  }
  return sum;
}

}  // namespace

double FixedRuleDielectricReflectanceKernel(double c, double alpha, long long* evals) {
  const KernelView k = MakeKernelView(c, alpha);
  long long count = 0;
  auto outer = [&](auto& ring, double weight) {
    const GaussRule01& go =
        CachedGaussLegendre01(dielectric_walk::NodesOf(kOuterNodes, kOuterWeight, weight));
    double part = 0;
    for (size_t q = 0; q < go.x.size(); ++q) part += go.w[q] * ring(go.x[q]);
    return part;
  };
  auto inner = [&](auto& f, const double* ps, int np) { return FixedPanels(f, ps, np, count); };
  const double r = KernelWalk(k, outer, inner);
  if (evals) *evals += count;
  return r;
}

double DielectricReflectanceKernel(double c, double alpha, double tol, IntegrationStats& stats) {
  const KernelView k = MakeKernelView(c, alpha);
  // Each outer panel to tol / 64, each ring's psi integral to tol / 640 (the outer weights are
  // at most ~ 1 / cos_m per unit v, graded by the smoothstep).
  auto outer = [&](auto& ring, double) {
    auto f = [&](double u) { return Channels<1>{ring(u)}; };
    const double xs[2] = {0, 1};
    return IntegrateAdaptive<1>(f, xs, 2, tol / 64, 2000)[0];
  };
  auto inner = [&](auto& f, const double* ps, int np) {
    // x in [j, j + 1] is panel j's smoothstep variable.
    auto g = [&](double x) {
      const int j = std::min(static_cast<int>(x), np - 2);
      double jac;
      const double psi = Smooth(ps[j], ps[j + 1], x - j, &jac);
      ++stats.evals;
      return Channels<1>{jac * f(psi)};
    };
    double xs[kMaxBreaks];
    for (int j = 0; j < np; ++j) xs[j] = j;
    return IntegrateAdaptive<1>(g, xs, np, tol / 640, 2000)[0];
  };
  return KernelWalk(k, outer, inner);
}

double DielectricReflectanceKernelRow::At(double c) const {
  const double x = std::sqrt(std::max(0.0, 1 - c));
  double num = 0, den = 0;
  for (size_t j = 0; j < t.size(); ++j) {
    const double d = x - t[j];
    if (d == 0) return k[j];
    const double q = weights[j] / d;
    num += q * k[j];
    den += q;
  }
  return num / den;
}

DielectricReflectanceKernelRow MakeDielectricReflectanceKernelRow(double alpha) {
  DielectricReflectanceKernelRow row;
  row.alpha = alpha;
  // The nodes in c: [0, cSplit] on geometric panels from alpha / 16 by 4 (the grazing layer),
  // Gauss in c; [cSplit, 1] at Chebyshev points (second kind) in t = sqrt(1 - c) over [0, tMax].
  std::vector<double> cs = {0};
  for (double b = std::max(alpha, MinAlpha) / 16; b < kDielectricKernelSplit; b *= 4)
    cs.push_back(b);
  cs.push_back(kDielectricKernelSplit);
  std::vector<double> at;  // every node's c: the panels' in order, then the Chebyshev points
  std::vector<size_t> first = {0};
  for (size_t i = 0; i + 1 < cs.size(); ++i) {
    const GaussRule01& g =
        CachedGaussLegendre01(dielectric_walk::NodesOf(kLowNodes, kLowEnd, cs[i + 1]));
    for (size_t q = 0; q < g.x.size(); ++q) at.push_back(cs[i] + (cs[i + 1] - cs[i]) * g.x[q]);
    first.push_back(at.size());
  }
  const double tMax = std::sqrt(1 - kDielectricKernelSplit);
  const int n = kChebyshevPoints;
  for (int j = 0; j < n; ++j) {
    const double t = tMax * (1 - std::cos(Pi * j / (n - 1))) / 2;
    row.t.push_back(t);
    row.weights.push_back((j % 2 ? -1.0 : 1.0) * (j == 0 || j == n - 1 ? 0.5 : 1.0));
    at.push_back(1 - t * t);
  }
  // K at every node on the calling arena's threads (isolated: a thread waiting for them takes no
  // other task, which could wait for this row in CachedDielectricReflectanceKernelRow), then
  // summed in the nodes' order: the bits of one thread's sums, for any thread count.
  std::vector<double> k(at.size());
  std::vector<long long> evals(at.size(), 0);
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, at.size(), 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i)
                          k[i] = FixedRuleDielectricReflectanceKernel(at[i], alpha, &evals[i]);
                      });
  });
  for (size_t i = 0; i + 1 < cs.size(); ++i) {
    const GaussRule01& g =
        CachedGaussLegendre01(dielectric_walk::NodesOf(kLowNodes, kLowEnd, cs[i + 1]));
    double part = 0;
    for (size_t q = 0; q < g.x.size(); ++q) part += g.w[q] * at[first[i] + q] * k[first[i] + q];
    row.lowIntegral += part * (cs[i + 1] - cs[i]);
  }
  row.k.assign(k.begin() + static_cast<std::ptrdiff_t>(first.back()), k.end());
  for (long long e : evals) row.evals += e;
  return row;
}

std::shared_ptr<const DielectricReflectanceKernelRow> CachedDielectricReflectanceKernelRow(
    double alpha) {
  using Row = std::shared_ptr<const DielectricReflectanceKernelRow>;
  struct Entry {
    std::once_flag once;
    Row row;
  };
  static std::mutex mutex;
  static std::map<std::uint64_t, std::shared_ptr<Entry>> rows;
  constexpr size_t kMaxRows = 1 << 13;  // ~1.2 KB each: 10 MB at most
  std::uint64_t key;
  std::memcpy(&key, &alpha, sizeof key);
  std::shared_ptr<Entry> entry;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = rows.find(key);
    if (it != rows.end()) {
      entry = it->second;
    } else if (rows.size() < kMaxRows) {
      entry = std::make_shared<Entry>();
      rows.emplace(key, entry);
    }
  }
  if (!entry)
    return std::make_shared<const DielectricReflectanceKernelRow>(
        MakeDielectricReflectanceKernelRow(alpha));
  std::call_once(entry->once, [&] {
    entry->row = std::make_shared<const DielectricReflectanceKernelRow>(
        MakeDielectricReflectanceKernelRow(alpha));
  });
  return entry->row;
}

double KernelDielectricExitAverageR(double alpha, double eta, long long* evals) {
  const auto row = CachedDielectricReflectanceKernelRow(alpha);
  if (evals) *evals += row->evals;
  return DielectricExitAverageRFromKernel(*row, eta);
}

double DielectricExitAverageRFromKernel(const DielectricReflectanceKernelRow& row, double eta) {
  const double cCrit = std::sqrt((1 - eta) * (1 + eta));
  const double lo = kDielectricKernelSplit;
  const GaussRule01& g = CachedGaussLegendre01(kEtaNodes);
  double sum = row.lowIntegral;
  // [lo, cCrit]: F = 1 (total internal reflection), graded in sqrt(cCrit - c) towards cCrit.
  // [cCrit, mid]: graded in sqrt(c - cCrit); [mid, 1]: in t = sqrt(1 - c).
  const double mid = cCrit + (1 - cCrit) / 2;
  const double sLo = std::sqrt(std::max(0.0, cCrit - lo)), sMid = std::sqrt(mid - cCrit);
  const double tMid = std::sqrt(1 - mid);
  double below = 0, above = 0, top = 0;
  for (size_t q = 0; q < g.x.size(); ++q) {
    const double s1 = sLo * g.x[q], c1 = cCrit - s1 * s1;
    below += g.w[q] * 2 * s1 * c1 * row.At(c1);
    const double s2 = sMid * g.x[q], c2 = cCrit + s2 * s2;
    above += g.w[q] * 2 * s2 * c2 * FrDielectric(c2, eta) * row.At(c2);
    const double t3 = tMid * g.x[q], c3 = 1 - t3 * t3;
    top += g.w[q] * 2 * t3 * c3 * FrDielectric(c3, eta) * row.At(c3);
  }
  sum += below * sLo + above * sMid + top * tMid;
  return sum;
}

}  // namespace kiln
