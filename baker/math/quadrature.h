// Globally adaptive Gauss-Kronrod quadrature (Piessens et al. 1983, QUADPACK qag with the
// 7-point Gauss / 15-point Kronrod pair), for vector-valued integrands, deterministic.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "baker/math/constants.h"

namespace kiln {

template <int N>
using Channels = std::array<double, N>;

/// Nodes (ascending) and weights of the n-point Gauss-Legendre rule on [0, 1]: Newton on P_n
/// from Tricomi's first guess, in double; the weights sum to 1.
inline void GaussLegendre01(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0);
  weights.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(Pi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        double pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[n - 1 - i] = (1 + x) / 2;
    weights[n - 1 - i] = 1 / ((1 - x * x) * dp * dp);  // 2 / ((1 - x^2) P'^2), halved for [0, 1]
  }
}

/// A Gauss-Legendre rule on [0, 1]: nodes x (ascending) and weights w.
struct GaussRule01 {
  std::vector<double> x, w;
};

/// The most nodes CachedGaussLegendre01 keeps.
constexpr int kMaxCachedGaussNodes = 64;

/// The n-point rule of GaussLegendre01, n clamped to [1, kMaxCachedGaussNodes]; all of them are
/// built once, on first use (a function-local static: thread-safe), and shared by the fixed rules.
inline const GaussRule01& CachedGaussLegendre01(int n) {
  static const std::vector<GaussRule01> rules = [] {
    std::vector<GaussRule01> r(kMaxCachedGaussNodes + 1);
    for (int k = 1; k <= kMaxCachedGaussNodes; ++k) GaussLegendre01(k, r[k].x, r[k].w);
    return r;
  }();
  return rules[n < 1 ? 1 : n > kMaxCachedGaussNodes ? kMaxCachedGaussNodes : n];
}

template <std::size_t N>
std::array<double, N>& operator+=(std::array<double, N>& a, const std::array<double, N>& b) {
  for (std::size_t c = 0; c < N; ++c) a[c] += b[c];
  return a;
}
template <std::size_t N>
std::array<double, N> operator*(double s, std::array<double, N> a) {
  for (double& x : a) x *= s;
  return a;
}

namespace gk15 {
// Kronrod abscissae on [-1, 1] (positive half, descending), xgk[1], xgk[3], xgk[5], xgk[7] are the
// 7-point Gauss nodes. Values from QUADPACK dqk15.
constexpr double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                           0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                           0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                           0.207784955007898467600689403773245, 0.0};
constexpr double wgk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                          0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
}  // namespace gk15

/// QUADPACK's rescaling of a panel's error, min(1, r^1.5) for r = 200 |K15 - G7| / spread, as
/// r sqrt(r) (a tenth of pow's time; within an ulp of it); 1 for r >= 1 and for NaN, as
/// std::min(1.0, std::pow(r, 1.5)).
inline double ErrorScale(double r) { return r < 1 ? r * std::sqrt(r) : 1.0; }

/// The 15 nodes of a Gauss-Kronrod panel on [a, b], ascending: x[7] the centre, x[j] and x[14 -
/// j] the centre -+ half-width xgk[j].
inline void GaussKronrod15Nodes(double a, double b, double x[15]) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  x[7] = centre;
  for (int j = 0; j < 7; ++j) {
    x[j] = centre - half * gk15::xgk[j];
    x[14 - j] = centre + half * gk15::xgk[j];
  }
}

/// Whether integrand F evaluates a panel's nodes at once: `f.EvaluateNodes(x, n, out)` writes
/// out[i] = f(x[i]) for i < n (so it must give f's values, whatever lanes it computes them in).
template <class F, int N, class = void>
struct EvaluatesNodes : std::false_type {};
template <class F, int N>
struct EvaluatesNodes<F, N,
                      std::void_t<decltype(std::declval<F&>().EvaluateNodes(
                          std::declval<const double*>(), 0, std::declval<Channels<N>*>()))>>
    : std::true_type {};

/// One Gauss-Kronrod 7-15 panel on [a, b]: the Kronrod estimate and QUADPACK's error estimate
/// (|K15 - G7| rescaled by the integrand's spread, max over channels). An integrand with
/// EvaluateNodes (EvaluatesNodes) gets the panel's 15 nodes in one call.
template <int N, class F>
Channels<N> GaussKronrod15(F& f, double a, double b, double& err) {
  const double half = 0.5 * (b - a);
  double x[15];
  GaussKronrod15Nodes(a, b, x);
  Channels<N> fv[15];
  if constexpr (EvaluatesNodes<F, N>::value) {
    f.EvaluateNodes(x, 15, fv);
  } else {
    for (int j = 0; j < 15; ++j) fv[j] = f(x[j]);
  }
  // Channels innermost (each channel's sums in the order of the scalar rule: the same bits), so
  // that the compiler can take the channels together.
  Channels<N> k, g, kabs, mean, asc;
  for (int c = 0; c < N; ++c) {
    k[c] = gk15::wgk[7] * fv[7][c];
    g[c] = gk15::wg[3] * fv[7][c];
    kabs[c] = std::abs(k[c]);
  }
  for (int j = 0; j < 7; ++j)
    for (int c = 0; c < N; ++c) {
      const double pair = fv[j][c] + fv[14 - j][c];
      k[c] += gk15::wgk[j] * pair;
      kabs[c] += gk15::wgk[j] * (std::abs(fv[j][c]) + std::abs(fv[14 - j][c]));
      if (j % 2 == 1) g[c] += gk15::wg[j / 2] * pair;
    }
  for (int c = 0; c < N; ++c) {
    mean[c] = 0.5 * k[c];
    asc[c] = gk15::wgk[7] * std::abs(fv[7][c] - mean[c]);
  }
  for (int j = 0; j < 7; ++j)
    for (int c = 0; c < N; ++c)
      asc[c] += gk15::wgk[j] * (std::abs(fv[j][c] - mean[c]) + std::abs(fv[14 - j][c] - mean[c]));
  Channels<N> resk{};
  err = 0;
  for (int c = 0; c < N; ++c) {
    double e = std::abs((k[c] - g[c]) * half);
    const double spread = asc[c] * std::abs(half);
    if (spread != 0 && e != 0) e = spread * ErrorScale(200 * e / spread);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    e = std::max(e, 50 * eps * kabs[c] * std::abs(half));
    if (!std::isfinite(e)) e = std::numeric_limits<double>::max();
    err = std::max(err, e);
    resk[c] = k[c] * half;
  }
  return resk;
}

