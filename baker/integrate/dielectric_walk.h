// The walk over the visible microfacet normals of the GGX dielectric (models/dielectric_bsdf.h,
// Walter et al. 2007) that the glass rules share: the E tables' {E_R, E_T}
// (dielectric_albedo.cpp) and the split-sum BTDF pair {T_lobe, T_F} (dielectric_btdf.cpp) are the
// same integral with another integrand,
//     (1 / pi) int_0^1 dv int_0^pi dphi_m  integrand(theta_m(v), cos phi_m),
// v = a^2 / (a^2 + tan^2 theta_m) (GGX's complementary CDF of D cos), over panels in v (outer:
// where the integrand's threshold curves meet phi_m = 0 or pi, grazing sweeps, GGX's tail) and in
// phi_m (inner: the thresholds on each azimuth circle), every panel smoothstep-mapped (derivations
// in the two files). The walk is written once here, templated over the problem, which supplies
//     int ThetaBreaks(double* thetas) const;   outer boundaries in theta_m, 0 .. pi/2 (sorted)
//     int PhiBreaks(PolarParam h, double* phis) const;  inner boundaries at h (>= 2, or 0)
//     Channels<2> Integrand(PolarParam h, double cosPhi) const;  (without the 1 / pi)
// and the members mu, st (sin theta_o), gDen (mu + mu Lambda(o)) and dist (GGX).
// Two rules walk it: the fixed rule (the bake's: Gauss nodes per panel by the panel's weight
// class, summed in one order: deterministic) and adaptive Gauss-Kronrod to a tolerance (the
// reference the tests hold the fixed rule to).
#pragma once
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "baker/integrate/hemisphere.h"
#include "baker/math/quadrature.h"
#include "baker/math/sincos_half_turn.h"
#include "baker/models/microfacet.h"

