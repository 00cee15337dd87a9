// `kiln verify`: checks every claim a kiln file makes. One entry point per file type; today a
// table (VerifyTableFile): its declared lookup error (the bake's search, repeated), its declared
// bake error (texels against a reference that is not the bake's rule, bake_error.h) and, for a
// fitted kind, the kind's own check (QuantityInfo::verifyTable: an LTC table's fit and polygon
// errors). The CLI (cli/cmd_verify.cpp) only parses options and prints.
#pragma once
#include <string>
#include <vector>

#include "baker/bake/lookup_error.h"
#include "baker/verify/bake_error.h"

namespace kiln::verify {

/// How hard verify looks (kiln verify's options; docs/cli.md).
struct VerifyOptions {
  long long budget = 0;  ///< the lookup search's reference evaluations (0: the bake's budget)
  long long points = 0;  ///< random points of the lookup search, besides its cells
  long long cells = 0;   ///< lookup search: at most this many cells (0: as the budget allows)
  double tol = 0;        ///< > 0: the lookup search's reference by adaptive quadrature to tol
  /// With tol > 0: the search's cells and random points of a kind with a verification reference
  /// of its own (QuantityInfo::verifyReference; an average: adaptive quadrature over mu of E by
  /// its 3D table's rule, which that table's check holds to adaptive) take that reference; the
  /// declared worst point keeps the whole integral's adaptive quadrature.
  bool outerReference = false;
  int threads = 0;     ///< 0: all cores
  std::string filter;  ///< "" (the declared one), "linear" or "cubic" (then not checked)
  /// Sampled nodes of the bake-error check, or kBakeAllNodes: every node (bake_error.h).
  int bakeNodes = kBakeSampleNodes;
};

/// The verdict on one table file.
struct TableVerdict {
  std::string file;
  bool ok = false;
  std::string error;  ///< non-empty: the file does not load or evaluate (nothing else is set)
  std::string name, filter;
  bool checked = true;         ///< false: measured with another filter than the declared one
  LookupErrorReport lookup;    ///< the repeated search
  std::string lookupWhere;     ///< lookup.WhereText
  double declaredLookup = -1;  ///< kiln.lookup_error.max
  bool lookupOk = true;        ///< max within the declared bound (+ the references' tolerances)
  BakeErrorCheck bake;         ///< the bake-error check
  std::string bakeWhere;       ///< bake.WhereText
  std::string fitSummary;      ///< a fitted kind's own check: what it measured ("" for none)
  std::string fitProblem;      ///< ... and why it failed ("" when it passed)
  double seconds = 0;          ///< wall time of the checks
  double bakeSeconds = 0;      ///< ... of which the bake-error check
};

/// The files `path` names: itself, or the `.exr` files of a folder (a table stored in parts
/// once: its first part), sorted. Throws std::invalid_argument ("verify: no such file or folder
/// 'PATH'") when it does not exist.
std::vector<std::string> VerifyInputs(const std::string& path);

/// Checks one table file (any format LoadAnyTable reads): loads it, rebuilds its spec, checks
/// its axes against the model's ranges and its channels against its kind, then the lookup error
/// (the bake's search; fails above declared + the references' tolerances + the bake error), the
/// bake error (CheckBakeError) and the kind's own check. Never throws for a bad file: `error`
/// says why (one line).
TableVerdict VerifyTableFile(const std::string& path, const VerifyOptions& opt);

/// Why `spec`'s axes leave its model's parameter ranges ("" when they do not): the evaluators
/// clamp, so verify would compare texels with the clamped model. An engine-grid sheen table
/// that says it clamps there itself (sheen_roughness_min) is inside.
std::string AxesOutsideModel(const TableSpec& spec);

}  // namespace kiln::verify
