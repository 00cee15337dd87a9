#include "baker/bench/bench.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <thread>

#include <unistd.h>

#include "baker/bench/call_timing.h"
#include "baker/bench/estimate_table.h"
#include "baker/bench/reference.h"
#include "baker/fit/fit.h"
#include "baker/bake/bake.h"
#include "baker/io/atomic_write.h"
#include "baker/tables/catalogue.h"
#include "baker/util/threads.h"

namespace kiln {
namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// A table kind of the sweep: a catalogue table, its axis sizes for the sweep, and the sizes of
/// the size sweep.
struct Kind {
  std::string table;
  std::vector<int> base;
  std::vector<std::vector<int>> sizes;
};

/// What a scale measures.
struct Plan {
  std::vector<Kind> kinds;
  std::vector<double> tols;
  std::vector<int> mcSamples, glOrders;
  int sizeSweepSamples = 1024;  ///< Monte Carlo samples of the size sweep and the baker issue
  int issueSize = 128;          ///< the baker issue's ggx-dfg table
  ReferenceOptions ref;
  long long lookupCalls = 0, evaluateCalls = 0, integrateCalls = 0;
  int batches = 0;
  double runtimeTableTol = 1e-4;  ///< tolerance of the 1D tables the runtime section looks up
  std::vector<int> runtime1DSize;
  /// Coefficients per channel of the ggx-dfg fit the runtime section times (docs/fits.md): the
  /// fit's least squares are most of a Tiny run, whose form only has to be timed.
  int fitTerms = 144;
};

Plan MakePlan(BenchScale scale) {
  Plan p;
  if (scale == BenchScale::Full) {
    p.kinds = {{"ggx-dfg", {64, 64}, {{16, 16}, {32, 32}, {64, 64}, {128, 128}}},
               {"burley-albedo", {32, 32}, {{16, 16}, {32, 32}, {64, 64}, {128, 128}, {256, 256}}},
               {"ggx-fresnel-albedo", {32, 32, 16}, {{8, 8, 8}, {16, 16, 8}, {32, 32, 16}}},
               {"oren-nayar-albedo", {32, 32}, {}}};
    p.tols = {1e-4, 1e-6, 1e-8};
    p.mcSamples = {64, 256, 1024, 4096, 16384, 65536};
    p.glOrders = {8, 16, 32, 64, 128};
    p.issueSize = 128;
    p.ref.maxCellCentres = 2048;
    p.ref.randomPoints = 500;
    p.lookupCalls = 1 << 20;
    p.evaluateCalls = 1 << 18;
    p.integrateCalls = 16;
    p.batches = 7;
    p.runtime1DSize = {64};
  } else if (scale == BenchScale::Quick) {
    p.kinds = {{"ggx-dfg", {24, 24}, {{12, 12}, {24, 24}}},
               {"burley-albedo", {32, 32}, {{16, 16}, {32, 32}, {64, 64}}},
               {"ggx-fresnel-albedo", {12, 12, 6}, {{6, 6, 6}, {12, 12, 6}}}};
    p.tols = {1e-4, 1e-8};
    p.mcSamples = {64, 256, 1024, 4096};
    p.glOrders = {8, 16, 32, 64};
    p.issueSize = 24;
    p.ref.maxCellCentres = 256;
    p.ref.randomPoints = 128;
    p.lookupCalls = 1 << 18;
    p.evaluateCalls = 1 << 16;
    p.integrateCalls = 2;
    p.batches = 5;
    p.runtime1DSize = {16};
  } else {
    p.kinds = {{"ggx-dfg", {8, 8}, {{6, 6}, {8, 8}}},
               {"burley-albedo", {8, 8}, {{8, 8}}},
               {"ggx-fresnel-albedo", {4, 4, 3}, {{4, 4, 3}}}};
    p.tols = {1e-4, 1e-6};
    p.mcSamples = {64, 256, 1024};
    p.glOrders = {8, 16};
    p.sizeSweepSamples = 256;
    p.issueSize = 8;
    p.ref.tol = 1e-9;
    p.ref.maxCellCentres = 32;
    p.ref.randomPoints = 16;
    p.lookupCalls = 4096;
    p.evaluateCalls = 4096;
    p.integrateCalls = 1;
    p.batches = 3;
    p.runtime1DSize = {8};
    p.fitTerms = 12;
  }
  return p;
}

TableSpec Sized(const std::string& name, const std::vector<int>& sizes) {
  TableSpec s = CatalogueTable(name);
  // The bench compares E itself with Monte Carlo and Gauss-Legendre: a table stored as a
  // residual against a closed form (ggx-fresnel-albedo's E_residual) is baked as E here.
  if (s.channels.size() == 1 && s.channels[0] == "E_residual") {
    const QuantityInfo& q = Describe(s.quantity);
    s.channels = q.makeSpec(s.model, s.axes).channels;
    s.meanings = q.makeSpec(s.model, s.axes).meanings;
  }
  if (sizes.size() != s.axes.size())
    throw std::invalid_argument("bench: table '" + name + "' has " + std::to_string(s.axes.size()) +
                                " axes");
  for (size_t d = 0; d < sizes.size(); ++d) s.axes[d].size = sizes[d];
  return s;
}

std::string SizeText(const TableSpec& s) {
  std::string t;
  for (const AxisSpec& a : s.axes) t += (t.empty() ? "" : "x") + std::to_string(a.size);
  return t;
}

std::string Fmt3(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string Sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}

/// A baked table with its median wall time.
struct Measured {
  Table table;
  double seconds = 0;
  int runs = 0;
  long long evals = 0;
};

/// Runs `once(evals)` (which returns a table) 1, 3 or 5 times by the first run's wall time and
/// keeps the first table and the median time.
template <class F>
Measured TimeRuns(F&& once) {
  Measured m;
  std::vector<double> t;
  for (;;) {
    auto t0 = Clock::now();
    long long evals = 0;
    Table table = once(evals);
    t.push_back(Since(t0));
    if (t.size() == 1) {
      m.table = std::move(table);
      m.evals = evals;
    }
    size_t want = t[0] < 0.25 ? 5 : t[0] < 1 ? 3 : 1;
    if (t.size() >= want) break;
  }
  std::sort(t.begin(), t.end());
  m.seconds = t[t.size() / 2];
  m.runs = static_cast<int>(t.size());
  return m;
}

/// Runs every `once` once per round, `rounds` rounds, and keeps each one's first table and
/// median time: the machine's speed drifts by tens of percent over seconds, so times that are to
/// be compared are taken side by side.
std::vector<Measured> InterleavedRuns(const std::vector<std::function<Table(long long&)>>& once,
                                      int rounds) {
  std::vector<Measured> m(once.size());
  std::vector<std::vector<double>> times(once.size());
  for (int r = 0; r < rounds; ++r)
    for (size_t i = 0; i < once.size(); ++i) {
      auto t0 = Clock::now();
      long long evals = 0;
      Table t = once[i](evals);
      times[i].push_back(Since(t0));
      if (r == 0) {
        m[i].table = std::move(t);
        m[i].evals = evals;
      }
    }
  for (size_t i = 0; i < once.size(); ++i) {
    std::sort(times[i].begin(), times[i].end());
    m[i].seconds = times[i][times[i].size() / 2];
    m[i].runs = rounds;
  }
  return m;
}

class Bench {
 public:
  Bench(const BenchOptions& opt, std::FILE* log)
      : opt_(opt), plan_(MakePlan(opt.scale)), log_(log), threads_(ThreadCount(opt.threads)) {
    plan_.ref.threads = threads_;
  }

