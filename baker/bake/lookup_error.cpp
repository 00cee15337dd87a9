#include "baker/bake/lookup_error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

#include "baker/integrate/hemisphere.h"
#include "baker/tables/prepared_reference.h"
#include "baker/util/threads.h"

namespace kiln {
namespace {

/// Golden-section iterations per axis and sweep of the climb (2 + this many evaluations, and one
/// more at a bracket end on the cell's face; the bracket shrinks by 0.618^8 = 0.021 of its width).
constexpr int kGoldenIterations = 8;
/// Sweeps over the axes of the climb, and the half-width of the bracket around the current best
/// in each (cell-local coordinates).
constexpr double kSweepHalfWidth[] = {0.25, 0.0625};
constexpr int kSweeps = 2;
/// Share of the budget the probes take when not every cell can be probed (the rest climbs).
constexpr double kProbeShare = 0.6;
/// Tables of at most this many cells whose automatic budget probes only some of them (a costly
/// reference: each point of an average is a whole mu integral) have every other cell's centre
/// evaluated too, outside the budget, and the worst of those probed in full (MeasureLookupError).
constexpr size_t kCentreSweepCells = 1024;
/// Channels a point's lookup keeps on the stack (more take the heap).
constexpr size_t kStackChannels = 16;

/// One measured point: the error, with the cubic filter, and whether it lies in the path-
/// dependent corner (first cell of axis 1 of a table over mu).
struct Sample {
  double err = 0, cubic = 0;
  bool inCorner = false;
  long long integrand = 0;
  double refError = 0;        ///< the reference's distance bound from the bake's method here
  double x[3] = {0, 0, 0};    ///< the point, axis units
  bool reused = false;        ///< LookupSearchOptions::reuse supplied the reference
  std::vector<double> exact;  ///< the reference, kept when the search records (opt.record)
};

/// Cell-local probe points u in [0, 1]^D over the D axes with more than one node.
std::vector<std::array<double, 3>> ProbePoints(int D) {
  std::vector<std::array<double, 3>> p;
  p.push_back({0.5, 0.5, 0.5});
  for (int m = 0; m < (1 << D); ++m) {
    std::array<double, 3> u{0.5, 0.5, 0.5};
    for (int a = 0; a < D; ++a) u[a] = (m >> a) & 1 ? 0.8 : 0.2;
    p.push_back(u);
  }
  for (int a = 0; a < D; ++a)
    for (double s : {0.05, 0.95}) {
      std::array<double, 3> u{0.5, 0.5, 0.5};
      u[a] = s;
      p.push_back(u);
    }
  return p;
}

}  // namespace

size_t SearchMemo::KeyHash::operator()(const Key& k) const {
  uint64_t h = 0x9E3779B97F4A7C15ull;
  for (uint64_t v : k) {
    h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
  }
  return static_cast<size_t>(h ^ (h >> 31));
}

namespace {
/// A point's key: the bits of its three axis values (unused axes 0).
std::array<uint64_t, 3> MemoKey(const double* x) {
  std::array<uint64_t, 3> k{};
  std::memcpy(k.data(), x, sizeof k);
  return k;
}
}  // namespace

void SearchMemo::Add(const double* x, Entry entry) { map_.emplace(MemoKey(x), std::move(entry)); }

void SearchMemo::Reserve(size_t n) { map_.reserve(n); }

const SearchMemo::Entry* SearchMemo::Find(const double* x) const {
  auto it = map_.find(MemoKey(x));
  return it == map_.end() ? nullptr : &it->second;
}

std::string LookupErrorReport::WhereText(const TableSpec& spec) const {
  std::string s;
  char buf[64];
  for (size_t d = 0; d < where.size() && d < spec.axes.size(); ++d) {
    std::snprintf(buf, sizeof buf, "%s%s=%.6g", s.empty() ? "" : " ", spec.axes[d].name.c_str(),
                  where[d]);
    s += buf;
  }
  return s;
}

std::vector<double> CellErrorEstimates(const LutView& view, int firstChannel) {
  const int dims = view.dims;
  int n[3] = {view.size(0), view.size(1), view.size(2)};
  int nc[3];
  for (int d = 0; d < 3; ++d) nc[d] = std::max(1, n[d] - 1);
  // Per axis, per node: max over channels of |second difference| along that axis; an end node
  // takes its neighbour's (the one stencil that reaches it). Each node and each cell on its own
  // (in parallel, the same values for any thread count).
  const size_t nodes = static_cast<size_t>(n[0]) * n[1] * n[2];
  std::vector<double> sd[3];
  for (int d = 0; d < dims; ++d) {
    sd[d].assign(nodes, 0.0);
    if (n[d] < 3) continue;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, nodes, 4096), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t k = r.begin(); k != r.end(); ++k) {
            int i[3] = {static_cast<int>(k % n[0]), static_cast<int>(k / n[0] % n[1]),
                        static_cast<int>(k / n[0] / n[1])};
            int j = std::min(std::max(i[d], 1), n[d] - 2);  // stencil centre
            int lo[3] = {i[0], i[1], i[2]}, mid[3] = {i[0], i[1], i[2]}, hi[3] = {i[0], i[1], i[2]};
            lo[d] = j - 1;
            mid[d] = j;
            hi[d] = j + 1;
            double m = 0;
            for (int c = firstChannel; c < view.channels; ++c) {
              double f0 = view.at(lo[0], lo[1], lo[2], c), f1 = view.at(mid[0], mid[1], mid[2], c),
                     f2 = view.at(hi[0], hi[1], hi[2], c);
              m = std::max(m, std::abs(f0 - 2 * f1 + f2));
            }
            sd[d][k] = m;
          }
        });
  }
  const size_t cells = static_cast<size_t>(nc[0]) * nc[1] * nc[2];
  std::vector<double> est(cells, 0.0);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, cells, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          int c[3] = {static_cast<int>(k % nc[0]), static_cast<int>(k / nc[0] % nc[1]),
                      static_cast<int>(k / nc[0] / nc[1])};
          double e = 0;
          for (int d = 0; d < dims; ++d) {
            double m = 0;
            for (int corner = 0; corner < 8; ++corner) {
              int i[3];
              for (int a = 0; a < 3; ++a) i[a] = std::min(c[a] + ((corner >> a) & 1), n[a] - 1);
              m = std::max(m, sd[d][i[0] + static_cast<size_t>(n[0]) *
                                               (i[1] + static_cast<size_t>(n[1]) * i[2])]);
            }
            e += m / 8;  // h^2 f'' / 8 with h = 1 node spacing
          }
          est[k] = e;
        }
      });
  return est;
}

