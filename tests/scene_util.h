// Helpers the scene tests share: the committed scenes, plan queries, temporary files.
#pragma once
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "baker/scene/plan.h"
#include "cli_util.h"

namespace kiln::test {

/// tests/scenes/<name> in the source tree.
inline std::string ScenePath(const std::string& name) {
  return std::string(KILN_SOURCE_DIR) + "/tests/scenes/" + name;
}

/// The planned table names, in plan order.
inline std::vector<std::string> TableNames(const Plan& plan) {
  std::vector<std::string> names;
  for (const PlannedTable& t : plan.tables) names.push_back(t.spec.name);
  return names;
}

/// The planned table `name`, or nullptr.
inline const PlannedTable* FindTable(const Plan& plan, const std::string& name) {
  for (const PlannedTable& t : plan.tables)
    if (t.spec.name == name) return &t;
  return nullptr;
}

/// The axis `name` of `spec`, or nullptr.
inline const AxisSpec* FindAxis(const TableSpec& spec, const std::string& name) {
  for (const AxisSpec& a : spec.axes)
    if (a.name == name) return &a;
  return nullptr;
}

/// The note of this kind about `topic`, or nullptr.
inline const PlanNote* FindNote(const Plan& plan, SceneNote::Kind kind, const std::string& topic) {
  for (const PlanNote& n : plan.notes)
    if (n.kind == kind && n.topic == topic) return &n;
  return nullptr;
}

/// A fresh empty folder under /tmp, unique to this process and tag.
inline std::string SceneTempDir(const std::string& tag) {
  std::string dir = "/tmp/kiln_scene_test_" + tag + "_" + std::to_string(getpid());
  RemoveTree(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Plans a glTF or kiln scene given as text (written to a temporary file named `file`).
inline Plan PlanText(const std::string& text, const std::string& file = "scene.gltf",
                     PlanOptions opt = {}) {
  std::string dir = SceneTempDir("text");
  WriteText(dir + "/" + file, text);
  Plan plan = PlanSceneFile(dir + "/" + file, opt);
  RemoveTree(dir);
  return plan;
}

/// A one-material glTF 2.0 asset: `material` is the material's JSON object.
inline std::string OneMaterialGltf(const std::string& material) {
  return R"({"asset": {"version": "2.0"}, "materials": [)" + material + "]}";
}

}  // namespace kiln::test
