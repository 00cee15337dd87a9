#include "baker/bench/catalogue_report.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "baker/bake/bake.h"
#include "baker/bench/estimate_table.h"
#include "baker/quantities/monte_carlo.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"
#include "baker/util/median.h"

namespace kiln {

namespace {

/// The yardstick's table and samples per texel (kCatalogueYardstick).
constexpr int kYardstickSize = 128;
constexpr int kYardstickSamples = 1024;

double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

const char* MethodOf(const TableSpec& spec, const BakeStats& st) {
  if (!st.derivedFrom.empty()) return "derived";
  if (UsesFixedRule(spec)) return "fixed rule";
  if (spec.Method().rfind("closed form", 0) == 0) return "closed form";
  return "adaptive";
}

/// The sampled texels of `t` against adaptive quadrature at opt.refTol, on opt.threads threads,
/// one task per sampled texel; the max over them in texel order afterwards (the same figure for
/// any thread count). Fills row.sampledError, sampled and referenceSeconds.
void CheckSampledTexels(const TableSpec& spec, const Table& t, const CatalogueBenchOptions& opt,
                        CatalogueBenchRow& row) {
  const size_t nc = spec.channels.size();
  const size_t firstChannel = static_cast<size_t>(Describe(spec.quantity).firstIntegralChannel);
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<size_t> sampled = SampledTexels(spec.TexelCount(), opt.samples);
  std::vector<double> sampleError(sampled.size(), 0);
  tbb::task_arena arena(std::max(1, opt.threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, sampled.size(), 1),
                      [&](const tbb::blocked_range<size_t>& b) {
                        for (size_t k = b.begin(); k != b.end(); ++k) {
                          const size_t i = sampled[k];
                          double x[3];
                          NodeEvaluationPoint(spec, i, x);  // a layer: its limit, as the bake
                          IntegrationStats is;
                          std::vector<double> ref = EvaluateSpec(spec, x, opt.refTol, is);
                          // A fitted table's coefficient channels are not integrals: only the
                          // integral channels have a reference (firstIntegralChannel).
                          for (size_t c = firstChannel; c < nc; ++c) {
                            double e = std::abs(static_cast<double>(t.data[i * nc + c]) - ref[c]) /
                                       std::max(1.0, std::abs(ref[c]));
                            if (!(e <= sampleError[k])) sampleError[k] = e;  // NaN propagates
                          }
                        }
                      });
  });
  for (double e : sampleError)
    if (!(e <= row.sampledError)) row.sampledError = e;
  row.sampled = static_cast<int>(sampled.size());
  row.referenceSeconds = SecondsSince(t0);
}

/// Bakes one table as `kiln bake` does (derived from a table before it where its kind says so)
/// and, with opt.reference, checks its sampled texels.
CatalogueBenchRow BenchTable(const TableSpec& spec, const CatalogueBenchOptions& opt,
                             NodeValueCache& nodeValues) {
  BakeOptions bo;
  bo.threads = opt.threads;
  bo.measureLookupError = opt.lookupError;
  BakeStats st;
  Table t = BakeTable(spec, bo, &st, nodeValues.SourceFor(spec), nodeValues.KeepFor(spec));
  CatalogueBenchRow r;
  r.table = spec.name;
  r.kind = QuantityName(spec.quantity);
  r.method = MethodOf(spec, st);
  r.texels = static_cast<long long>(spec.TexelCount());
  r.seconds = st.seconds;
  r.evalsPerTexel = r.texels > 0 ? static_cast<double>(st.evals) / r.texels : 0;
  r.searchSeconds = opt.lookupError ? st.lookupSeconds : 0;
  r.searchPoints = st.lookupPoints;
  r.declared = t.bakeError;
  if (opt.reference) CheckSampledTexels(spec, t, opt, r);
  return r;
}

void PrintKind(std::FILE* log, const CatalogueKindRow& k, double yardstick) {
  std::fprintf(log, "%-28s %6d %10lld %9.3f %11.4g %9lld %9.3f %11.4g %9.1f\n", k.kind.c_str(),
               k.tables, k.texels, k.seconds, k.TexelsPerSecond(), k.searchPoints, k.searchSeconds,
               k.SearchesPerSecond(), k.Times(yardstick));
}