namespace {

/// One climb: its best point, where it is in the cell, and what it spent.
struct Climb {
  Sample best;
  std::array<double, 3> u{};
  long long evals = 0, integrand = 0, reused = 0;
  double refError = 0;
  std::vector<Sample> visited;  ///< every point evaluated, kept when the search records
};

/// The state of one search (MeasureLookupError), its steps in the order they run: the cells'
/// order, the probes within the budget, the centre sweep of a small table, the random points,
/// the climbs, and the reductions into the report.
class LookupSearch {
 public:
  LookupSearch(const TableSpec& spec, const LutView& view, const LookupSearchOptions& opt);
  /// The cells in search order: corners, then edge and other cells alternately, each by
  /// estimate descending (index on ties); at most opt.maxCells.
  void OrderCells();
  /// Probes, cell after cell in search order, until kProbeShare of the budget is spent (all of
  /// it when every cell is probed within it).
  void Probe();
  /// A small table the automatic budget probed only in part: every other cell's centre, and the
  /// worst of them probed in full (outside the budget).
  void SweepCentres();
  /// opt.randomPoints fixed-seed points, uniform in warped coordinates.
  void RandomPoints();
  /// Climbs, in the cells whose worst probe erred most, in chunks until the budget is spent.
  void Climbs();
  /// The report: deterministic reductions in search order.
  LookupErrorReport Report();
  /// Every point's reference into opt.record (a search of the default reference only).
  void Record();

 private:
  Sample Evaluate(size_t cell, const std::array<double, 3>& u) const;
  /// The point (axis units) at cell-local u of `cell`, as PointAtWarped places it.
  void PointIn(size_t cell, const std::array<double, 3>& u, double* x) const;
  /// Lets the kind integrate these (cell, probe) points together before they are evaluated
  /// (QuantityInfo::prepareSearch): only sooner, never other values.
  void Prepare(const std::vector<std::pair<size_t, size_t>>& what);
  bool Spent(double share) const;
  /// Whether the search evaluates the default reference (SearchReference): reuse and record.
  bool DefaultReference() const { return opt_.refTol <= 0 && !opt_.bakeRule; }
  void EvaluateAll(std::vector<Sample>& out, size_t base,
                   const std::vector<std::pair<size_t, size_t>>& what);
  /// The climb in the cell at `slot` of order_; `speculate`: evaluate a point ahead on a
  /// second thread (the same climb, sooner when it has a thread to itself).
  Climb ClimbCell(size_t slot, bool speculate) const;

