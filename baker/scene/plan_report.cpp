#include "baker/scene/plan_report.h"

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "baker/bake/bake.h"
#include "baker/io/table_json.h"
#include "baker/scene/scene_json.h"

namespace kiln {
namespace {

const char* NoteHeading(SceneNote::Kind kind) {
  switch (kind) {
    case SceneNote::Kind::NoTable:
      return "needs no table";
    case SceneNote::Kind::NoEffect:
      return "present but without effect";
    case SceneNote::Kind::NotYet:
      return "would need a table kiln cannot bake yet";
    case SceneNote::Kind::Unknown:
      return "unknown to kiln (ignored)";
    case SceneNote::Kind::Unused:
      return "unused";
  }
  return "";
}

std::string Join(const std::vector<std::string>& items, const std::string& sep) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : sep) + i;
  return s;
}

}  // namespace

TableState StateOf(const TableSpec& spec, const std::string& dir) {
  std::string path = dir + "/" + spec.name + ".exr";
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return TableState::Missing;
  return StoredSpecHash(path) == spec.Hash() ? TableState::UpToDate : TableState::Stale;
}

const char* StateName(TableState state) {
  switch (state) {
    case TableState::UpToDate:
      return "up to date";
    case TableState::Stale:
      return "stale";
    case TableState::Missing:
      return "missing";
  }
  return "";
}

std::string AxesText(const TableSpec& spec) {
  std::vector<std::string> parts;
  for (const AxisSpec& a : spec.axes)
    parts.push_back(a.name + " " + ExactNumber(a.lo) + ".." + ExactNumber(a.hi) + " (" +
                    std::to_string(a.size) + ", " + warpName(a.warp) + ")");
  return Join(parts, " x ");
}

std::string FormatPlan(const Plan& plan, const std::string& dir) {
  std::string out;
  size_t texels = 0, upToDate = 0;
  std::vector<TableState> states;
  for (const PlannedTable& t : plan.tables) {
    states.push_back(StateOf(t.spec, dir));
    texels += t.spec.TexelCount();
    upToDate += states.back() == TableState::UpToDate;
  }
  out += "scene " + plan.scenePath + " (" + plan.format + ", " +
         std::to_string(plan.materialCount) + " material" + (plan.materialCount == 1 ? "" : "s") +
         "): " + std::to_string(plan.tables.size()) + " table" +
         (plan.tables.size() == 1 ? "" : "s") + ", " + std::to_string(texels) + " texels; " +
         std::to_string(upToDate) + " up to date in " + dir + "\n";
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    const PlannedTable& t = plan.tables[i];
    const TableSpec& s = t.spec;
    out += "\n" + s.name + "  [" + StateName(states[i]) + "]\n";
    const QuantityInfo& q = Describe(s.quantity);
    out +=
        "  " + std::string(q.name) + " (" + Join(s.channels, ", ") + "): " + q.description + "\n";
    out += "  axes: " + AxesText(s) + " = " + std::to_string(s.TexelCount()) + " texels, " +
           std::to_string(s.TexelCount() * s.channels.size() * 4) + " bytes as float32\n";
    std::vector<std::string> used;
    for (const auto& [axis, v] : t.ranges) used.push_back(axis + " " + v.Text());
    if (!used.empty()) out += "  scene uses: " + Join(used, ", ") + "\n";
    if (!s.params.empty()) {
      std::vector<std::string> fixed;
      for (const auto& [k, v] : s.params) fixed.push_back(k + " = " + ExactNumber(v));
      out += "  fixed (axis dropped): " + Join(fixed, ", ") + "\n";
    }
    out += "  needed by:\n";
    for (const std::string& r : t.reasons) out += "    " + r + "\n";
  }
  for (SceneNote::Kind kind :
       {SceneNote::Kind::NoTable, SceneNote::Kind::NoEffect, SceneNote::Kind::NotYet,
        SceneNote::Kind::Unknown, SceneNote::Kind::Unused}) {
    bool heading = false;
    for (const PlanNote& n : plan.notes) {
      if (n.kind != kind) continue;
      if (!heading) out += std::string("\n") + NoteHeading(kind) + ":\n";
      heading = true;
      out += "  " + n.topic + ": " + n.why;
      if (!n.materials.empty()) out += " [" + Join(n.materials, ", ") + "]";
      out += "\n";
    }
  }
  return out;
}

std::vector<TableState> PlanStates(const Plan& plan, const std::string& dir) {
  std::vector<TableState> states;
  for (const PlannedTable& t : plan.tables) states.push_back(StateOf(t.spec, dir));
  return states;
}

namespace {

const char* NoteKind(SceneNote::Kind kind) {
  switch (kind) {
    case SceneNote::Kind::NoTable:
      return "no table";
    case SceneNote::Kind::NoEffect:
      return "no effect";
    case SceneNote::Kind::NotYet:
      return "not yet";
    case SceneNote::Kind::Unknown:
      return "unknown";
    case SceneNote::Kind::Unused:
      return "unused";
  }
  return "";
}

}  // namespace

std::string FormatPlanJson(const Plan& plan, const std::string& dir) {
  using nlohmann::ordered_json;
  std::vector<TableState> states = PlanStates(plan, dir);
  ordered_json doc;
  doc["scene"] = plan.scenePath;
  doc["format"] = plan.format;
  doc["materials"] = plan.materialCount;
  doc["dir"] = dir;
  doc["tables"] = ordered_json::array();
  size_t counts[3] = {0, 0, 0};
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    const PlannedTable& t = plan.tables[i];
    const TableSpec& s = t.spec;
    ++counts[static_cast<int>(states[i])];
    ordered_json e;
    e["name"] = s.name;
    e["state"] = StateName(states[i]);
    e["file"] = dir + "/" + s.name + ".exr";
    e["quantity"] = Describe(s.quantity).name;
    e["model"] = s.model;
    e["channels"] = s.channels;
    e["axes"] = AxesJson(s.TableAxes());
    e["params"] = ordered_json::object();
    for (const auto& [k, v] : s.params) e["params"][k] = v;
    e["texels"] = s.TexelCount();
    e["bytes_float32"] = s.TexelCount() * s.channels.size() * 4;
    e["scene_uses"] = ordered_json::object();
    for (const auto& [axis, v] : t.ranges) e["scene_uses"][axis] = v.Text();
    e["needed_by"] = t.reasons;
    e["spec_hash"] = s.Hash();
    doc["tables"].push_back(e);
  }
  doc["up_to_date"] = counts[static_cast<int>(TableState::UpToDate)];
  doc["stale"] = counts[static_cast<int>(TableState::Stale)];
  doc["missing"] = counts[static_cast<int>(TableState::Missing)];
  doc["notes"] = ordered_json::array();
  for (const PlanNote& n : plan.notes)
    doc["notes"].push_back({{"kind", NoteKind(n.kind)},
                            {"topic", n.topic},
                            {"why", n.why},
                            {"materials", n.materials}});
  doc["warnings"] = plan.warnings;
  return doc.dump(2) + "\n";
}

}  // namespace kiln
