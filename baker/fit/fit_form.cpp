#include "baker/fit/fit_form.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kiln {

namespace {
/// The most coefficients per axis the evaluators keep on the stack.
constexpr int kMaxDegree = 31;

/// The smallest scale c of the Layer warp: kiln's smallest alpha (models/roughness.h MinAlpha),
/// below which the lobes' grazing layer keeps its width.
constexpr float kLayerFloor = 1e-12f;
/// The LayerEta warp's smallest scale: sqrt(eta^2 - 1) at the float just above 1 (fit.h
/// kEtaLayerFloor).
constexpr float kEtaLayerScaleF = 4.8828137e-4f;
/// Bisection steps inverting the Layer warp (double).
constexpr int kLayerBisections = 200;

/// The layer warp's scale c at axis 1's clamped value r, in float (the emitted code's steps).
float LayerScaleFloat(FitWarp warp, float r) {
  if (warp == FitWarp::LayerEta)
    return std::max(std::sqrt(std::abs(r * r - 1.0f)), kEtaLayerScaleF);
  return std::max(r * r, kLayerFloor);
}

/// x clamped to the axis, in float.
float ClampedFloat(const FitAxis& axis, float x) {
  return std::min(std::max(x, static_cast<float>(axis.lo)), static_cast<float>(axis.hi));
}

/// The warped coordinate s in [-1, 1] of the clamped value v on `axis`, in float (the emitted
/// code's steps); r: axis 1's clamped value (Layer only).
float WarpedFloat(const FitAxis& axis, float v, float r) {
  const float lo = static_cast<float>(axis.lo);
  const float inv = static_cast<float>(1.0 / (axis.hi - axis.lo));
  float u = (v - lo) * inv;
  if (axis.warp == FitWarp::Sqrt) u = std::sqrt(u);
  if (axis.warp == FitWarp::Root4) u = std::sqrt(std::sqrt(u));
  if (IsLayerWarp(axis.warp)) {
    const float c = LayerScaleFloat(axis.warp, r);
    u = (std::sqrt(std::sqrt(u)) + u * (1.0f + c) / (u + c)) * 0.5f;
  }
  return u * 2.0f - 1.0f;
}

/// The double form of WarpedFloat's warp: w in [0, 1] of u in [0, 1].
double WarpDouble(FitWarp warp, double u, double r) {
  if (warp == FitWarp::Sqrt) return std::sqrt(u);
  if (warp == FitWarp::Root4) return std::sqrt(std::sqrt(u));
  if (IsLayerWarp(warp)) {
    const double c = warp == FitWarp::LayerEta ? std::max(std::sqrt(std::abs(r * r - 1)),
                                                          static_cast<double>(kEtaLayerScaleF))
                                               : std::max(r * r, static_cast<double>(kLayerFloor));
    return 0.5 * (std::sqrt(std::sqrt(u)) + u * (1 + c) / (u + c));
  }
  return u;
}

/// The Power form's t of the clamped value v, in float (the emitted code's steps).
float PowerVariableFloat(const FitAxis& axis, float v) {
  float t = PowerSubtractsLo(axis) ? v - static_cast<float>(axis.lo) : v;
  if (axis.warp == FitWarp::Sqrt) t = std::sqrt(t);
  if (axis.warp == FitWarp::Root4) t = std::sqrt(std::sqrt(t));
  return t;
}

/// A one-axis Power form's channels: Horner's rule from the highest coefficient down.
void EvaluatePower(const FitForm& form, const float* x, float* out) {
  const float t = PowerVariableFloat(form.axes[0], ClampedFloat(form.axes[0], x[0]));
  const int n = form.axes[0].degree + 1;
  const float* c = form.coefficients.data();
  for (size_t ch = 0; ch < form.channels.size(); ++ch, c += n) {
    float p = c[n - 1];
    for (int k = n - 2; k >= 0; --k) p = c[k] + t * p;
    out[ch] = p;
  }
}

/// T_0..T_degree at s, in float, by the recurrence the emitted code runs.
void ChebyshevFloat(float s, int degree, float* t) {
  t[0] = 1.0f;
  if (degree >= 1) t[1] = s;
  const float s2 = s + s;
  for (int k = 2; k <= degree; ++k) t[k] = s2 * t[k - 1] - t[k - 2];
}
}  // namespace

const char* FitWarpName(FitWarp w) {
  switch (w) {
    case FitWarp::Linear:
      return "linear";
    case FitWarp::Sqrt:
      return "sqrt";
    case FitWarp::Root4:
      return "root4";
    case FitWarp::Layer:
      return "layer";
    case FitWarp::LayerEta:
      return "layer-eta";
  }
  return "linear";
}

FitWarp FitWarpFromName(const std::string& name) {
  for (FitWarp w :
       {FitWarp::Linear, FitWarp::Sqrt, FitWarp::Root4, FitWarp::Layer, FitWarp::LayerEta})
    if (name == FitWarpName(w)) return w;
  throw std::invalid_argument("unknown fit warp '" + name +
                              "' (linear, sqrt, root4, layer, layer-eta)");
}

const char* FitBasisName(FitBasis b) { return b == FitBasis::Power ? "horner" : "chebyshev"; }