  const TableSpec& spec_;
  const LutView& view_;
  /// view_ prepared once: its sampleDouble is view_.sample, bit for bit, without preparing the
  /// axes again at every point.
  LutSampler sampler_;
  PreparedReference reference_;  ///< SearchReference and EvaluateSpec of spec_, resolved once
  const LookupSearchOptions& opt_;
  size_t dims_;
  int n_[3] = {1, 1, 1}, nc_[3] = {1, 1, 1};
  std::vector<int> active_;  ///< axes with more than one node
  int D_ = 0;
  size_t allCells_ = 0;
  int first_ = 0;  ///< the first integral channel (QuantityInfo::firstIntegralChannel)
  /// Resolved once: the kind's verification reference (with opt.verifyReference), whether the
  /// table is over mu and more (Sample::inCorner) and its axis 1.
  decltype(QuantityInfo::verifyReference) verifyReference_ = nullptr;
  bool overMu_ = false;
  /// The reference is a fixed rule that spreads each point over the threads
  /// (QuantityInfo::parallelPoint).
  bool pointsParallel_ = false;
  Axis axis1_{};
  std::vector<size_t> order_, fullOrder_;
  std::vector<std::array<double, 3>> probes_;
  long long P_ = 0, C_ = 0;
  long long callBudget_ = 0, integrandBudget_ = 0, calls_ = 0, integrand_ = 0, probeCalls_ = 0;
  tbb::task_arena arena_;
  std::vector<Sample> probeSamples_, sweepSamples_;
  std::vector<size_t> cellBestProbe_;
  std::vector<Climb> climbed_;
};

int ThreadsOf(const LookupSearchOptions& opt) { return ThreadCount(opt.threads); }

LookupSearch::LookupSearch(const TableSpec& spec, const LutView& view,
                           const LookupSearchOptions& opt)
    : spec_(spec),
      view_(view),
      sampler_(view),
      reference_(spec),
      opt_(opt),
      dims_(spec.axes.size()),
      arena_(ThreadsOf(opt)) {
  for (size_t d = 0; d < dims_ && d < 3; ++d) {
    n_[d] = std::max(1, spec.axes[d].size);
    nc_[d] = std::max(1, n_[d] - 1);
    if (n_[d] > 1) active_.push_back(static_cast<int>(d));
  }
  D_ = static_cast<int>(active_.size());
  allCells_ = static_cast<size_t>(nc_[0]) * nc_[1] * nc_[2];
  // A fitted table's coefficient channels are not integrals (QuantityInfo::firstIntegralChannel).
  first_ = Describe(spec.quantity).firstIntegralChannel;
  if (opt.verifyReference) verifyReference_ = Describe(spec.quantity).verifyReference;
  pointsParallel_ = Describe(spec.quantity).parallelPoint && opt.refTol <= 0 && UsesFixedRule(spec);
  overMu_ = dims_ >= 2 && spec.axes[0].name == "mu";
  if (dims_ >= 2) axis1_ = spec.axes[1].ToAxis();
  probes_ = ProbePoints(D_);
  P_ = static_cast<long long>(probes_.size());
  C_ = kSweeps * D_ * (kGoldenIterations + 3);  // at most
  // The budget, in reference evaluations and (automatic budget only) integrand evaluations,
  // spent in chunks whose sizes depend on what was spent before, never on timing or threads.
  // A budget below one cell's probes still probes the first cell (a corner) in full: a search
  // that evaluates nothing has no report.
  callBudget_ = opt.budget > 0 ? std::max(opt.budget, P_) : kLookupBudgetCalls;
  integrandBudget_ = opt.budget > 0 ? 0 : kLookupBudgetIntegrand;
}

void LookupSearch::OrderCells() {
  std::vector<double> est;
  arena_.execute([&] { est = CellErrorEstimates(view_, first_); });
  est.resize(allCells_, 0.0);
  std::vector<size_t> corners, edges, others;
  for (size_t k = 0; k < allCells_; ++k) {
    int c[3] = {static_cast<int>(k % nc_[0]), static_cast<int>(k / nc_[0] % nc_[1]),
                static_cast<int>(k / nc_[0] / nc_[1])};
    int atEnd = 0;
    for (int a : active_) atEnd += c[a] == 0 || c[a] == nc_[a] - 1;
    if (atEnd == D_)
      corners.push_back(k);
    else if (atEnd >= D_ - 1)
      edges.push_back(k);
    else
      others.push_back(k);
  }
  auto byEstimate = [&](size_t a, size_t b) {
    return est[a] > est[b] || (est[a] == est[b] && a < b);
  };
  // The probes reach at most the first ceil(budget / P) cells (each chunk stays within the
  // budget), and only a table of at most kCentreSweepCells cells reads the rest (SweepCentres):
  // a larger one orders only those (a total order, index on ties: the same first cells).
  size_t wanted = corners.size() + edges.size() + others.size();
  if (allCells_ > kCentreSweepCells && P_ > 0)
    wanted = std::min(wanted, static_cast<size_t>((callBudget_ + P_ - 1) / P_));
  if (opt_.maxCells > 0) wanted = std::min(wanted, static_cast<size_t>(opt_.maxCells));
  auto sortFront = [&](std::vector<size_t>& v) {
    const size_t front = std::min(v.size(), wanted);
    std::partial_sort(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(front), v.end(),
                      byEstimate);
    v.resize(front);
  };
  sortFront(edges);
  sortFront(others);
  order_ = corners;
  for (size_t i = 0; i < std::max(edges.size(), others.size()); ++i) {
    if (i < edges.size()) order_.push_back(edges[i]);
    if (i < others.size()) order_.push_back(others[i]);
  }
  if (order_.size() > wanted) order_.resize(wanted);
}

void LookupSearch::PointIn(size_t cell, const std::array<double, 3>& u, double* x) const {
  int c[3] = {static_cast<int>(cell % nc_[0]), static_cast<int>(cell / nc_[0] % nc_[1]),
              static_cast<int>(cell / nc_[0] / nc_[1])};
  double t[3] = {0, 0, 0};
  for (int i = 0; i < D_; ++i) {
    int a = active_[i];
    double ua = std::min(1.0, std::max(0.0, u[i]));
    t[a] = std::min(1.0, (c[a] + ua) / static_cast<double>(n_[a] - 1));
  }
  PointAtWarped(spec_, t, x);
}

void LookupSearch::Prepare(const std::vector<std::pair<size_t, size_t>>& what) {
  const QuantityInfo& q = Describe(spec_.quantity);
  const bool fixedRule = opt_.refTol <= 0 && (opt_.bakeRule || !q.searchRule);
  if (!q.prepareSearch || !fixedRule || !UsesFixedRule(spec_) || what.empty()) return;
  std::vector<double> points(3 * what.size(), 0.0);
  for (size_t i = 0; i < what.size(); ++i)
    PointIn(what[i].first, probes_[what[i].second], &points[3 * i]);
  arena_.execute([&] { q.prepareSearch(spec_, points.data(), what.size()); });
}

Sample LookupSearch::Evaluate(size_t cell, const std::array<double, 3>& u) const {
  double x[3] = {0, 0, 0};
  PointIn(cell, u, x);
  IntegrationStats st;
  std::vector<double> exact;
  Sample s;
  s.reused = DefaultReference() && opt_.reuse && opt_.reuse(x, exact, st);
  if (!s.reused)
    exact = opt_.refTol > 0 ? (verifyReference_ ? verifyReference_(spec_, x, opt_.refTol, st)
                                                : EvaluateSpec(spec_, x, opt_.refTol, st))
            : opt_.bakeRule ? reference_.Bake(x, st)
                            : reference_.Search(x, st);
  if (opt_.bakeRule) st.errorEstimate = 0;  // the bake's own rule
  // One float per channel of the table, and at least one per exact value (a table with fewer
  // channels than its quantity then compares the missing ones against 0): on the stack for
  // up to kStackChannels of them.
  const size_t nGot = std::max<size_t>(static_cast<size_t>(view_.channels), exact.size());
  float stackGot[kStackChannels];
  std::vector<float> heapGot(nGot > kStackChannels ? nGot : 0);
  float* got = nGot > kStackChannels ? heapGot.data() : stackGot;
  std::fill(got, got + nGot, 0.0f);
  sampler_.sampleDouble(x, got, opt_.filter);
  for (size_t ch = static_cast<size_t>(first_); ch < exact.size(); ++ch)
    s.err = std::max(s.err, std::abs(got[ch] - exact[ch]));
  if (opt_.alsoCubic) {
    sampler_.sampleDouble(x, got, Filter::Cubic);
    for (size_t ch = static_cast<size_t>(first_); ch < exact.size(); ++ch)
      s.cubic = std::max(s.cubic, std::abs(got[ch] - exact[ch]));
  }
  s.inCorner = overMu_ && axis1_.texel(x[1]) < 1;
  s.integrand = st.evals;
  s.refError = opt_.refTol > 0 ? 0.0 : st.errorEstimate;
  std::copy(x, x + 3, s.x);
  if (opt_.record && DefaultReference()) s.exact = std::move(exact);
  return s;
}

bool LookupSearch::Spent(double share) const {
  return calls_ >= static_cast<long long>(share * static_cast<double>(callBudget_)) ||
         (integrandBudget_ > 0 &&
          integrand_ >= static_cast<long long>(share * static_cast<double>(integrandBudget_)));
}

void LookupSearch::Probe() {
  const long long allProbes = static_cast<long long>(order_.size()) * P_;
  const double probeShare = allProbes <= callBudget_ * kProbeShare || C_ == 0 ? 1.0 : kProbeShare;
  // The probes' samples in one block (growing it chunk by chunk moved them all, again and again).
  probeSamples_.reserve(static_cast<size_t>(std::min(allProbes, callBudget_)));
  while (calls_ < allProbes && !Spent(probeShare)) {
    long long chunk =
        std::min({std::max({8LL, P_, calls_ / 8}), allProbes - calls_, callBudget_ - calls_});
    if (chunk <= 0) break;
    size_t base = probeSamples_.size();
    probeSamples_.resize(base + static_cast<size_t>(chunk));
    std::vector<std::pair<size_t, size_t>> what;
    for (size_t i = base; i < probeSamples_.size(); ++i)
      what.push_back({order_[i / P_], static_cast<size_t>(i % P_)});
    Prepare(what);
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(base, probeSamples_.size(), 1),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i != r.end(); ++i)
                            probeSamples_[i] = Evaluate(order_[i / P_], probes_[i % P_]);
                        });
    });
    for (size_t i = base; i < probeSamples_.size(); ++i) integrand_ += probeSamples_[i].integrand;
    calls_ += chunk;
  }
  probeCalls_ = calls_;
  fullOrder_ = order_;
  order_.resize(static_cast<size_t>((probeCalls_ + P_ - 1) / P_));
}

