// Reads a kiln scene manifest: materials naming any kiln model with the parameter values they use
// (docs/scene.md has the schema):
//
//   {"kiln_scene": 1,
//    "materials": [
//      {"name": "steel", "model": "ggx", "roughness": [0.2, 0.6]},
//      {"name": "glass", "model": "ggx", "roughness": 0.05, "eta": 1.5},
//      {"name": "skin", "model": "burley", "roughness": "any"},
//      {"name": "gold", "model": "ggx", "roughness": 0.3, "eta": 0.47, "k": 2.8,
//       "tables": ["dfg", "fresnel-conductor"]},
//      {"name": "plaster", "model": "lambert"}]}
//
// A parameter is one number, an interval [lo, hi], or "any" (the whole axis); an axis parameter
// a table needs and the material omits spans the whole axis. "tables" (optional) picks the table
// kinds; by default: microfacet models dfg, albedo, albedo-avg (+ fresnel-albedo for ggx with eta,
// + fresnel-conductor with k > 0), other models albedo, albedo-avg, Lambert none.
#pragma once
#include <string>
#include <vector>

#include "baker/scene/scene.h"
#include "baker/scene/scene_json.h"

namespace kiln {

/// Reads a parsed kiln scene manifest. Throws SceneError naming the file and the JSON pointer for
/// an unknown version, model, key or table kind, or a value outside the model's range.
Scene ReadKilnScene(const Json& doc, const std::string& path);

/// The names of the table kinds a kiln scene may ask for (QuantityInfo::sceneKind), in registry
/// order.
const std::vector<std::string>& SceneTableKinds();

}  // namespace kiln
