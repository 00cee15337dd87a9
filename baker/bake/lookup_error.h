// The lookup error of a table: interpolated value against the reference, found by a search that
// ranks the cells by the interpolation error the table's own node values predict, always takes
// the cells on the domain's corners and edges, and climbs to the local maximum inside each
// (docs/accuracy.md "Lookup error"). The bake declares its bound from it and `kiln verify` repeats
// it.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "baker/tables/spec.h"
#include "kiln/lut.h"

namespace kiln {

struct LookupErrorReport {
  double max = 0;  ///< the largest |lookup - reference| found (max over channels)
  double rms = 0;  ///< over the fixed probe points of the searched cells
  /// Max outside the first cell of the second axis (roughness < r_1 or eta < eta_1) of a table
  /// over mu: there (mu -> 0, roughness -> 0) or (mu -> 0, eta -> 1) is a path-dependent limit
  /// (E ~ g(mu / alpha), F ~ g(mu / sqrt(eta - 1))) that no tensor grid interpolates
  /// (docs/accuracy.md "Lookup error"). Equal to max for other tables.
  double maxOutsideCorner = 0;
  std::vector<double> where;            ///< the parameter values of the worst point, axis order
  double cubicMax = -1, cubicRms = -1;  ///< with the cubic filter at the probe points (alsoCubic)
  long long points = 0;                 ///< reference evaluations (probes + climbs)
  long long cells = 0;                  ///< cells probed
  long long climbed = 0;                ///< cells in which the search climbed
  long long allCells = 0;               ///< cells of the table
  long long budget = 0;                 ///< the reference evaluations the search was allowed
  /// Of `points`, those LookupSearchOptions::reuse supplied (counted, charged and compared
  /// like the others: only not evaluated again).
  long long reused = 0;
  /// How far the search's reference may lie from the bake's method at the points it evaluated
  /// (SearchReference's errorEstimate, max over the points; 0 for the bake's own method or an
  /// adaptive reference): the true max can exceed `max` by this much.
  double referenceError = 0;
  std::string WhereText(const TableSpec& spec) const;  ///< "mu=0.0001 roughness=0.01"
};

/// The reference values a search evaluated (SearchReference, its default form), by point: the
/// bits of the point's axis values. A table derived from the searched one reads them where its
/// own search's points coincide (LookupSearchOptions::reuse,
/// QuantityInfo::searchDerivesFromSource).
class SearchMemo {
 public:
  struct Entry {
    std::vector<double> values;  ///< the reference, one value per channel of the searched table
    long long evals = 0;         ///< IntegrationStats::evals of its evaluation
    double errorEstimate = 0;    ///< IntegrationStats::errorEstimate of its evaluation
  };
  /// Keeps the reference at x (the first one kept for a point stays). Not thread-safe.
  void Add(const double* x, Entry entry);
  /// Room for n references in all, so that adding them does not rehash. Not thread-safe.
  void Reserve(size_t n);
  /// The reference kept at x, or null. Thread-safe while nothing is added.
  const Entry* Find(const double* x) const;
  size_t size() const { return map_.size(); }