void LookupSearch::EvaluateAll(std::vector<Sample>& out, size_t base,
                               const std::vector<std::pair<size_t, size_t>>& what) {
  out.resize(base + what.size());
  Prepare(what);
  arena_.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, what.size(), 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i)
                          out[base + i] = Evaluate(what[i].first, probes_[what[i].second]);
                      });
  });
}

void LookupSearch::SweepCentres() {
  // A small table the automatic budget probed only in part (a search of 3 of 345 cells declared
  // 8.3e-4 for ggx-dielectric-albedo-r-exit-avg where `kiln verify --budget 20000` found 9.8e-4):
  // the last cell's probes completed, every unprobed cell's centre evaluated, and as many of
  // them as were probed (at least 8), by centre error descending, probed in full and searched
  // like the others; outside the budget (the climbs keep theirs), deterministic.
  const long long allProbes = static_cast<long long>(fullOrder_.size()) * P_;
  if (!(opt_.budget == 0 && opt_.maxCells == 0 && allCells_ <= kCentreSweepCells &&
        probeCalls_ < allProbes && P_ > 0))
    return;
  std::vector<std::pair<size_t, size_t>> rest;  // (cell, probe)
  for (size_t i = probeSamples_.size(); i < order_.size() * static_cast<size_t>(P_); ++i)
    rest.push_back({order_[i / P_], i % P_});
  EvaluateAll(probeSamples_, probeSamples_.size(), rest);
  std::vector<std::pair<size_t, size_t>> centres;
  for (size_t k = order_.size(); k < fullOrder_.size(); ++k) centres.push_back({fullOrder_[k], 0});
  EvaluateAll(sweepSamples_, 0, centres);
  std::vector<size_t> byCentre(centres.size());
  for (size_t i = 0; i < byCentre.size(); ++i) byCentre[i] = i;
  std::stable_sort(byCentre.begin(), byCentre.end(),
                   [&](size_t a, size_t b) { return sweepSamples_[a].err > sweepSamples_[b].err; });
  const size_t more = std::min(byCentre.size(), std::max<size_t>(8, order_.size()));
  std::vector<bool> taken(centres.size(), false);
  std::vector<std::pair<size_t, size_t>> full;
  for (size_t j = 0; j < more; ++j) {
    taken[byCentre[j]] = true;
    for (long long q = 1; q < P_; ++q)
      full.push_back({centres[byCentre[j]].first, static_cast<size_t>(q)});
  }
  std::vector<Sample> fullSamples;
  EvaluateAll(fullSamples, 0, full);
  for (size_t j = 0; j < more; ++j) {
    order_.push_back(centres[byCentre[j]].first);
    probeSamples_.push_back(sweepSamples_[byCentre[j]]);
    for (long long q = 1; q < P_; ++q)
      probeSamples_.push_back(
          fullSamples[j * static_cast<size_t>(P_ - 1) + static_cast<size_t>(q - 1)]);
  }
  std::vector<Sample> untaken;
  for (size_t i = 0; i < centres.size(); ++i)
    if (!taken[i]) untaken.push_back(sweepSamples_[i]);
  sweepSamples_.swap(untaken);
  probeCalls_ = static_cast<long long>(probeSamples_.size());
}

