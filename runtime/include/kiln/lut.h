// kiln/lut.h: the header-only sampling core of the kiln runtime.
//
// Depends on the C++ standard library only. Nothing here allocates, throws or
// touches global state, so a const LutView may be sampled from any number of
// threads at once.
//
// Grid convention (node-centred): an axis of N nodes over [lo, hi] with warp w
// holds values at
//     x_i = lo + (hi - lo) * w^-1(i / (N - 1)),   i = 0 .. N-1,
// so both ends of every axis are nodes. A value x maps to the continuous node
// index ("texel coordinate") s = w((x - lo) / (hi - lo)) * (N - 1), and to the
// texture coordinate (0.5 + s) / N for hardware bilinear filtering.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "kiln/lut_float_path.h"
#include "kiln/lut_inline.h"

namespace kiln {

/// How an axis spends its nodes. A warp maps the normalized coordinate
/// y = (x - lo) / (hi - lo) in [0, 1] to the warped coordinate t in [0, 1];
/// nodes are uniform in t.
///   Linear: t = y        (nodes uniform in x)
///   Sqrt:   t = sqrt(y)  (nodes dense near lo)
///   Square: t = y^2      (nodes dense near hi)
///   Log:    t = ln(x / lo) / ln(hi / lo)  (nodes uniform in ln x; needs 0 < lo < hi)
///   Root4:  t = y^(1/4)  (nodes very dense near lo: a layer of width w at lo is
///                         resolved once w^(1/4) >> 4 / N)
///   Root4Layer: t = (y^(1/4) + y (1 + c) / (y + c)) / 2, c = max(r^2, 1e-12) for r > 0,
///           where r is the value of axis 1 (clamped to that axis). Only on axis 0 of a table
///           of two or more axes, a view-cosine axis before a roughness axis: near
///           grazing a microfacet albedo is a function of mu / alpha (alpha = r^2), a
///           layer whose width goes to 0 with the roughness. The second term reaches
///           half its range at y ~ c, so about a quarter of the nodes lie inside the
///           layer at every roughness and the corner (mu, r) -> (0, 0) interpolates
///           like the rest of the table; the first keeps root4's nodes in the bulk.
///           At r = 0 exactly the layer has collapsed (c = 0, the smooth limit): every y,
///           y = 0 included, maps to the outer half t = (y^(1/4) + 1) / 2, the limit of the
///           formula as c -> 0+ for y > 0. A lookup at r = 0 reads only the nodes from
///           t_s = floor((N - 1) / 2) / (N - 1) on (the last node at or below 1/2), which hold
///           the smooth (mirror) values, those at t <= 1/2 the value at mu = 0; the nodes
///           t < t_s of that row hold the layer's limit r -> 0+, read by 0 < r < r_1.
///   LayerEta: t = y (1 + c) / (y + c), c = sqrt(|eta^2 - 1|) (floored at 1e-12), where eta
///           is the value of axis 1 (clamped to that axis). Only on axis 0 of a table of two
///           or more axes, a view-cosine axis before an index axis: as eta -> 1 a dielectric
///           Fresnel term is G(mu / c), a layer of width c (for eta < 1, c is the cosine of
///           the critical angle, the kink of total reflection). Half of the nodes lie inside
///           mu < c at every eta, and mu / c at a fixed t tends to t / (1 - t) as c -> 0, so
///           rows of neighbouring eta interpolate like values of one function. At eta = 1
///           exactly (c = 0) y = 0 maps to t = 0 and every y > 0 to t = 1: the nodes t < 1 of
///           that row hold the layer's limit G(t / (1 - t)), the last node the value at mu = 1.
///   Angle:  t = 1 - (2 / pi) acos(y)  (nodes uniform in the angle theta = acos(y):
///                         a function of theta_o, smooth in the angle, has a square-root
///                         point at y = 1 (mu = cos theta) that this resolves)
///   Root4LayerSplit: a mu axis split at a point s: a constant (Axis::split, see below) or,
///           by default, the critical cosine s = sqrt(1 - eta^2) of total internal reflection,
///           eta the value of axis 2 (clamped to that axis; s is clamped into
///           [lo + (hi - lo) / 64, hi - (hi - lo) / 64], so for eta >= 1 it sits near lo). Only
///           on axis 0 of a 3-axis table (mu, roughness, eta), or of 2 or 3 axes with a
///           constant split; c is the Root4Layer scale of axis 1. With y = (x - lo) / (hi - lo),
///           y_s = (s - lo) / (hi - lo) and m = y_s / 2, three pieces, each a Root4Layer warp
///           L(d, c') of the distance d from a layer end (L at c' = 0: the collapsed form):
///             y <= m:       t = L(y / m, c / m) / 4                       (the grazing layer)
///             m < y <= y_s: t = 1/2 - L((y_s - y) / m, c / m) / 4         (the kink, below)
///             y > y_s:      t = 1/2 + L((y - y_s) / (1 - y_s), c / (1 - y_s)) / 2 (above)
///           so x = s is t = 1/2 in every eta layer (a grid line when N - 1 is even): a kink
///           of the tabulated function at s, which rows of other eta hold at other mu, stays
///           on one grid line, and nodes crowd it over a width ~c on both sides. The size must
///           satisfy (N - 1) % 8 == 0 (t = 1/8, 3/8, 1/2, 3/4 are nodes). At r = 0 (c = 0) each
///           piece collapses as Root4Layer does: the nodes t < 1/8 and 3/8 < t < 3/4 of that
///           row hold the layers' limit r -> 0+, read only by 0 < r < r_1 (holdsLayerLimit).
///           Where the split comes from is data of the axis (Axis::split): NaN (the default,
///           and every file without the attribute kiln.axis<i>.split) is the critical cosine of
///           axis 2's eta as above (a 3-axis table); a finite value lo < split < hi is a
///           constant split point, the same in every layer, and then axis 2 is not read (a
///           table of two or three axes): a kink at a fixed x = split (e.g. a max() of the
///           model) is a grid line at every value of axis 1.
///   Root4LayerAngle: t = L(u, c), u = (2 / pi) asin(y), L the Root4Layer warp (c from axis 1
///           as there, and its collapsed form at c = 0): nodes dense at both ends. At y -> 0
///           u ~ 0.64 y, so the grazing layer is graded as by Root4Layer; at y -> 1 u is
///           linear in the angle theta = acos(y), so a function with a (1 - mu)^(3/2) =
///           (theta^2 / 2)^(3/2) point at mu = 1 (a microfacet albedo at high roughness,
///           the normals clipped at the visibility horizon) is smooth in t there. Same rules
///           as Root4Layer: axis 0 of a table of two or more axes, coupled to axis 1.
///   Root4LayerSplit2: a mu axis split at two points of axis 2's eta, the critical cosine
///           x_c = sqrt(1 - eta^2) (the kink of total internal reflection) and x_e = eta
///           (theta_o + theta_c = pi / 2: the microfacets facing the view near the horizon
///           leave total internal reflection, a one-sided point of a rough dielectric's
///           transmission at high roughness), each clamped into [lo + (hi - lo) / 64, hi -
///           (hi - lo) / 64]. Only on axis 0 of a 3-axis table (mu, roughness, eta), eta the
///           value of axis 2 (clamped to that axis), c the Root4Layer scale of axis 1. With
///           y = (x - lo) / (hi - lo), a <= b the two breaks in y (their min and max: they
///           cross at eta = 1 / sqrt(2)), m = a / 2, n = (a + b) / 2, w = (b - a) / 2, five
///           pieces, each a Root4Layer warp L(d, c') of the distance d from a layer end
///           (collapsed at c' = 0), between the lines T0 = 5/16, T1 = 8/16, T2 = 10/16,
///           T3 = 13/16 of t (kSplit2T0 .. kSplit2T3):
///             y <= m:      t = T0 L(y / m, c / m)                          (grazing layer)
///             m < y <= a:  t = T1 - (T1 - T0) L((a - y) / m, c / m)        (below a)
///             a < y <= n:  t = T1 + (T2 - T1) L((y - a) / w, c / w)        (above a)
///             n < y <= b:  t = T3 - (T3 - T2) L((b - y) / w, c / w)        (below b)
///             y > b:       t = T3 + (1 - T3) L((y - b) / (1 - b), c / (1 - b)) (above b)
///           so both breaks are grid lines (t = 8/16 and 13/16) in every eta layer, with
///           nodes crowded on both sides of each, quartically (root4) at every roughness, over
///           ~c besides. c / w is capped at 1e12 (w -> 0). At eta = 1 / sqrt(2) (w = 0) the
///           two middle pieces have zero width: their nodes all sit at x = a, the inverse
///           stays finite and continuous in eta, and a lookup at y <= a maps below T1, above a
///           from T3 on. The size must satisfy (N - 1) % 32 == 0 (the lines and the middles of
///           the pieces are nodes). At r = 0 (c = 0) each piece collapses as Root4Layer does:
///           the nodes t < T0 / 2, (T0 + T1) / 2 < t < (T1 + T2) / 2 and (T2 + T3) / 2 < t <
///           (T3 + 1) / 2 of that row hold the layers' limit r -> 0+, read only by 0 < r < r_1
///           (holdsLayerLimit). The third argument of warped/unwarped/texel (`split`) is, for
///           this warp, axis 2's eta (LutView::splitAt), from which it places both breaks.
///   Arcsine: t = (2 / pi) asin(sqrt(y)), y = sin^2(t pi / 2) (nodes uniform in the arcsine
///           distribution's CDF): dense at both ends, as sqrt at lo (y ~ 2.47 t^2) and as
///           square at hi (1 - y ~ 2.47 (1 - t)^2), about linear in between (dy/dt <= pi / 2).
///           A roughness axis whose function bends most near r = 1 while its first cell must
///           stay thin (the layer of a coupled mu axis at r -> 0).
enum class Warp {
  Linear,
  Sqrt,
  Square,
  Log,
  Root4,
  Root4Layer,
  Angle,
  LayerEta,
  Root4LayerSplit,
  Root4LayerAngle,
  Root4LayerSplit2,
  Arcsine
};

/// The file/CLI name of a warp: "linear", "sqrt", "square", "log", "root4", "root4-layer",
/// "angle", "layer-eta", "root4-layer-split", "root4-layer-angle", "root4-layer-split2" or
/// "arcsine".
/// Returns "unknown" for a value outside the enumeration.
inline const char* warpName(Warp warp) noexcept {
  switch (warp) {
    case Warp::Linear:
      return "linear";
    case Warp::Sqrt:
      return "sqrt";
    case Warp::Square:
      return "square";
    case Warp::Log:
      return "log";
    case Warp::Root4:
      return "root4";
    case Warp::Root4Layer:
      return "root4-layer";
    case Warp::Angle:
      return "angle";
    case Warp::LayerEta:
      return "layer-eta";
    case Warp::Root4LayerSplit:
      return "root4-layer-split";
    case Warp::Root4LayerAngle:
      return "root4-layer-angle";
    case Warp::Root4LayerSplit2:
      return "root4-layer-split2";
    case Warp::Arcsine:
      return "arcsine";
  }
  return "unknown";
}

/// Parses a warp name as written by warpName (exact, case-sensitive match).
/// On success stores the warp in `warp` and returns true; otherwise leaves
/// `warp` untouched and returns false. A null name is rejected.
inline bool warpFromName(const char* name, Warp& warp) noexcept {
  if (name == nullptr) return false;
  const Warp all[] = {Warp::Linear,
                      Warp::Sqrt,
                      Warp::Square,
                      Warp::Log,
                      Warp::Root4,
                      Warp::Root4Layer,
                      Warp::Angle,
                      Warp::LayerEta,
                      Warp::Root4LayerSplit,
                      Warp::Root4LayerAngle,
                      Warp::Root4LayerSplit2,
                      Warp::Arcsine};
  for (Warp candidate : all) {
    if (std::strcmp(name, warpName(candidate)) == 0) {
      warp = candidate;
      return true;
    }
  }
  return false;
}

/// Interpolation filter of LutView::sample.
///   Linear: multilinear in texel (warped) space.
///   Cubic:  Catmull-Rom per axis in texel space. Beyond the ends, ghost nodes
///           are extrapolated quadratically (p[-1] = 3 p[0] - 3 p[1] + p[2], and
///           mirrored at the far end), so quadratics are reproduced exactly in
///           every cell. May overshoot the data range.
///           An axis with fewer than 3 nodes is interpolated linearly.
enum class Filter { Linear, Cubic };

/// How close (in nodes) a texel coordinate must be to an integer to be snapped onto it
/// (Axis::texel), so that a lookup at a node reads that node alone.
constexpr double kNodeSnap = 1e-9;

/// pi, for the Angle warp.
constexpr double kPi = 3.14159265358979323846;

/// The layer scale of the Root4Layer warp, from the value r of the axis it couples
/// to (clamped to that axis; NaN maps to its lo): c = max(r^2, 1e-12) for r > 0, and
/// c = 0 at r = 0 exactly (the collapsed layer, the smooth limit).
inline double layerScale(double lo, double hi, double r) noexcept {
  const double rc = !(r > lo) ? lo : (!(r < hi) ? hi : r);
  if (rc == 0.0) return 0.0;
  const double c = rc * rc;
  return c > 1e-12 ? c : 1e-12;
}

/// The layer scale of the LayerEta warp, from the value eta of the axis it couples
/// to (clamped to that axis; NaN maps to its lo): c = max(sqrt(|eta^2 - 1|), 1e-12)
/// for eta != 1, and c = 0 at eta = 1 exactly (no interface: the layer collapsed).
inline double etaLayerScale(double lo, double hi, double eta) noexcept {
  const double ec = !(eta > lo) ? lo : (!(eta < hi) ? hi : eta);
  const double c = std::sqrt(std::fabs((ec - 1.0) * (ec + 1.0)));
  if (c == 0.0) return 0.0;
  return c > 1e-12 ? c : 1e-12;
}

/// True for the warps that read another axis (Root4Layer, LayerEta, Root4LayerSplit,
/// Root4LayerAngle, Root4LayerSplit2): only on axis 0 of a table of two or more axes (three
/// for Root4LayerSplit without a constant split, and for Root4LayerSplit2), coupled to axis 1.
inline bool isLayerWarp(Warp warp) noexcept {
  return warp == Warp::Root4Layer || warp == Warp::LayerEta || warp == Warp::Root4LayerSplit ||
         warp == Warp::Root4LayerAngle || warp == Warp::Root4LayerSplit2;
}

/// True for the warps whose layer scale is the roughness's (layerScale): Root4Layer,
/// Root4LayerSplit, Root4LayerAngle, Root4LayerSplit2.
inline bool isRoughnessLayerWarp(Warp warp) noexcept {
  return warp == Warp::Root4Layer || warp == Warp::Root4LayerSplit ||
         warp == Warp::Root4LayerAngle || warp == Warp::Root4LayerSplit2;
}

/// True for the warps that read axis 2 (Root4LayerSplit without a constant split,
/// Root4LayerSplit2): axis 0 of a 3-axis table only.
inline bool readsAxis2(Warp warp, bool constantSplit) noexcept {
  return (warp == Warp::Root4LayerSplit && !constantSplit) || warp == Warp::Root4LayerSplit2;
}

/// The split point of a Root4LayerSplit axis 0 over [lo0, hi0] at the value eta of axis 2
/// (clamped to [lo2, hi2]; NaN maps to lo2): the critical cosine sqrt(1 - eta^2) (0 for
/// eta >= 1), clamped into [lo0 + (hi0 - lo0) / 64, hi0 - (hi0 - lo0) / 64].
inline double criticalSplit(double lo0, double hi0, double lo2, double hi2, double eta) noexcept {
  const double ec = !(eta > lo2) ? lo2 : (!(eta < hi2) ? hi2 : eta);
  const double q = (1.0 - ec) * (1.0 + ec);
  const double s = q > 0.0 ? std::sqrt(q) : 0.0;
  const double a = lo0 + (hi0 - lo0) / 64.0, b = hi0 - (hi0 - lo0) / 64.0;
  return s < a ? a : (s > b ? b : s);
}

/// The value of axis 2 a Root4LayerSplit2 axis 0 reads: eta clamped to [lo2, hi2] (NaN maps to
/// lo2); the axis places its two breaks from it (Axis::split2Breaks).
inline double clampedEta(double lo2, double hi2, double eta) noexcept {
  return !(eta > lo2) ? lo2 : (!(eta < hi2) ? hi2 : eta);
}

/// The layer scale of an axis 0 with warp `warp0` at the value x1 of axis 1 (`axis1`'s
/// lo and hi clamp it): layerScale for Root4Layer, Root4LayerSplit and Root4LayerAngle,
/// etaLayerScale for LayerEta, 1e-12 (ignored) for the other warps.
inline double layerScaleFor(Warp warp0, double lo1, double hi1, double x1) noexcept {
  if (isRoughnessLayerWarp(warp0)) return layerScale(lo1, hi1, x1);
  if (warp0 == Warp::LayerEta) return etaLayerScale(lo1, hi1, x1);
  return 1e-12;
}

/// One axis of a table: `size` nodes over [lo, hi] placed by `warp`.
/// A plain aggregate; it is usable (valid()) when size >= 1, lo and hi are
/// finite, lo < hi, and lo > 0 for the log warp.
/// Every mapping takes the layer scale c of the Root4Layer warp (layerScale() of
/// the coupled axis' value); the other warps ignore it.
struct Axis {
  double lo = 0.0;
  double hi = 1.0;
  int size = 1;
  Warp warp = Warp::Linear;
  /// The split point of a Root4LayerSplit axis: NaN (default) for the critical cosine of axis
  /// 2's eta (criticalSplit), a finite lo < split < hi for a constant one. Ignored (and NaN)
  /// on any other warp.
  double split = std::numeric_limits<double>::quiet_NaN();

