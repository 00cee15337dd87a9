// The glass kinds' bake by columns of eta (dielectric_columns.h).
#include "baker/quantities/dielectric_columns.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

#include "baker/integrate/dielectric_albedo.h"
#include "baker/models/roughness.h"

namespace kiln {
namespace {

std::uint64_t BitsOf(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

struct Column {
  double a, b;
  std::vector<size_t> texels;
  std::vector<double> etas;
  std::vector<std::array<double, 3>> points;  ///< each texel's evaluation point (kept for store)
};

}  // namespace

bool MuRoughnessColumnOf(const std::array<double, 3>& point, double* a, double* b, double* eta) {
  const auto [mu, r, e] = point;
  if (r == 0 || !(e >= kDielectricTableEtaMin)) return false;
  *a = mu;
  *b = std::max(AlphaFromPerceptual(r), MinAlpha);
  *eta = e;
  return true;
}

void BakeDielectricColumns(const TableSpec& spec, int threads, const DielectricColumnBake& how,
                           Table& table, std::vector<long long>& evals,
                           std::vector<double>& errors) {
  const size_t n = spec.TexelCount();
  const size_t nc = spec.channels.size();
  std::vector<size_t> alone;
  std::vector<Column> columns;
  std::map<std::pair<std::uint64_t, std::uint64_t>, size_t> open;  // key -> its last column
  for (size_t i = 0; i < n; ++i) {
    double x[3], a, b, eta;
    NodeEvaluationPoint(spec, i, x);
    if (!how.columnOf(x, &a, &b, &eta)) {
      alone.push_back(i);
      continue;
    }
    const auto key = std::make_pair(BitsOf(a), BitsOf(b));
    auto it = open.find(key);
    if (it == open.end() || columns[it->second].texels.size() >= kMaxDielectricColumn) {
      columns.push_back({a, b, {}, {}, {}});
      open[key] = columns.size() - 1;
      it = open.find(key);
    }
    columns[it->second].texels.push_back(i);
    columns[it->second].etas.push_back(eta);
    columns[it->second].points.push_back({x[0], x[1], x[2]});
  }
  auto put = [&](size_t i, const std::vector<double>& v, long long e, double err) {
    for (size_t c = 0; c < nc; ++c) table.data[i * nc + c] = static_cast<float>(v[c]);
    evals[i] = e;
    errors[i] = err;
  };
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, alone.size(), 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t k = r.begin(); k != r.end(); ++k) {
                          double x[3];
                          NodeEvaluationPoint(spec, alone[k], x);
                          IntegrationStats st;
                          put(alone[k], EvaluateSpec(spec, x, st), st.evals, st.errorEstimate);
                        }
                      });
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, columns.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t k = r.begin(); k != r.end(); ++k) {
            const Column& col = columns[k];
            const int m = static_cast<int>(col.etas.size());
            std::vector<std::array<double, 2>> out(m);
            long long e = 0;
            how.column(col.a, col.b, col.etas.data(), m, out.data(), &e);
            for (int j = 0; j < m; ++j)
              put(col.texels[j], how.store(col.points[j].data(), out[j]), e, how.bound);
          }
        });
  });
}

}  // namespace kiln