void LookupSearch::RandomPoints() {
  // A fixed seed per index.
  std::vector<Sample> randomSamples(static_cast<size_t>(std::max(0LL, opt_.randomPoints)));
  arena_.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, randomSamples.size(), 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i) {
                          uint64_t h = 0x9E3779B97F4A7C15ull * (i + 1);
                          size_t cell = 0, stride = 1;
                          std::array<double, 3> u{0.5, 0.5, 0.5};
                          for (int a = 0; a < 3; ++a) {
                            h ^= h >> 31;
                            h *= 0xBF58476D1CE4E5B9ull;
                            h ^= h >> 29;
                            double texel = static_cast<double>(h >> 11) * 0x1p-53 * nc_[a];
                            int c = std::min(nc_[a] - 1, static_cast<int>(texel));
                            cell += stride * static_cast<size_t>(c);
                            stride *= static_cast<size_t>(nc_[a]);
                            for (int i2 = 0; i2 < D_; ++i2)
                              if (active_[i2] == a) u[i2] = texel - c;
                          }
                          randomSamples[i] = Evaluate(cell, u);
                        }
                      });
  });
  probeSamples_.insert(probeSamples_.end(), randomSamples.begin(), randomSamples.end());
  probeSamples_.insert(probeSamples_.end(), sweepSamples_.begin(), sweepSamples_.end());
}

