// The bake-error check of `kiln verify`: a file's texels at a sample of its nodes against a
// reference that is not the bake's rule (adaptive quadrature well under the declared bake error,
// or the kind's closed form), each compared with the bake error the file declares.
#pragma once
#include <string>
#include <vector>

#include "baker/tables/spec.h"
#include "kiln/table.h"

namespace kiln::verify {

/// Nodes sampled beyond the corners and the worst-first nodes (Latin hypercube, kBakeSampleSeed).
constexpr int kBakeSampleNodes = 24;
/// The Latin hypercube's seed: the same nodes every run.
constexpr unsigned long long kBakeSampleSeed = 0x6b696c6e;
/// sampleNodes for every node of the table, compared whatever the evaluations (`kiln verify
/// --all-nodes`).
constexpr int kBakeAllNodes = -1;
/// Nodes taken worst-first: those whose value departs most from the line through their
/// neighbours (a node that holds something else than its neighbours' function).
constexpr int kBakeWorstNodes = 8;
/// Integrand evaluations the reference may spend per table once the corners are done (counted,
/// never timed: the same nodes for any thread count).
constexpr long long kBakeCheckIntegrand = 3000000;
/// The reference's tolerance is the declared bake error divided by this (capped at
/// kBakeRefTolMax, at least kBakeRefTolMin), and the check allows twice it on top of the claim.
constexpr double kBakeRefTolDivisor = 20;
constexpr double kBakeRefTolMax = 1e-8;
constexpr double kBakeRefTolMin = 1e-12;

/// What the check found.
struct BakeErrorCheck {
  double max = 0;             ///< worst |texel - reference| / max(1, |reference|)
  std::vector<double> where;  ///< the node of that worst, axis units
  double declared = -1;       ///< kiln.bake_error
  double refTol = 0;          ///< the reference's tolerance
  long long nodes = 0;        ///< nodes compared
  long long evals = 0;        ///< the reference's integrand evaluations
  bool ok = true;             ///< max <= declared + 2 refTol
  std::string WhereText(const TableSpec& spec) const;  ///< "mu=0.5 roughness=0.3"
};

/// The nodes the check compares, as texel indices in order: every corner of the grid, the
/// kBakeWorstNodes nodes that depart most from their neighbours (WorstNodes), then
/// `sampleNodes` nodes of a Latin hypercube over the node indices (seed `seed`), or with
/// kBakeAllNodes every other node in index order; no index twice.
std::vector<size_t> BakeCheckNodes(const TableSpec& spec, const Table& table, int sampleNodes,
                                   unsigned long long seed);

/// Checks `table`'s texels at BakeCheckNodes (channels from the kind's firstIntegralChannel on)
/// against EvaluateSpec(spec, x, refTol) at each node's evaluation point (NodeEvaluationPoint):
/// adaptive quadrature, or the exact form of a closed-form kind, never the bake's fixed rule.
/// refTol: `tol` when > 0, else the declared bake error / kBakeRefTolDivisor within
/// [kBakeRefTolMin, kBakeRefTolMax]. The corners always; the other nodes in chunks until
/// kBakeCheckIntegrand integrand evaluations are spent (deterministic for any `threads`), or
/// with sampleNodes = kBakeAllNodes every node whatever they cost.
/// Throws std::invalid_argument for a table that declares no bake error.
BakeErrorCheck CheckBakeError(const TableSpec& spec, const Table& table, int sampleNodes,
                              double tol, int threads);

}  // namespace kiln::verify
