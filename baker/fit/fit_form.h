// A closed-form fit of a table (`kiln fit`, docs/fits.md): per channel, a tensor product of
// Chebyshev polynomials in warped axes. Axis d's value x is clamped to [lo, hi], mapped to
// w = ((x - lo) / (hi - lo))^p (p = 1, 1/2 or 1/4: the warp) and to s = 2 w - 1 in [-1, 1];
// the channel is sum_ij c_ij T_i(s_0) T_j(s_1). A one-axis fit may instead be a power series
// evaluated by Horner's rule (FitBasis::Power). The evaluation here is the float arithmetic the
// emitted C++, GLSL and HLSL perform, in the same order, so the bound measured with it holds for
// the emitted code.
#pragma once
#include <string>
#include <vector>

namespace kiln {

/// The warp of one fitted axis: w = u^p with u the axis value normalised to [0, 1], or (Layer,
/// axis 0 of a (mu, roughness) fit only) kiln's root4-layer warp with an unclamped scale:
/// w = (u^(1/4) + u (1 + c) / (u + c)) / 2, c = max(r^2, 1e-12) with r axis 1's clamped value
/// (the table's root4-layer warp), which follows the grazing layer of a microfacet lobe (a
/// function of mu / alpha, alpha = r^2, at least kiln's smallest alpha 1e-12). LayerEta (axis 0
/// of a (mu, eta) fit only) is the same warp with c = max(sqrt(|eta^2 - 1|), 4.8828137e-4), eta
/// axis 1's clamped value (the table's layer-eta warp; the floor is the float just above 1's,
/// fit.h kEtaLayerFloor): dielectric Fresnel's grazing layer near eta = 1 is a function of
/// mu / sqrt(eta^2 - 1).
enum class FitWarp { Linear, Sqrt, Root4, Layer, LayerEta };

/// Whether `w` is one of the layer warps (Layer, LayerEta): axis 0's warp scaled by axis 1.
inline bool IsLayerWarp(FitWarp w) { return w == FitWarp::Layer || w == FitWarp::LayerEta; }

/// "linear", "sqrt", "root4", "layer".
const char* FitWarpName(FitWarp w);
/// The warp named `name`; throws std::invalid_argument for another name.
FitWarp FitWarpFromName(const std::string& name);

/// The polynomial basis of a fit. Chebyshev: the tensor product above. Power (one axis only):
/// c_0 + t (c_1 + t (c_2 + ... + t c_n)) by Horner's rule in t = warp(v - lo), v the clamped
/// axis value and the warp's power of the plain difference (sqrt, root4): the normalisation
/// 1 / (hi - lo) is folded into the coefficients. A linear axis has t = v (the shift folded in
/// too), and v - lo is skipped for lo = 0 (PowerSubtractsLo).
enum class FitBasis { Chebyshev, Power };

/// "chebyshev", "horner".
const char* FitBasisName(FitBasis b);
/// The basis named `name`; throws std::invalid_argument for another name.
FitBasis FitBasisFromName(const std::string& name);

/// One fitted axis: its declared domain, warp and polynomial degree.
struct FitAxis {
  std::string name;
  double lo = 0, hi = 1;
  FitWarp warp = FitWarp::Linear;
  int degree = 0;
};

/// A fitted closed form: axes (the table's order, 1 or 2), channels, and per channel the
/// (degree_0 + 1) x (degree_1 + 1) coefficients in float, axis 0 slowest.
struct FitForm {
  std::string table;  ///< the table's name, e.g. "ggx-dfg"
  std::vector<std::string> channels;
  std::vector<FitAxis> axes;
  std::vector<float> coefficients;       ///< channel-major, then axis 0's index, then axis 1's
  FitBasis basis = FitBasis::Chebyshev;  ///< Power: one axis, coefficients of t^0 .. t^degree

  /// Coefficients per channel: the product of (degree + 1) over the axes.
  int TermsPerChannel() const;
  /// The float operations of one evaluation of every channel: clamps, warps (sqrt counted as
  /// one), the Chebyshev recurrences and the multiply-adds of the sums (multiply and add each one);
  /// a Power form: the clamp, v - lo unless lo = 0, the warp's sqrt and per channel a multiply
  /// and an add per degree.
  int OperationCount() const;
  /// The sqrt among them.
  int SqrtCount() const;
};

/// The fit's channels at x (axis values in the table's order), in float as the emitted code
/// computes them; `out` gets channels.size() values.
void EvaluateFit(const FitForm& form, const float* x, float* out);

/// The Chebyshev values T_0..T_degree at s in [-1, 1], in double (the least-squares design).
void ChebyshevRow(int degree, double s, double* t);

/// Whether a Power form's t subtracts lo from v: a sqrt or root4 warp of an axis with lo != 0.
inline bool PowerSubtractsLo(const FitAxis& axis) {
  return axis.lo != 0 && axis.warp != FitWarp::Linear;
}

/// The Power form's variable t = warp(v - lo) of the clamped value v of a one-axis fit, in
/// double (the least-squares design; the float evaluation takes the same steps).
double PowerVariable(const FitAxis& axis, double v);

/// The warped coordinates s in [-1, 1] (one per axis) of the point x, in double.
void WarpedCoordinates(const FitForm& form, const double* x, double* s);

/// The point x at warped coordinates s (the inverse of WarpedCoordinates; a Layer axis 0 by
/// bisection at axis 1's value).
void PointAtWarped(const FitForm& form, const double* s, double* x);

}  // namespace kiln
