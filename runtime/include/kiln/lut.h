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
    return std::fabs(s - nearest) <= 1e-9 ? nearest : s;
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
  /// `channels` floats to out. The interpolation runs in double on the
  /// stored floats; at a node the stored value is returned bit for bit.
  /// Writes zeros when the view is not valid().
  void sample(const double* x, float* out, Filter filter = Filter::Linear) const noexcept {
    if (!valid()) {
      for (int c = 0; c < channels; ++c) out[c] = 0.0f;
      return;
    }
    Stencil stencil[3];
    const double c = layerScaleAt(x), split = splitAt(x);
    for (int d = 0; d < 3; ++d) {
      if (d < dims) stencil[d] = makeStencil(axis[d], x[d], filter, c, split);
    }
    for (int c = 0; c < channels; ++c) {
      double sum = 0.0;
      bool started = false;
      for (int k2 = 0; k2 < stencil[2].count; ++k2) {
        for (int k1 = 0; k1 < stencil[1].count; ++k1) {
          const double w21 = stencil[2].weight[k2] * stencil[1].weight[k1];
          if (w21 == 0.0) continue;
          const std::size_t row = offset(0, stencil[1].index[k1], stencil[2].index[k2]);
          for (int k0 = 0; k0 < stencil[0].count; ++k0) {
            const double w = w21 * stencil[0].weight[k0];
            // Zero weights are skipped so a node lookup is a single
            // product 1 * v (exact, even for -0).
            if (w == 0.0) continue;
            const double v =
                static_cast<double>(data[row +
                                         static_cast<std::size_t>(stencil[0].index[k0]) *
                                             static_cast<std::size_t>(channels) +
                                         static_cast<std::size_t>(c)]);
            sum = started ? sum + w * v : w * v;
            started = true;
          }
        }
      }
      // A cubic may overshoot its nodes; near the largest float that would round to
      // infinity, so the result saturates at the largest finite float instead.
      const double fmax = static_cast<double>(std::numeric_limits<float>::max());
      if (sum > fmax) sum = fmax;
      if (sum < -fmax) sum = -fmax;
      out[c] = static_cast<float>(sum);
    }
  }

 private:
  /// Nodes and weights one axis contributes to a lookup (at most 4).
  struct Stencil {
    int index[4] = {0, 0, 0, 0};
    double weight[4] = {1.0, 0.0, 0.0, 0.0};
    int count = 1;
  };

  static int clampIndex(int i, int n) noexcept { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

  /// Offset of channel 0 of node (i0, i1, i2) in data.
  std::size_t offset(int i0, int i1, int i2) const noexcept {
    const std::size_t n0 = static_cast<std::size_t>(size(0));
    const std::size_t n1 = static_cast<std::size_t>(size(1));
    return ((static_cast<std::size_t>(i2) * n1 + static_cast<std::size_t>(i1)) * n0 +
            static_cast<std::size_t>(i0)) *
           static_cast<std::size_t>(channels);
  }

  static Stencil makeStencil(const Axis& a, double x, Filter filter, double c,
                             double split) noexcept {
    Stencil st;
    const int n = a.size;
    if (n <= 1) return st;  // single node, weight 1
    const double s = a.texel(x, c, split);
    int i = static_cast<int>(std::floor(s));
    if (i > n - 2) i = n - 2;
    if (i < 0) i = 0;
    const double f = s - static_cast<double>(i);
    if (filter == Filter::Linear || n < 3) {
      st.count = 2;
      st.index[0] = i;
      st.index[1] = i + 1;
      st.weight[0] = 1.0 - f;
      st.weight[1] = f;
      return st;
    }
    // Catmull-Rom weights for nodes i-1, i, i+1, i+2. Exactly (0, 1, 0, 0)
    // at f = 0 and (0, 0, 1, 0) at f = 1.
    double wm1 = 0.5 * (((-f + 2.0) * f - 1.0) * f);
    double w0 = 0.5 * ((3.0 * f - 5.0) * f * f + 2.0);
    double w1 = 0.5 * (((-3.0 * f + 4.0) * f + 1.0) * f);
    double w2 = 0.5 * ((f - 1.0) * f * f);
    // Fold the quadratically extrapolated ghost nodes into the real ones (n >= 3 here), so
    // that quadratics are reproduced exactly in the edge cells too.
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
    st.count = 0;
    const int idx[4] = {i - 1, i, i + 1, i + 2};
    const double wts[4] = {wm1, w0, w1, w2};
    for (int k = 0; k < 4; ++k) {
      if (idx[k] < 0 || idx[k] > n - 1) continue;
      st.index[st.count] = idx[k];
      st.weight[st.count] = wts[k];
      ++st.count;
    }
    return st;
  }
};

}  // namespace kiln