  std::vector<BenchRow> Run() {
    for (const Kind& k : plan_.kinds) Sweep(k);
    BakerIssue();
    for (const Kind& k : plan_.kinds) SizeSweep(k);
    Threads();
    Runtime();
    return rows_;
  }

 private:
  static std::string Key(const TableSpec& s) { return s.name + "@" + SizeText(s); }

  const Reference& Ref(const TableSpec& spec) {
    auto it = refs_.find(Key(spec));
    if (it != refs_.end()) return it->second;
    Reference r = ComputeReference(spec, plan_.ref);
    Log("reference %s %s: tol %.0e, %zu nodes + %zu cell centres (of %zu) + %zu random points, "
        "%.2f s\n",
        spec.name.c_str(), SizeText(spec).c_str(), plan_.ref.tol, spec.TexelCount(), r.cellCentres,
        r.totalCells, r.randomPoints, r.seconds);
    return refs_.emplace(Key(spec), std::move(r)).first->second;
  }

  const Measured& Kiln(const TableSpec& base, double tol, int threads) {
    std::string key = Key(base) + "|kiln|" + Sci(tol) + "|" + std::to_string(threads);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    TableSpec spec = base;
    spec.tol = tol;
    BakeOptions bo;
    bo.threads = threads;
    bo.measureLookupError = false;
    Measured m = TimeRuns([&](long long& evals) {
      BakeStats st;
      Table t = BakeTable(spec, bo, &st);
      evals = st.evals;
      return t;
    });
    return cache_.emplace(key, std::move(m)).first->second;
  }

