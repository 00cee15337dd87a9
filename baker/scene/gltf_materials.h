// glTF 2.0 materials -> what they need from kiln (docs/scene.md has the table):
//   pbrMetallicRoughness (or KHR_materials_pbrSpecularGlossiness): a GGX lobe (height-correlated
//     Smith): ggx-dfg (split-sum), ggx-albedo and ggx-albedo-avg (multiple-scattering
//     compensation) over the roughness values; the Lambert diffuse needs no table.
//   KHR_materials_clearcoat: a second GGX lobe: ggx-dfg over the clearcoat roughness.
//   KHR_materials_ior / _transmission (/ _volume, _dispersion): ggx-fresnel-albedo over the
//     base roughness and the IOR values.
//   the rest: no table (with the reason), no effect, not yet, or unknown.
// Roughness (and IOR) values: a factor alone is one exact value; a texture multiplies the factor,
// so roughness spans [0, factor]; a factor animated through KHR_animation_pointer spans the
// whole axis.
#pragma once
#include <set>
#include <string>

#include "baker/scene/scene.h"
#include "baker/scene/scene_json.h"

namespace kiln {

/// Appends the needs and notes of glTF material `material` (at JSON pointer `at`; `label` names
/// it in reasons, e.g. "'Steel' (/materials/0)") to `scene`. `animated` holds the JSON pointers
/// KHR_animation_pointer animates. Throws SceneError for an out-of-range value.
void AddGltfMaterial(const Json& material, const std::string& at, const std::string& label,
                     const std::set<std::string>& animated, const JsonReader& reader, Scene& scene);

/// True for a material extension AddGltfMaterial handles (or reports on by name).
bool IsKnownMaterialExtension(const std::string& name);

/// True for a glTF extension that is not about materials (meshes, textures, lights, ...): it
/// needs no table.
bool IsNonMaterialExtension(const std::string& name);

}  // namespace kiln