  /// True when split holds a constant split point (a finite value).
  bool hasConstantSplit() const noexcept { return std::isfinite(split); }

  /// True when the axis satisfies the conditions above ((size - 1) % 8 == 0 for
  /// Root4LayerSplit, (size - 1) % 32 == 0 for Root4LayerSplit2, a constant split only on
  /// Root4LayerSplit and strictly inside (lo, hi)).
  bool valid() const noexcept {
    return size >= 1 && std::isfinite(lo) && std::isfinite(hi) && lo < hi &&
           (warp != Warp::Log || lo > 0.0) &&
           (warp != Warp::Root4LayerSplit || (size >= 9 && (size - 1) % 8 == 0)) &&
           (warp != Warp::Root4LayerSplit2 || (size >= 33 && (size - 1) % 32 == 0)) &&
           (!hasConstantSplit() || (warp == Warp::Root4LayerSplit && lo < split && split < hi)) &&
           !std::isinf(split);
  }

  /// Position of node i: lo + (hi - lo) * w^-1(i / (N - 1)) (for the log warp
  /// lo * (hi / lo)^(i / (N - 1))). Exactly lo at i = 0 and exactly hi at
  /// i = N - 1; i is clamped to [0, N - 1]. An axis of size 1 has its single
  /// node at lo.
  double node(int i, double c = 1e-12, double split = 0.5) const noexcept {
    if (size <= 1 || i <= 0) return lo;
    if (i >= size - 1) return hi;
    return unwarped(static_cast<double>(i) / static_cast<double>(size - 1), c, split);
  }