void PrintSummary(std::FILE* log, const CatalogueBenchResult& run) {
  std::fprintf(log, "yardstick: %s, %.3f s (median of %zu runs:", kCatalogueYardstick,
               run.yardstickSeconds, run.yardstickRuns.size());
  for (double s : run.yardstickRuns) std::fprintf(log, " %.3f", s);
  std::fprintf(log, ")\n%-28s %6s %10s %9s %11s %9s %9s %11s %9s\n", "kind", "tables", "texels",
               "seconds", "texels/s", "searches", "seconds", "searches/s", "x yard");
  for (const CatalogueKindRow& k : run.kinds) PrintKind(log, k, run.yardstickSeconds);
  PrintKind(log, run.total, run.yardstickSeconds);
  const double y = run.yardstickSeconds;
  std::fprintf(log,
               "catalogue: %d tables, texels %.2f s + searches %.2f s = %.2f s = %.1fx the "
               "yardstick (texels %.1fx, searches %.1fx)\n",
               run.total.tables, run.total.seconds, run.total.searchSeconds,
               run.total.seconds + run.total.searchSeconds, run.total.Times(y),
               y > 0 ? run.total.seconds / y : 0, y > 0 ? run.total.searchSeconds / y : 0);
}

}  // namespace

std::vector<size_t> SampledTexels(size_t n, int samples) {
  std::vector<size_t> out;
  if (n == 0 || samples <= 0) return out;
  if (samples == 1 || n == 1) return {0};
  for (int k = 0; k < samples; ++k) {
    size_t i = static_cast<size_t>(std::llround(static_cast<double>(k) * (n - 1) / (samples - 1)));
    if (out.empty() || out.back() != i) out.push_back(i);
  }
  return out;
}

double RunCatalogueYardstick(int threads) {
  TableSpec spec = CatalogueTable("ggx-dfg", {});
  for (AxisSpec& a : spec.axes) a.size = kYardstickSize;
  auto t0 = std::chrono::steady_clock::now();
  EstimateDFGTablePerTexel(spec, kYardstickSamples, threads);
  return SecondsSince(t0);
}

void SumCatalogueKinds(const std::vector<CatalogueBenchRow>& rows,
                       std::vector<CatalogueKindRow>& kinds, CatalogueKindRow& total) {
  kinds.clear();
  total = CatalogueKindRow{};
  total.kind = "total";
  for (const CatalogueBenchRow& r : rows) {
    auto it = std::find_if(kinds.begin(), kinds.end(),
                           [&](const CatalogueKindRow& k) { return k.kind == r.kind; });
    if (it == kinds.end()) {
      kinds.push_back(CatalogueKindRow{});
      kinds.back().kind = r.kind;
      it = kinds.end() - 1;
    }
    for (CatalogueKindRow* k : {&*it, &total}) {
      k->tables += 1;
      k->texels += r.texels;
      k->searchPoints += r.searchPoints;
      k->seconds += r.seconds;
      k->searchSeconds += r.searchSeconds;
    }
  }
}

