#include "baker/scene/plan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

  // Merge the needs by table (kind, model), resolving "whole" against the catalogue axis.
  struct Group {
    Quantity kind;
    std::string model;
    TableSpec whole;
    std::map<std::string, ValueRange> ranges;
    std::vector<std::string> reasons;
  };
  std::vector<Group> groups;
  for (const TableNeed& need : scene.needs) {
    auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& x) {
      return x.kind == need.kind && x.model == need.model;
    });
    if (g == groups.end()) {
      groups.push_back({need.kind, need.model, WholeTableSpec(need.kind, need.model, opt), {}, {}});
      g = groups.end() - 1;
    }
    for (const AxisSpec& a : g->whole.axes) {
      auto found = need.ranges.find(a.name);
      // An axis the need does not bound spans the whole axis.
      ValueRange v = found == need.ranges.end() || found->second.whole
                         ? ValueRange::Between(a.lo, a.hi)
                         : found->second;
      if (a.name == "mu" && found == need.ranges.end()) continue;
      const QuantityInfo& q = Describe(need.kind);
      if (q.sceneDomain && found != need.ranges.end() && !found->second.whole &&
          (v.lo < a.lo || v.hi > a.hi))
        throw std::invalid_argument("plan: " + need.reason + ": " + a.name + " " + v.Text() +
                                    " is outside " + q.name + "'s domain " + a.name + " in [" +
                                    ShortNumber(a.lo) + ", " + ShortNumber(a.hi) + "] (" +
                                    q.sceneDomain + ")");
      auto have = g->ranges.find(a.name);
      g->ranges[a.name] = have == g->ranges.end() ? v : have->second.Union(v);
    }
    if (std::find(g->reasons.begin(), g->reasons.end(), need.reason) == g->reasons.end())
      g->reasons.push_back(need.reason);
  }
  for (Group& g : groups) {
    PlannedTable t;
    t.spec = g.whole;
    CutAxes(t.spec, g.ranges);
    t.reasons = g.reasons;
    t.ranges = g.ranges;
    plan.tables.push_back(std::move(t));
  }

  for (const SceneNote& n : scene.notes) {
    auto p = std::find_if(plan.notes.begin(), plan.notes.end(), [&](const PlanNote& x) {
      return x.kind == n.kind && x.topic == n.topic && x.why == n.why;
    });
    if (p == plan.notes.end()) {
      plan.notes.push_back({n.kind, n.topic, n.why, {}});
      p = plan.notes.end() - 1;
    }
    if (!n.material.empty() &&
        std::find(p->materials.begin(), p->materials.end(), n.material) == p->materials.end())
      p->materials.push_back(n.material);
  }
  return plan;
}

Plan PlanSceneFile(const std::string& path, const PlanOptions& opt) {
  return PlanScene(ReadScene(path), opt);
}

}  // namespace kiln