  /// The Root4Layer warp of y in [0, 1] (see Warp), c > 0.
  static double layerWarp(double y, double c) noexcept {
    return 0.5 * (std::sqrt(std::sqrt(y)) + y * (1.0 + c) / (y + c));
  }

  /// The Root4Layer warp of y in [0, 1] with its collapsed form at c = 0: (y^(1/4) + 1) / 2
  /// for y > 0 and 1/2 at y <= 0 (and 0 at y <= 0 for c > 0); 1 at y >= 1.
  static double layerWarpCollapsible(double y, double c) noexcept {
    if (!(y > 0.0)) return c == 0.0 ? 0.5 : 0.0;
    if (!(y < 1.0)) return 1.0;
    if (c == 0.0) return 0.5 * (std::sqrt(std::sqrt(y)) + 1.0);
    return layerWarp(y, c);
  }

  /// Inverse of layerWarpCollapsible: y in [0, 1] at t in [0, 1] (0 for t <= 1/2 at c = 0).
  /// Safeguarded Newton on s = y^(1/4), where the warp (s + s^4 (1 + c) / (s^4 + c)) / 2 is
  /// smooth with slope >= 1/2, as rtsafe (Numerical Recipes 9.4): a bisection of the bracket
  /// [sa, sb] whenever a step would leave it or would not halve the step before, so it cannot
  /// cycle. Deterministic, to the last bits.
  static double layerWarpInverse(double t, double c) noexcept {
    if (!(t > 0.0)) return 0.0;
    if (!(t < 1.0)) return 1.0;
    if (c == 0.0) {
      if (!(t > 0.5)) return 0.0;
      const double s = 2.0 * t - 1.0;
      return (s * s) * (s * s);
    }
    double sa = 0.0, sb = 1.0, s = t, step = 1.0, stepBefore = 1.0;
    for (int k = 0; k < 200; ++k) {
      const double s4 = (s * s) * (s * s);
      const double r = 0.5 * (s + s4 * (1.0 + c) / (s4 + c)) - t;
      if (r == 0.0) break;
      (r < 0.0 ? sa : sb) = s;
      const double q = (s4 + c) * (s4 + c);
      const double slope = 0.5 * (1.0 + 4.0 * (1.0 + c) * c * (s * s * s) / q);
      double next = s - r / slope;
      stepBefore = step;
      if (!(next > sa && next < sb) || std::fabs(2.0 * r) > std::fabs(stepBefore * slope)) {
        step = 0.5 * (sb - sa);
        next = sa + step;
      } else {
        step = r / slope;
      }
      const bool done = std::fabs(next - s) <= 1e-16 * next || !(sb > sa);
      s = next;
      if (done) break;
    }
    return (s * s) * (s * s);
  }

  /// True when, in a row where the layer collapsed (c = 0), the node at warped coordinate t
  /// holds the layer's limit rather than the smooth value: t < collapsedStart() for Root4Layer
  /// and LayerEta; t < 1/8 or 3/8 < t < 3/4 for Root4LayerSplit (the inner halves of its
  /// three pieces; a lookup at c = 0 maps to the outer halves only), the inner halves of the
  /// five pieces for Root4LayerSplit2 (see Warp). False for other warps.
  bool holdsLayerLimit(double t) const noexcept {
    if (warp == Warp::Root4LayerSplit) return t < 0.125 || (t > 0.375 && t < 0.75);
    if (warp == Warp::Root4LayerSplit2)
      return t < 0.5 * kSplit2T0 ||
             (t > 0.5 * (kSplit2T0 + kSplit2T1) && t < 0.5 * (kSplit2T1 + kSplit2T2)) ||
             (t > 0.5 * (kSplit2T2 + kSplit2T3) && t < 0.5 * (kSplit2T3 + 1.0));
    return t < collapsedStart();
  }

  /// From which node on a collapsed layer (c = 0) holds smooth values: for
  /// Root4Layer (and Root4LayerAngle) t_s = floor((N - 1) / 2) / (N - 1), the last node at or
  /// below 1/2
  /// (1/2 when N is odd; the lookups at c = 0 map to t >= 1/2, so they read these
  /// nodes only); 1 for LayerEta (its last node); 0 for the other warps. The nodes
  /// t < t_s of a collapsed row hold the layer's limit.
  double collapsedStart() const noexcept {
    if (warp == Warp::LayerEta) return 1.0;
    if ((warp != Warp::Root4Layer && warp != Warp::Root4LayerAngle) || size < 2) return 0.0;
    const int n1 = size - 1;
    return static_cast<double>(n1 / 2) / static_cast<double>(n1);
  }

  /// Warped coordinate t in [0, 1] of a value x. x is clamped to [lo, hi]
  /// (clamp to edge); a NaN x maps to t = 0 (to 1/2 for a Root4Layer or Root4LayerAngle
  /// axis at c = 0).
  double warped(double x, double c = 1e-12, double split = 0.5) const noexcept {
    if (warp == Warp::Root4LayerSplit) return splitWarped(x, c, split);
    if (warp == Warp::Root4LayerSplit2) return split2Warped(x, c, split);
    const bool collapsed = c == 0.0 && (warp == Warp::Root4Layer || warp == Warp::Root4LayerAngle);
    if (!(x > lo)) return collapsed ? 0.5 : 0.0;  // also catches NaN
    if (!(x < hi)) return 1.0;
    double t = 0.0;
    switch (warp) {
      case Warp::Linear:
        t = (x - lo) / (hi - lo);
        break;
      case Warp::Sqrt:
        t = std::sqrt((x - lo) / (hi - lo));
        break;
      case Warp::Square: {
        const double y = (x - lo) / (hi - lo);
        t = y * y;
        break;
      }
      case Warp::Log:
        t = std::log(x / lo) / std::log(hi / lo);
        break;
      case Warp::Root4:
        t = std::sqrt(std::sqrt((x - lo) / (hi - lo)));
        break;
      case Warp::Root4Layer:
        if (collapsed) {
          t = 0.5 * (std::sqrt(std::sqrt((x - lo) / (hi - lo))) + 1.0);
        } else {
          t = layerWarp((x - lo) / (hi - lo), c);
        }
        break;
      case Warp::LayerEta: {
        if (!(c > 0.0)) return 1.0;  // collapsed: every x > lo
        const double y = (x - lo) / (hi - lo);
        t = y * (1.0 + c) / (y + c);
        break;
      }
      case Warp::Angle:
        t = 1.0 - std::acos((x - lo) / (hi - lo)) * (2.0 / kPi);
        break;
      case Warp::Arcsine:
        t = std::asin(std::sqrt((x - lo) / (hi - lo))) * (2.0 / kPi);
        break;
      case Warp::Root4LayerAngle: {
        const double u = std::asin((x - lo) / (hi - lo)) * (2.0 / kPi);
        t = layerWarpCollapsible(u, c);
        break;
      }
      case Warp::Root4LayerSplit:
        break;  // splitWarped
      case Warp::Root4LayerSplit2:
        break;  // split2Warped
    }
    if (!(t >= 0.0)) return 0.0;  // NaN from an invalid axis
    return t < 1.0 ? t : 1.0;
  }

