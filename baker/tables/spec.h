// A table spec: which integral of which model, over which axes, into which channels. A spec
// fully determines a table's texels; its hash is what makes a baked file up to date.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "baker/integrate/hemisphere.h"
#include "baker/quantities/quantity.h"
#include "kiln/table.h"

namespace kiln {

/// One axis of a table: the parameter it spans, node-centred (DESIGN.md "Grid").
struct AxisSpec {
  std::string name;  ///< "mu", "roughness", "eta", "n", "k", "s", "mu_l", "mu_o", "phi"
  double lo = 0, hi = 1;
  int size = 2;
  Warp warp = Warp::Linear;
  Axis ToAxis() const { return Axis{lo, hi, size, warp}; }
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
  /// Hex FNV-1a 64 of everything that determines the texels (and the integrator version).
  std::string Hash() const;
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

/// The layer scale of a root4-layer axis 0 at the point x (kiln::layerScale of axis 1's value;
/// 1e-12 for any other warp).
double LayerScaleOf(const TableSpec& spec, const double* x);

/// The point x (axis units, one coordinate per axis) at warped coordinates t in [0, 1] per axis:
/// Axis::unwarped of each, a layered axis 0 placed by the layer scale at the other coordinates.
/// The one place that knows how a layered axis couples to the others (the bake's nodes, the
/// lookup-error points and the verify search all go through it).
void PointAtWarped(const TableSpec& spec, const double* t, double* x);

/// Coordinates of texel `index` (axis 0 fastest) at the nodes of the spec's axes; a root4-layer
/// axis 0 places its nodes by the value of axis 1 (lut.h, Warp::Root4Layer).
void NodeCoordinates(const TableSpec& spec, size_t index, double* x);

/// True when the bake computes the table's texels with its quantity's fixed rule (today GGX dfg
/// and albedo, integrate/fixed_rule_dfg.h) instead of adaptive quadrature.
bool UsesFixedRule(const TableSpec& spec);

/// The absolute error a fixed-rule texel is declared to (before float rounding): the rule's worst
/// over the 128 x 128 catalogue grid against adaptive quadrature at 1e-11 is 2.9e-7 (per band
/// of roughness, fixed_rule_dfg.cpp), which tests/integrate_fixed_rule.cpp and
/// tests/bake_tables.cpp re-check.
constexpr double kFixedRuleBound = 6e-7;

/// The channel values of `spec` at a point x (one coordinate per axis, axis order) by the
/// table's own bake method: the fixed rule where UsesFixedRule, else adaptive quadrature to
/// spec.tol. Throws std::invalid_argument for an unknown model.
std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, IntegrationStats& stats);

/// The same values by adaptive quadrature to `tol`, whatever the bake method (the independent
/// references of the bake and lookup error checks).
std::vector<double> EvaluateSpec(const TableSpec& spec, const double* x, double tol,
                                 IntegrationStats& stats);

}  // namespace kiln
