#include "baker/bench/reference.h"
#include "baker/math/splitmix.h"
#include "baker/util/threads.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>

namespace kiln {
namespace {

/// Runs f(i) for i in [0, n) on `threads` threads, summing the integrand evaluations f returns.
template <class F>
long long ParallelEvals(size_t n, int threads, F&& f) {
  std::atomic<long long> evals{0};
  tbb::task_arena arena(ThreadCount(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        long long local = 0;
                        for (size_t i = r.begin(); i != r.end(); ++i) local += f(i);
                        evals += local;
                      });
  });
  return evals.load();
}

}  // namespace

double AxisValueAtTexel(const Axis& a, double s) {
  if (a.size <= 1) return a.lo;
  return a.unwarped(s / (a.size - 1));
}

Reference ComputeReference(const TableSpec& spec, const ReferenceOptions& opt) {
  auto t0 = std::chrono::steady_clock::now();
  Reference ref;
  ref.dims = spec.axes.size();
  ref.channels = spec.channels.size();
  for (const AxisSpec& a : spec.axes) ref.axes.push_back(a.ToAxis());
  const std::vector<Axis>& axes = ref.axes;
  size_t dims = ref.dims, nc = ref.channels, texels = spec.TexelCount();
  // Nodes, exactly where BakeTable puts them (axis 0 fastest).
  ref.nodes.assign(texels * nc, 0);
  long long evals = ParallelEvals(texels, opt.threads, [&](size_t i) {
    double x[3] = {0, 0, 0};
    // (a layered axis 0 follows axis 1; a collapsed layer's nodes hold the layer's limit)
    NodeEvaluationPoint(spec, i, x);
    IntegrationStats st;
    std::vector<double> v = EvaluateSpec(spec, x, opt.tol, st);
    for (size_t c = 0; c < nc; ++c) ref.nodes[i * nc + c] = v[c];
    return st.evals;
  });
  // Lookup points in texel space: cell centres (subsampled), then random points.
  ref.totalCells = 1;
  for (const Axis& a : axes) ref.totalCells *= static_cast<size_t>(std::max(1, a.size - 1));
  ref.cellCentres = std::min(ref.totalCells, static_cast<size_t>(std::max(0, opt.maxCellCentres)));
  ref.randomPoints = static_cast<size_t>(std::max(0, opt.randomPoints));
  std::vector<double> texel;
  for (size_t j = 0; j < ref.cellCentres; ++j) {
    size_t cell = ref.cellCentres == ref.totalCells ? j : j * ref.totalCells / ref.cellCentres;
    for (size_t d = 0; d < dims; ++d) {
      size_t cellsHere = static_cast<size_t>(std::max(1, axes[d].size - 1));
      texel.push_back(static_cast<double>(cell % cellsHere) + 0.5);
      cell /= cellsHere;
    }
  }
  uint64_t seed = 0x6B696C6E62656E63ull;  // "kilnbenc"
  for (size_t j = 0; j < ref.randomPoints; ++j)
    for (size_t d = 0; d < dims; ++d)
      texel.push_back(SplitMixUniform(seed) * std::max(0, axes[d].size - 1));
  size_t count = texel.size() / std::max<size_t>(dims, 1);
  ref.points.resize(texel.size());
  ref.inCorner.assign(count, 0);
  bool overMu = dims >= 2 && spec.axes[0].name == "mu";
  for (size_t j = 0; j < count; ++j) {
    double* x = &ref.points[j * dims];
    for (size_t d = 0; d < dims; ++d) {
      x[d] = AxisValueAtTexel(axes[d], texel[j * dims + d]);
      if (overMu && (d == 1 || spec.axes[d].name == "eta") && texel[j * dims + d] < 1)
        ref.inCorner[j] = 1;
    }
    if (axes[0].size > 1)  // a root4-layer axis 0 follows axis 1
      x[0] = axes[0].unwarped(texel[j * dims] / (axes[0].size - 1), LayerScaleOf(spec, x),
                              SplitOf(spec, x));
  }
  ref.pointValues.assign(count * nc, 0);
  evals += ParallelEvals(count, opt.threads, [&](size_t j) {
    IntegrationStats st;
    std::vector<double> v = EvaluateSpec(spec, &ref.points[j * dims], opt.tol, st);
    for (size_t c = 0; c < nc; ++c) ref.pointValues[j * nc + c] = v[c];
    return st.evals;
  });
  ref.evals = evals;
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return ref;
}

ErrorStats BakeError(const Table& table, const Reference& ref) {
  ErrorStats e;
  size_t nc = ref.channels, n = nc ? ref.nodes.size() / nc : 0;
  if (table.data.size() != ref.nodes.size() || n == 0) return {NAN, NAN, NAN, {}};
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    double m = 0;
    for (size_t c = 0; c < nc; ++c)
      m = std::max(m,
                   std::abs(static_cast<double>(table.data[i * nc + c]) - ref.nodes[i * nc + c]));
    if (m > e.max || i == 0) {
      e.max = m;
      e.worstAt.clear();
      size_t k = i;
      for (const Axis& a : ref.axes) {
        e.worstAt.push_back(a.node(static_cast<int>(k % a.size)));
        k /= a.size;
      }
      if (ref.axes[0].warp == Warp::Root4Layer && ref.axes.size() >= 2)
        e.worstAt[0] = ref.axes[0].node(static_cast<int>(i % ref.axes[0].size),
                                        layerScale(ref.axes[1].lo, ref.axes[1].hi, e.worstAt[1]));
    }
    sum += m * m;
  }
  e.rms = std::sqrt(sum / static_cast<double>(n));
  return e;
}

ErrorStats LookupError(const Table& table, const Reference& ref, Filter filter) {
  ErrorStats e;
  size_t n = ref.PointCount(), nc = ref.channels;
  if (n == 0 || table.channels.size() != nc || nc > 8) return {NAN, NAN, NAN, {}};
  LutView view = table.view();
  double sum = 0;
  for (size_t j = 0; j < n; ++j) {
    float got[8];
    view.sample(&ref.points[j * ref.dims], got, filter);
    double m = 0;
    for (size_t c = 0; c < nc; ++c)
      m = std::max(m, std::abs(static_cast<double>(got[c]) - ref.pointValues[j * nc + c]));
    if (m > e.max || e.worstAt.empty()) {
      e.max = m;
      e.worstAt.assign(ref.points.begin() + j * ref.dims, ref.points.begin() + (j + 1) * ref.dims);
    }
    if (!ref.inCorner[j]) e.maxOffCorner = std::max(e.maxOffCorner, m);
    sum += m * m;
  }
  e.rms = std::sqrt(sum / static_cast<double>(n));
  return e;
}

}  // namespace kiln