  /// Inverse of warped(): the value x in [lo, hi] at warped coordinate t in [0, 1]
  /// (t is clamped). node(i) == unwarped(i / (N - 1)). Root4Layer has no closed
  /// form: safeguarded Newton to the last bits (deterministic); Root4LayerAngle is its
  /// inverse followed by sin(u pi / 2). A collapsed layer (c = 0) returns lo for every
  /// t <= 1/2 (Root4Layer, Root4LayerAngle) or t < 1 (LayerEta). For Root4LayerSplit2,
  /// `split` is axis 2's eta (see Warp).
  double unwarped(double t, double c = 1e-12, double split = 0.5) const noexcept {
    if (!(t > 0.0)) return lo;
    if (!(t < 1.0)) return hi;
    switch (warp) {
      case Warp::LayerEta: {
        if (!(c > 0.0)) return lo;
        return lo + (hi - lo) * (c * t / (1.0 + c - t));
      }
      case Warp::Root4Layer:
        return lo + (hi - lo) * layerWarpInverse(t, c);
      case Warp::Root4LayerAngle: {
        const double u = layerWarpInverse(t, c);
        return u <= 0.0 ? lo : lo + (hi - lo) * std::sin(u * (kPi / 2.0));
      }
      case Warp::Root4LayerSplit: {
        const double ys = (split - lo) / (hi - lo), m = 0.5 * ys;
        double y = 0.0;
        if (t <= 0.25) {
          y = m * layerWarpInverse(4.0 * t, c / m);
        } else if (t <= 0.5) {
          y = ys - m * layerWarpInverse(2.0 - 4.0 * t, c / m);
        } else {
          y = ys + (1.0 - ys) * layerWarpInverse(2.0 * t - 1.0, c / (1.0 - ys));
        }
        return lo + (hi - lo) * y;
      }
      case Warp::Root4LayerSplit2: {
        Split2 p;
        split2Breaks(split, c, p);
        double y = 0.0;
        if (t <= kSplit2T0) {
          y = p.m * layerWarpInverse(t / kSplit2T0, p.cm);
        } else if (t <= kSplit2T1) {
          y = p.a - p.m * layerWarpInverse((kSplit2T1 - t) / (kSplit2T1 - kSplit2T0), p.cm);
        } else if (t <= kSplit2T2) {
          y = p.a + p.w * layerWarpInverse((t - kSplit2T1) / (kSplit2T2 - kSplit2T1), p.cw);
        } else if (t <= kSplit2T3) {
          y = p.b - p.w * layerWarpInverse((kSplit2T3 - t) / (kSplit2T3 - kSplit2T2), p.cw);
        } else {
          y = p.b + (1.0 - p.b) * layerWarpInverse((t - kSplit2T3) / (1.0 - kSplit2T3), p.cb);
        }
        return lo + (hi - lo) * y;
      }
      case Warp::Linear:
        return lo + (hi - lo) * t;
      case Warp::Sqrt:
        return lo + (hi - lo) * (t * t);
      case Warp::Square:
        return lo + (hi - lo) * std::sqrt(t);
      case Warp::Log:
        return lo * std::exp(t * std::log(hi / lo));
      case Warp::Root4:
        return lo + (hi - lo) * ((t * t) * (t * t));
      case Warp::Angle:
        return lo + (hi - lo) * std::sin(t * (kPi / 2.0));
      case Warp::Arcsine: {
        const double s = std::sin(t * (kPi / 2.0));
        return lo + (hi - lo) * (s * s);
      }
    }
    return lo;
  }

  /// Continuous node index s = t * (N - 1) in [0, N - 1] of a value x (see
  /// warped() for clamping and NaN). A result within 1e-9 of an integer is
  /// snapped onto it, so texel(node(i)) == i exactly despite the rounding of
  /// the warp round trip, and a lookup at a node returns the stored value bit
  /// for bit. Always 0 on an axis of size 1.
  double texel(double x, double c = 1e-12, double split = 0.5) const noexcept {
    if (size <= 1) return 0.0;
    const double s = warped(x, c, split) * static_cast<double>(size - 1);
    const double nearest = std::floor(s + 0.5);
    return std::fabs(s - nearest) <= kNodeSnap ? nearest : s;
  }

  /// Texture coordinate of x for hardware bilinear filtering of a texture of
  /// `size` texels with texel centres at (i + 0.5) / size:
  /// (0.5 + texel(x)) / size. Lies in [0.5 / N, 1 - 0.5 / N].
  double gpuCoord(double x, double c = 1e-12, double split = 0.5) const noexcept {
    const int n = size > 1 ? size : 1;
    return (0.5 + texel(x, c, split)) / static_cast<double>(n);
  }

  /// The lines of t between the five pieces of a Root4LayerSplit2 axis (see Warp).
  static constexpr double kSplit2T0 = 5.0 / 16.0, kSplit2T1 = 8.0 / 16.0, kSplit2T2 = 10.0 / 16.0,
                          kSplit2T3 = 13.0 / 16.0;

  /// The pieces of a Root4LayerSplit2 axis at one eta: the breaks a <= b in y, m = a / 2,
  /// w = (b - a) / 2, and the layer scales of the pieces (cm = c / m, cw = c / w capped at
  /// 1e12, cb = c / (1 - b)).
  struct Split2 {
    double a = 0.0, b = 0.0, m = 0.0, w = 0.0, cm = 0.0, cw = 0.0, cb = 0.0;
  };

  /// The two breaks of a Root4LayerSplit2 axis at axis 2's value eta (already clamped to axis
  /// 2, LutView::splitAt): x_c = sqrt(1 - eta^2) (0 for eta >= 1) and x_e = eta, each clamped
  /// into [lo + (hi - lo) / 64, hi - (hi - lo) / 64], in y, ordered; and the pieces' scales.
  void split2Breaks(double eta, double c, Split2& p) const noexcept {
    const double q = (1.0 - eta) * (1.0 + eta);
    const double xc = q > 0.0 ? std::sqrt(q) : 0.0;
    const double e = eta == eta ? eta : lo;
    const double lo64 = lo + (hi - lo) / 64.0, hi64 = hi - (hi - lo) / 64.0;
    const double yc = ((xc < lo64 ? lo64 : (xc > hi64 ? hi64 : xc)) - lo) / (hi - lo);
    const double ye = ((e < lo64 ? lo64 : (e > hi64 ? hi64 : e)) - lo) / (hi - lo);
    p.a = yc < ye ? yc : ye;
    p.b = yc < ye ? ye : yc;
    p.m = 0.5 * p.a;
    p.w = 0.5 * (p.b - p.a);
    p.cm = c / p.m;
    p.cw = p.w > 0.0 && c / p.w < 1e12 ? c / p.w : (c > 0.0 ? 1e12 : 0.0);
    p.cb = c / (1.0 - p.b);
  }