CatalogueBenchResult RunCatalogueBench(const CatalogueBenchOptions& opt, std::FILE* log) {
  std::vector<TableSpec> specs;
  if (opt.only.empty())
    specs = DefaultCatalogue({});
  else
    for (const std::string& name : opt.only) specs.push_back(CatalogueTable(name, {}));
  if (log)
    std::fprintf(log,
                 "catalogue: %zu tables, %d threads; bake error at %d sampled texels per table "
                 "against adaptive quadrature at %g%s\n%-40s %-11s %8s %9s %12s %9s %9s %9s %9s\n",
                 specs.size(), opt.threads, opt.reference ? opt.samples : 0, opt.refTol,
                 opt.reference ? "" : " (skipped: --no-reference)", "table", "method", "texels",
                 "seconds", "evals/texel", "searches", "seconds", "declared", "sampled");
  CatalogueBenchResult run;
  // The yardstick runs spread over the run: before the first table, between, after the last.
  const int runs = std::max(0, opt.yardstickRuns);
  auto yardstickDue = [&](size_t table) {  // runs due before `table` (specs.size(): the end)
    int due = 0;
    for (int k = 0; k < runs; ++k) {
      const size_t at = runs == 1 ? 0 : (specs.size() * k + (runs - 1) / 2) / (runs - 1);
      due += at == table;
    }
    return due;
  };
  NodeValueCache nodeValues(specs);  // as the bake: a table derived from one baked before it
  for (size_t i = 0; i <= specs.size(); ++i) {
    for (int k = yardstickDue(i); k > 0; --k)
      run.yardstickRuns.push_back(RunCatalogueYardstick(opt.threads));
    if (i == specs.size()) break;
    CatalogueBenchRow r = BenchTable(specs[i], opt, nodeValues);
    if (log) {
      char sampled[16] = "-";
      if (opt.reference) std::snprintf(sampled, sizeof sampled, "%.1e", r.sampledError);
      std::fprintf(log, "%-40s %-11s %8lld %9.3f %12.0f %9lld %9.3f %9.1e %9s\n", r.table.c_str(),
                   r.method.c_str(), r.texels, r.seconds, r.evalsPerTexel, r.searchPoints,
                   r.searchSeconds, r.declared, sampled);
      std::fflush(log);
    }
    run.rows.push_back(r);
  }
  run.yardstickSeconds = Median(run.yardstickRuns);
  SumCatalogueKinds(run.rows, run.kinds, run.total);
  if (log) {
    double worst = 0;
    for (const CatalogueBenchRow& r : run.rows) worst = std::max(worst, r.sampledError);
    PrintSummary(log, run);
    if (opt.reference) std::fprintf(log, "worst sampled bake error %.1e\n", worst);
  }
  return run;
}

std::string CatalogueCsv(const CatalogueBenchResult& run) {
  std::string s =
      "row,name,method,texels,seconds,evals_per_texel,search_points,search_seconds,"
      "texels_per_second,searches_per_second,x_yardstick,declared_bake_error,"
      "sampled_bake_error,sampled_texels,reference_seconds\n";
  char buf[512];
  const double y = run.yardstickSeconds;
  for (const CatalogueBenchRow& r : run.rows) {
    CatalogueKindRow one;
    one.texels = r.texels;
    one.seconds = r.seconds;
    one.searchPoints = r.searchPoints;
    one.searchSeconds = r.searchSeconds;
    std::snprintf(buf, sizeof buf,
                  "table,%s,%s,%lld,%.6g,%.6g,%lld,%.6g,%.6g,%.6g,%.4g,%.3g,%.3g,%d,%.6g\n",
                  r.table.c_str(), r.method.c_str(), r.texels, r.seconds, r.evalsPerTexel,
                  r.searchPoints, r.searchSeconds, one.TexelsPerSecond(), one.SearchesPerSecond(),
                  one.Times(y), r.declared, r.sampledError, r.sampled, r.referenceSeconds);
    s += buf;
  }
  auto kindLine = [&](const char* what, const CatalogueKindRow& k) {
    std::snprintf(buf, sizeof buf, "%s,%s,,%lld,%.6g,,%lld,%.6g,%.6g,%.6g,%.4g,,,,\n", what,
                  k.kind.c_str(), k.texels, k.seconds, k.searchPoints, k.searchSeconds,
                  k.TexelsPerSecond(), k.SearchesPerSecond(), k.Times(y));
    s += buf;
  };
  for (const CatalogueKindRow& k : run.kinds) kindLine("kind", k);
  kindLine("total", run.total);
  std::snprintf(buf, sizeof buf, "yardstick,%s,mc-hammersley-per-texel,%d,%.6g,%d,,,,,1,,,,\n",
                kCatalogueYardstick, kYardstickSize * kYardstickSize, y, kYardstickSamples);
  s += buf;
  return s;
}

}  // namespace kiln