  /// Monte Carlo (gaussLegendre false: `n` Hammersley samples) or the n x n Gauss-Legendre rule.
  const Measured& Estimate(const TableSpec& spec, bool gaussLegendre, int n, int threads) {
    std::string key = Key(spec) + (gaussLegendre ? "|gl|" : "|mc|") + std::to_string(n) + "|" +
                      std::to_string(threads);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    std::string method = gaussLegendre ? std::to_string(n) + "x" + std::to_string(n) +
                                             " Gauss-Legendre rule, importance-sampled map"
                                       : std::to_string(n) +
                                             "-sample Hammersley Monte Carlo, "
                                             "importance sampling";
    Measured m = TimeRuns([&](long long& evals) {
      PointSet points = gaussLegendre ? GaussLegendrePoints(n) : HammersleyPoints(n);
      BakeStats st;
      Table t = EstimateTable(spec, points, method, threads, &st);
      evals = st.evals;
      return t;
    });
    return cache_.emplace(key, std::move(m)).first->second;
  }

  BenchRow Row(const std::string& section, const std::string& method, const TableSpec& spec,
               double setting, int threads, const Measured& m) {
    const Reference& ref = Ref(spec);
    BenchRow r;
    r.section = section;
    r.method = method;
    r.table = spec.name;
    r.dims = static_cast<int>(spec.axes.size());
    r.size = SizeText(spec);
    r.texels = static_cast<long long>(spec.TexelCount());
    r.setting = setting;
    r.threads = threads;
    r.seconds = m.seconds;
    r.runs = m.runs;
    r.evals = m.evals;
    ErrorStats b = BakeError(m.table, ref), lin = LookupError(m.table, ref, Filter::Linear),
               cub = LookupError(m.table, ref, Filter::Cubic);
    r.bakeMax = b.max;
    r.bakeRms = b.rms;
    r.linearMax = lin.max;
    r.linearRms = lin.rms;
    r.cubicMax = cub.max;
    r.cubicRms = cub.rms;
    r.linearMaxOffCorner = lin.maxOffCorner;
    r.bytes = static_cast<long long>(m.table.data.size() * sizeof(float));
    auto at = [&](const std::vector<double>& x) {
      std::string s;
      for (size_t d = 0; d < x.size(); ++d) s += " " + spec.axes[d].name + "=" + Fmt3(x[d]);
      return s;
    };
    std::string warps;
    for (const AxisSpec& a : spec.axes) warps += " " + a.name + ":" + warpName(a.warp);
    r.note = "warps" + warps + "; max bake error at" + at(b.worstAt) +
             "; max linear lookup error at" + at(lin.worstAt);
    return r;
  }

  void Add(const BenchRow& r) {
    rows_.push_back(r);
    if (r.section == "runtime") {
      Log("%-11s %-18s %-18s %-9s %10.1f ns/call %s%s\n", r.section.c_str(), r.method.c_str(),
          r.table.c_str(), r.size.c_str(), r.nsPerCall, r.note.c_str(),
          r.evals ? (" (" + std::to_string(r.evals) + " evals per call)").c_str() : "");
      return;
    }
    Log("%-11s %-18s %-18s %-9s %-7g %2d thr %8.3f s (%d) %11lld evals  bake %.1e/%.1e  "
        "lookup lin %.1e (off corner %.1e) cub %.1e%s%s\n",
        r.section.c_str(), r.method.c_str(), r.table.c_str(), r.size.c_str(), r.setting, r.threads,
        r.seconds, r.runs, r.evals, r.bakeMax, r.bakeRms, r.linearMax, r.linearMaxOffCorner,
        r.cubicMax, r.note.empty() ? "" : "  ", r.note.c_str());
  }

