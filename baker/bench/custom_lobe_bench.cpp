#include "baker/bench/custom_lobe_bench.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "baker/custom/loader.h"
#include "baker/tables/catalogue.h"
#include "baker/util/median.h"

namespace kiln {
namespace {

/// Node values of one bake, its integrand evaluations and its wall and CPU seconds.
struct NodeBake {
  std::vector<double> values;
  long long evals = 0;
  double seconds = 0, cpu = 0;
};

/// CPU seconds of this process so far, all threads.
double CpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The first channel at nodes [begin, end) of `spec` by adaptive quadrature to `tol`; returns
/// the integrand evaluations.
long long EvaluateNodes(const TableSpec& spec, double tol, size_t begin, size_t end,
                        double* values) {
  long long evals = 0;
  for (size_t i = begin; i != end; ++i) {
    double x[3];
    NodeEvaluationPoint(spec, i, x);
    IntegrationStats stats;
    values[i] = EvaluateSpec(spec, x, tol, stats)[0];
    evals += stats.evals;
  }
  return evals;
}

/// Every node of `spec` by adaptive quadrature to `tol` on `threads` threads.
NodeBake BakeAdaptive(const TableSpec& spec, double tol, int threads) {
  size_t nodes = 1;
  for (const AxisSpec& a : spec.axes) nodes *= static_cast<size_t>(a.size);
  NodeBake out;
  out.values.resize(nodes);
  std::atomic<long long> evals{0};
  const double cpuStart = CpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nodes), [&](const auto& r) {
      evals += EvaluateNodes(spec, tol, r.begin(), r.end(), out.values.data());
    });
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.cpu = CpuSeconds() - cpuStart;
  out.evals = evals;
  return out;
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// The last lines of the run: evaluations, node difference, medians and ratios.
void PrintSummary(const CustomLobeBenchResult& r, std::FILE* log) {
  std::fprintf(log, "evaluations per bake: %s %lld, %s %lld; max node difference %.3g\n",
               r.lobeTable.c_str(), r.lobeEvals, r.builtinTable.c_str(), r.builtinEvals,
               r.maxDifference);
  std::fprintf(log,
               "median: %s %.3f s (CPU %.3f s), %s %.3f s (CPU %.3f s); ratio %.2f (CPU %.2f)\n",
               r.lobeTable.c_str(), r.lobeMedian, r.lobeCpuMedian, r.builtinTable.c_str(),
               r.builtinMedian, r.builtinCpuMedian, r.ratio, r.cpuRatio);
}

}  // namespace

CustomLobeBenchResult RunCustomLobeBench(const CustomLobeBenchOptions& opt, std::FILE* log) {
  if (opt.rounds < 1 || opt.size < 2 || opt.threads < 1)
    throw std::invalid_argument("bench: --rounds >= 1, --size >= 2 and -j >= 1 are needed");
  const ModelInfo& lobe =
      EndsWith(opt.source, ".so") ? LoadModelLibrary(opt.source) : LoadModelSource(opt.source);
  CatalogueOptions sized;
  sized.size = opt.size;
  CustomLobeBenchResult r;
  r.lobeTable = lobe.id + "-albedo";
  r.builtinTable = opt.against + "-albedo";
  const TableSpec user = CatalogueTable(r.lobeTable, sized);
  const TableSpec builtin = CatalogueTable(r.builtinTable, sized);
  r.tol = user.tol;
  if (log)
    std::fprintf(log,
                 "custom lobe: %s against %s, %d x %d nodes, adaptive quadrature to %g, %d "
                 "threads, %d interleaved rounds\n",
                 r.lobeTable.c_str(), r.builtinTable.c_str(), opt.size, opt.size, r.tol,
                 opt.threads, opt.rounds);
  const NodeBake lobeBake = BakeAdaptive(user, r.tol, opt.threads);  // warm-up, untimed
  const NodeBake builtinBake = BakeAdaptive(builtin, r.tol, opt.threads);
  r.lobeEvals = lobeBake.evals;
  r.builtinEvals = builtinBake.evals;
  for (size_t i = 0; i < lobeBake.values.size() && i < builtinBake.values.size(); ++i)
    r.maxDifference =
        std::max(r.maxDifference, std::abs(lobeBake.values[i] - builtinBake.values[i]));
  for (int round = 0; round < opt.rounds; ++round) {
    const NodeBake a = BakeAdaptive(user, r.tol, opt.threads);
    const NodeBake b = BakeAdaptive(builtin, r.tol, opt.threads);
    r.lobeSeconds.push_back(a.seconds);
    r.lobeCpu.push_back(a.cpu);
    r.builtinSeconds.push_back(b.seconds);
    r.builtinCpu.push_back(b.cpu);
    if (log)
      std::fprintf(log, "  round %d: %s %.3f s (CPU %.3f s), %s %.3f s (CPU %.3f s)\n", round + 1,
                   r.lobeTable.c_str(), a.seconds, a.cpu, r.builtinTable.c_str(), b.seconds, b.cpu);
  }
  r.lobeMedian = Median(r.lobeSeconds);
  r.builtinMedian = Median(r.builtinSeconds);
  r.lobeCpuMedian = Median(r.lobeCpu);
  r.builtinCpuMedian = Median(r.builtinCpu);
  r.ratio = r.lobeMedian / r.builtinMedian;
  r.cpuRatio = r.lobeCpuMedian / r.builtinCpuMedian;
  if (log) PrintSummary(r, log);
  return r;
}

}  // namespace kiln
