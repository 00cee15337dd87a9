#include "baker/scene/plan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "baker/models/registry.h"
#include "baker/scene/axis_narrowing.h"
#include "baker/scene/scene_json.h"
#include "baker/tables/catalogue.h"

namespace kiln {
namespace {

std::string NameTag(const std::string& axis) {
  if (axis == "roughness") return "r";
  if (axis == "eta") return "ior";
  return axis;
}

bool HasRoughness(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (!m) m = FindBsdfModel(model);
  if (!m) return false;
  for (const ParamInfo& p : m->params)
    if (p.name == "roughness") return true;
  return false;
}

/// Cuts the axes of `spec` to `ranges` and renames it (see plan.h).
void CutAxes(TableSpec& spec, const std::map<std::string, ValueRange>& ranges) {
  struct Cut {
    size_t axis;
    bool drop;
    double value;
    AxisSpec narrowed;
    std::string tag;
  };
  std::vector<Cut> cuts;
  for (size_t i = 0; i < spec.axes.size(); ++i) {
    const AxisSpec& a = spec.axes[i];
    auto found = ranges.find(a.name);
    if (found == ranges.end() || found->second.whole) continue;
    if (a.name == "roughness" && !HasRoughness(spec.model)) continue;  // a constant axis
    ValueRange v = found->second;
    if (v.lo == a.lo && v.hi == a.hi) continue;
    std::string tag =
        NameTag(a.name) + ShortNumber(v.lo) + (v.Single() ? "" : "-" + ShortNumber(v.hi));
    if (v.Single())
      cuts.push_back({i, Describe(spec.quantity).readsParams, v.lo, SliceAxis(a, v.lo), tag});
    else
      cuts.push_back({i, false, 0, NarrowAxis(a, v.lo, v.hi), tag});
  }
  size_t dropped = std::count_if(cuts.begin(), cuts.end(), [](const Cut& c) { return c.drop; });
  if (dropped == spec.axes.size()) cuts.back().drop = false;  // keep the last axis, as a slice
  std::vector<AxisSpec> axes;
  for (size_t i = 0; i < spec.axes.size(); ++i) {
    auto cut = std::find_if(cuts.begin(), cuts.end(), [&](const Cut& c) { return c.axis == i; });
    if (cut == cuts.end()) {
      axes.push_back(spec.axes[i]);
    } else if (cut->drop) {
      spec.params[spec.axes[i].name] = cut->value;
    } else {
      axes.push_back(cut->narrowed);
    }
  }
  // A layered mu axis (root4-layer, layer-eta) reads axis 1: when that axis became a parameter
  // (a single roughness of ggx-fresnel-albedo), its layer scale is fixed and axis 1 is another
  // parameter or gone, so mu takes root4 (a layer warp on a 1D table or coupled to the wrong
  // axis would be invalid or wrong).
  const bool axis1Dropped =
      std::any_of(cuts.begin(), cuts.end(), [](const Cut& c) { return c.axis == 1 && c.drop; });
  if (axis1Dropped && !axes.empty() && isLayerWarp(spec.axes[0].warp) &&
      axes[0].name == spec.axes[0].name)
    axes[0].warp = Warp::Root4, axes[0].split = std::nan("");
  // root4-layer-split(2) reads axis 2 too: without it (a single eta), mu takes root4-layer.
  const bool axis2Dropped =
      std::any_of(cuts.begin(), cuts.end(), [](const Cut& c) { return c.axis == 2 && c.drop; });
  if (!axis1Dropped && axis2Dropped &&
      readsAxis2(spec.axes[0].warp, std::isfinite(spec.axes[0].split)) && !axes.empty() &&
      axes[0].name == spec.axes[0].name)
    axes[0].warp = Warp::Root4Layer;
  spec.axes = axes;
  for (const Cut& c : cuts) spec.name += "-" + c.tag;
}

/// The values of `need` on each axis of `whole` (an axis the need does not bound spans the whole
/// axis; mu is left out unless bounded). A kind with a scene domain (QuantityInfo::sceneDomain)
/// keeps only the part of each range inside its axis: `outside` then says what was cut, and the
/// result is false when nothing is left. A need the scene names itself (TableNeed::named) throws
/// std::invalid_argument instead.
bool NeedRanges(const TableNeed& need, const TableSpec& whole,
                std::map<std::string, ValueRange>& ranges, std::string& outside) {
  const QuantityInfo& q = Describe(need.kind);
  for (const AxisSpec& a : whole.axes) {
    auto found = need.ranges.find(a.name);
    if (a.name == "mu" && found == need.ranges.end()) continue;
    bool bounded = found != need.ranges.end() && !found->second.whole;
    ValueRange v = bounded ? found->second : ValueRange::Between(a.lo, a.hi);
    if (q.sceneDomain && bounded && (v.lo < a.lo || v.hi > a.hi)) {
      const std::string value = a.name + " " + v.Text() + " is outside ";
      const std::string domain =
          "[" + ShortNumber(a.lo) + ", " + ShortNumber(a.hi) + "] (" + q.sceneDomain + ")";
      if (need.named)
        throw std::invalid_argument("plan: " + need.reason + ": " + value + q.name + "'s domain " +
                                    a.name + " in " + domain);
      outside += std::string(outside.empty() ? "" : "; ") + value + "its domain " + domain;
      v = ValueRange::Between(std::max(v.lo, a.lo), std::min(v.hi, a.hi));
      if (v.lo > v.hi) return false;
    }
    ranges[a.name] = v;
  }
  return true;
}

/// A note (kind NotYet) on table `table` for the material of `need`: `why` says which of its
/// values the table's domain leaves out.
void AddOutsideNote(std::vector<SceneNote>& notes, const TableNeed& need, const std::string& table,
                    const std::string& why) {
  notes.push_back({SceneNote::Kind::NotYet, table, why, need.material});
}

}  // namespace

TableSpec WholeTableSpec(Quantity kind, const std::string& model, const PlanOptions& opt) {
  if (!FindModel(model) && !FindBsdfModel(model) && model != "none")
    throw std::invalid_argument("plan: unknown model '" + model + "'");
  CatalogueOptions copt;
  copt.size = opt.size;
  const QuantityInfo& q = Describe(kind);
  TableSpec s = q.makeSpec(model, q.defaultAxes(model));
  for (const std::vector<TableSpec>& list : {DefaultCatalogue(copt), OnRequestTables(copt)})
    for (const TableSpec& c : list)
      if (c.name == s.name && c.quantity == kind) return c;
  // A kind of a model the catalogue does not list: the kind's default axes.
  if (opt.size > 0)
    for (AxisSpec& a : s.axes)
      if (a.size > 2 || a.name != "roughness") a.size = opt.size;  // as the catalogue resizes
  return s;
}

Plan PlanScene(const Scene& scene, const PlanOptions& opt) {
  Plan plan;
  plan.scenePath = scene.path;
  plan.format = scene.format;
  plan.materialCount = scene.materialCount;
  plan.warnings = scene.warnings;

  // Merge the needs by table (kind, model), resolving "whole" against the catalogue axis. Each
  // need, reason, note and material is placed by one hash lookup: linear in the scene's size.
  struct Group {
    Quantity kind;
    std::string model;
    TableSpec whole;
    std::map<std::string, ValueRange> ranges;
    std::vector<std::string> reasons;
    std::unordered_set<std::string> reasonSet;
  };
  std::vector<Group> groups;
  std::unordered_map<std::string, size_t> groupOf;     // "kind model" -> index in groups
  std::unordered_map<std::string, TableSpec> wholeOf;  // "kind model" -> WholeTableSpec
  std::vector<SceneNote> outsideNotes;  // values outside a table's domain (NeedRanges)
  for (const TableNeed& need : scene.needs) {
    ++plan.mergeProbes;
    std::string key = std::to_string(static_cast<int>(need.kind)) + " " + need.model;
    auto whole = wholeOf.find(key);
    if (whole == wholeOf.end())
      whole = wholeOf.emplace(key, WholeTableSpec(need.kind, need.model, opt)).first;
    std::map<std::string, ValueRange> ranges;
    std::string outside;
    if (!NeedRanges(need, whole->second, ranges, outside)) {
      AddOutsideNote(outsideNotes, need, whole->second.name, outside + ": not planned");
      continue;
    }
    if (!outside.empty())
      AddOutsideNote(outsideNotes, need, whole->second.name, outside + ": planned over the rest");
    auto [slot, added] = groupOf.emplace(key, groups.size());
    if (added) groups.push_back({need.kind, need.model, whole->second, {}, {}, {}});
    Group* g = &groups[slot->second];
    for (const auto& [axis, v] : ranges) {
      auto have = g->ranges.find(axis);
      g->ranges[axis] = have == g->ranges.end() ? v : have->second.Union(v);
    }
    ++plan.mergeProbes;
    if (g->reasonSet.insert(need.reason).second) g->reasons.push_back(need.reason);
  }
  for (Group& g : groups) {
    PlannedTable t;
    t.spec = g.whole;
    CutAxes(t.spec, g.ranges);
    t.reasons = std::move(g.reasons);
    t.ranges = g.ranges;
    plan.tables.push_back(std::move(t));
  }

  // Notes of the same kind, topic and reason merge; each lists its materials once, first seen
  // first.
  std::unordered_map<std::string, size_t> noteOf;  // "kind\ntopic\nwhy" -> index in plan.notes
  std::vector<std::unordered_set<std::string>> noteMaterials;
  auto mergeNote = [&](const SceneNote& n) {
    ++plan.mergeProbes;
    std::string key = std::to_string(static_cast<int>(n.kind)) + "\n" + n.topic + "\n" + n.why;
    auto [slot, added] = noteOf.emplace(key, plan.notes.size());
    if (added) {
      plan.notes.push_back({n.kind, n.topic, n.why, {}});
      noteMaterials.emplace_back();
    }
    ++plan.mergeProbes;
    if (!n.material.empty() && noteMaterials[slot->second].insert(n.material).second)
      plan.notes[slot->second].materials.push_back(n.material);
  };
  for (const SceneNote& n : scene.notes) mergeNote(n);
  for (const SceneNote& n : outsideNotes) mergeNote(n);
  return plan;
}

Plan PlanSceneFile(const std::string& path, const PlanOptions& opt) {
  return PlanScene(ReadScene(path), opt);
}

}  // namespace kiln