  void Sweep(const Kind& k) {
    TableSpec spec = Sized(k.table, k.base);
    if (UsesFixedRule(spec)) {  // one method, no tolerance: the fixed rule and its bound
      const Measured& m = Kiln(spec, spec.tol, threads_);
      Add(Row("sweep", "kiln-fixed-rule", spec, m.table.bakeError - 0x1p-24, threads_, m));
    } else {
      for (double tol : plan_.tols)
        Add(Row("sweep", "kiln", spec, tol, threads_, Kiln(spec, tol, threads_)));
    }
    for (int n : plan_.mcSamples)
      Add(Row("sweep", "mc-hammersley", spec, n, threads_, Estimate(spec, false, n, threads_)));
    for (int n : plan_.glOrders)
      Add(Row("sweep", "gauss-legendre", spec, static_cast<double>(n) * n, threads_,
              Estimate(spec, true, n, threads_)));
  }

  void SizeSweep(const Kind& k) {
    for (const std::vector<int>& sizes : k.sizes) {
      TableSpec spec = Sized(k.table, sizes);
      Add(Row("size", "kiln", spec, spec.tol, threads_, Kiln(spec, spec.tol, threads_)));
      Add(Row("size", "mc-hammersley", spec, plan_.sizeSweepSamples, threads_,
              Estimate(spec, false, plan_.sizeSweepSamples, threads_)));
    }
  }

  /// `kiln bake --only ggx-dfg --size N -j 2` (texels, lookup-error check, EXR write) against
  /// the Monte Carlo bake of the same table on 2 threads. The machine's speed drifts by tens of
  /// percent over seconds, so every variant runs once per round, rounds repeated, medians kept:
  /// the ratios come from times taken side by side.
  void BakerIssue() {
    TableSpec spec = Sized("ggx-dfg", {plan_.issueSize, plan_.issueSize});
    const int threads = 2, n = plan_.sizeSweepSamples, rounds = 7;
    const std::string size = std::to_string(plan_.issueSize);
    std::string dir =
        (std::filesystem::temp_directory_path() / ("kiln-bench-" + std::to_string(::getpid())))
            .string();
    std::filesystem::create_directories(dir);
    BakeOptions texels, command;
    texels.threads = command.threads = threads;
    texels.measureLookupError = false;
    command.measureLookupError = true;
    PointSet points = HammersleyPoints(n);
    const std::string mcMethod =
        std::to_string(n) + "-sample Hammersley Monte Carlo, importance sampling";
    double lookupSeconds = 0;
    struct Variant {
      std::string method, note;
      double setting;
      std::function<Table(long long&)> once;
    };
    std::vector<Variant> v;
    auto kilnBake = [&](const BakeOptions& bo, bool write) {
      return [&, bo, write](long long& evals) {
        BakeStats st;
        Table t = BakeTable(spec, bo, &st);
        if (write) WriteBakedTable(dir, t, false, false, threads);
        evals = st.evals;
        if (bo.measureLookupError) lookupSeconds = st.lookupSeconds;
        return t;
      };
    };
    auto mcBake = [&](bool write) {
      return [&, write](long long& evals) {
        BakeStats st;
        Table t = EstimateTable(spec, points, mcMethod, threads, &st);
        if (write) WriteBakedTable(dir, t, false, false, threads);
        evals = st.evals;
        return t;
      };
    };
    v.push_back({"kiln", "texels only (BakeTable wall time)", spec.tol, kilnBake(texels, false)});
    v.push_back({"kiln-bake-command",
                 "as kiln bake --only ggx-dfg --size " + size +
                     " -j 2: texels + its lookup-error check + EXR write",
                 spec.tol, kilnBake(command, true)});
    v.push_back({"kiln-bake-written",
                 "as kiln bake --only ggx-dfg --size " + size +
                     " -j 2 --no-lookup-error: texels + EXR write",
                 spec.tol, kilnBake(texels, true)});
    v.push_back({"mc-hammersley",
                 "GGX importance sampling, height-correlated Smith (the Filament/UE4 DFG "
                 "estimator), half vectors of a row computed once",
                 double(n), mcBake(false)});
    v.push_back({"mc-hammersley-written", "the Monte Carlo bake + the same EXR write", double(n),
                 mcBake(true)});
    v.push_back({"mc-hammersley-per-texel",
                 "the same estimator with every texel drawing its own points and half "
                 "vectors, as Filament's libs/ibl DFV and the UE4/LearnOpenGL listings",
                 double(n), [&](long long& evals) {
                   BakeStats st;
                   Table t = EstimateDFGTablePerTexel(spec, n, threads, &st);
                   evals = st.evals;
                   return t;
                 }});
    std::vector<std::function<Table(long long&)>> once;
    for (const Variant& x : v) once.push_back(x.once);
    std::vector<Measured> measured = InterleavedRuns(once, rounds);
    std::filesystem::remove_all(dir);
    for (size_t i = 0; i < v.size(); ++i) {
      const Variant& x = v[i];
      BenchRow row = Row("baker-issue", x.method, spec, x.setting, threads, measured[i]);
      row.note = x.note +
                 (x.method == "kiln-bake-command"
                      ? " (lookup-error check " + Sci(lookupSeconds) + " s in the last run)"
                      : "") +
                 "; median of " + std::to_string(rounds) + " rounds, variants interleaved; " +
                 row.note;
      Add(row);
    }
  }