 private:
  using Key = std::array<uint64_t, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  std::unordered_map<Key, Entry, KeyHash> map_;
};

/// A reference supplied before it is evaluated: true when it filled `exact` and `stats` with
/// what the search's reference would return at x (the same bits), false to evaluate it.
using SearchReuse =
    std::function<bool(const double* x, std::vector<double>& exact, IntegrationStats& stats)>;

/// How hard the search looks.
struct LookupSearchOptions {
  /// Most reference evaluations per table. 0: the automatic budget, at most kLookupBudgetCalls
  /// reference and kLookupBudgetIntegrand integrand evaluations (IntegrationStats::evals, so a
  /// costly adaptive reference gets fewer points; counted, never timed: deterministic). A budget
  /// below one cell's probes is raised to them (the first cell, a corner, is always probed).
  long long budget = 0;
  long long maxCells = 0;  ///< search at most this many cells (0: as the budget allows)
  /// Also this many fixed-seed random points, uniform in warped coordinates (outside the budget;
  /// counted in max, rms and points).
  long long randomPoints = 0;
  double refTol = 0;  ///< > 0: adaptive quadrature to refTol as the reference
  /// With refTol > 0: the kind's verification reference (QuantityInfo::verifyReference, an
  /// average's adaptive mu integral of E) to refTol where it has one, instead of EvaluateSpec.
  bool verifyReference = false;
  int threads = 0;  ///< 0: all cores
  Filter filter = Filter::Linear;
  bool alsoCubic = false;  ///< also sample the probe points with the cubic filter
  /// Evaluate the points by the bake's own rule (EvaluateSpec), not its verification-grade form
  /// (QuantityInfo::searchRule): referenceError 0, at the bake rule's cost.
  bool bakeRule = false;
  /// Filled with every point's reference and stats (the default reference only: not with
  /// bakeRule or refTol), for a derived table's search to reuse.
  SearchMemo* record = nullptr;
  /// Asked first at every point of the default reference (not with bakeRule or refTol): the
  /// same values sooner, so the same report (rep.reused counts its points).
  SearchReuse reuse;
};

/// The automatic budget: most reference evaluations per table (closed forms reach it). Over the
/// catalogue, a quarter of the former 200,000 and 2e7 found the same max on 70 of 74 tables and
/// the others within 11% (docs/accuracy.md "Lookup error"): 0.4 of them leaves a margin.
constexpr long long kLookupBudgetCalls = 80000;
/// The automatic budget: most integrand evaluations per table (fixed rules and adaptive
/// references; about half a second of one core; the probes and the first climbs finish their
/// chunk, so a search can overrun it).
constexpr long long kLookupBudgetIntegrand = 8000000;

/// The derivative-based estimate of the linear-interpolation error of every cell (axis 0
/// fastest; cells per axis = nodes - 1): per axis, h^2 f'' / 8 taken from the node values as
/// |f(i-1) - 2 f(i) + f(i+1)| / 8 in warped coordinates at both nodes of the cell along that axis
/// (so a kink, whose second difference jumps, shows in the cells on either side), the max over
/// the cell's corners and the channels, summed over the axes.
/// Channels before `firstChannel` are left out (a fitted table's coefficients). Runs on the
/// calling thread's oneTBB arena; the same values for any thread count.
std::vector<double> CellErrorEstimates(const LutView& view, int firstChannel = 0);

/// Searches the table for its largest |view.sample(x, filter) - reference(x)| (max over
/// channels), reference = SearchReference(spec, x, stats) (the bake's method, or its cheaper
/// verification-grade form, QuantityInfo::searchRule; their distance in rep.referenceError) or,
/// with opt.refTol > 0, adaptive quadrature to refTol. Cells searched, in order until the budget is
/// spent: the domain's corner cells, then the cells along the domain's edges (first or last
/// cell on all axes but at most one) and the others alternately, each by CellErrorEstimates
/// descending. In each: fixed probe points (centre, the 2^d points at 0.2 / 0.8 of the cell,
/// the 2d points at 0.05 / 0.95 of the cell on one axis and 0.5 on the others). Then in the
/// cells whose probes erred most: coordinate-wise golden section from the worst probe, in the
/// cell's warped coordinates, clamped to the cell, to a local maximum. A table of at most 1,024
/// cells whose automatic budget probed only some of them (a costly reference) also gets every
/// other cell's centre, outside the budget, and the worst of those (as many as were probed, at
/// least 8) probed in full before the climbs. Every point is placed by PointAtWarped. Before
/// each batch of points (a chunk of probes, the centre sweep) the kind may integrate the batch
/// together (QuantityInfo::prepareSearch: the same values, sooner).
/// Deterministic: the same report for any thread count (oneTBB).
LookupErrorReport MeasureLookupError(const TableSpec& spec, const LutView& view,
                                     const LookupSearchOptions& opt);

/// The bound a baked table declares: (the searched max + the reference's distance from the bake's
/// method, referenceError) times this margin, for local maxima the climb stops short of and
/// cells the budget did not reach (kiln verify repeats the search and checks max <= bound + the
/// reference's own tolerance).
constexpr double kDeclaredBoundMargin = 1.5;

}  // namespace kiln