namespace {

/// One golden-section bracket [lo, hi] of the climb along one axis, with its two inner points
/// and their errors.
struct Bracket {
  double lo = 0, hi = 1, x1 = 0, x2 = 0, f1 = 0, f2 = 0;
  bool newIsX1 = false;  ///< which inner point Advance placed last
};

/// The golden ratio's conjugate, 0.618: the bracket shrinks by it per iteration.
const double kGolden = 0.5 * (std::sqrt(5.0) - 1.0);

/// One golden-section iteration: keeps the inner point that erred more (x1 on a tie goes) and
/// returns the new inner point, whose error Settle then records.
double Advance(Bracket& b) {
  b.newIsX1 = b.f1 > b.f2;
  if (b.newIsX1) {
    b.hi = b.x2;
    b.x2 = b.x1;
    b.f2 = b.f1;
    b.x1 = b.hi - kGolden * (b.hi - b.lo);
    return b.x1;
  }
  b.lo = b.x1;
  b.x1 = b.x2;
  b.f1 = b.f2;
  b.x2 = b.lo + kGolden * (b.hi - b.lo);
  return b.x2;
}

/// The error f of the point Advance placed last.
void Settle(Bracket& b, double f) { (b.newIsX1 ? b.f1 : b.f2) = f; }

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

Climb LookupSearch::ClimbCell(size_t slot, bool speculate) const {
  size_t cell = order_[slot];
  Climb cl;
  cl.u = probes_[cellBestProbe_[slot]];
  cl.best = probeSamples_[slot * P_ + cellBestProbe_[slot]];
  // Along axis `axis` the points differ in u[axis] only (cl.u moves along it alone): a point is
  // evaluated (eval, thread-safe) and then used (use: in the serial order, the only one that
  // counts it, keeps the best and records it), so that a point evaluated ahead gives the same
  // climb.
  int axis = 0;
  auto eval = [&](double v) {
    std::array<double, 3> u = cl.u;
    u[axis] = v;
    return Evaluate(cell, u);
  };
  auto use = [&](double v, Sample s) {
    ++cl.evals;
    cl.reused += s.reused;
    cl.integrand += s.integrand;
    cl.refError = std::max(cl.refError, s.refError);
    const double err = s.err;
    if (s.err > cl.best.err) {
      cl.best = s;
      cl.u[axis] = v;
    }
    if (opt_.record && DefaultReference()) cl.visited.push_back(std::move(s));
    return err;
  };
  // With `speculate` (a climb alone on more than one thread), the point after the next one is
  // evaluated beside it, as if the next one erred more than the point it is compared with; it
  // is used when the climb goes there (half the time), else dropped (never counted).
  bool haveAhead = false;
  double aheadAt = 0;
  Sample ahead;
  // On the last iteration the point ahead is the bracket's end on the cell's face, when the
  // climb evaluates it (below).
  auto next = [&](const Bracket& b, double v, bool last) {
    if (haveAhead && SameBits(aheadAt, v)) {
      haveAhead = false;
      return use(v, std::move(ahead));
    }
    haveAhead = false;
    Sample s;
    double w = 0;
    if (last) {
      haveAhead = b.lo == 0.0 || b.hi == 1.0;
      w = b.lo == 0.0 ? 0.0 : 1.0;
    } else {
      Bracket guess = b;
      Settle(guess, std::numeric_limits<double>::infinity());
      w = Advance(guess);
      haveAhead = true;
    }
    if (speculate && haveAhead) {
      tbb::parallel_invoke([&] { s = eval(v); }, [&] { ahead = eval(w); });
      aheadAt = w;
    } else {
      haveAhead = false;
      s = eval(v);
    }
    return use(v, std::move(s));
  };
  // The bracket's end at v, evaluated ahead or now.
  auto end = [&](double v) {
    if (haveAhead && SameBits(aheadAt, v)) {
      haveAhead = false;
      use(v, std::move(ahead));
    } else {
      use(v, eval(v));
    }
  };
  for (int sweep = 0; sweep < kSweeps; ++sweep)
    for (axis = 0; axis < D_; ++axis) {
      const double centre = cl.u[axis], w = kSweepHalfWidth[sweep];
      Bracket b;
      b.lo = std::max(0.0, centre - w);
      b.hi = std::min(1.0, centre + w);
      b.x1 = b.hi - kGolden * (b.hi - b.lo);
      b.x2 = b.lo + kGolden * (b.hi - b.lo);
      if (speculate) {
        Sample s1, s2;
        tbb::parallel_invoke([&] { s1 = eval(b.x1); }, [&] { s2 = eval(b.x2); });
        b.f1 = use(b.x1, std::move(s1));
        b.f2 = use(b.x2, std::move(s2));
      } else {
        b.f1 = use(b.x1, eval(b.x1));
        b.f2 = use(b.x2, eval(b.x2));
      }
      haveAhead = false;
      for (int it = 0; it < kGoldenIterations; ++it) {
        const double v = Advance(b);
        Settle(b, next(b, v, it + 1 == kGoldenIterations));
      }
      // A maximum on the cell's face (a layer along a node line, the domain's boundary): the
      // golden section never evaluates its bracket's ends.
      if (b.lo == 0.0) end(0.0);
      if (b.hi == 1.0) end(1.0);
      haveAhead = false;
    }
  return cl;
}

void LookupSearch::Climbs() {
  std::vector<double> cellMax(order_.size(), 0.0);
  cellBestProbe_.assign(order_.size(), 0);
  for (size_t i = 0; i < static_cast<size_t>(probeCalls_); ++i)
    if (i % P_ == 0 || probeSamples_[i].err > cellMax[i / P_]) {
      cellMax[i / P_] = probeSamples_[i].err;
      cellBestProbe_[i / P_] = i % P_;
    }
  std::vector<size_t> rank(order_.size());
  for (size_t i = 0; i < rank.size(); ++i) rank[i] = i;
  std::stable_sort(rank.begin(), rank.end(),
                   [&](size_t a, size_t b) { return cellMax[a] > cellMax[b]; });
  // At least one cell climbs (two when the probes left budget).
  while (C_ > 0 && climbed_.size() < rank.size() && (climbed_.empty() || !Spent(1.0))) {
    size_t chunk =
        std::min(rank.size() - climbed_.size(), std::max<size_t>(2, climbed_.size() / 8));
    if (!climbed_.empty() && callBudget_ - calls_ < C_) break;
    chunk = climbed_.empty()
                ? std::min<size_t>(chunk, Spent(1.0) ? 1 : 2)
                : std::min<size_t>(chunk, static_cast<size_t>((callBudget_ - calls_) / C_));
    size_t base = climbed_.size();
    climbed_.resize(base + chunk);
    // Fewer climbs than threads: each climb evaluates ahead on the idle ones (ClimbCell), unless
    // the kind's rule spreads each point over them already (QuantityInfo::parallelPoint).
    const bool speculate =
        chunk < static_cast<size_t>(arena_.max_concurrency()) && !pointsParallel_;
    arena_.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(base, climbed_.size(), 1),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t j = r.begin(); j != r.end(); ++j)
                            climbed_[j] = ClimbCell(rank[j], speculate);
                        });
    });
    for (size_t j = base; j < climbed_.size(); ++j) {
      calls_ += climbed_[j].evals;
      integrand_ += climbed_[j].integrand;
    }
  }
}