  void Threads() {
    const Kind& k = plan_.kinds.front();
    TableSpec spec = Sized(k.table, k.base);
    std::vector<int> counts = {1};
    if (threads_ > 1) counts.push_back(threads_);
    const int n = plan_.sizeSweepSamples;
    PointSet points = HammersleyPoints(n);
    std::vector<std::function<Table(long long&)>> once;
    for (int c : counts)
      once.push_back([&, c](long long& evals) {
        BakeOptions bo;
        bo.threads = c;
        bo.measureLookupError = false;
        BakeStats st;
        Table t = BakeTable(spec, bo, &st);
        evals = st.evals;
        return t;
      });
    for (int c : counts)
      once.push_back([&, c](long long& evals) {
        BakeStats st;
        Table t = EstimateTable(
            spec, points, std::to_string(n) + "-sample Hammersley Monte Carlo, importance sampling",
            c, &st);
        evals = st.evals;
        return t;
      });
    std::vector<Measured> m = InterleavedRuns(once, 7);
    const std::string how = "median of 7 rounds, thread counts interleaved";
    for (size_t i = 0; i < counts.size(); ++i) {
      BenchRow r = Row("threads", "kiln", spec, spec.tol, counts[i], m[i]);
      r.note = (m[i].table.data == m[0].table.data
                    ? "texels bit-identical to the 1-thread bake"
                    : "texels DIFFER from the 1-thread bake") +  // must not
               std::string("; ") +
               how;
      Add(r);
    }
    for (size_t i = 0; i < counts.size(); ++i) {
      BenchRow r = Row("threads", "mc-hammersley", spec, n, counts[i], m[counts.size() + i]);
      r.note = how;
      Add(r);
    }
  }

  void AddTiming(const std::string& method, const std::string& table, int dims,
                 const std::string& size, double setting, const CallTiming& t,
                 const std::string& note) {
    BenchRow r;
    r.section = "runtime";
    r.method = method;
    r.table = table;
    r.dims = dims;
    r.size = size;
    r.setting = setting;
    r.threads = 1;
    r.seconds = t.seconds;
    r.runs = plan_.batches;
    r.evals = t.evalsPerCall;
    r.nsPerCall = t.nsPerCall;
    r.note = note;
    Add(r);
  }

