#include "baker/bake/lookup_error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdio>
#include <thread>

namespace kiln {

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

LookupErrorReport MeasureLookupError(const TableSpec& spec, const LutView& view,
                                     long long randomPoints, double refTol, int threads,
                                     Filter filter, long long maxCells, bool alsoCubic) {
  size_t dims = spec.axes.size();
  size_t allCells = 1;
  for (const AxisSpec& a : spec.axes) allCells *= static_cast<size_t>(std::max(1, a.size - 1));
  size_t cells = maxCells > 0 ? std::min(allCells, static_cast<size_t>(maxCells)) : allCells;
  size_t total = cells + static_cast<size_t>(std::max(0LL, randomPoints));
  LookupErrorReport rep;
  std::vector<double> err(total, 0);
  std::vector<char> inCorner(total, 0);
  std::vector<double> errCubic(alsoCubic ? total : 0, 0);
  auto point = [&](size_t i, double* x) {
    size_t k = i < cells ? i * allCells / cells : 0;  // evenly strided when cells < allCells
    uint64_t s = 0x9E3779B97F4A7C15ull * (i - cells + 1);
    double t[3] = {0, 0, 0};
    for (size_t d = 0; d < dims; ++d) {
      int cellsHere = std::max(1, spec.axes[d].size - 1);
      double texel;
      if (i < cells) {
        texel = static_cast<double>(k % cellsHere) + 0.5;
        k /= cellsHere;
      } else {
        s ^= s >> 31;
        s *= 0xBF58476D1CE4E5B9ull;
        s ^= s >> 29;
        texel = static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0) * cellsHere;
      }
      t[d] = spec.axes[d].size > 1 ? texel / (spec.axes[d].size - 1) : 0;
    }
    PointAtWarped(spec, t, x);
  };
  int n = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  tbb::task_arena arena(n);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, total, 1), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i != r.end(); ++i) {
            double x[3] = {0, 0, 0};
            point(i, x);
            IntegrationStats st;
            std::vector<double> exact =
                refTol > 0 ? EvaluateSpec(spec, x, refTol, st) : EvaluateSpec(spec, x, st);
            // One float per channel of the table, and at least one per exact value (a table with
            // fewer channels than its quantity then compares the missing ones against 0).
            std::vector<float> got(std::max<size_t>(view.channels, exact.size()), 0.0f);
            view.sample(x, got.data(), filter);
            double m = 0;
            for (size_t c = 0; c < exact.size(); ++c) m = std::max(m, std::abs(got[c] - exact[c]));
            err[i] = m;
            if (alsoCubic) {
              view.sample(x, got.data(), Filter::Cubic);
              double mc = 0;
              for (size_t c = 0; c < exact.size(); ++c)
                mc = std::max(mc, std::abs(got[c] - exact[c]));
              errCubic[i] = mc;
            }
            inCorner[i] =
                dims >= 2 && spec.axes[0].name == "mu" && spec.axes[1].ToAxis().texel(x[1]) < 1;
          }
        });
  });
  size_t worst = 0;
  double sum = 0;
  for (size_t i = 0; i < total; ++i) {
    if (err[i] > err[worst]) worst = i;
    if (!inCorner[i]) rep.maxOutsideCorner = std::max(rep.maxOutsideCorner, err[i]);
    sum += err[i] * err[i];
  }
  rep.max = err[worst];
  rep.rms = std::sqrt(sum / static_cast<double>(total));
  if (alsoCubic) {
    double sumCubic = 0;
    rep.cubicMax = 0;
    for (double e : errCubic) {
      rep.cubicMax = std::max(rep.cubicMax, e);
      sumCubic += e * e;
    }
    rep.cubicRms = std::sqrt(sumCubic / static_cast<double>(total));
  }
  rep.points = static_cast<long long>(total);
  double x[3];
  point(worst, x);
  rep.where.assign(x, x + dims);
  return rep;
}

}  // namespace kiln
