#include "baker/tables/spec.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "baker/models/registry.h"
#include "baker/tables/engine_layout.h"
#include "baker/tables/prepared_reference.h"

namespace kiln {
namespace {

/// Bump when an integrator changes the texels it produces: every baked file becomes stale.
constexpr const char* kIntegratorVersion = "kiln-integrators-2";

std::string G17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// True when the table has a point on the smooth limit: its quantity's smoothLimit accepts the
/// lower corner of its axes (roughness 0 when the roughness axis starts there).
bool SmoothLimitApplies(const TableSpec& spec) {
  const QuantityInfo& q = Describe(spec.quantity);
  if (!q.smoothLimit || spec.axes.size() > 3) return false;
  double x[3] = {0, 0, 0};
  for (size_t d = 0; d < spec.axes.size(); ++d) x[d] = spec.axes[d].lo;
  std::vector<double> values;
  return q.smoothLimit(spec, x, values);
}

/// Where a sheen spec is evaluated: x with its roughness raised to params[sheen_roughness_min]
/// (the engine grid's shader clamp, engine_layout.h) copied into `buf`; x itself for any other
/// spec (a FilamentCloth ggx table clamps only its cloth channel, in the dfg kind).
/// Whether SheenClampedPoint moves the points of `spec`.
bool SheenClampApplies(const TableSpec& spec) {
  return spec.params.count(kSheenRoughnessMinParam) && IsSheen(spec.model) && spec.axes.size() <= 3;
}

const double* SheenClampedPoint(const TableSpec& spec, const double* x, double* buf) {
  if (!SheenClampApplies(spec)) return x;
  for (size_t d = 0; d < spec.axes.size(); ++d)
    buf[d] = spec.axes[d].name == "roughness" ? SheenRoughnessFor(spec, x[d]) : x[d];
  return buf;
}

/// The code hash of the model `id` names (ModelInfo::codeHash): a user's lobe's; "" for a
/// built-in model or an id no model has.
std::string CodeHashOf(const std::string& id) {
  const ModelInfo* m = FindModel(id);
  return m ? m->codeHash : "";
}

}  // namespace

std::string TableSpec::ParamsText() const {
  std::string s;
  for (const auto& [k, v] : params) s += (s.empty() ? "" : ";") + k + "=" + G17(v);
  return s;
}

std::string TableSpec::Method() const {
  const QuantityInfo& q = Describe(quantity);
  std::string method = UsesFixedRule(*this) ? q.fixedRuleMethod(*this) : q.method(*this);
  // A user's lobe: its id and hash in the header (the hash is in HashText too), once (an
  // average's method quotes its E table's, which already names them).
  const std::string hash = CodeHashOf(model);
  const std::string lobe = "; custom model '" + model + "', hash " + hash;
  if (!hash.empty() && method.find(lobe) == std::string::npos) method += lobe;
  return method;
}

std::string TableSpec::HashText() const {
  const QuantityInfo& q = Describe(quantity);
  std::string text = std::string(kIntegratorVersion) + "|" + std::to_string(kFormatVersion) + "|" +
                     name + "|" + model + "|" + QuantityName(quantity) + "|" + G17(tol) + "|" +
                     ParamsText();
  // The kind's fixed-rule version (its tuned node counts, QuantityInfo::fixedRuleVersion): its
  // tables, and only its, re-bake when it changes ("2" everywhere: the hashes of before).
  if (UsesFixedRule(*this))
    text += std::string("|fixed-rule:") +
            (q.fixedRuleVersionOf ? q.fixedRuleVersionOf(*this) : q.fixedRuleVersion);
  // Roughness 0 as the smooth limit (QuantityInfo::smoothLimit) changed the texels of the tables
  // it applies to, and only theirs: they re-bake, the rest of the catalogue keeps its hash.
  if (SmoothLimitApplies(*this)) text += "|smooth-limit:1";
  // A user's lobe (baker/custom/): the hash of its source or library, so an edited lobe makes
  // its tables stale.
  if (const std::string hash = CodeHashOf(model); !hash.empty()) text += "|model-hash:" + hash;
  for (const std::string& c : channels) text += "|c:" + c;
  for (const AxisSpec& a : axes)
    text += "|a:" + a.name + "," + G17(a.lo) + "," + G17(a.hi) + "," + std::to_string(a.size) +
            "," + warpName(a.warp) + (std::isfinite(a.split) ? ",split=" + G17(a.split) : "");
  return text;
}

std::string TableSpec::Hash() const {
  const std::string text = HashText();
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::vector<TableAxis> TableSpec::TableAxes() const {
  std::vector<TableAxis> out;
  for (const AxisSpec& a : axes) out.push_back({a.name, a.ToAxis()});
  return out;
}

size_t TableSpec::TexelCount() const {
  size_t n = 1;
  for (const AxisSpec& a : axes) n *= static_cast<size_t>(a.size);
  return n;
}

Table TableShell(const TableSpec& spec, const std::string& generator, const std::string& method) {
  Table t;
  t.generator = generator;
  t.name = spec.name;
  t.model = spec.model;
  t.quantity = QuantityName(spec.quantity);
  t.channels = spec.channels;
  t.channelMeanings = spec.meanings;
  t.axes = spec.TableAxes();
  t.params = spec.ParamsText();
  t.method = method;
  t.data.assign(spec.TexelCount() * spec.channels.size(), 0.0f);
  return t;
}

TableSpec SpecFromTable(const Table& table) {
  TableSpec s;
  s.name = table.name;
  s.model = table.model;
  const QuantityInfo* q = FindQuantity(table.quantity);
  if (!q)
    throw std::invalid_argument("table '" + table.name + "': unknown quantity '" + table.quantity +
                                "'");
  s.quantity = q->id;
  s.channels = table.channels;
  s.meanings = table.channelMeanings;
  for (const TableAxis& a : table.axes)
    s.axes.push_back({a.name, a.axis.lo, a.axis.hi, a.axis.size, a.axis.warp, a.axis.split});
  try {
    for (const std::string& kv : splitList(table.params, ';')) {
      size_t eq = kv.find('=');
      if (eq == std::string::npos)
        throw std::invalid_argument("table '" + table.name + "': bad params entry '" + kv + "'");
      s.params[kv.substr(0, eq)] = std::stod(kv.substr(eq + 1));
    }
  } catch (const std::exception& e) {
    throw std::invalid_argument("cannot read kiln.params '" + table.params + "' (" + e.what() +
                                ")");
  }
  s.tol = table.tolerance;
  return s;
}

double LayerScaleOf(const TableSpec& spec, const double* x) {
  if (spec.axes.size() < 2) return 1e-12;
  return layerScaleFor(spec.axes[0].warp, spec.axes[1].lo, spec.axes[1].hi, x[1]);
}

double SplitOf(const TableSpec& spec, const double* x) {
  if (spec.axes.size() == 3 && spec.axes[0].warp == Warp::Root4LayerSplit2)
    return clampedEta(spec.axes[2].lo, spec.axes[2].hi, x[2]);
  if (spec.axes.size() < 2 || spec.axes[0].warp != Warp::Root4LayerSplit) return 0.5;
  if (std::isfinite(spec.axes[0].split)) return spec.axes[0].split;
  if (spec.axes.size() != 3) return 0.5;
  return criticalSplit(spec.axes[0].lo, spec.axes[0].hi, spec.axes[2].lo, spec.axes[2].hi, x[2]);
}

void PointAtWarped(const TableSpec& spec, const double* t, double* x) {
  // A layered axis 0 is placed last, once, by the value of axis 1 (its inverse is iterative)
  // and, for root4-layer-split(2), the split point (the eta) axis 2 gives.
  const bool layered = spec.axes.size() >= 2 && isLayerWarp(spec.axes[0].warp);
  for (size_t d = 0; d < spec.axes.size(); ++d)
    if (d != 0 || !layered) x[d] = spec.axes[d].ToAxis().unwarped(t[d]);
  if (layered) x[0] = spec.axes[0].ToAxis().unwarped(t[0], LayerScaleOf(spec, x), SplitOf(spec, x));
}

bool LayerLimitPointAtWarped(const TableSpec& spec, const double* t, double* x) {
  PointAtWarped(spec, t, x);
  if (spec.axes.size() < 2 || !isLayerWarp(spec.axes[0].warp)) return false;
  const Axis a0 = spec.axes[0].ToAxis();
  if (LayerScaleOf(spec, x) != 0.0 || !a0.holdsLayerLimit(t[0])) return false;
  // The smallest value of axis 1 past the collapse point where the layer has a scale: r = 1e-6
  // (c = alpha = 1e-12, the floor every r in (0, 1e-6] shares), or the double next to eta = 1
  // (c = 2.1e-8; F there is the layer's limit G(mu / c) to ~1e-8, FrDielectric has no
  // cancellation).
  if (isRoughnessLayerWarp(spec.axes[0].warp))
    x[1] = 1e-6;
  else
    x[1] = std::nextafter(x[1], x[1] < spec.axes[1].hi ? spec.axes[1].hi : spec.axes[1].lo);
  x[0] = a0.unwarped(t[0], LayerScaleOf(spec, x), SplitOf(spec, x));
  return true;
}

namespace {

/// The warped coordinates i / (N - 1) of texel `index` (axis 0 fastest): exactly 0 and 1 at the
/// ends, where unwarped returns lo and hi exactly.
void NodeWarpedCoordinates(const TableSpec& spec, size_t index, double* t) {
  for (size_t d = 0; d < spec.axes.size() && d < 3; ++d) {
    const AxisSpec& a = spec.axes[d];
    int i = static_cast<int>(index % a.size);
    t[d] = a.size > 1 ? static_cast<double>(i) / static_cast<double>(a.size - 1) : 0.0;
    index /= a.size;
  }
}

}  // namespace

void NodeCoordinates(const TableSpec& spec, size_t index, double* x) {
  double t[3] = {0, 0, 0};
  NodeWarpedCoordinates(spec, index, t);
  PointAtWarped(spec, t, x);
}

void NodeEvaluationPoint(const TableSpec& spec, size_t index, double* x) {
  double t[3] = {0, 0, 0};
  NodeWarpedCoordinates(spec, index, t);
  LayerLimitPointAtWarped(spec, t, x);
}

bool UsesFixedRule(const TableSpec& spec) {
  const QuantityInfo& q = Describe(spec.quantity);
  return q.usesFixedRule && q.usesFixedRule(spec);
}

std::vector<double> EvaluateSpec(const TableSpec& spec, const double* xIn,
                                 IntegrationStats& stats) {
  double buf[3];
  const double* x = SheenClampedPoint(spec, xIn, buf);
  const QuantityInfo& q = Describe(spec.quantity);
  std::vector<double> smooth;
  if (q.smoothLimit && q.smoothLimit(spec, x, smooth)) return smooth;
  if (UsesFixedRule(spec)) return Describe(spec.quantity).fixedRule(spec, x, stats);
  return EvaluateSpec(spec, x, spec.tol, stats);
}

std::vector<double> SearchReference(const TableSpec& spec, const double* xIn,
                                    IntegrationStats& stats) {
  double buf[3];
  const double* x = SheenClampedPoint(spec, xIn, buf);
  const QuantityInfo& q = Describe(spec.quantity);
  std::vector<double> smooth;
  if (q.smoothLimit && q.smoothLimit(spec, x, smooth)) return smooth;
  if (q.searchRule && UsesFixedRule(spec)) return q.searchRule(spec, x, stats);
  std::vector<double> v = EvaluateSpec(spec, x, stats);
  stats.errorEstimate = 0;
  return v;
}

std::vector<double> EvaluateSpec(const TableSpec& spec, const double* xIn, double tol,
                                 IntegrationStats& stats) {
  double buf[3];
  const double* x = SheenClampedPoint(spec, xIn, buf);
  const QuantityInfo& q = Describe(spec.quantity);
  std::vector<double> smooth;
  if (q.smoothLimit && q.smoothLimit(spec, x, smooth)) return smooth;
  return q.evaluate(spec, x, tol, stats);
}

PreparedReference::PreparedReference(const TableSpec& spec)
    : spec_(spec),
      q_(Describe(spec.quantity)),
      clamp_(SheenClampApplies(spec)),
      fixed_(UsesFixedRule(spec)) {}

std::vector<double> PreparedReference::Search(const double* x, IntegrationStats& stats) const {
  if (clamp_) return SearchReference(spec_, x, stats);
  // SearchReference with x unclamped: the smooth limit, the search rule, else EvaluateSpec
  // (whose own smooth-limit check at the same x has already failed).
  std::vector<double> smooth;
  if (q_.smoothLimit && q_.smoothLimit(spec_, x, smooth)) return smooth;
  if (q_.searchRule && fixed_) return q_.searchRule(spec_, x, stats);
  std::vector<double> v =
      fixed_ ? q_.fixedRule(spec_, x, stats) : q_.evaluate(spec_, x, spec_.tol, stats);
  stats.errorEstimate = 0;
  return v;
}

std::vector<double> PreparedReference::Bake(const double* x, IntegrationStats& stats) const {
  if (clamp_) return EvaluateSpec(spec_, x, stats);
  std::vector<double> smooth;
  if (q_.smoothLimit && q_.smoothLimit(spec_, x, smooth)) return smooth;
  return fixed_ ? q_.fixedRule(spec_, x, stats) : q_.evaluate(spec_, x, spec_.tol, stats);
}

}  // namespace kiln