 private:
  /// warped() of a Root4LayerSplit2 axis (see Warp): x clamped to [lo, hi], NaN to lo; eta is
  /// axis 2's value.
  double split2Warped(double x, double c, double eta) const noexcept {
    const double xc = !(x > lo) ? lo : (!(x < hi) ? hi : x);
    const double y = (xc - lo) / (hi - lo);
    Split2 p;
    split2Breaks(eta, c, p);
    double t = 0.0;
    if (y <= p.m) {
      t = kSplit2T0 * layerWarpCollapsible(y / p.m, p.cm);
    } else if (y <= p.a) {
      t = kSplit2T1 - (kSplit2T1 - kSplit2T0) * layerWarpCollapsible((p.a - y) / p.m, p.cm);
    } else if (y <= p.a + p.w && p.w > 0.0) {
      t = kSplit2T1 + (kSplit2T2 - kSplit2T1) * layerWarpCollapsible((y - p.a) / p.w, p.cw);
    } else if (y <= p.b && p.w > 0.0) {
      t = kSplit2T3 - (kSplit2T3 - kSplit2T2) * layerWarpCollapsible((p.b - y) / p.w, p.cw);
    } else {
      t = kSplit2T3 + (1.0 - kSplit2T3) * layerWarpCollapsible((y - p.b) / (1.0 - p.b), p.cb);
    }
    if (!(t >= 0.0)) return 0.0;
    return t < 1.0 ? t : 1.0;
  }

  /// warped() of a Root4LayerSplit axis (see Warp): x clamped to [lo, hi], NaN to lo.
  double splitWarped(double x, double c, double split) const noexcept {
    const double xc = !(x > lo) ? lo : (!(x < hi) ? hi : x);
    const double y = (xc - lo) / (hi - lo), ys = (split - lo) / (hi - lo), m = 0.5 * ys;
    double t = 0.0;
    if (y <= m) {
      t = 0.25 * layerWarpCollapsible(y / m, c / m);
    } else if (y <= ys) {
      t = 0.5 - 0.25 * layerWarpCollapsible((ys - y) / m, c / m);
    } else {
      t = 0.5 + 0.5 * layerWarpCollapsible((y - ys) / (1.0 - ys), c / (1.0 - ys));
    }
    if (!(t >= 0.0)) return 0.0;
    return t < 1.0 ? t : 1.0;
  }
};

/// A non-owning view of a table of `dims` (1..3) axes and `channels` float
/// channels, interleaved:
///     data[((i2 * size1 + i1) * size0 + i0) * channels + c]
/// which is an image of width size0 and height size1 * size2 (3D slices
/// stacked vertically; slice i2 occupies rows i2*size1 .. i2*size1 + size1-1;
/// a 1D table is size0 x 1). Axes at index >= dims are ignored (treated as a
/// single node). The view is a literal type: it can be a constexpr value.
struct LutView {
  const float* data = nullptr;
  int channels = 0;
  int dims = 0;
  Axis axis[3] = {};

  /// Number of nodes along axis d (1 for d >= dims).
  int size(int d) const noexcept { return d >= 0 && d < dims && d < 3 ? axis[d].size : 1; }

  /// Number of floats the data array holds: size0 * size1 * size2 * channels.
  std::size_t valueCount() const noexcept {
    return static_cast<std::size_t>(size(0)) * static_cast<std::size_t>(size(1)) *
           static_cast<std::size_t>(size(2)) *
           static_cast<std::size_t>(channels > 0 ? channels : 0);
  }

  /// True when data is set, channels >= 1, dims is 1..3, every used axis is
  /// valid(), and a layer warp (isLayerWarp) sits only on axis 0 of a view of 2+ axes.
  /// sample() and at() return zeros on an invalid view.
  bool valid() const noexcept {
    if (data == nullptr || channels < 1 || dims < 1 || dims > 3) return false;
    for (int d = 0; d < dims; ++d) {
      if (!axis[d].valid()) return false;
      if (isLayerWarp(axis[d].warp) && (d != 0 || dims < 2)) return false;
      if (readsAxis2(axis[d].warp, axis[d].hasConstantSplit()) && dims != 3) return false;
    }
    return true;
  }

  /// The split point of axis 0 at the point x: for a Root4LayerSplit axis 0 its constant
  /// split, or criticalSplit of axis 2's value when the split is NaN; for a Root4LayerSplit2
  /// axis 0 axis 2's value clamped to that axis (clampedEta), from which it places its two
  /// breaks; 0.5, ignored, otherwise.
  double splitAt(const double* x) const noexcept {
    if (dims == 3 && axis[0].warp == Warp::Root4LayerSplit2)
      return clampedEta(axis[2].lo, axis[2].hi, x[2]);
    if (dims < 2 || axis[0].warp != Warp::Root4LayerSplit) return 0.5;
    if (axis[0].hasConstantSplit()) return axis[0].split;
    if (dims != 3) return 0.5;
    return criticalSplit(axis[0].lo, axis[0].hi, axis[2].lo, axis[2].hi, x[2]);
  }

  /// The layer scale of axis 0 at the point x (layerScaleFor; 1e-12 when axis 0
  /// has no layer warp).
  double layerScaleAt(const double* x) const noexcept {
    if (dims < 2) return 1e-12;
    return layerScaleFor(axis[0].warp, axis[1].lo, axis[1].hi, x[1]);
  }

  /// Stored value of channel c at node (i0, i1, i2). Indices are clamped to
  /// the grid (unused axes to 0), so any input is safe.
  float at(int i0, int i1, int i2, int c) const noexcept {
    if (!valid()) return 0.0f;
    return data[offset(clampIndex(i0, size(0)), clampIndex(i1, size(1)), clampIndex(i2, size(2))) +
                static_cast<std::size_t>(clampIndex(c, channels))];
  }

  /// Interpolates every channel at the point x (dims values, in axis order,
  /// in axis units; each is clamped to its axis, NaN maps to lo) and writes
  /// `channels` floats to out: the reference lookup, in double (LutSampler::sampleDouble: the
  /// baker measures the tables' lookup errors with it); at a node the stored value is returned
  /// bit for bit. Writes zeros when the view is not valid().
  /// Builds a LutSampler (validating the view) and samples through it; to look up many
  /// points, build the LutSampler once.
  void sample(const double* x, float* out, Filter filter = Filter::Linear) const noexcept;

 private:
  static int clampIndex(int i, int n) noexcept { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

  /// Offset of channel 0 of node (i0, i1, i2) in data.
  std::size_t offset(int i0, int i1, int i2) const noexcept {
    const std::size_t n0 = static_cast<std::size_t>(size(0));
    const std::size_t n1 = static_cast<std::size_t>(size(1));
    return ((static_cast<std::size_t>(i2) * n1 + static_cast<std::size_t>(i1)) * n0 +
            static_cast<std::size_t>(i0)) *
           static_cast<std::size_t>(channels);
  }
};

/// A LutView prepared for many lookups: it validates the view once and holds, per axis, the
/// constants a lookup needs (node count, lo, hi - lo, its inverse when that division is exact
/// as a product, the node stride), so a lookup is a few flops per axis and 2^dims (linear) or up
/// to 4^dims (cubic) loads per channel, with no validation, no allocation, no exception and no
/// global state. It copies the view (not the data: the data must outlive the sampler).
///
/// Two paths; sample() and the batch call take the float path wherever it applies and give the
/// same floats for a point, sampleDouble() and LutView::sample (which calls it) the double path:
///  - The float path (floatPath()): a linear lookup on a table whose axes all have the linear,
///    sqrt or root4 warp, or root4-layer on axis 0 (ggx-dfg and most of the catalogue), and
///    whose texels are finite and at most detail::kFloatPathMaxValue in magnitude. Warps,
///    cells and interpolation in float (kiln/lut_float_path.h), branch-free but for the choice
///    of warp. A texel coordinate within detail::kFloatNodeSnap (N - 1) of a node is snapped
///    onto it, so a lookup at a node returns the stored float bit for bit; elsewhere a result
///    is within  sum_d 2 kFloatNodeSnap (N_d - 1) G_d + kFloatLerpUlps ulp(V)  of the double
///    lookup below (G_d: the largest difference of neighbouring texels along axis d, V: the
///    largest |texel|). A table's declared lookup error is that of the double path.
///  - The double path (every other lookup): the texel coordinates of Axis::texel (snapped onto
///    nodes within kNodeSnap), double weights, summed in the order of the nodes in memory.
/// A const sampler may be used from any number of threads at once.
class LutSampler {
 public:
  /// An invalid sampler: every lookup writes zeros (of no channel).
  LutSampler() noexcept = default;

  /// Prepares `view`; valid() is view.valid().
  explicit LutSampler(const LutView& view) noexcept : LutSampler(view, true) {}

 private:
  friend struct LutView;