/// A list that keeps its first K elements inline and moves them to the heap (reserving
/// capacityHint) on the K+1st push: IntegrateAdaptive's panels, which most integrals keep few of,
/// without an allocation per call (the inner integral of a nested one is a call per outer node).
template <class T, int K>
class InlineList {
 public:
  explicit InlineList(int capacityHint) : hint_(capacityHint) {}
  InlineList(const InlineList&) = delete;
  InlineList& operator=(const InlineList&) = delete;
  int size() const { return size_; }
  T& operator[](int i) { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  void push_back(const T& v) {
    if (size_ < K) {
      inline_[size_++] = v;
      return;
    }
    if (size_ == K) {
      heap_.reserve(static_cast<size_t>(std::max(hint_, 2 * K)));
      heap_.assign(inline_, inline_ + K);
    }
    heap_.push_back(v);
    data_ = heap_.data();
    ++size_;
  }

 private:
  T inline_[K];
  std::vector<T> heap_;
  T* data_ = inline_;
  int size_ = 0, hint_;
};

/// Panels IntegrateAdaptive keeps inline before it allocates.
constexpr int kInlinePanels = 64;

/// A panel's error and index, ranked for IntegrateAdaptive's choice of the panel to bisect.
struct PanelRank {
  double err;
  int index;
};

/// Heap order of PanelRank: a ranks below b when its error is smaller, or equal with a later
/// index; the top is the first panel of the largest error (errors are never NaN: GaussKronrod15).
struct LessWorst {
  bool operator()(const PanelRank& a, const PanelRank& b) const {
    return a.err < b.err || (a.err == b.err && a.index > b.index);
  }
};

/// Integral of f over [breaks[0], breaks[n-1]] (breaks ascending; each gap is a first panel),
/// bisecting the panel with the largest error until the summed error estimate is below absTol
/// or maxPanels is reached. errOut (optional) receives the summed estimate; capped (optional) is
/// set to true when it stopped with the estimate above absTol (at maxPanels, or at the resolution
/// of double), and left alone otherwise.
template <int N, class F>
Channels<N> IntegrateAdaptive(F&& f, const double* breaks, int n, double absTol,
                              int maxPanels = 200, double* errOut = nullptr,
                              bool* capped = nullptr) {
  struct Panel {
    double a, b;
    Channels<N> value;
    double err;
  };
  InlineList<Panel, kInlinePanels> panels(maxPanels + n);
  double total = 0;
  for (int i = 0; i + 1 < n; ++i) {
    if (!(breaks[i + 1] > breaks[i])) continue;
    Panel p{breaks[i], breaks[i + 1], {}, 0};
    p.value = GaussKronrod15<N>(f, p.a, p.b, p.err);
    total += p.err;
    panels.push_back(p);
  }
  // The worst panel is the first of the largest error (a linear scan's choice), kept on top of a
  // heap of (err, index): a bisection costs log(panels), not a scan of them all.
  InlineList<PanelRank, kInlinePanels> heap(maxPanels + n);
  for (int i = 0; i < panels.size(); ++i) heap.push_back({panels[i].err, i});
  std::make_heap(heap.begin(), heap.end(), LessWorst());
  while (total > absTol && panels.size() < maxPanels && heap.size() > 0) {
    const int worst = heap[0].index;
    Panel& w = panels[worst];
    double mid = 0.5 * (w.a + w.b);
    if (!(mid > w.a && mid < w.b)) break;  // panel at the resolution of double
    Panel left{w.a, mid, {}, 0}, right{mid, w.b, {}, 0};
    left.value = GaussKronrod15<N>(f, left.a, left.b, left.err);
    right.value = GaussKronrod15<N>(f, right.a, right.b, right.err);
    total += left.err + right.err - w.err;
    panels[worst] = left;
    panels.push_back(right);
    std::pop_heap(heap.begin(), heap.end(), LessWorst());
    heap[heap.size() - 1] = {left.err, worst};
    std::push_heap(heap.begin(), heap.end(), LessWorst());
    heap.push_back({right.err, panels.size() - 1});
    std::push_heap(heap.begin(), heap.end(), LessWorst());
  }
  Channels<N> sum{};
  double errSum = 0;
  for (int i = 0; i < panels.size(); ++i) {
    sum += panels[i].value;
    errSum += panels[i].err;
  }
  if (errOut) *errOut = errSum;
  if (capped && total > absTol) *capped = true;
  return sum;
}

}  // namespace kiln
