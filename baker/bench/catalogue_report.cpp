#include "baker/bench/catalogue_report.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "baker/bake/bake.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"

namespace kiln {

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

std::vector<CatalogueBenchRow> RunCatalogueBench(const CatalogueBenchOptions& opt, std::FILE* log) {
  std::vector<TableSpec> specs;
  if (opt.only.empty())
    specs = DefaultCatalogue({});
  else
    for (const std::string& name : opt.only) specs.push_back(CatalogueTable(name, {}));
  if (log)
    std::fprintf(log,
                 "catalogue: %zu tables, %d threads; bake error at %d sampled texels per table "
                 "against adaptive quadrature at %g\n%-40s %-11s %8s %9s %12s %9s %9s\n",
                 specs.size(), opt.threads, opt.samples, opt.refTol, "table", "method", "texels",
                 "seconds", "evals/texel", "declared", "sampled");
  std::vector<CatalogueBenchRow> rows;
  double totalSeconds = 0, worst = 0;
  NodeValueCache nodeValues(specs);  // as the bake: a table derived from one baked before it
  for (const TableSpec& spec : specs) {
    BakeOptions bo;
    bo.threads = opt.threads;
    bo.measureLookupError = false;
    BakeStats st;
    Table t = BakeTable(spec, bo, &st, nodeValues.SourceFor(spec), nodeValues.KeepFor(spec));
    CatalogueBenchRow r;
    r.table = spec.name;
    r.method = !st.derivedFrom.empty()                      ? "derived"
               : UsesFixedRule(spec)                        ? "fixed rule"
               : spec.Method().rfind("closed form", 0) == 0 ? "closed form"
                                                            : "adaptive";
    r.texels = static_cast<long long>(spec.TexelCount());
    r.seconds = st.seconds;
    r.evalsPerTexel = r.texels > 0 ? static_cast<double>(st.evals) / r.texels : 0;
    r.declared = t.bakeError;
    const size_t nc = spec.channels.size();
    const size_t firstChannel = static_cast<size_t>(Describe(spec.quantity).firstIntegralChannel);
    auto t0 = std::chrono::steady_clock::now();
    // The references on opt.threads threads, one task per sampled texel; the max over them in
    // texel order afterwards (the same figure for any thread count).
    const std::vector<size_t> sampled = SampledTexels(spec.TexelCount(), opt.samples);
    std::vector<double> sampleError(sampled.size(), 0);
    tbb::task_arena arena(std::max(1, opt.threads));
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<size_t>(0, sampled.size(), 1),
          [&](const tbb::blocked_range<size_t>& b) {
            for (size_t k = b.begin(); k != b.end(); ++k) {
              const size_t i = sampled[k];
              double x[3];
              NodeEvaluationPoint(spec, i, x);  // where the bake evaluates (a layer: its limit)
              IntegrationStats is;
              std::vector<double> ref = EvaluateSpec(spec, x, opt.refTol, is);
              // A fitted table's coefficient channels are not integrals: only the integral
              // channels have a reference (QuantityInfo::firstIntegralChannel).
              for (size_t c = firstChannel; c < nc; ++c) {
                double e = std::abs(static_cast<double>(t.data[i * nc + c]) - ref[c]) /
                           std::max(1.0, std::abs(ref[c]));
                if (!(e <= sampleError[k])) sampleError[k] = e;  // NaN propagates
              }
            }
          });
    });
    for (double e : sampleError)
      if (!(e <= r.sampledError)) r.sampledError = e;
    r.sampled = static_cast<int>(sampled.size());
    r.referenceSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    totalSeconds += r.seconds;
    worst = std::max(worst, r.sampledError);
    if (log) {
      std::fprintf(log, "%-40s %-11s %8lld %9.3f %12.0f %9.1e %9.1e\n", r.table.c_str(),
                   r.method.c_str(), r.texels, r.seconds, r.evalsPerTexel, r.declared,
                   r.sampledError);
      std::fflush(log);
    }
    rows.push_back(r);
  }
  if (log)
    std::fprintf(log,
                 "catalogue: %zu tables, texels %.2f s in all; worst sampled bake error %.1e\n",
                 rows.size(), totalSeconds, worst);
  return rows;
}

std::string CatalogueCsv(const std::vector<CatalogueBenchRow>& rows) {
  std::string s =
      "table,method,texels,seconds,evals_per_texel,declared_bake_error,sampled_bake_error,"
      "sampled_texels,reference_seconds\n";
  char buf[256];
  for (const CatalogueBenchRow& r : rows) {
    std::snprintf(buf, sizeof buf, "%s,%s,%lld,%.6g,%.6g,%.3g,%.3g,%d,%.6g\n", r.table.c_str(),
                  r.method.c_str(), r.texels, r.seconds, r.evalsPerTexel, r.declared,
                  r.sampledError, r.sampled, r.referenceSeconds);
    s += buf;
  }
  return s;
}

}  // namespace kiln