FitBasis FitBasisFromName(const std::string& name) {
  if (name == "chebyshev") return FitBasis::Chebyshev;
  if (name == "horner") return FitBasis::Power;
  throw std::invalid_argument("unknown fit form '" + name + "' (chebyshev, horner)");
}

double PowerVariable(const FitAxis& axis, double v) {
  const double t = PowerSubtractsLo(axis) ? v - axis.lo : v;
  return WarpDouble(axis.warp, t, 0);
}

int FitForm::TermsPerChannel() const {
  int n = 1;
  for (const FitAxis& a : axes) n *= a.degree + 1;
  return n;
}

int FitForm::SqrtCount() const {
  int n = 0;
  for (const FitAxis& a : axes)
    n += a.warp == FitWarp::Sqrt       ? 1
         : a.warp == FitWarp::Linear   ? 0
         : a.warp == FitWarp::LayerEta ? 3  // root4 and sqrt(|eta^2 - 1|)
                                       : 2;
  return n;
}

int FitForm::OperationCount() const {
  int ops = SqrtCount();
  if (basis == FitBasis::Power) {
    const int nc = static_cast<int>(channels.size());
    return ops + 2 + (PowerSubtractsLo(axes[0]) ? 1 : 0) + nc * 2 * axes[0].degree;
  }
  for (const FitAxis& a : axes) {
    ops += 2 + 2 + 2;                            // clamp, normalise, s = 2 w - 1
    if (a.warp == FitWarp::Layer) ops += 8;      // r r, max, u + c, 1 + c, mul, div, add, half
    if (a.warp == FitWarp::LayerEta) ops += 10;  // the same and - 1, abs
    if (a.degree >= 2) ops += 1 + 2 * (a.degree - 1);  // s + s, then a multiply-subtract each
  }
  const int nc = static_cast<int>(channels.size());
  if (axes.size() == 1) return ops + nc * 2 * (axes[0].degree + 1);
  const int n0 = axes[0].degree + 1, n1 = axes[1].degree + 1;
  return ops + nc * (2 * n0 * n1 + 2 * n0);
}

void WarpedCoordinates(const FitForm& form, const double* x, double* s) {
  const size_t dims = form.axes.size();
  double v[2];
  for (size_t d = 0; d < dims; ++d)
    v[d] = std::min(std::max(x[d], form.axes[d].lo), form.axes[d].hi);
  for (size_t d = 0; d < dims; ++d) {
    const FitAxis& a = form.axes[d];
    s[d] = 2 * WarpDouble(a.warp, (v[d] - a.lo) / (a.hi - a.lo), dims == 2 ? v[1] : 0) - 1;
  }
}

void PointAtWarped(const FitForm& form, const double* s, double* x) {
  const size_t dims = form.axes.size();
  for (size_t k = dims; k-- > 0;) {
    const FitAxis& a = form.axes[k];
    const double w = std::min(std::max(0.5 * (s[k] + 1), 0.0), 1.0);
    double u = w;
    if (a.warp == FitWarp::Sqrt) u = w * w;
    if (a.warp == FitWarp::Root4) u = (w * w) * (w * w);
    if (IsLayerWarp(a.warp)) {
      double lo = 0, hi = 1;  // the warp increases in u
      for (int i = 0; i < kLayerBisections && hi > lo; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (WarpDouble(a.warp, mid, dims == 2 ? x[1] : 0) < w ? lo : hi) = mid;
      }
      u = w <= 0 ? 0 : w >= 1 ? 1 : hi;
    }
    x[k] = std::min(std::max(a.lo + u * (a.hi - a.lo), a.lo), a.hi);
  }
}

void ChebyshevRow(int degree, double s, double* t) {
  t[0] = 1;
  if (degree >= 1) t[1] = s;
  for (int k = 2; k <= degree; ++k) t[k] = 2 * s * t[k - 1] - t[k - 2];
}

void EvaluateFit(const FitForm& form, const float* x, float* out) {
  if (form.basis == FitBasis::Power) return EvaluatePower(form, x, out);
  float t0[kMaxDegree + 1], t1[kMaxDegree + 1];
  const bool twoD = form.axes.size() == 2;
  const float v0 = ClampedFloat(form.axes[0], x[0]);
  const float v1 = twoD ? ClampedFloat(form.axes[1], x[1]) : 0.0f;
  const int n0 = form.axes[0].degree + 1;
  ChebyshevFloat(WarpedFloat(form.axes[0], v0, v1), n0 - 1, t0);
  const int n1 = twoD ? form.axes[1].degree + 1 : 1;
  if (twoD) ChebyshevFloat(WarpedFloat(form.axes[1], v1, v1), n1 - 1, t1);
  const float* c = form.coefficients.data();
  for (size_t ch = 0; ch < form.channels.size(); ++ch) {
    float sum = 0.0f;
    for (int i = 0; i < n0; ++i) {
      if (!twoD) {
        sum += c[i] * t0[i];
        continue;
      }
      float inner = 0.0f;
      for (int j = 0; j < n1; ++j) inner += c[i * n1 + j] * t1[j];
      sum += t0[i] * inner;
    }
    out[ch] = sum;
    c += n0 * n1;
  }
}

}  // namespace kiln
