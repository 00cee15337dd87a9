// A scene as the planner sees it: not meshes or textures, only what its materials need from
// kiln. A reader (glTF, glb, kiln scene manifest) turns a file into a list of table needs, each
// a table kind of a model over the parameter values the materials use, plus notes on what needs
// no table and why. The planner (plan.h) merges the needs into table specs.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "baker/tables/quantity.h"

namespace kiln {

/// The values one material parameter takes: the closed interval [lo, hi] (lo == hi: one exact
/// value, e.g. a glTF factor without a texture), or the catalogue's whole axis (`whole`: the
/// reader cannot bound it, e.g. an animated factor or "any" in a kiln scene).
struct ValueRange {
  double lo = 0, hi = 0;
  bool whole = false;

  static ValueRange Exactly(double v) { return {v, v, false}; }
  static ValueRange Between(double lo, double hi) { return {lo, hi, false}; }
  static ValueRange Whole() { return {0, 0, true}; }

  bool Single() const { return !whole && lo == hi; }
  /// The smallest range holding both (the union of two intervals is their hull).
  ValueRange Union(const ValueRange& o) const;
  /// "0.3", "0.2..0.6" or "whole axis".
  std::string Text() const;
};

/// One table a material needs: table kind `kind` of model `model` over the values in `ranges`.
/// kind is a quantity the planner can narrow (QuantityInfo::sceneKind). An axis missing from
/// `ranges` (mu always) spans its catalogue range.
struct TableNeed {
  Quantity kind = Quantity::Dfg;
  std::string model;                         ///< "ggx", ...; "none" for the Fresnel tables
  std::map<std::string, ValueRange> ranges;  ///< by axis name: "roughness", "eta", "n", "k"
  std::string reason;                        ///< who needs it and why, one line
  std::string material;  ///< the material that needs it, e.g. "'Glass' (/materials/0)"
  /// The scene names this table kind itself (a kiln scene's "tables"): a value outside the
  /// kind's domain is an error. Otherwise (a table the reader derived, e.g. from a glTF IOR)
  /// the planner leaves the table out for that value and says so in a note.
  bool named = false;
};

/// Something in a scene that needs no table (or cannot have one yet), and why.
struct SceneNote {
  enum class Kind {
    NoTable,   ///< handled without a table (closed form, or covered by another table)
    NoEffect,  ///< present in the file but without effect on shading (e.g. a zero factor)
    NotYet,    ///< would need a table kiln cannot bake yet
    Unknown,   ///< an extension kiln does not know
    Unused,    ///< a material no mesh primitive uses
  };
  Kind kind = Kind::NoTable;
  std::string topic;  ///< "Lambert diffuse", "KHR_materials_sheen", ...
  std::string why;    ///< one line
  std::string
      material;  ///< the material it concerns, e.g. "'Velvet' (/materials/2)"; "" for the file
};

/// What a scene file asks of kiln.
struct Scene {
  std::string path;
  std::string format;     ///< "glTF", "glb" or "kiln scene"
  int materialCount = 0;  ///< materials the planner looked at (used ones; glTF default included)
  std::vector<TableNeed> needs;
  std::vector<SceneNote> notes;
  std::vector<std::string> warnings;  ///< e.g. an unknown extension in extensionsRequired
};

/// Reads a scene: a glTF 2.0 file (.gltf JSON or .glb binary, told apart by the 'glTF' magic) or
/// a kiln scene manifest (a JSON object with "kiln_scene"). Throws SceneError (scene_error.h)
/// naming the file and the place for a file kiln cannot use.
Scene ReadScene(const std::string& path);

}  // namespace kiln
