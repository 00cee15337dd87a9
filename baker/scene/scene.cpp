#include "baker/scene/scene.h"

#include <algorithm>

#include "baker/scene/glb.h"
#include "baker/scene/gltf_reader.h"
#include "baker/scene/kiln_scene_reader.h"
#include "baker/scene/scene_json.h"

namespace kiln {

ValueRange ValueRange::Union(const ValueRange& o) const {
  if (whole || o.whole) return Whole();
  return Between(std::min(lo, o.lo), std::max(hi, o.hi));
}

std::string ValueRange::Text() const {
  if (whole) return "whole axis";
  if (lo == hi) return ExactNumber(lo);
  return ExactNumber(lo) + ".." + ExactNumber(hi);
}

Scene ReadScene(const std::string& path) {
  std::string bytes = ReadSceneFile(path);
  bool glbName = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  if (IsGlb(bytes) || glbName) return ReadGltf(path, bytes);
  Json doc = ParseSceneJson(bytes, path);
  if (doc.is_object() && doc.contains("kiln_scene")) return ReadKilnScene(doc, path);
  if (doc.is_object() && !doc.contains("asset"))
    throw SceneError(
        path, "/", "neither a glTF 2.0 asset (no \"asset\") nor a kiln scene (no \"kiln_scene\")");
  return ReadGltfDocument(doc, path, "glTF");
}

}  // namespace kiln
