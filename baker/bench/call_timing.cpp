#include "baker/bench/call_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <vector>

#include "baker/integrate/quantities.h"
#include "baker/math/splitmix.h"

namespace kiln {
namespace {

constexpr int kInputs = 4096;

/// Keeps results alive so the timed loops are not optimised away.
volatile double g_sink = 0;

/// CPU time of the calling thread in ns: a batch's time without the time other processes held
/// the core (a batch of a few ms is otherwise often cut by the scheduler on a shared machine).
double ThreadCpuNs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e9 + static_cast<double>(ts.tv_nsec);
}

/// Median ns per call (thread CPU time) of `batch` (which makes `calls` calls) over `batches`
/// runs.
template <class F>
CallTiming MedianOfBatches(long long calls, int batches, F&& batch) {
  std::vector<double> ns;
  auto start = std::chrono::steady_clock::now();
  for (int b = 0; b < std::max(1, batches); ++b) {
    const double t0 = ThreadCpuNs();
    batch();
    ns.push_back((ThreadCpuNs() - t0) / static_cast<double>(calls));
  }
  std::sort(ns.begin(), ns.end());
  CallTiming t;
  t.nsPerCall = ns[ns.size() / 2];
  t.calls = calls;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace

CallTiming TimeLookups(const Table& table, Filter filter, long long calls, int batches,
                       LookupCall how) {
  const LutView view = table.view();
  const LutSampler sampler(view);
  const int dims = view.dims, nc = view.channels;
  // Points packed by dims (the batch call's layout): point i is x[i * dims .. + dims - 1].
  std::vector<double> x(static_cast<size_t>(kInputs) * static_cast<size_t>(dims), 0);
  uint64_t seed = 11;
  for (int i = 0; i < kInputs; ++i)
    for (int d = 0; d < dims; ++d)
      x[i * dims + d] = Lerp(SplitMixUniform(seed), view.axis[d].lo, view.axis[d].hi);
  std::vector<float> out(static_cast<size_t>(kInputs) * static_cast<size_t>(nc));
  if (how == LookupCall::Batch) {
    return MedianOfBatches(calls, batches, [&] {
      double sum = 0;
      for (long long done = 0; done < calls; done += kInputs) {
        const size_t n = static_cast<size_t>(std::min<long long>(kInputs, calls - done));
        sampler.sample(x.data(), n, out.data(), filter);
        for (size_t i = 0; i < n; ++i) sum += out[i * nc];
      }
      g_sink = g_sink + sum;
    });
  }
  // One loop per way, so neither is compiled around the other's code.
  float stack[8];
  float* one = nc <= 8 ? stack : out.data();
  if (how == LookupCall::Sampler) {
    return MedianOfBatches(calls, batches, [&] {
      double sum = 0;
      for (long long i = 0; i < calls; ++i) {
        sampler.sample(&x[(i % kInputs) * dims], one, filter);
        sum += one[0];
      }
      g_sink = g_sink + sum;
    });
  }
  return MedianOfBatches(calls, batches, [&] {
    double sum = 0;
    for (long long i = 0; i < calls; ++i) {
      view.sample(&x[(i % kInputs) * dims], one, filter);
      sum += one[0];
    }
    g_sink = g_sink + sum;
  });
}

namespace {

/// A plain bilinear lookup of an n x n table of two interleaved float channels at
/// (u, v) in [0, 1]^2 (clamped), texel centres at the ends (node-centred, as kiln's grids).
void PlainBilinear(const float* table, int n, float u, float v, float* out) {
  const float last = static_cast<float>(n - 1);
  const float s = std::min(std::max(u, 0.0f), 1.0f) * last;
  const float t = std::min(std::max(v, 0.0f), 1.0f) * last;
  const int i = std::min(static_cast<int>(s), n - 2), j = std::min(static_cast<int>(t), n - 2);
  const float fs = s - static_cast<float>(i), ft = t - static_cast<float>(j);
  const float* p = table + (static_cast<size_t>(j) * n + i) * 2;
  const float* q = p + static_cast<size_t>(n) * 2;
  for (int c = 0; c < 2; ++c) {
    const float a = p[c] + fs * (p[2 + c] - p[c]);
    const float b = q[c] + fs * (q[2 + c] - q[c]);
    out[c] = a + ft * (b - a);
  }
}

}  // namespace

CallTiming TimePlainBilinear(long long calls, int batches) {
  const int n = kPlainTableSize;
  std::vector<float> table(static_cast<size_t>(n) * n * 2);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float mu = static_cast<float>(i) / (n - 1), a = static_cast<float>(j) / (n - 1);
      table[(static_cast<size_t>(j) * n + i) * 2] = mu * (1 - a);
      table[(static_cast<size_t>(j) * n + i) * 2 + 1] = a * a;
    }
  std::vector<float> mu(kInputs), r(kInputs);
  uint64_t seed = 11;
  for (int i = 0; i < kInputs; ++i) {
    mu[i] = static_cast<float>(SplitMixUniform(seed));
    r[i] = static_cast<float>(SplitMixUniform(seed));
  }
  return MedianOfBatches(calls, batches, [&] {
    double sum = 0;
    float out[2];
    for (long long i = 0; i < calls; ++i) {
      const size_t k = static_cast<size_t>(i % kInputs);
      PlainBilinear(table.data(), n, mu[k], std::sqrt(r[k]), out);
      sum += out[0];
    }
    g_sink = g_sink + sum;
  });
}

namespace {

/// The shape of a plain trilinear table (PlainTrilinear).
struct PlainGrid {
  int n0 = 2, n1 = 2, n2 = 2, channels = 1;
};

/// A plain trilinear lookup of a node-centred table at (u, v, w) in [0, 1]^3 (clamped): the
/// cell and fraction per axis, then seven lerps per channel.
void PlainTrilinear(const float* table, const PlainGrid& g, float u, float v, float w, float* out) {
  auto cell = [](float x, int n, int& i) {
    const float s = std::min(std::max(x, 0.0f), 1.0f) * static_cast<float>(n - 1);
    i = std::min(static_cast<int>(s), n - 2);
    return s - static_cast<float>(i);
  };
  int i = 0, j = 0, k = 0;
  const float fu = cell(u, g.n0, i), fv = cell(v, g.n1, j), fw = cell(w, g.n2, k);
  const size_t sx = static_cast<size_t>(g.channels), sy = sx * g.n0, sz = sy * g.n1;
  const float* p = table + k * sz + j * sy + i * sx;
  for (int c = 0; c < g.channels; ++c) {
    const float* q = p + c;
    const float a = q[0] + fu * (q[sx] - q[0]), b = q[sy] + fu * (q[sy + sx] - q[sy]);
    const float d = q[sz] + fu * (q[sz + sx] - q[sz]);
    const float e = q[sz + sy] + fu * (q[sz + sy + sx] - q[sz + sy]);
    const float near = a + fv * (b - a), far = d + fv * (e - d);
    out[c] = near + fw * (far - near);
  }
}

}  // namespace

CallTiming TimePlainTrilinear(int n0, int n1, int n2, int channels, long long calls, int batches) {
  PlainGrid g;
  g.n0 = std::max(n0, 2);
  g.n1 = std::max(n1, 2);
  g.n2 = std::max(n2, 2);
  g.channels = std::max(channels, 1);
  std::vector<float> table(static_cast<size_t>(g.n0) * g.n1 * g.n2 * g.channels);
  uint64_t seed = 17;
  for (float& t : table) t = static_cast<float>(SplitMixUniform(seed));
  std::vector<float> x(static_cast<size_t>(kInputs) * 3);
  for (float& v : x) v = static_cast<float>(SplitMixUniform(seed));
  std::vector<float> out(static_cast<size_t>(g.channels));
  return MedianOfBatches(calls, batches, [&] {
    double sum = 0;
    for (long long i = 0; i < calls; ++i) {
      const float* p = &x[static_cast<size_t>(i % kInputs) * 3];
      PlainTrilinear(table.data(), g, p[0], std::sqrt(p[1]), p[2], out.data());
      sum += out[0];
    }
    g_sink = g_sink + sum;
  });
}

CallTiming TimeFit(const FitForm& form, long long calls, int batches) {
  const size_t dims = form.axes.size();
  std::vector<float> x(kInputs * dims);
  uint64_t seed = 13;
  for (int i = 0; i < kInputs; ++i)
    for (size_t d = 0; d < dims; ++d)
      x[i * dims + d] = static_cast<float>(
          form.axes[d].lo + SplitMixUniform(seed) * (form.axes[d].hi - form.axes[d].lo));
  return MedianOfBatches(calls, batches, [&] {
    double sum = 0;
    float out[4];
    for (long long i = 0; i < calls; ++i) {
      EvaluateFit(form, &x[static_cast<size_t>(i % kInputs) * dims], out);
      sum += out[0];
    }
    g_sink = g_sink + sum;
  });
}

CallTiming TimeEvaluate(const AnyModel& model, long long calls, int batches) {
  std::vector<Vec3> wo(kInputs), wi(kInputs);
  uint64_t seed = 12;
  for (int i = 0; i < kInputs; ++i) {
    wo[i] = DirectionFromMuPhi(SplitMixUniform(seed), 2 * Pi * SplitMixUniform(seed));
    wi[i] = DirectionFromMuPhi(SplitMixUniform(seed), 2 * Pi * SplitMixUniform(seed));
  }
  return MedianOfBatches(calls, batches, [&] {
    double sum = 0;
    for (long long i = 0; i < calls; ++i) sum += Evaluate(model, wo[i % kInputs], wi[i % kInputs]);
    g_sink = g_sink + sum;
  });
}

CallTiming TimeDirectionalAlbedo(const AnyModel& model, double tol, long long calls, int batches) {
  IntegrationOptions opt;
  opt.tol = tol;
  long long evals = 0;
  CallTiming t = MedianOfBatches(calls, batches, [&] {
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
