#include "baker/bench/estimate_table.h"
#include "baker/util/threads.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace kiln {
namespace {

/// kiln.generator of the tables the bench's estimators make.
constexpr const char* kBenchGenerator = "kiln 0.1.0 bench";

/// Filament's DFV loop for one texel: n Hammersley points, GGX importance sampling of h, height-
/// correlated Smith visibility, weight 4 Vis mu_l (v.h) / (n.h), Fc = (1 - v.h)^5.
std::array<double, 2> DFGPerTexel(int n, double mu, double alpha) {
  const double a2 = alpha * alpha;
  const Vec3 v = ViewDirection(mu);
  double a = 0, b = 0;
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * Pi * i / n, u = RadicalInverse2(static_cast<uint32_t>(i));
    const double den = 1 + (a2 - 1) * u;
    const double cosT = std::sqrt((1 - u) / den),
                 sinT = std::sqrt(a2 * u / den);  // exact as alpha -> 0
    const Vec3 h{sinT * std::cos(phi), sinT * std::sin(phi), cosT};
    const double voh = Dot(v, h);
    const Vec3 l = 2 * voh * h - v;
    if (!(l.z > 0) || !(voh > 0)) continue;
    // Height-correlated Smith: Vis = G / (4 mu_o mu_l) = 0.5 / (mu_l Lv + mu_o Ll).
    const double vis = 0.5 / (l.z * std::sqrt(mu * mu * (1 - a2) + a2) +
                              mu * std::sqrt(l.z * l.z * (1 - a2) + a2));
    const double g = 4 * vis * l.z * voh / h.z, fc = Pow5(1 - voh);
    a += (1 - fc) * g;
    b += fc * g;
  }
  return {a / n, b / n};
}

}  // namespace

Table EstimateDFGTablePerTexel(const TableSpec& spec, int n, int threads, BakeStats* stats) {
  if (!(Describe(spec.quantity).monteCarlo == &kGgxDfgMonteCarlo && EstimatorSupports(spec)))
    throw std::invalid_argument("table '" + spec.name +
                                "': no per-texel Monte Carlo estimator for it");
  Table t = TableShell(spec, kBenchGenerator,
                       std::to_string(n) + "-sample Hammersley Monte Carlo, per-texel sampling");
  const int width = spec.axes[0].size, rSize = spec.axes[1].size;
  Axis muAxis = spec.axes[0].ToAxis(), rAxis = spec.axes[1].ToAxis();
  auto t0 = std::chrono::steady_clock::now();
  tbb::task_arena arena(ThreadCount(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, rSize, 1), [&](const tbb::blocked_range<int>& b) {
      for (int k = b.begin(); k != b.end(); ++k) {
        const double r = rAxis.node(k), alpha = MonteCarloAlpha(r);
        const double c =
            spec.axes[0].warp == Warp::Root4Layer ? layerScale(rAxis.lo, rAxis.hi, r) : 1e-12;
        float* out = &t.data[static_cast<size_t>(k) * width * 2];
        for (int i = 0; i < width; ++i) {
          std::array<double, 2> ab = DFGPerTexel(n, muAxis.node(i, c), alpha);
          out[2 * i] = static_cast<float>(ab[0]);
          out[2 * i + 1] = static_cast<float>(ab[1]);
        }
      }
    });
  });
  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats->evals = static_cast<long long>(spec.TexelCount()) * n;
    stats->lookupSeconds = 0;
  }
  return t;
}

Table EstimateTable(const TableSpec& spec, const PointSet& points, const std::string& method,
                    int threads, BakeStats* stats) {
  if (!EstimatorSupports(spec))
    throw std::invalid_argument("table '" + spec.name + "': no Monte Carlo estimator for it");
  Table t = TableShell(spec, kBenchGenerator, method);
  size_t nc = spec.channels.size();
  size_t width = static_cast<size_t>(spec.axes[0].size);
  size_t rows = spec.TexelCount() / width;
  auto t0 = std::chrono::steady_clock::now();
  MonteCarloRows fill = Describe(spec.quantity).monteCarlo->prepare(spec, points);
  auto row = [&](size_t k) { fill(k, &t.data[k * width * nc]); };
  tbb::task_arena arena(ThreadCount(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rows, 1),
                      [&](const tbb::blocked_range<size_t>& b) {
                        for (size_t k = b.begin(); k != b.end(); ++k) row(k);
                      });
  });
  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats->evals = static_cast<long long>(spec.TexelCount() * points.size());
    stats->lookupSeconds = 0;
  }
  return t;
}

}  // namespace kiln