  /// Prepares `view`, and its float path only when `floatPath` (LutView::sample, which takes
  /// the double path, skips the scan of the texels it needs).
  LutSampler(const LutView& view, bool floatPath) noexcept : view_(view), valid_(view.valid()) {
    if (!valid_) return;
    std::size_t stride = static_cast<std::size_t>(view.channels);
    for (int d = 0; d < 3; ++d) {
      Prepared& p = axis_[d];
      const int n = view.size(d);
      p.n = n;
      p.last = static_cast<double>(n - 1);
      p.stride = stride;
      p.step = n > 1 ? stride : 0;
      stride *= static_cast<std::size_t>(n);
      if (d >= view.dims) continue;
      const Axis& a = view.axis[d];
      p.warp = a.warp;
      p.lo = a.lo;
      p.hi = a.hi;
      p.range = a.hi - a.lo;
      p.invRange = 1.0 / p.range;
      // Multiplying by 1 / range gives the quotient bit for bit when range is a power of two
      // (its inverse is then exact): the common [0, 1] axes.
      int e = 0;
      p.exactInverse = std::frexp(p.range, &e) == 0.5 && p.invRange * p.range == 1.0 &&
                       std::isnormal(p.invRange);
    }
    coupled_ = view.dims >= 2 && isLayerWarp(view.axis[0].warp);
    split_ = coupled_ && (view.axis[0].warp == Warp::Root4LayerSplit ||
                          view.axis[0].warp == Warp::Root4LayerSplit2);
    if (floatPath && prepareFloatPath(view) &&
        detail::floatPathValues(view.data, view.valueCount())) {
      floatLayer_ = coupled_;
      floatLinear_ = floatLinearFor(view.dims, view.channels);
      if (floatLayer_ && float_[1].warp == detail::FloatWarp::Sqrt) {
        floatLinear_ = floatLayerSqrtFor(view.dims, view.channels);
        floatPair_ = detail::floatAxisPair(float_[0], float_[1], axis_[1].lo, axis_[1].hi);
        floatLayerSqrt2_ = view.dims == 2 && view.channels == 2;
      }
    }
  }

 public:
  /// True when the view it was built from is valid() (LutView::valid).
  bool valid() const noexcept { return valid_; }

  /// True when linear lookups take the float path (see the class comment): every axis has the
  /// linear, sqrt or root4 warp, or axis 0 root4-layer, and every texel is finite and at most
  /// detail::kFloatPathMaxValue in magnitude.
  bool floatPath() const noexcept { return floatLinear_ != nullptr; }

  /// The view it samples.
  const LutView& view() const noexcept { return view_; }

  /// Interpolates every channel at the point x (view().dims values in axis order, in axis
  /// units; each is clamped to its axis, NaN maps to lo) and writes view().channels floats to
  /// out: LutView::sample's contract and results. Zeros when the sampler is not valid().
  void sample(const double* x, float* out, Filter filter = Filter::Linear) const noexcept {
    if (floatLayerSqrt2_ && filter == Filter::Linear) {
      floatLayerSqrt<2, 2>(x, out);  // the catalogue's common form, inlined
      return;
    }
    if (floatLinear_ != nullptr && filter == Filter::Linear) {
      (this->*floatLinear_)(x, out);
      return;
    }
    if (!valid_) {
      for (int c = 0; c < view_.channels; ++c) out[c] = 0.0f;
      return;
    }
    sampleValid(x, out, filter, true);
  }

  /// The double path for every lookup (see the class comment), the float path never: the
  /// reference LutView::sample gives and the baker's lookup errors are measured with.
  void sampleDouble(const double* x, float* out, Filter filter = Filter::Linear) const noexcept {
    if (!valid_) {
      for (int c = 0; c < view_.channels; ++c) out[c] = 0.0f;
      return;
    }
    sampleValid(x, out, filter, false);
  }

  /// Batch lookup of `count` points. Layout: point k is xs[k * dims .. k * dims + dims - 1]
  /// (dims = view().dims values per point, packed, in axis order) and its channels go to
  /// out[k * channels .. k * channels + channels - 1] (channels = view().channels), the
  /// interleaved layout of the table's own data. Each point gives what sample(x, out, filter)
  /// gives; zeros for every point when the sampler is not valid().
  void sample(const double* xs, std::size_t count, float* out,
              Filter filter = Filter::Linear) const noexcept {
    const std::size_t nc = static_cast<std::size_t>(view_.channels > 0 ? view_.channels : 0);
    if (!valid_) {
      for (std::size_t i = 0; i < count * nc; ++i) out[i] = 0.0f;
      return;
    }
    if (view_.dims == 1) {
      sampleBatch<1>(xs, count, out, filter);
    } else if (view_.dims == 2) {
      sampleBatch<2>(xs, count, out, filter);
    } else {
      sampleBatch<3>(xs, count, out, filter);
    }
  }

 private:
  /// Per-axis constants of a lookup (axes at d >= dims: one node, step 0).
  struct Prepared {
    double lo = 0.0, hi = 1.0, range = 1.0, invRange = 1.0, last = 0.0;
    std::size_t stride = 0;  ///< floats between neighbouring nodes
    std::size_t step = 0;    ///< stride, or 0 on an axis of one node
    int n = 1;
    Warp warp = Warp::Linear;
    bool exactInverse = false;
  };

  /// Sets the float path's constants (float_) of every axis; true when every axis of the view
  /// has a warp the float path computes (linear, sqrt, root4; root4-layer on axis 0).
  bool prepareFloatPath(const LutView& view) noexcept {
    for (int d = 0; d < 3; ++d) {
      detail::FloatAxis& f = float_[d];
      const Prepared& p = axis_[d];
      f.stride = p.stride;
      f.last = static_cast<float>(p.n - 1);
      f.snap = detail::kFloatNodeSnap * f.last;
      if (d >= view.dims) continue;
      f.lo = p.lo;
      f.invRange = p.invRange;
      if (p.warp == Warp::Linear) {
        f.warp = detail::FloatWarp::Linear;
      } else if (p.warp == Warp::Sqrt) {
        f.warp = detail::FloatWarp::Sqrt;
      } else if (p.warp == Warp::Root4) {
        f.warp = detail::FloatWarp::Root4;
      } else if (p.warp == Warp::Root4Layer && d == 0) {
        f.warp = detail::FloatWarp::Root4Layer;
      } else {
        return false;
      }
    }
    return true;
  }

  /// The float path's interpolation of C channels (C = 0: the view's) from the cells of the
  /// D axes: detail::floatLerp along axis 0, then 1, then 2.
  template <int D, int C>
  KILN_INLINE void floatTaps(const detail::FloatCell& k0, const detail::FloatCell& k1,
                             const detail::FloatCell& k2, float* out) const noexcept {
    using detail::floatLerp;
    const std::size_t s0 = k0.step, s1 = k1.step;
    const float* p = view_.data + (k0.offset + k1.offset + k2.offset);
    const float* q = p + k2.step;
    const float f0 = k0.f, f1 = k1.f, f2 = k2.f;
    if (C == 2) {
      detail::floatTaps2<D>(p, s0, s1, k2.step, f0, f1, f2, out);
      return;
    }
    const int nc = C > 0 ? C : view_.channels;
    for (int ch = 0; ch < nc; ++ch) {
      float v = floatLerp(p[ch], p[s0 + ch], f0);
      if (D >= 2) v = floatLerp(v, floatLerp(p[s1 + ch], p[s1 + s0 + ch], f0), f1);
      if (D >= 3) {
        const float w = floatLerp(floatLerp(q[ch], q[s0 + ch], f0),
                                  floatLerp(q[s1 + ch], q[s1 + s0 + ch], f0), f1);
        v = floatLerp(v, w, f2);
      }
      out[ch] = v;
    }
  }

  /// Axis 0's root4-layer scale at the point x, from axis 1 (0 when axis 0 has another warp).
  KILN_INLINE float floatLayerScaleAt(const double* x) const noexcept {
    return floatLayer_ ? detail::floatLayerScale(axis_[1].lo, axis_[1].hi, x[1]) : 0.0f;
  }

  /// The float path's linear lookup on a table of D axes and C channels (C = 0: any number):
  /// warps, cells and interpolation in float (kiln/lut_float_path.h), axis 0's layer scale
  /// from axis 1 (detail::floatLayerScale) when it has the root4-layer warp. Scalar code, no
  /// arrays: the cells stay in registers.
  template <int D, int C>
  KILN_INLINE void floatLinear(const double* x, float* out) const noexcept {
    using detail::floatCellAt;
    const float c = floatLayerScaleAt(x);
    const detail::FloatCell k0 = floatCellAt(float_[0], x[0], c);
    const detail::FloatCell k1 = D >= 2 ? floatCellAt(float_[1], x[1], c) : detail::FloatCell{};
    const detail::FloatCell k2 = D >= 3 ? floatCellAt(float_[2], x[2], c) : detail::FloatCell{};
    floatTaps<D, C>(k0, k1, k2, out);
  }