LookupErrorReport LookupSearch::Report() {
  LookupErrorReport rep;
  rep.allCells = static_cast<long long>(allCells_);
  rep.budget = callBudget_;
  double sum = 0, sumCubic = 0;
  long long worstProbe = 0;
  for (size_t i = 0; i < probeSamples_.size(); ++i) {
    const Sample& s = probeSamples_[i];
    if (s.err > probeSamples_[static_cast<size_t>(worstProbe)].err)
      worstProbe = static_cast<long long>(i);
    if (!s.inCorner) rep.maxOutsideCorner = std::max(rep.maxOutsideCorner, s.err);
    sum += s.err * s.err;
    sumCubic += s.cubic * s.cubic;
    rep.referenceError = std::max(rep.referenceError, s.refError);
    rep.cubicMax = std::max(rep.cubicMax, s.cubic);
    rep.reused += s.reused;
  }
  rep.max = probeSamples_[static_cast<size_t>(worstProbe)].err;
  const Sample& w = probeSamples_[static_cast<size_t>(worstProbe)];
  rep.where.assign(w.x, w.x + dims_);
  long long points = static_cast<long long>(probeSamples_.size());
  for (const Climb& cl : climbed_) {
    points += cl.evals;
    rep.reused += cl.reused;
    rep.referenceError = std::max(rep.referenceError, cl.refError);
    if (!cl.best.inCorner) rep.maxOutsideCorner = std::max(rep.maxOutsideCorner, cl.best.err);
    if (cl.best.err > rep.max) {
      rep.max = cl.best.err;
      rep.where.assign(cl.best.x, cl.best.x + dims_);
    }
  }
  const double count = static_cast<double>(std::max<size_t>(1, probeSamples_.size()));
  rep.rms = std::sqrt(sum / count);
  if (opt_.alsoCubic)
    rep.cubicRms = std::sqrt(sumCubic / count);
  else
    rep.cubicMax = -1;
  rep.points = points;
  rep.cells = static_cast<long long>(order_.size());
  rep.climbed = static_cast<long long>(climbed_.size());
  return rep;
}

void LookupSearch::Record() {
  if (!opt_.record || !DefaultReference()) return;
  // The references move into the memo (Report reads no sample's `exact`).
  size_t n = probeSamples_.size();
  for (const Climb& cl : climbed_) n += cl.visited.size();
  opt_.record->Reserve(opt_.record->size() + n);
  auto add = [&](Sample& s) {
    if (!s.exact.empty())
      opt_.record->Add(s.x, SearchMemo::Entry{std::move(s.exact), s.integrand, s.refError});
  };
  for (Sample& s : probeSamples_) add(s);
  for (Climb& cl : climbed_)
    for (Sample& s : cl.visited) add(s);
}

}  // namespace

LookupErrorReport MeasureLookupError(const TableSpec& spec, const LutView& view,
                                     const LookupSearchOptions& opt) {
  LookupSearch search(spec, view, opt);
  search.OrderCells();
  search.Probe();
  search.SweepCentres();
  search.RandomPoints();
  search.Climbs();
  search.Record();
  return search.Report();
}

}  // namespace kiln
