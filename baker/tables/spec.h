// A table spec: which integral of which model, over which axes, into which channels. A spec
// fully determines a table's texels; its hash is what makes a baked file up to date.
#pragma once
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "baker/integrate/hemisphere.h"
#include "baker/tables/quantity.h"
#include "kiln/table.h"

namespace kiln {

/// One axis of a table: the parameter it spans, node-centred (DESIGN.md "Grid").
struct AxisSpec {
  std::string name;  ///< "mu", "roughness", "eta", "n", "k", "s", "mu_l", "mu_o", "phi"
  double lo = 0, hi = 1;
  int size = 2;
  Warp warp = Warp::Linear;
  /// A constant split point of a root4-layer-split axis (Axis::split); NaN: the critical cosine
  /// of axis 2's eta, or no split (other warps).
  double split = std::numeric_limits<double>::quiet_NaN();
  Axis ToAxis() const { return Axis{lo, hi, size, warp, split}; }
};

/// What a table holds: one table kind (quantity; baker/quantities/ describes each, with its
/// axes and channels) of one model over its axes.
struct TableSpec {
  std::string name;                   ///< file stem, e.g. "ggx-dfg"
  std::string model;                  ///< model id, or "none"
  Quantity quantity = Quantity::Dfg;  ///< written to files as QuantityName(quantity)
  std::vector<std::string> channels, meanings;
  std::vector<AxisSpec> axes;
  std::map<std::string, double> params;  ///< fixed model parameters (brdf: roughness)
  double tol = 1e-8;                     ///< absolute integration tolerance per texel

  /// "key=value;..." of params, %.17g.
  std::string ParamsText() const;
  /// The integration method, in words, for the kiln.method attribute.
  std::string Method() const;
  /// Hex FNV-1a 64 of HashText().
  std::string Hash() const;
  /// Everything that determines the texels, as text: the integrator version, format, name,
  /// model, quantity, tolerance, params, the kind's fixed-rule version where its rule bakes the
  /// table (QuantityInfo::fixedRuleVersion), the smooth-limit tag, channels and axes.
  std::string HashText() const;
  /// The axes as the runtime sees them.
  std::vector<TableAxis> TableAxes() const;
  /// Number of texels.
  size_t TexelCount() const;
};

/// The spec a baked table was made from, rebuilt from its attributes (name, model, quantity,
/// channels, axes, params, tolerance). Its Hash() equals the table's specHash when the file was
/// made by this version of kiln. Throws std::invalid_argument naming the table for an unknown
/// quantity ("table 'x': unknown quantity 'y'") or unparseable params ("cannot read kiln.params
/// '...' (...)").
TableSpec SpecFromTable(const Table& table);

/// A table of `spec` before its texels: name, model, quantity, channels and their meanings,
/// axes, params, the given generator and method, and zeroed texels. The bake and the bench's
/// estimators fill in the rest.
Table TableShell(const TableSpec& spec, const std::string& generator, const std::string& method);

/// The layer scale of a layered axis 0 (root4-layer, layer-eta) at the point x
/// (kiln::layerScaleFor of axis 1's value: 0 where the layer collapses, at roughness 0 or
/// eta = 1 exactly; 1e-12 for any other warp).
double LayerScaleOf(const TableSpec& spec, const double* x);

/// The split point of a root4-layer-split axis 0 at the point x: its constant split, or
/// kiln::criticalSplit of axis 2's value (the critical cosine sqrt(1 - eta^2)) when it has none;
/// for a root4-layer-split2 axis 0 axis 2's value (kiln::clampedEta), from which the warp places
/// its two breaks; 0.5 (ignored) for any other axis 0.
double SplitOf(const TableSpec& spec, const double* x);

/// The point x (axis units, one coordinate per axis) at warped coordinates t in [0, 1] per axis:
/// Axis::unwarped of each, a layered axis 0 placed by the layer scale at the other coordinates.
/// The one place that knows how a layered axis couples to the others (the bake's nodes, the
/// lookup-error points and the verify search all go through it).
void PointAtWarped(const TableSpec& spec, const double* t, double* x);

/// Where the value stored for warped coordinates t is evaluated: PointAtWarped, except where
/// the layer of a layered axis 0 has collapsed (layer scale 0: roughness 0, eta = 1) and t[0]
/// lies below Axis::collapsedStart(). There the node holds the layer's limit, the value at the
/// smallest axis-1 value that has a layer (root4-layer: r = 1e-6, alpha = 1e-12; layer-eta: the
/// double next to eta = 1), at axis 0 placed with that scale; returns true for such a point.
/// Lookups at 0 < r < r_1 (1 < eta < eta_1) then interpolate layer values with layer values,
/// and a lookup at the collapse point itself reads only the nodes t >= collapsedStart() (which
/// hold the smooth values, the value at mu = lo up to t = 1/2).
bool LayerLimitPointAtWarped(const TableSpec& spec, const double* t, double* x);

/// Coordinates of texel `index` (axis 0 fastest) at the nodes of the spec's axes; a layered
/// axis 0 places its nodes by the value of axis 1 (lut.h, Warp::Root4Layer, Warp::LayerEta).
/// A lookup at these coordinates returns the texel.
void NodeCoordinates(const TableSpec& spec, size_t index, double* x);

/// Where the bake evaluates texel `index`: NodeCoordinates, moved to the layer's limit where
/// the layer collapsed (LayerLimitPointAtWarped).
void NodeEvaluationPoint(const TableSpec& spec, size_t index, double* x);

/// True when the bake computes the table's texels with its quantity's fixed rule (today GGX dfg
/// and albedo, integrate/fixed_rule_dfg.h) instead of adaptive quadrature.
bool UsesFixedRule(const TableSpec& spec);

/// The absolute error a fixed-rule texel is declared to (before float rounding): the rule's worst
/// over the 128 x 128 catalogue grid against adaptive quadrature at 1e-11 is 2.9e-7 (per band
/// of roughness, fixed_rule_dfg.cpp), which tests/integrate_fixed_rule.cpp and
/// tests/bake_tables.cpp re-check.
constexpr double kFixedRuleBound = 6e-7;

/// The channel values of `spec` at a point x (one coordinate per axis, axis order) by the
/// table's own bake method: the quantity's smooth limit where it applies (roughness exactly 0
/// of a microfacet model, QuantityInfo::smoothLimit), else the fixed rule where UsesFixedRule,
/// else adaptive quadrature to spec.tol. Throws std::invalid_argument for an unknown model.
std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, IntegrationStats& stats);

/// The reference of the lookup-error search (baker/bake/lookup_error.h) at x: the smooth limit
/// where it applies, else the quantity's searchRule where UsesFixedRule and it has one (a
/// verification-grade form of the fixed rule: stats.errorEstimate is its distance bound from the
/// bake's rule, stats.evals charged at the bake rule's rate), else EvaluateSpec (errorEstimate
/// then set to 0: the bake's own method).
std::vector<double> SearchReference(const TableSpec& spec, const double* x,
                                    IntegrationStats& stats);

/// The same values by adaptive quadrature to `tol`, whatever the bake method (the independent
/// references of the bake and lookup error checks); the smooth limit is exact at roughness 0.
std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, double tol,
                                 IntegrationStats& stats);

}  // namespace kiln