  /// floatLinear<D, C> on a table whose axis 0 has the root4-layer warp and axis 1 the sqrt
  /// warp (the catalogue's common form), the same floats: the cells of axes 0 and 1 at once
  /// (detail::floatCellsLayerSqrt), no choice of warp.
  template <int D, int C>
  KILN_INLINE void floatLayerSqrt(const double* x, float* out) const noexcept {
    detail::FloatCell k0, k1, k2;
    detail::floatCellsLayerSqrt(floatPair_, x, k0, k1);
    if (D >= 3) k2 = detail::floatCellAt(float_[2], x[2], 0.0f);  // c: read by axis 0 only
    floatTaps<D, C>(k0, k1, k2, out);
  }

  /// The float path's batch call: on a table with a root4-layer axis 0 and a sqrt axis 1, one
  /// point after the other through floatLayerSqrt; on another table with a root4-layer axis 0,
  /// 4 points at a time, their cells axis by axis (detail::floatCells4: 4 lanes of SSE2 where
  /// available), then their taps; the other points (and every point of other tables) one by
  /// one. The same floats as floatLinear for every point.
  template <int D, int C>
  void floatBatch(const double* xs, std::size_t count, float* out) const noexcept {
    const std::size_t nc = static_cast<std::size_t>(C > 0 ? C : view_.channels);
    std::size_t k = 0;
    if (floatLayer_ && float_[1].warp == detail::FloatWarp::Sqrt) {
      for (; k < count; ++k) floatLayerSqrt<D, C>(xs + k * D, out + k * nc);
      return;
    }
    // Without a root4-layer axis the warps are cheap: one point after the other is faster.
    for (; floatLayer_ && k + 4 <= count; k += 4) {
      const double* x = xs + k * D;
      float c[4];
      for (int j = 0; j < 4; ++j) c[j] = floatLayerScaleAt(x + j * D);
      detail::FloatCell cells[3][4];
      for (int d = 0; d < D; ++d) detail::floatCells4(float_[d], x + d, D, c, cells[d]);
      for (int j = 0; j < 4; ++j)
        floatTaps<D, C>(cells[0][j], D >= 2 ? cells[1][j] : detail::FloatCell{},
                        D >= 3 ? cells[2][j] : detail::FloatCell{}, out + (k + j) * nc);
    }
    for (; k < count; ++k) floatLinear<D, C>(xs + k * D, out + k * nc);
  }

  /// A float-path lookup of one point (floatLinear<D, C>).
  using FloatLookup = void (LutSampler::*)(const double*, float*) const noexcept;

  /// floatLinear<D, C> for a table of `dims` axes and `channels` channels (1 and 2 unrolled).
  static FloatLookup floatLinearFor(int dims, int channels) noexcept {
    static constexpr FloatLookup kByShape[3][3] = {
        {&LutSampler::floatLinear<1, 0>, &LutSampler::floatLinear<1, 1>,
         &LutSampler::floatLinear<1, 2>},
        {&LutSampler::floatLinear<2, 0>, &LutSampler::floatLinear<2, 1>,
         &LutSampler::floatLinear<2, 2>},
        {&LutSampler::floatLinear<3, 0>, &LutSampler::floatLinear<3, 1>,
         &LutSampler::floatLinear<3, 2>}};
    return kByShape[dims - 1][channels <= 2 ? channels : 0];
  }

  /// floatLayerSqrt<D, C> for a table of `dims` (2 or 3) axes and `channels` channels.
  static FloatLookup floatLayerSqrtFor(int dims, int channels) noexcept {
    static constexpr FloatLookup kByShape[2][3] = {
        {&LutSampler::floatLayerSqrt<2, 0>, &LutSampler::floatLayerSqrt<2, 1>,
         &LutSampler::floatLayerSqrt<2, 2>},
        {&LutSampler::floatLayerSqrt<3, 0>, &LutSampler::floatLayerSqrt<3, 1>,
         &LutSampler::floatLayerSqrt<3, 2>}};
    return kByShape[dims - 2][channels <= 2 ? channels : 0];
  }

  /// A lookup on a valid sampler: the float path where it applies and `floatPath` allows it,
  /// the double path otherwise.
  void sampleValid(const double* x, float* out, Filter filter, bool floatPath) const noexcept {
    const bool cubic = filter == Filter::Cubic;
    if (floatPath && floatLinear_ != nullptr && !cubic) {
      (this->*floatLinear_)(x, out);
      return;
    }
    if (view_.dims == 1) {
      cubic ? sampleCubic<1>(x, out) : sampleLinear<1>(x, out);
    } else if (view_.dims == 2) {
      cubic ? sampleCubic<2>(x, out) : sampleLinear<2>(x, out);
    } else {
      cubic ? sampleCubic<3>(x, out) : sampleLinear<3>(x, out);
    }
  }

  /// Axis::warped of x on axis d (c and split: axis 0's layer scale and split point), with
  /// (x - lo) / (hi - lo) taken from the prepared constants (the same double) for the common
  /// warps; the others call Axis::warped out of line.
  KILN_INLINE double warpedOf(int d, double x, double c, double split) const noexcept {
    const Prepared& p = axis_[d];
    const bool layer = p.warp == Warp::Root4Layer;
    if (p.warp != Warp::Linear && p.warp != Warp::Sqrt && p.warp != Warp::Root4 && !layer)
      return otherWarped(d, x, c, split);
    const bool collapsed = layer && c == 0.0;
    if (!(x > p.lo)) return collapsed ? 0.5 : 0.0;  // also catches NaN
    if (!(x < p.hi)) return 1.0;
    const double y = p.exactInverse ? (x - p.lo) * p.invRange : (x - p.lo) / p.range;
    double t = y;
    if (p.warp == Warp::Sqrt) {
      t = std::sqrt(y);
    } else if (p.warp == Warp::Root4) {
      t = std::sqrt(std::sqrt(y));
    } else if (layer) {
      t = collapsed ? 0.5 * (std::sqrt(std::sqrt(y)) + 1.0) : Axis::layerWarp(y, c);
    }
    if (!(t >= 0.0)) return 0.0;
    return t < 1.0 ? t : 1.0;
  }

  /// Axis::warped of the warps warpedOf does not inline.
  KILN_NOINLINE double otherWarped(int d, double x, double c, double split) const noexcept {
    return view_.axis[d].warped(x, c, split);
  }

  /// The cell of axis d at warped coordinate t: node index i in [0, N - 2] (0 when N = 1) and
  /// fraction f in [0, 1], the floor of Axis::texel's s = t (N - 1) (snapped onto an integer
  /// within kNodeSnap) and s - floor, from one truncation: the same numbers as texel().
  KILN_INLINE int cellOf(int d, double t, double& f) const noexcept {
    const Prepared& p = axis_[d];
    f = 0.0;
    if (p.n <= 1) return 0;
    const double s = t * p.last;
    int i = static_cast<int>(s);                     // s >= 0: truncation is floor
    const double frac = s - static_cast<double>(i);  // exact
    if (frac <= kNodeSnap) {
      // snapped down onto node i: f = 0
    } else if ((static_cast<double>(i) + 1.0) - s <= kNodeSnap) {
      ++i;  // snapped up onto node i + 1
    } else {
      f = frac;
    }
    if (i > p.n - 2) {  // s = N - 1: the last cell at f = 1
      f = static_cast<double>(i) - static_cast<double>(p.n - 2);
      i = p.n - 2;
    }
    return i;
  }

  /// The cells (node index, fraction) of the D axes at x: cellOf of Axis::warped, with axis
  /// 0's layer scale and split point at x (LutView::layerScaleAt, splitAt) when it is coupled.
  template <int D>
  KILN_INLINE void cellsAt(const double* x, int* cell, double* frac) const noexcept {
    double c = 1e-12, split = 0.5;
    if (coupled_) {
      c = layerScaleFor(axis_[0].warp, axis_[1].lo, axis_[1].hi, x[1]);
      if (split_) split = view_.splitAt(x);
    }
    for (int d = 0; d < D; ++d) cell[d] = cellOf(d, warpedOf(d, x[d], c, split), frac[d]);
  }

  /// Adds the tap w * v to sum, skipping a zero weight (so a node lookup is the single product
  /// 1 * v, exact even for -0 and beside non-finite texels).
  static KILN_INLINE void addTap(double& sum, double w, float v) noexcept {
    if (w != 0.0) sum = sum + w * static_cast<double>(v);
  }