namespace kiln {
namespace dielectric_walk {

/// Most outer (theta_m) and inner (phi_m) panel boundaries a problem returns.
constexpr int kMaxThetaBreaks = 64;
constexpr int kMaxPhiBreaks = 40;

/// Gauss nodes per panel by class. An outer panel [v_a, v_b] takes outerNodes[k] for the first k
/// with its weight bound W > outerWeight[k] (outerNodes[3] below them all), W = (v_a - v_b) (mu +
/// sin_o tan theta_m(v_b)) / gDen (the integrand is at most (c / cos_m) / gDen, c = o.m <= mu
/// cos_m + sin_o sin_m, for every weight w(c) <= 1); an inner panel of a ring of that outer panel
/// takes innerNodes[k][q] for the first q with its width in radians > innerWidth[q]. Equal counts
/// in every class: one Gauss rule for all panels.
struct NodeClasses {
  int outerNodes[4];
  double outerWeight[3];
  int innerNodes[4][4];  ///< [outer class][inner width class]
  double innerWidth[3];
};

/// The node classes of a rule's options (DielectricRuleOptions, DielectricBtdfRuleOptions: the
/// same four fields by name): the inner counts the same for the rings of every outer class.
template <class Options>
NodeClasses ClassesOf(const Options& o) {
  NodeClasses c;
  for (int k = 0; k < 4; ++k) {
    c.outerNodes[k] = o.outerNodes[k];
    for (int q = 0; q < 4; ++q) c.innerNodes[k][q] = o.innerNodes[q];
  }
  for (int k = 0; k < 3; ++k) {
    c.outerWeight[k] = o.outerWeight[k];
    c.innerWidth[k] = o.innerWidth[k];
  }
  return c;
}

/// The class of x: the first k with x > bounds[k], else 3.
inline int ClassOf(const double* bounds, double x) {
  for (int k = 0; k < 3; ++k)
    if (x > bounds[k]) return k;
  return 3;
}

/// The node count of a class: counts[ClassOf(bounds, x)].
inline int NodesOf(const int* counts, const double* bounds, double x) {
  return counts[ClassOf(bounds, x)];
}

/// cos(phi) for phi in [0, pi] (every azimuth the walks visit): -sin(x), x = phi - pi/2 in
/// [-pi/2, pi/2], by sin's Taylor series to x^21 in Horner form (truncation below 2e-18;
/// rounding within 4e-16 absolute of std::cos over [0, pi], tests/integrate_dielectric_column.cpp).
/// The fixed rules' walks take it for libm's cos, a third of their time before: the same bits for
/// every C library.
inline double CosHalfTurn(double phi) {
  const double x = phi - Pi / 2, x2 = x * x;
  double p = 1.9572941063391263e-20;
  p = p * x2 - 8.2206352466243295e-18;
  p = p * x2 + 2.8114572543455206e-15;
  p = p * x2 - 7.6471637318198164e-13;
  p = p * x2 + 1.6059043836821613e-10;
  p = p * x2 - 2.505210838544172e-08;
  p = p * x2 + 2.7557319223985893e-06;
  p = p * x2 - 0.00019841269841269841;
  p = p * x2 + 0.0083333333333333332;
  p = p * x2 - 0.16666666666666666;
  p = p * x2 + 1;
  return -x * p;
}

/// The smoothstep map of panel [a, b] at t in [0, 1]: the point and its Jacobian.
inline double Smooth(double a, double b, double t, double* jac) {
  *jac = (b - a) * 6 * t * (1 - t);
  return a + (b - a) * t * t * (3 - 2 * t);
}

/// The outer boundaries in v (decreasing from 1) of the problem's theta_m boundaries; returns
/// their count.
template <class Problem>
int VBreaks(const Problem& p, double* vs) {
  double thetas[kMaxThetaBreaks];
  const int nt = p.ThetaBreaks(thetas);
  for (int i = 0; i < nt; ++i) vs[i] = i == 0 ? 1.0 : p.dist.VFromTheta(thetas[i]);
  return nt;
}

/// The weight class of the outer panel [va, vb] (v decreasing): its share of dv times the
/// integrand's bound at its small-v end, (mu + sin_o tan theta_m) / gDen (the tail panel, ending
/// at v = 0, is unbounded: top class).
template <class Problem>
int OuterClass(const Problem& p, const NodeClasses& rule, double va, double vb) {
  const double weight =
      vb > 0 ? (va - vb) * (p.mu + p.st * p.dist.alpha * std::sqrt((1 - vb) / vb)) / p.gDen
             : INFINITY;
  return ClassOf(rule.outerWeight, weight);
}

/// The ring at the Gauss node t (weight w) of the outer panel [va, vb], smoothstep-mapped: false
/// where its v or its Jacobian is not positive (no ring); else its normal's polar parameters h and
/// its outer weight wo (w times the Jacobian and 1 / pi).
template <class Problem>
bool OuterRing(const Problem& p, double va, double vb, double t, double w, PolarParam* h,
               double* wo) {
  double jac;
  const double vv = Smooth(va, vb, t, &jac);
  jac = -jac;
  if (!(vv > 0) || !(jac > 0)) return false;
  *h = p.dist.FromV(vv);
  *wo = w * jac / Pi;
  return true;
}

/// Walks the fixed rule's panels with node classes `rule` in its one summation order: panels in
/// order of v, rings (theta_m nodes) in order within each, azimuth panels in order within a ring.
/// For each ring: visit.BeginRing(h); visit.Panel(a, b, g) for each of its azimuth panels [a, b]
/// of positive width with its Gauss rule g on [0, 1] (the nodes are Smooth(a, b, g.x[j]) with
/// weights g.w[j] times the smoothstep's Jacobian, in order of j); visit.EndRing(wo), wo the
/// ring's outer weight times its Jacobian and 1 / pi. Returns the azimuth nodes of those panels
/// (the integrand evaluations).
template <class Problem, class Visitor>
long long WalkPanels(const Problem& p, const NodeClasses& rule, Visitor& visit) {
  double vs[kMaxThetaBreaks];
  const int nt = VBreaks(p, vs);
  long long count = 0;
  for (int i = 0; i + 1 < nt; ++i) {
    const int outerClass = OuterClass(p, rule, vs[i], vs[i + 1]);
    const int* innerNodes = rule.innerNodes[outerClass];
    const GaussRule01& go = CachedGaussLegendre01(rule.outerNodes[outerClass]);
    for (size_t ko = 0; ko < go.x.size(); ++ko) {
      PolarParam h;
      double wo;
      if (!OuterRing(p, vs[i], vs[i + 1], go.x[ko], go.w[ko], &h, &wo)) continue;
      double phis[kMaxPhiBreaks];
      const int np = p.PhiBreaks(h, phis);
      visit.BeginRing(h);
      for (int k = 0; k + 1 < np; ++k) {
        const double width = phis[k + 1] - phis[k];
        if (!(width > 0)) continue;
        const GaussRule01& gi = CachedGaussLegendre01(NodesOf(innerNodes, rule.innerWidth, width));
        count += static_cast<long long>(gi.x.size());
        visit.Panel(phis[k], phis[k + 1], gi);
      }
      visit.EndRing(wo);
    }
  }
  return count;
}

/// Walks the fixed rule's nodes (WalkPanels' order): for each ring visit.BeginRing(h);
/// visit.Node(h, phi, w) for each of its azimuth nodes (w the inner Gauss weight times the
/// smoothstep's Jacobian); visit.EndRing(wo). The visitor sums: FixedWalk below one integrand,
/// the glass tables' eta columns (dielectric_albedo.cpp, dielectric_btdf.cpp) one per eta.
/// Returns the azimuth nodes visited (the integrand evaluations).
template <class Problem, class Visitor>
long long WalkNodes(const Problem& p, const NodeClasses& rule, Visitor& visit) {
  struct Nodes {
    Visitor& visit;
    PolarParam h{};
    void BeginRing(const PolarParam& ring) {
      h = ring;
      visit.BeginRing(ring);
    }
    void Panel(double a, double b, const GaussRule01& g) {
      for (size_t j = 0; j < g.x.size(); ++j) {
        double dj;
        const double phi = Smooth(a, b, g.x[j], &dj);
        visit.Node(h, phi, g.w[j] * dj);
      }
    }
    void EndRing(double wo) { visit.EndRing(wo); }
  } nodes{visit};
  return WalkPanels(p, rule, nodes);
}

/// The integral by the fixed rule with node classes `rule` (WalkNodes); evals (optional)
/// accumulates the integrand evaluations.
template <class Problem>
Channels<2> FixedWalk(const Problem& p, const NodeClasses& rule, long long* evals) {
  struct Sum {
    const Problem& p;
    Channels<2> sum{0, 0}, circle{0, 0};
    void BeginRing(const PolarParam&) { circle = Channels<2>{0, 0}; }
    void Node(const PolarParam& h, double phi, double w) {
      circle += w * p.Integrand(h, CosHalfTurn(phi));
    }
    void EndRing(double wo) { sum += wo * circle; }
  } s{p};
  const long long count = WalkNodes(p, rule, s);
  if (evals) *evals += count;
  return s.sum;
}

/// The azimuth at AdaptiveWalk's inner variable y of a ring with boundaries phis[0 .. np - 1]
/// (np >= 2): y's panel k = [k, k + 1] smoothstep-mapped onto [phis[k], phis[k + 1]]; *dj gets
/// the Jacobian.
inline double RingAzimuth(const double* phis, int np, double y, double* dj) {
  const int k = std::min(static_cast<int>(y), np - 2);
  return Smooth(phis[k], phis[k + 1], y - k, dj);
}

/// Whether Problem evaluates a ring's azimuth nodes together: p.RingOf(h) returns an object
/// whose Nodes(y, phis, np, n, out) writes, for i < n, out[i] = dj * p.Integrand(h,
/// SinCosHalfTurn(phi).cos) with phi = RingAzimuth(phis, np, y[i], &dj) (those bits; the ring's
/// constants computed once).
template <class P, class = void>
struct HasRingNodes : std::false_type {};
template <class P>
struct HasRingNodes<P, std::void_t<decltype(std::declval<const P&>().RingOf(PolarParam{}))>>
    : std::true_type {};

/// The signature of a lane kernel of LaneRing (dielectric_adaptive_nodes.h: AlbedoNodes,
/// BtdfNodes).
template <class Lanes>
using LaneKernel = void (*)(const Lanes&, const double*, const double*, int, int, Channels<2>*);

/// A problem's RingOf (HasRingNodes): a panel's nodes by the lane kernel Kernel with the ring's
/// constants `lanes` where `simd` (dielectric_simd::Enabled()), else by the problem's Integrand
/// one node at a time; Kernel must give the scalar path's bits.
template <class Problem, class Lanes, LaneKernel<Lanes> Kernel>
struct LaneRing {
  const Problem& p;
  PolarParam h;
  bool simd;
  Lanes lanes;
  void Nodes(const double* y, const double* phis, int np, int n, Channels<2>* out) const {
    if (simd) {
      Kernel(lanes, y, phis, np, n, out);
      return;
    }
    for (int i = 0; i < n; ++i) {
      double dj;
      const double phi = RingAzimuth(phis, np, y[i], &dj);
      out[i] = dj * p.Integrand(h, SinCosHalfTurn(phi).cos);
    }
  }
};

/// AdaptiveWalk's inner integrand on the ring h: y in [0, np - 1], its panel k = [k, k + 1]
/// smoothstep-mapped onto the azimuths [phis[k], phis[k + 1]]; dj times the problem's
/// Integrand, counted in stats.evals.
template <class Problem>
struct CircleIntegrand {
  const Problem& p;
  PolarParam h;
  const double* phis;
  int np;
  IntegrationStats& stats;
  Channels<2> operator()(double y) const {
    double dj;
    const double phi = RingAzimuth(phis, np, y, &dj);
    ++stats.evals;
    return dj * p.Integrand(h, SinCosHalfTurn(phi).cos);
  }
};

/// CircleIntegrand with a Gauss-Kronrod panel's nodes at once (quadrature.h, EvaluateNodes) by
/// the ring's Nodes (HasRingNodes): the same values.
template <class Problem, class Ring>
struct CircleNodes : CircleIntegrand<Problem> {
  Ring ring;
  void EvaluateNodes(const double* y, int n, Channels<2>* out) const {
    this->stats.evals += n;
    ring.Nodes(y, this->phis, this->np, n, out);
  }
};

/// The integral by adaptive Gauss-Kronrod on the same panels: outer to opt.tol / 2, each circle
/// to a tenth of opt.tol scaled by the circle's weight in the outer rule. stats.evals
/// accumulates the evaluations, stats.errorEstimate gets the outer rule's estimate. A problem
/// with RingOf (HasRingNodes) has each inner panel's 15 nodes evaluated in one call.
template <class Problem>
Channels<2> AdaptiveWalk(const Problem& p, const IntegrationOptions& opt, IntegrationStats& stats) {
  double vs[kMaxThetaBreaks];
  const int nt = VBreaks(p, vs);
  const int panels = nt - 1;
  const double innerTol = opt.tol / 10;
  // Outer variable x in [0, panels], panel i at [i, i + 1], v decreasing from vs[i] to vs[i+1].
  auto circle = [&](double x) -> Channels<2> {
    const int i = std::min(static_cast<int>(x), panels - 1);
    double jac;
    const double vv = Smooth(vs[i], vs[i + 1], x - i, &jac);
    jac = -jac;
    if (!(vv > 0) || !(jac > 0)) return Channels<2>{};
    const PolarParam h = p.dist.FromV(vv);
    double phis[kMaxPhiBreaks];
    const int np = p.PhiBreaks(h, phis);
    if (np < 2) return Channels<2>{};
    double ys[kMaxPhiBreaks];
    for (int k = 0; k < np; ++k) ys[k] = k;
    // The outer rule weighs this by jac / pi: a circle of tiny weight needs less precision.
    const double tolHere = innerTol * Pi / (jac * panels);
    const CircleIntegrand<Problem> inner{p, h, phis, np, stats};
    if constexpr (HasRingNodes<Problem>::value) {
      CircleNodes<Problem, decltype(p.RingOf(h))> f{inner, p.RingOf(h)};
      return (jac / Pi) * IntegrateAdaptive<2>(f, ys, np, tolHere, opt.maxPanels);
    } else {
      return (jac / Pi) * IntegrateAdaptive<2>(inner, ys, np, tolHere, opt.maxPanels);
    }
  };
  double xs[kMaxThetaBreaks];
  for (int i = 0; i <= panels; ++i) xs[i] = i;
  double err = 0;
  const Channels<2> r =
      IntegrateAdaptive<2>(circle, xs, panels + 1, opt.tol / 2, opt.maxPanels, &err);
  stats.errorEstimate = err;
  return r;
}

}  // namespace dielectric_walk
}  // namespace kiln
