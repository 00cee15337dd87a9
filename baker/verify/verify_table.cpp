// One table file's checks (verify.h, VerifyTableFile).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

/// The relative rounding of a value printed with 6 significant digits (%.6g), and some.
constexpr double kWhereDigitsSlack = 1e-5;

/// The point the table's own search found worst, axis order, read from kiln.lookup_error.where
/// ("max 0.000565 at roughness=0.674056 eta=1.45686, ..."): empty when the text does not name a
/// value of every axis inside the axis's range (up to the text's rounding, then clamped to it).
std::vector<double> DeclaredWorstPoint(const TableSpec& spec, const std::string& where) {
  const size_t at = where.find(" at ");
  if (at == std::string::npos) return {};
  const std::string list = where.substr(at + 4, where.find(',', at) - (at + 4));
  std::vector<double> x(spec.axes.size(), NAN);
  size_t pos = 0;
  while (pos < list.size()) {
    const size_t end = std::min(list.find(' ', pos), list.size());
    const std::string item = list.substr(pos, end - pos);
    const size_t eq = item.find('=');
    for (size_t d = 0; eq != std::string::npos && d < spec.axes.size(); ++d)
      if (item.compare(0, eq, spec.axes[d].name) == 0 && eq == spec.axes[d].name.size())
        x[d] = std::strtod(item.c_str() + eq + 1, nullptr);
    pos = end + 1;
  }
  // The text has 6 significant digits: a value rounded past an end of its axis is that end.
  for (size_t d = 0; d < x.size(); ++d) {
    const AxisSpec& a = spec.axes[d];
    const double slack = kWhereDigitsSlack * std::max({std::abs(a.lo), std::abs(a.hi), 1e-300});
    if (!(x[d] >= a.lo - slack && x[d] <= a.hi + slack)) return {};
    x[d] = std::min(std::max(x[d], a.lo), a.hi);
  }
  return x;
}

/// The lookup error at the table's declared worst point (DeclaredWorstPoint), against the
/// search's reference (adaptive quadrature to opt.tol, else SearchReference), folded into
/// `rep` as one more point: a search whose budget does not reach that cell still checks the
/// bound where the bake found it tightest.
void CheckDeclaredWorstPoint(const TableSpec& spec, const Table& t, const VerifyOptions& opt,
                             Filter filter, LookupErrorReport& rep) {
  const std::vector<double> at = DeclaredWorstPoint(spec, t.lookupError.where);
  if (at.empty()) return;
  double x[3] = {0, 0, 0};
  std::copy(at.begin(), at.end(), x);
  IntegrationStats st;
  const std::vector<double> exact =
      opt.tol > 0 ? EvaluateSpec(spec, x, opt.tol, st) : SearchReference(spec, x, st);
  const LutView view = t.view();
  std::vector<float> got(std::max<size_t>(view.channels, exact.size()), 0.0f);
  view.sample(x, got.data(), filter);
  double err = 0;
  for (size_t c = size_t(Describe(spec.quantity).firstIntegralChannel); c < exact.size(); ++c)
    err = std::max(err, std::abs(got[c] - exact[c]));
  ++rep.points;
  if (opt.tol <= 0) rep.referenceError = std::max(rep.referenceError, st.errorEstimate);
  const bool inCorner =
      spec.axes.size() >= 2 && spec.axes[0].name == "mu" && spec.axes[1].ToAxis().texel(x[1]) < 1;
  if (!inCorner) rep.maxOutsideCorner = std::max(rep.maxOutsideCorner, err);
  if (err > rep.max) {
    rep.max = err;
    rep.where = at;
  }
}

/// The repeated lookup-error search, checked against the declared bound.
void CheckLookupError(const TableSpec& spec, const Table& t, const VerifyOptions& opt,
                      TableVerdict& v) {
  LookupSearchOptions so;
  so.budget = opt.budget;
  so.maxCells = opt.cells;
  so.randomPoints = opt.points;
  so.refTol = opt.tol;
  so.verifyReference = opt.outerReference;
  so.threads = opt.threads;
  so.filter = v.filter == "cubic" ? Filter::Cubic : Filter::Linear;
  v.lookup = MeasureLookupError(spec, t.view(), so);
  CheckDeclaredWorstPoint(spec, t, opt, so.filter, v.lookup);
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
