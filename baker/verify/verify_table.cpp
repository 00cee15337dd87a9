// One table file's checks (verify.h, VerifyTableFile).
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "baker/io/texture_readers.h"
#include "baker/models/registry.h"
#include "baker/tables/engine_layout.h"
#include "baker/verify/verify.h"

namespace kiln::verify {
namespace {

std::string Full(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Throws std::invalid_argument when the table's channels are not its kind's.
void CheckChannels(const TableSpec& spec, const Table& t) {
  double lo[3] = {0, 0, 0};
  for (size_t d = 0; d < spec.axes.size() && d < 3; ++d) lo[d] = spec.axes[d].lo;
  IntegrationStats stats;
  size_t channels = EvaluateSpec(spec, lo, stats).size();
  if (channels != t.channels.size())
    throw std::invalid_argument(std::to_string(t.channels.size()) + " channel(s), but quantity '" +
                                t.quantity + "' has " + std::to_string(channels));
}

/// The repeated lookup-error search, checked against the declared bound.
void CheckLookupError(const TableSpec& spec, const Table& t, const VerifyOptions& opt,
                      TableVerdict& v) {
  LookupSearchOptions so;
  so.budget = opt.budget;
  so.maxCells = opt.cells;
  so.randomPoints = opt.points;
  so.refTol = opt.tol;
  so.threads = opt.threads;
  so.filter = v.filter == "cubic" ? Filter::Cubic : Filter::Linear;
  v.lookup = MeasureLookupError(spec, t.view(), so);
  v.lookupWhere = v.lookup.WhereText(spec);
  v.declaredLookup = t.lookupError.max;
  // The reference itself is only good to its tolerance (--tol, or the table's own, plus the
  // bake error the texels declare), and a verification-grade search reference adds its distance
  // from the bake's method: allow that much on top of the bound.
  const double refTol = opt.tol > 0 ? opt.tol : spec.tol;
  v.lookupOk = !v.checked ||
               (t.lookupError.max >= 0 &&
                v.lookup.max <= t.lookupError.max + refTol + t.bakeError + v.lookup.referenceError);
}

}  // namespace

std::string AxesOutsideModel(const TableSpec& spec) {
  const ModelInfo* m = FindModel(spec.model);
  if (!m) return "";
  for (const AxisSpec& a : spec.axes)
    for (const ParamInfo& q : m->params)
      if (q.name == a.name &&
          ((a.name == "roughness" ? SheenRoughnessFor(spec, a.lo) : a.lo) < q.lo || a.hi > q.hi))
        return "axis " + a.name + " [" + Full(a.lo) + ", " + Full(a.hi) + "] is outside model '" +
               spec.model + "''s range [" + Full(q.lo) + ", " + Full(q.hi) + "]";
  return "";
}

TableVerdict VerifyTableFile(const std::string& path, const VerifyOptions& opt) {
  TableVerdict v;
  v.file = path;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    // Any format kiln writes: the texels as stored, so a float16 or unorm16 file is measured
    // with its rounding.
    Table t = LoadAnyTable(path);
    TableSpec spec = SpecFromTable(t);  // throws for an unknown quantity or unreadable params
    std::string outside = AxesOutsideModel(spec);
    if (!outside.empty()) throw std::invalid_argument(outside);
    CheckChannels(spec, t);
    v.name = t.name;
    v.filter = opt.filter.empty() ? t.lookupError.filter : opt.filter;
    v.checked = v.filter == t.lookupError.filter;
    CheckLookupError(spec, t, opt, v);
    const auto b0 = std::chrono::steady_clock::now();
    v.bake = CheckBakeError(spec, t, opt.bakeNodes, 0, opt.threads);
    v.bakeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - b0).count();
    v.bakeWhere = v.bake.WhereText(spec);
    // A fitted table (ltc) also re-measures its own claims (QuantityInfo::verifyTable).
    if (auto check = Describe(spec.quantity).verifyTable)
      v.fitProblem = check(t, opt.threads, v.fitSummary);
  } catch (const std::exception& e) {
    v.error = e.what();
    v.ok = false;
    return v;
  }
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  v.ok = v.lookupOk && v.bake.ok && v.fitProblem.empty();
  return v;
}

}  // namespace kiln::verify
