// Reads a glTF 2.0 asset (.gltf JSON or .glb container) into a Scene of table needs.
//
// Checked (SceneError names the file and the JSON pointer): JSON syntax, asset.version 2.x (and
// minVersion), the glb header, every index a material depends on (mesh primitive -> material,
// KHR_materials_variants mapping -> material, textureInfo -> texture, texture -> image/sampler),
// and the material values kiln reads (factors in [0, 1], ior >= 1 or 0, ...).
//
// Which materials: when the asset has meshes, the materials their primitives use (a primitive
// without a material uses glTF's default material: roughness 1, metallic 1); the others are
// reported as unused. An asset without meshes (a material library) plans every material.
// Unknown extensions are reported and ignored; one listed in extensionsRequired also adds a
// warning (the plan is still made: it covers what kiln understands).
#pragma once
#include <string>

#include "baker/scene/scene.h"
#include "baker/scene/scene_json.h"

namespace kiln {

/// Reads the .gltf or .glb file `path` whose bytes are `bytes` (a glb: bytes starting with the
/// magic 'glTF', or any file named *.glb).
Scene ReadGltf(const std::string& path, const std::string& bytes);

/// Reads an already parsed glTF document (`format`: "glTF" or "glb", for the report).
Scene ReadGltfDocument(const Json& doc, const std::string& path, const std::string& format);

}  // namespace kiln