  /// Per filter: LutView::sample (lookup-*), a prepared LutSampler (sampler-*) and its batch
  /// call (batch-*); the notes give each against a plain bilinear lookup, and a 3D table's also
  /// against a plain trilinear lookup of its size (a row of its own), each timed again just
  /// before the row.
  void Lookups(const Table& t, const std::string& size) {
    const std::string batches = "median of " + std::to_string(plan_.batches) + " batches of " +
                                std::to_string(plan_.lookupCalls) + " ";
    double plain3Ns = 0;
    if (t.dims() == 3) {
      const LutView v = t.view();
      const CallTiming plain = TimePlainTrilinear(v.size(0), v.size(1), v.size(2), v.channels,
                                                  plan_.lookupCalls, plan_.batches);
      plain3Ns = plain.nsPerCall;
      AddTiming("plain-trilinear", t.name, 3, size, NAN, plain,
                batches +
                    "float trilinear lookups of a table of this size and channel count, "
                    "sqrt roughness, no warp");
    }
    struct Way {
      const char* prefix;
      LookupCall how;
      const char* what;
    };
    const Way ways[] = {{"lookup", LookupCall::View, "LutView::sample calls"},
                        {"sampler", LookupCall::Sampler, "LutSampler::sample calls"},
                        {"batch", LookupCall::Batch, "points through LutSampler's batch call"}};
    for (Filter filter : {Filter::Linear, Filter::Cubic}) {
      for (const Way& w : ways) {
        // The plain lookups timed again just before, so that a ratio compares timings taken
        // under the same load of a shared machine.
        const double plain2 = TimePlainBilinear(plan_.lookupCalls, plan_.batches).nsPerCall;
        const double plain3 =
            plain3Ns > 0 ? TimePlainTrilinear(t.view().size(0), t.view().size(1), t.view().size(2),
                                              t.view().channels, plan_.lookupCalls, plan_.batches)
                               .nsPerCall
                         : 0.0;
        const CallTiming timing = TimeLookups(t, filter, plan_.lookupCalls, plan_.batches, w.how);
        std::string ratio = "; " + Fmt3(timing.nsPerCall / plain2) + "x plain-bilinear";
        if (plain3 > 0) ratio += "; " + Fmt3(timing.nsPerCall / plain3) + "x plain-trilinear";
        ratio += " (each timed just before)";
        AddTiming(std::string(w.prefix) + (filter == Filter::Linear ? "-linear" : "-cubic"), t.name,
                  t.dims(), size, NAN, timing, batches + w.what + ratio);
      }
    }
  }

  /// The floor: a plain bilinear lookup (call_timing.h), once per run, before the tables.
  void PlainLookup() {
    const CallTiming timing = TimePlainBilinear(plan_.lookupCalls, plan_.batches);
    plainNs_ = timing.nsPerCall;
    const std::string n = std::to_string(kPlainTableSize);
    AddTiming("plain-bilinear", "rg-sqrt-roughness", 2, n + "x" + n, NAN, timing,
              "median of " + std::to_string(plan_.batches) + " batches of " +
                  std::to_string(plan_.lookupCalls) +
                  " float bilinear lookups, 2 channels, sqrt roughness (as Cycles' "
                  "lookup_table_read_2D)");
  }

  /// The ggx-dfg closed form of `kiln fit --terms N` (Plan::fitTerms; docs/fits.md) against the
  /// lookups: ns per evaluation, and its error against the exact integrals in the note.
  void FitEvaluation() {
    FitOptions opt;
    opt.terms = plan_.fitTerms;
    opt.threads = threads_;
    const FitResult fit = FitTable(CatalogueTable("ggx-dfg"), opt);
    const CallTiming timing = TimeFit(fit.form, plan_.lookupCalls, plan_.batches);
    const std::string ratio =
        plainNs_ > 0 ? "; " + Fmt3(timing.nsPerCall / plainNs_) + "x plain-bilinear" : "";
    AddTiming("fit-evaluate", "ggx-dfg", 2, std::to_string(fit.form.TermsPerChannel()) + " terms",
              NAN, timing,
              "median of " + std::to_string(plan_.batches) + " batches of " +
                  std::to_string(plan_.lookupCalls) + " EvaluateFit calls, " +
                  std::to_string(fit.form.OperationCount()) + " operations; max error " +
                  Sci(fit.error.maxOffJump) + " off the mirror's jump (" + Sci(fit.error.max) +
                  " on it), median " + Sci(fit.error.median) + " against the exact integrals" +
                  ratio);
  }

