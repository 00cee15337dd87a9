#include "baker/bench/call_timing.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "baker/integrate/quantities.h"

namespace kiln {
namespace {

constexpr int kInputs = 4096;

/// Keeps results alive so the timed loops are not optimised away.
volatile double g_sink = 0;

double Uniform(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (z >> 11) * (1.0 / 9007199254740992.0);
}

/// Median ns per call of `batch` (which makes `calls` calls) over `batches` runs.
template <class F>
CallTiming Median(long long calls, int batches, F&& batch) {
  std::vector<double> ns;
  auto start = std::chrono::steady_clock::now();
  for (int b = 0; b < std::max(1, batches); ++b) {
    auto t0 = std::chrono::steady_clock::now();
    batch();
    auto t1 = std::chrono::steady_clock::now();
    ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() /
                 static_cast<double>(calls));
  }
  std::sort(ns.begin(), ns.end());
  CallTiming t;
  t.nsPerCall = ns[ns.size() / 2];
  t.calls = calls;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace

CallTiming TimeLookups(const Table& table, Filter filter, long long calls, int batches) {
  LutView view = table.view();
  int dims = view.dims;
  std::vector<double> x(static_cast<size_t>(kInputs) * 3, 0);
  uint64_t seed = 11;
  for (int i = 0; i < kInputs; ++i)
    for (int d = 0; d < dims; ++d)
      x[i * 3 + d] = Lerp(Uniform(seed), view.axis[d].lo, view.axis[d].hi);
  return Median(calls, batches, [&] {
    double sum = 0;
    float out[8];
    for (long long i = 0; i < calls; ++i) {
      view.sample(&x[(i % kInputs) * 3], out, filter);
      sum += out[0];
    }
    g_sink = g_sink + sum;
  });
}

CallTiming TimeEvaluate(const AnyModel& model, long long calls, int batches) {
  std::vector<Vec3> wo(kInputs), wi(kInputs);
  uint64_t seed = 12;
  for (int i = 0; i < kInputs; ++i) {
    wo[i] = DirectionFromMuPhi(Uniform(seed), 2 * Pi * Uniform(seed));
    wi[i] = DirectionFromMuPhi(Uniform(seed), 2 * Pi * Uniform(seed));
  }
  return Median(calls, batches, [&] {
    double sum = 0;
    for (long long i = 0; i < calls; ++i) sum += Evaluate(model, wo[i % kInputs], wi[i % kInputs]);
    g_sink = g_sink + sum;
  });
}

CallTiming TimeDirectionalAlbedo(const AnyModel& model, double tol, long long calls, int batches) {
  IntegrationOptions opt;
  opt.tol = tol;
  long long evals = 0;
  CallTiming t = Median(calls, batches, [&] {
    double sum = 0;
    evals = 0;
    for (long long i = 0; i < calls; ++i) {
      IntegrationStats st;
      double mu = (static_cast<double>(i % 16) + 0.5) / 16;
      RhoParts e = DirectionalAlbedo(model, mu, opt, st);
      sum += e.lin + e.quad;
      evals += st.evals;
    }
    g_sink = g_sink + sum;
  });
  t.evalsPerCall = calls > 0 ? evals / calls : 0;
  return t;
}

}  // namespace kiln