  /// Multilinear interpolation of D axes from their cells: 2^D taps, summed in the order of the
  /// nodes in memory (axis 2 outermost) with the weights (w2 w1) w0, zero weights skipped.
  /// Scalar code, no arrays: the weights and offsets stay in registers.
  template <int D>
  KILN_INLINE void linearTaps(const int* cell, const double* frac, float* out) const noexcept {
    std::size_t base = 0;
    for (int d = 0; d < D; ++d) base += static_cast<std::size_t>(cell[d]) * axis_[d].stride;
    const float* p = view_.data + base;
    const std::size_t s0 = axis_[0].step, s1 = D >= 2 ? axis_[1].step : 0,
                      s2 = D >= 3 ? axis_[2].step : 0;
    const double a0 = 1.0 - frac[0], b0 = frac[0];
    const double a1 = D >= 2 ? 1.0 - frac[1] : 1.0, b1 = D >= 2 ? frac[1] : 0.0;
    const double a2 = D >= 3 ? 1.0 - frac[2] : 1.0, b2 = D >= 3 ? frac[2] : 0.0;
    const double w00 = D >= 3 ? a2 * a1 : a1, w01 = D >= 3 ? a2 * b1 : b1;
    const double w10 = b2 * a1, w11 = b2 * b1;  // used when D = 3
    const double fmax = static_cast<double>(std::numeric_limits<float>::max());
    for (int c = 0; c < view_.channels; ++c) {
      double sum = -0.0;  // -0 + v == v for every v: the first term is taken as is
      if (D == 1) {
        addTap(sum, a0, p[c]);
        addTap(sum, b0, p[s0 + c]);
      } else {
        addTap(sum, w00 * a0, p[c]);
        addTap(sum, w00 * b0, p[s0 + c]);
        addTap(sum, w01 * a0, p[s1 + c]);
        addTap(sum, w01 * b0, p[s1 + s0 + c]);
        if (D == 3) {
          addTap(sum, w10 * a0, p[s2 + c]);
          addTap(sum, w10 * b0, p[s2 + s0 + c]);
          addTap(sum, w11 * a0, p[s2 + s1 + c]);
          addTap(sum, w11 * b0, p[s2 + s1 + s0 + c]);
        }
      }
      if (sum > fmax) sum = fmax;
      if (sum < -fmax) sum = -fmax;
      out[c] = static_cast<float>(sum);
    }
  }

  /// Multilinear lookup on a table of D axes.
  template <int D>
  void sampleLinear(const double* x, float* out) const noexcept {
    int cell[3];
    double frac[3];
    cellsAt<D>(x, cell, frac);
    linearTaps<D>(cell, frac, out);
  }

  /// Catmull-Rom weights of axis d in cell i at fraction f (see Filter): up to 4 taps,
  /// quadratically extrapolated ghost nodes folded into the real ones; linear when N < 3.
  int cubicAxis(int d, int i, double f, std::size_t* offset, double* weight) const noexcept {
    const Prepared& p = axis_[d];
    const int n = p.n;
    if (n <= 1) {
      offset[0] = 0;
      weight[0] = 1.0;
      return 1;
    }
    if (n < 3) {
      offset[0] = static_cast<std::size_t>(i) * p.stride;
      offset[1] = offset[0] + p.stride;
      weight[0] = 1.0 - f;
      weight[1] = f;
      return 2;
    }
    double wm1 = 0.5 * (((-f + 2.0) * f - 1.0) * f);
    double w0 = 0.5 * ((3.0 * f - 5.0) * f * f + 2.0);
    double w1 = 0.5 * (((-3.0 * f + 4.0) * f + 1.0) * f);
    double w2 = 0.5 * ((f - 1.0) * f * f);
    if (i == 0) {  // p[-1] = 3 p[0] - 3 p[1] + p[2]
      w0 += 3.0 * wm1;
      w1 -= 3.0 * wm1;
      w2 += wm1;
      wm1 = 0.0;
    }
    if (i == n - 2) {  // p[n] = 3 p[n-1] - 3 p[n-2] + p[n-3]
      w1 += 3.0 * w2;
      w0 -= 3.0 * w2;
      wm1 += w2;
      w2 = 0.0;
    }
    const double wts[4] = {wm1, w0, w1, w2};
    int count = 0;
    for (int k = 0; k < 4; ++k) {
      const int j = i - 1 + k;
      if (j < 0 || j > n - 1) continue;
      offset[count] = static_cast<std::size_t>(j) * p.stride;
      weight[count] = wts[k];
      ++count;
    }
    return count;
  }

  /// Per-axis Catmull-Rom (Filter::Cubic) from the cells: up to 4^D taps, summed in the order
  /// and with the weights ((w2 w1) w0) of the linear path, straight from the per-axis stencils.
  template <int D>
  void cubicTaps(const int* cell, const double* frac, float* out) const noexcept {
    std::size_t o[3][4] = {};
    double w[3][4] = {{1.0}, {1.0}, {1.0}};
    int count[3] = {1, 1, 1};
    for (int d = 0; d < D; ++d) count[d] = cubicAxis(d, cell[d], frac[d], o[d], w[d]);
    const double fmax = static_cast<double>(std::numeric_limits<float>::max());
    for (int c = 0; c < view_.channels; ++c) {
      const float* p = view_.data + c;
      double sum = -0.0;  // -0 + v == v for every v: the first term is taken as is
      for (int k2 = 0; k2 < count[2]; ++k2) {
        for (int k1 = 0; k1 < count[1]; ++k1) {
          const double w21 = w[2][k2] * w[1][k1];
          const float* row = p + o[2][k2] + o[1][k1];
          for (int k0 = 0; k0 < count[0]; ++k0) addTap(sum, w21 * w[0][k0], row[o[0][k0]]);
        }
      }
      if (sum > fmax) sum = fmax;
      if (sum < -fmax) sum = -fmax;
      out[c] = static_cast<float>(sum);
    }
  }

  /// Per-axis Catmull-Rom lookup on a table of D axes.
  template <int D>
  void sampleCubic(const double* x, float* out) const noexcept {
    int cell[3];
    double frac[3];
    cellsAt<D>(x, cell, frac);
    cubicTaps<D>(cell, frac, out);
  }

  /// The batch call on a valid sampler, in blocks of kBatchBlock points: the cells of a block
  /// first, then its taps, so the warps of many points are in flight at once.
  template <int D>
  void sampleBatch(const double* xs, std::size_t count, float* out, Filter filter) const noexcept {
    const std::size_t nc = static_cast<std::size_t>(view_.channels);
    if (floatLinear_ != nullptr && filter == Filter::Linear) {
      if (nc == 1) {
        floatBatch<D, 1>(xs, count, out);
      } else if (nc == 2) {
        floatBatch<D, 2>(xs, count, out);
      } else {
        floatBatch<D, 0>(xs, count, out);
      }
      return;
    }
    int cell[kBatchBlock][3];
    double frac[kBatchBlock][3];
    for (std::size_t b = 0; b < count; b += kBatchBlock) {
      const std::size_t m = count - b < kBatchBlock ? count - b : kBatchBlock;
      for (std::size_t k = 0; k < m; ++k) cellsAt<D>(xs + (b + k) * D, cell[k], frac[k]);
      if (filter == Filter::Cubic) {
        for (std::size_t k = 0; k < m; ++k) cubicTaps<D>(cell[k], frac[k], out + (b + k) * nc);
      } else {
        for (std::size_t k = 0; k < m; ++k) linearTaps<D>(cell[k], frac[k], out + (b + k) * nc);
      }
    }
  }

  /// Points per block of the batch call.
  static constexpr std::size_t kBatchBlock = 32;

  LutView view_{};
  Prepared axis_[3] = {};
  bool valid_ = false;
  bool coupled_ = false;  ///< axis 0 has a layer warp (reads axis 1, maybe axis 2)
  bool split_ = false;    ///< axis 0 has a split warp (LutView::splitAt)
  detail::FloatAxis float_[3] = {};
  FloatLookup floatLinear_ = nullptr;  ///< the float path of linear lookups, if it applies
  bool floatLayer_ = false;            ///< ... and axis 0 has the root4-layer warp
  bool floatLayerSqrt2_ = false;       ///< ... and axis 1 sqrt, 2 axes, 2 channels
  detail::FloatAxisPair floatPair_{};  ///< axes 0 and 1 for floatLayerSqrt
};

inline void LutView::sample(const double* x, float* out, Filter filter) const noexcept {
  LutSampler(*this, false).sampleDouble(x, out, filter);
}

}  // namespace kiln
