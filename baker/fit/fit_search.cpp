// The max-error search of a fit against the exact integrals (fit.h MeasureFitError).
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "baker/fit/fit.h"
#include "baker/math/splitmix.h"

namespace kiln {

namespace {
constexpr int kGrid2D = 129;           ///< grid points per axis of a 2D search (uniform in s)
constexpr int kGrid1D = 4097;          ///< grid points of a 1D search
constexpr int kRandomPoints = 2048;    ///< fixed-seed random points, uniform in s
constexpr int kClimbStarts = 12;       ///< worst points the pattern search climbs from
constexpr int kClimbSteps = 60;        ///< most steps per climb
constexpr double kClimbFinest = 1e-7;  ///< the climb stops below this step in s

/// A point of the search in warped coordinates s (one per axis) and its error.
struct Probe {
  double s[2] = {0, 0};
  double error = 0;
};

/// |fit - exact| (max over channels) at warped coordinates s; the point is rounded to float
/// first, so the exact integral is taken where the float fit is evaluated.
double ErrorAt(const TableSpec& spec, const FitForm& form, FitEvaluator f, const double* s,
               double* where = nullptr) {
  const size_t dims = form.axes.size();
  float xf[2];
  double x[2];
  PointAtWarped(form, s, x);
  for (size_t d = 0; d < dims; ++d) {
    xf[d] = static_cast<float>(x[d]);
    xf[d] = std::min(std::max(xf[d], static_cast<float>(form.axes[d].lo)),
                     static_cast<float>(form.axes[d].hi));
    x[d] = xf[d];
    // A float rounded outside the declared double domain is moved back inside it.
    x[d] = std::min(std::max(x[d], form.axes[d].lo), form.axes[d].hi);
    if (where) where[d] = x[d];
  }
  IntegrationStats stats;
  std::vector<double> exact = EvaluateSpec(spec, x, stats);
  float out[16];
  f(form, xf, out);
  double e = 0;
  for (size_t c = 0; c < form.channels.size(); ++c) e = std::max(e, std::fabs(out[c] - exact[c]));
  return e;
}

/// The grid and random probes of the search, before their errors.
std::vector<Probe> StartProbes(size_t dims) {
  std::vector<Probe> probes;
  const int g = dims == 1 ? kGrid1D : kGrid2D;
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < (dims == 1 ? 1 : g); ++j) {
      Probe p;
      p.s[0] = -1 + 2.0 * i / (g - 1);
      p.s[1] = -1 + 2.0 * j / (g - 1);
      probes.push_back(p);
    }
  uint64_t state = 0x6b696c6e666974ull;  // "kilnfit"
  for (int k = 0; k < kRandomPoints; ++k) {
    Probe p;
    for (size_t d = 0; d < dims; ++d) p.s[d] = -1 + 2 * SplitMixUniform(state);
    probes.push_back(p);
  }
  return probes;
}

/// A pattern search from `p` uphill in the error, inside [-1, 1]^dims; evaluations counted.
Probe Climb(const TableSpec& spec, const FitForm& form, FitEvaluator f, Probe p, double step,
            long long& evals) {
  const size_t dims = form.axes.size();
  for (int it = 0; it < kClimbSteps && step > kClimbFinest; ++it) {
    Probe best = p;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = (dims == 1 ? 0 : -1); dy <= (dims == 1 ? 0 : 1); ++dy) {
        if (dx == 0 && dy == 0) continue;
        Probe q = p;
        q.s[0] = std::min(std::max(p.s[0] + dx * step, -1.0), 1.0);
        q.s[1] = std::min(std::max(p.s[1] + dy * step, -1.0), 1.0);
        q.error = ErrorAt(spec, form, f, q.s);
        ++evals;
        if (q.error > best.error) best = q;
      }
    if (best.error > p.error)
      p = best;
    else
      step *= 0.5;
  }
  return p;
}
}  // namespace

FitErrorReport MeasureFitError(const TableSpec& spec, const FitForm& form, int threads,
                               FitEvaluator f) {
  const size_t dims = form.axes.size();
  std::vector<Probe> probes = StartProbes(dims);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), probes.size(),
                      [&](size_t i) { probes[i].error = ErrorAt(spec, form, f, probes[i].s); });
  });
  FitErrorReport rep;
  rep.points = static_cast<long long>(probes.size());
  std::vector<double> errors(probes.size());
  for (size_t i = 0; i < probes.size(); ++i) errors[i] = probes[i].error;
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  rep.median = errors[errors.size() / 2];
  // Climb from the worst probes (stable order: error, then index).
  std::vector<size_t> order(probes.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return probes[a].error > probes[b].error; });
  const size_t starts = std::min<size_t>(kClimbStarts, order.size());
  std::vector<Probe> tops(starts);
  std::vector<long long> evals(starts, 0);
  const double step = 2.0 / ((dims == 1 ? kGrid1D : kGrid2D) - 1);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), starts, [&](size_t k) {
      tops[k] = Climb(spec, form, f, probes[order[k]], step, evals[k]);
    });
  });
  Probe worst = probes[order[0]];
  for (size_t k = 0; k < starts; ++k) {
    rep.points += evals[k];
    if (tops[k].error > worst.error) worst = tops[k];
  }
  // The max off the mirror's jump (fit.h kLayerJumpMu), over the probes and the climbs' tops.
  const bool layerAxes = dims == 2 && form.axes[0].name == "mu" && form.axes[1].name == "roughness";
  const bool etaAxes = dims == 2 && form.axes[0].name == "mu" && form.axes[1].name == "eta";
  auto onJump = [&](const Probe& p) {
    double x[2];
    PointAtWarped(form, p.s, x);
    return (layerAxes && static_cast<float>(x[1]) == 0.0f && x[0] < kLayerJumpMu) ||
           (etaAxes && static_cast<float>(x[1]) == 1.0f && x[0] < kEtaJumpMu);
  };
  for (const Probe& p : probes)
    if (!onJump(p)) rep.maxOffJump = std::max(rep.maxOffJump, p.error);
  for (const Probe& p : tops)
    if (!onJump(p)) rep.maxOffJump = std::max(rep.maxOffJump, p.error);
  rep.where.assign(dims, 0.0);
  rep.max = ErrorAt(spec, form, f, worst.s, rep.where.data());
  return rep;
}

}  // namespace kiln
