// kiln/stored.h: tables whose axes or channels are not the physical parameters and the quantity
// themselves, and the conversions between the two (runtime/FORMAT.md, "Stored forms").
//
// A table may be looked up on coordinates derived from the physical ones (e.g. cos(phi) instead
// of phi) and may store a bounded, smooth multiple of its quantity (e.g. f max(mu_l, mu_o)
// instead of a BRDF f that grows without bound at the horizon, or the exact conductor Fresnel
// term minus a closed form that carries its grazing dip). The form is read from the
// file's kiln.quantity and axis names, so files that store the quantity itself keep working.
// Header-only; needs kiln/table.h (no OpenEXR).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// How a table's axes and channels relate to the physical parameters and the quantity.
enum class StoredForm {
  /// The axes are the physical parameters and the channels the quantity itself.
  Plain,
  /// kiln.quantity "brdf" with axes (mu_l, mu_o, cos_phi): channels are f itself, looked up on
  /// cos(phi) (f is piecewise linear in cos(phi), with its kink at cos(phi) = 0 on a node).
  BrdfCosPhi,
  /// kiln.quantity "brdf" with axes (mu_max, mu_ratio, cos_phi), for a reciprocal BRDF:
  /// mu_max = max(mu_l, mu_o), mu_ratio = min(mu_l, mu_o) / mu_max, and every channel is
  /// f * mu_max (bounded where f grows as 1/mu_max at the horizon).
  BrdfSymmetric,
  /// kiln.quantity "blinn-phong-normalization" with channels exact_ratio, approx_ratio: each is
  /// the factor divided by its linear part (s + 2) / (8 pi).
  BlinnPhongRatio,
  /// kiln.quantity "fresnel-conductor" with channel F_residual, on axes (mu, n, k): the exact
  /// conductor reflectance F minus conductorFresnelApprox(mu, n, k), the closed form that
  /// carries the grazing dip; the quantity is the sample plus that closed form.
  ConductorResidual,
};

/// The textbook approximation of the conductor Fresnel reflectance at eta = n + i k and
/// cos(theta) = mu in [0, 1]: the mean of r_s = (e - 2 n mu + mu^2) / (e + 2 n mu + mu^2) and
/// r_p = (e mu^2 - 2 n mu + 1) / (e mu^2 + 2 n mu + 1), e = n^2 + k^2. Exact at mu = 1 and at
/// mu = 0 (F = 1); what fresnel-conductor tables store is the exact F minus this.
inline double conductorFresnelApprox(double mu, double n, double k) {
  const double e = n * n + k * k, mu2 = mu * mu;
  const double rs = (e - 2.0 * n * mu + mu2) / (e + 2.0 * n * mu + mu2);
  const double rp = (e * mu2 - 2.0 * n * mu + 1.0) / (e * mu2 + 2.0 * n * mu + 1.0);
  return 0.5 * (rs + rp);
}

/// The stored form of a table of kiln.quantity `quantity` whose axis 0 and axis 2 are named
/// `axis0` and `axis2` ("" when absent) and whose channel 0 is `channel0`.
inline StoredForm storedFormOf(const std::string& quantity, const std::string& axis0,
                               const std::string& axis2, const std::string& channel0) {
  if (quantity == "brdf" && axis0 == "mu_max") return StoredForm::BrdfSymmetric;
  if (quantity == "brdf" && axis2 == "cos_phi") return StoredForm::BrdfCosPhi;
  if (quantity == "blinn-phong-normalization" && channel0 == "exact_ratio")
    return StoredForm::BlinnPhongRatio;
  if (quantity == "fresnel-conductor" && channel0 == "F_residual")
    return StoredForm::ConductorResidual;
  return StoredForm::Plain;
}

/// The stored form of `table` (storedFormOf its quantity, axis and channel names).
inline StoredForm storedForm(const Table& table) {
  auto axisName = [&](int d) {
    return d < table.dims() ? table.axes[static_cast<std::size_t>(d)].name : std::string();
  };
  return storedFormOf(table.quantity, axisName(0), axisName(2),
                      table.channels.empty() ? std::string() : table.channels[0]);
}

/// The table coordinates (axis order) of the physical point p. For a brdf table p is
/// (mu_l, mu_o, phi), phi the azimuth difference in radians; otherwise the axes' own parameters.
/// `dims` values are read and written.
inline void storedCoordinates(StoredForm form, const double* p, double* x, int dims) {
  for (int d = 0; d < dims; ++d) x[d] = p[d];
  if (form == StoredForm::BrdfCosPhi || form == StoredForm::BrdfSymmetric) x[2] = std::cos(p[2]);
  if (form == StoredForm::BrdfSymmetric) {
    const double hi = std::max(p[0], p[1]), lo = std::min(p[0], p[1]);
    x[0] = hi;
    x[1] = hi > 0.0 ? lo / hi : 0.0;
  }
}

/// Turns the `channels` values sampled at table coordinates x (storedCoordinates of p) into the
/// quantity itself, in place. BrdfSymmetric divides by mu_max clamped to axis 0's range
/// [lo0, hi0] (the point the lookup clamped to); BlinnPhongRatio multiplies by (s + 2) / (8 pi)
/// at s = x[0] clamped to [lo0, hi0]. Plain and BrdfCosPhi leave them as they are.
inline void quantityFromStored(StoredForm form, const double* x, double lo0, double hi0,
                               double* values, int channels) {
  const double x0 = std::min(std::max(x[0], lo0), hi0);
  double scale = 1.0;
  if (form == StoredForm::BrdfSymmetric) scale = 1.0 / x0;
  if (form == StoredForm::BlinnPhongRatio) scale = (x0 + 2.0) / (8.0 * 3.14159265358979323846);
  for (int c = 0; c < channels; ++c) values[c] *= scale;
}

/// Samples `table` at the physical point p (see storedCoordinates) and writes the quantity
/// itself, one double per channel, to out: what `kiln sample` prints.
inline void sampleQuantity(const Table& table, const double* p, double* out,
                           Filter filter = Filter::Linear) {
  const StoredForm form = storedForm(table);
  const int dims = table.dims() < 3 ? table.dims() : 3;
  double x[3] = {0.0, 0.0, 0.0};
  storedCoordinates(form, p, x, dims);
  const int n = static_cast<int>(table.channels.size());
  float got[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  float* buf = got;
  std::vector<float> many;
  if (n > 4) {
    many.resize(static_cast<std::size_t>(n));
    buf = many.data();
  }
  table.view().sample(x, buf, filter);
  for (int c = 0; c < n; ++c) out[c] = static_cast<double>(buf[c]);
  if (form == StoredForm::ConductorResidual && dims == 3) {
    // Add back the closed form at the point the lookup clamped to.
    double c[3];
    for (int d = 0; d < 3; ++d) {
      const Axis& a = table.axes[static_cast<std::size_t>(d)].axis;
      c[d] = std::min(std::max(x[d], a.lo), a.hi);
    }
    out[0] += conductorFresnelApprox(c[0], c[1], c[2]);
    return;
  }
  if (dims >= 1) {
    const Axis& a0 = table.axes[0].axis;
    quantityFromStored(form, x, a0.lo, a0.hi, out, n);
  }
}

}  // namespace kiln
