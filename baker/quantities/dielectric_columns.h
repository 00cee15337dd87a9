// The glass kinds' bake by columns of eta (QuantityInfo::bakeTable for the entering side's E
// tables and averages, quantities/dielectric_albedo.cpp and dielectric_albedo_avg.cpp): on the
// entering side the fixed rule's walk does not depend on eta (integrate/dielectric_albedo.cpp,
// "Columns"), so the texels that share every other coordinate are integrated together, one
// column per task, and each texel gets the bits the kind's per-point fixed rule gives it.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "baker/tables/spec.h"
#include "kiln/table.h"

namespace kiln {

/// How a kind's texels form columns.
struct DielectricColumnBake {
  /// The column of point x: false for a texel the bake evaluates alone (EvaluateSpec: the
  /// smooth limit, an eta off the column rule's side); else its column's key (a, b) and its eta.
  std::function<bool(const double* x, double* a, double* b, double* eta)> columnOf;
  /// {E_R, E_T} (or their averages) of a column at n etas into out; evals: one texel's.
  std::function<void(double a, double b, const double* etas, int n, std::array<double, 2>* out,
                     long long* evals)>
      column;
  /// The stored channel values at x from {E_R, E_T} there (the kind's Stored).
  std::function<std::vector<double>(const double* x, std::array<double, 2> e)> store;
  double bound = 0;  ///< each column texel's declared error (the rule's bound)
};

/// DielectricColumnBake::columnOf of a (mu, roughness, eta) texel of an entering-side 3D table
/// (the E tables, the BTDF pair): key (mu, alpha = max(r^2, MinAlpha)) and its eta; false at
/// roughness 0 (the smooth limit) or eta below kDielectricTableEtaMin (evaluated alone).
bool MuRoughnessColumnOf(const std::array<double, 3>& point, double* a, double* b, double* eta);

/// Fills table.data, evals and errors of `spec` (QuantityInfo::bakeTable's contract) by
/// columns: texels grouped by their key in index order, at most kMaxDielectricColumn per column,
/// one column per task; the same bits for any thread count.
void BakeDielectricColumns(const TableSpec& spec, int threads, const DielectricColumnBake& how,
                           Table& table, std::vector<long long>& evals,
                           std::vector<double>& errors);

}  // namespace kiln
