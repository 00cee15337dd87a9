// The plan: a scene's table needs merged into the table specs to bake.
//
// Needs of the same kind and model (from any material or lobe) merge into one table over the
// union (hull) of their values. Each axis the scene bounds is then cut to those values:
//   - the catalogue's whole range: the catalogue axis (the spec, hence the file, is the
//     catalogue's own when no axis is cut);
//   - an interval: NarrowAxis (the catalogue's node density, fewer nodes, at least 2);
//   - one value: the axis is dropped and the value recorded in the spec's params when the
//     quantity reads it from there (QuantityInfo::readsParams; fresnel-albedo: a 3D table at one
//     IOR is 2D), otherwise a 2-node SliceAxis with a node exactly at the value (dfg, albedo, ...);
//     a table never loses its last axis (that one becomes a slice).
// Names say what was cut, axis by axis: "-r" roughness, "-ior" eta, "-n", "-k", each followed by
// the value or "lo-hi" (6 significant digits): ggx-dfg-r0.3-0.6, ggx-fresnel-albedo-r0.1-ior1.5.
#pragma once
#include <string>
#include <vector>

#include "baker/scene/scene.h"
#include "baker/tables/spec.h"

namespace kiln {

struct PlanOptions {
  int size = 0;  ///< 0: catalogue sizes; else every catalogue axis gets this size before narrowing
};

/// One table to bake, and why.
struct PlannedTable {
  TableSpec spec;
  std::vector<std::string> reasons;          ///< the needs merged into it, one line each
  std::map<std::string, ValueRange> ranges;  ///< the values the scene uses, by axis name
};

/// Notes of the same kind, topic and reason, with every material they concern.
struct PlanNote {
  SceneNote::Kind kind = SceneNote::Kind::NoTable;
  std::string topic, why;
  std::vector<std::string> materials;
};

struct Plan {
  std::string scenePath, format;
  int materialCount = 0;
  std::vector<PlannedTable> tables;  ///< in the order of the first need of each
  std::vector<PlanNote> notes;
  std::vector<std::string> warnings;
  /// Entries the merge looked at to place the scene's needs, their reasons and its notes (a
  /// lookup in a hash table counts one): the planner's work, linear in the scene's size.
  size_t mergeProbes = 0;
};

/// Plans `scene`. Throws std::invalid_argument for a need the planner cannot build (an unknown
/// model: a reader bug, readers check it).
Plan PlanScene(const Scene& scene, const PlanOptions& opt = {});

/// ReadScene(path), then PlanScene.
Plan PlanSceneFile(const std::string& path, const PlanOptions& opt = {});

/// The catalogue spec of table kind `kind` of `model` (all axes whole), resized by opt.size.
TableSpec WholeTableSpec(Quantity kind, const std::string& model, const PlanOptions& opt = {});

}  // namespace kiln