  void Direct(const std::string& label, const AnyModel& m) {
    AddTiming("evaluate", label, 0, "", NAN, TimeEvaluate(m, plan_.evaluateCalls, plan_.batches),
              "Evaluate(model, wo, wi), median of " + std::to_string(plan_.batches) + " batches");
    for (double tol : {1e-4, 1e-8})
      AddTiming("directional-albedo", label, 0, "", tol,
                TimeDirectionalAlbedo(m, tol, plan_.integrateCalls, plan_.batches),
                "DirectionalAlbedo(model, mu) at tol " + Sci(tol) + "; evals column: per call");
  }

  /// Per model: lookups in its 1D, 2D (and 3D) tables against evaluating and integrating it.
  void Runtime() {
    PlainLookup();
    FitEvaluation();
    for (const Kind& k : plan_.kinds) {
      TableSpec spec = Sized(k.table, k.base);
      std::string model = spec.model;
      // A table with an eta axis (ggx-fresnel-albedo) is of the model with exact Fresnel.
      const bool fresnel = std::any_of(spec.axes.begin(), spec.axes.end(),
                                       [](const AxisSpec& a) { return a.name == "eta"; });
      // 1D: the average-albedo table of the same model (its lookup cost does not depend on tol).
      if (!fresnel) {
        TableSpec avg = Sized(TableName(Quantity::AlbedoAvg, model), plan_.runtime1DSize);
        avg.tol = plan_.runtimeTableTol;
        BakeOptions bo;
        bo.threads = threads_;
        bo.measureLookupError = false;
        Lookups(BakeTable(avg, bo), SizeText(avg));
      }
      Lookups(Kiln(spec, spec.tol, threads_).table, SizeText(spec));
      if (fresnel) {
        ModelParams p;
        p.roughness = 0.5;
        p.eta = 1.5;
        Direct("ggx eta=1.5", MakeModel("ggx", p));
      } else {
        ModelParams p;
        p.roughness = 0.5;
        Direct(model, MakeModel(model, p));
      }
    }
  }

  template <class... A>
  void Log(const char* format, A... args) {
    if (!log_) return;
    std::fprintf(log_, format, args...);
    std::fflush(log_);
  }

  BenchOptions opt_;
  Plan plan_;
  std::FILE* log_;
  int threads_;
  std::map<std::string, Reference> refs_;
  std::map<std::string, Measured> cache_;
  std::vector<BenchRow> rows_;
  double plainNs_ = 0;  ///< ns per plain bilinear lookup (PlainLookup), 0 before it ran
};

/// The 1-minute load average (other processes share the cores), or NaN where unknown.
double LoadAverage() {
  double load[1] = {NAN};
  return getloadavg(load, 1) == 1 ? load[0] : NAN;
}

}  // namespace

BenchResult RunBench(const BenchOptions& opt, std::FILE* log) {
  auto t0 = Clock::now();
  double loadBefore = LoadAverage();
  BenchResult result;
  result.rows = Bench(opt, log).Run();
  result.summary = BenchSummary(result.rows);
  result.seconds = Since(t0);
  char machine[160];
  std::snprintf(
      machine, sizeof machine,
      "machine: %u hardware threads; 1-minute load average %.2f at the start, %.2f at the end",
      std::thread::hardware_concurrency(), loadBefore, LoadAverage());
  result.summary.push_back(machine);
  std::filesystem::create_directories(opt.outDir);
  std::string csv = CsvText(result.rows), svg = BenchSvg(result.rows);
  writeAtomically(opt.outDir + "/bench.csv", [&](const std::string& tmp) { writeBytes(tmp, csv); });
  writeAtomically(opt.outDir + "/bench.svg", [&](const std::string& tmp) { writeBytes(tmp, svg); });
  if (log) {
    std::fprintf(log, "\n");
    for (const std::string& line : result.summary) std::fprintf(log, "%s\n", line.c_str());
    std::fprintf(log, "bench: %zu rows in %.1f s; wrote %s/bench.csv and %s/bench.svg\n",
                 result.rows.size(), result.seconds, opt.outDir.c_str(), opt.outDir.c_str());
  }
  return result;
}

}  // namespace kiln
