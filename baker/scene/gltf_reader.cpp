#include "baker/scene/gltf_reader.h"

#include <algorithm>
#include <set>
#include <vector>

#include "baker/scene/glb.h"
#include "baker/scene/gltf_materials.h"

namespace kiln {
namespace {

/// Checks asset.version (and minVersion): glTF 2.x only.
void CheckVersion(const Json& doc, const JsonReader& r) {
  const Json* asset = JsonReader::Find(doc, "asset");
  if (!asset) r.Fail("/asset", "missing: not a glTF 2.0 asset (asset.version is required)");
  r.Object(*asset, "/asset");
  auto major = [&](const char* key, bool required) {
    const Json* v = JsonReader::Find(*asset, key);
    std::string at = PointerChild("/asset", key);
    if (!v) {
      if (required) r.Fail(at, "missing (a glTF 2.0 asset has asset.version \"2.0\")");
      return -1;
    }
    std::string text = r.String(*v, at);
    size_t dot = text.find('.');
    bool ok = dot != std::string::npos && dot > 0 && dot + 1 < text.size() &&
              std::all_of(text.begin(), text.end(),
                          [](char c) { return (c >= '0' && c <= '9') || c == '.'; }) &&
              text.find('.', dot + 1) == std::string::npos && text.size() <= 12;
    if (!ok) r.Fail(at, "\"" + text + "\" is not a glTF version (MAJOR.MINOR)");
    int m = std::stoi(text.substr(0, dot)), minor = std::stoi(text.substr(dot + 1));
    if (m != 2) r.Fail(at, "glTF " + text + " is not supported: kiln reads glTF 2.x");
    if (std::string(key) == "minVersion" && minor > 0)
      r.Fail(at, "minVersion " + text + ": kiln reads glTF 2.0");
    return m;
  };
  major("version", true);
  major("minVersion", false);
}

/// Every textureInfo (an object under a key ending in "Texture", outside "extras") in `v` must
/// name a texture. Iterative, depth first in document order: the stack holds one frame per level
/// (the parser bounds the depth), and a frame's JSON pointer is only built for a message.
void CheckTextureInfos(const Json& v, const std::string& at, size_t textures, const JsonReader& r) {
  struct Frame {
    const Json* value;
    Json::const_iterator next;  ///< the next child to visit
    size_t index = 0;           ///< its index, for an array
  };
  std::vector<Frame> stack;
  auto push = [&](const Json& value) {
    if (value.is_object() || value.is_array()) stack.push_back({&value, value.cbegin(), 0});
  };
  // The pointer of the child the top frame is visiting.
  auto pointer = [&]() {
    std::string p = at;
    for (const Frame& f : stack)
      p = f.value->is_object() ? PointerChild(p, f.next.key()) : PointerChild(p, f.index);
    return p;
  };
  push(v);
  while (!stack.empty()) {
    Frame& top = stack.back();
    if (top.next == top.value->cend()) {
      stack.pop_back();
      if (!stack.empty()) {
        ++stack.back().next;
        ++stack.back().index;
      }
      continue;
    }
    const Json& child = *top.next;
    if (top.value->is_object()) {
      const std::string& key = top.next.key();
      if (key == "extras") {  // application data: not glTF's to check
        ++top.next;
        continue;
      }
      bool textureInfo = key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0;
      if (textureInfo) {
        if (!child.is_object()) r.Object(child, pointer());
        const Json* index = JsonReader::Find(child, "index");
        if (!index) r.Fail(pointer(), "textureInfo without \"index\"");
        if ((!index->is_number_integer() && !index->is_number_unsigned()) ||
            index->get<long long>() < 0 || index->get<unsigned long long>() >= textures)
          r.Index(*index, PointerChild(pointer(), "index"), textures, "texture");
      }
    }
    if (child.is_object() || child.is_array()) {
      push(child);
    } else {
      ++top.next;
      ++top.index;
    }
  }
}

/// Textures must name existing images and samplers (also through KHR_texture_basisu & co.).
void CheckTextures(const Json& doc, const JsonReader& r) {
  const Json& textures = r.ArrayOrEmpty(doc, "", "textures");
  size_t images = r.ArrayOrEmpty(doc, "", "images").size();
  size_t samplers = r.ArrayOrEmpty(doc, "", "samplers").size();
  for (size_t i = 0; i < textures.size(); ++i) {
    std::string at = PointerChild("/textures", i);
    const Json& t = r.Object(textures[i], at);
    if (const Json* s = JsonReader::Find(t, "source"))
      r.Index(*s, PointerChild(at, "source"), images, "image");
    if (const Json* s = JsonReader::Find(t, "sampler"))
      r.Index(*s, PointerChild(at, "sampler"), samplers, "sampler");
    if (const Json* ext = JsonReader::Find(t, "extensions")) {
      r.Object(*ext, PointerChild(at, "extensions"));
      for (auto it = ext->begin(); it != ext->end(); ++it)
        if (const Json* s = JsonReader::Find(*it, "source"))
          r.Index(*s,
                  PointerChild(PointerChild(PointerChild(at, "extensions"), it.key()), "source"),
                  images, "image");
    }
  }
}

/// The JSON pointers KHR_animation_pointer animates.
std::set<std::string> AnimatedPointers(const Json& doc, const JsonReader& r) {
  std::set<std::string> out;
  const Json& animations = r.ArrayOrEmpty(doc, "", "animations");
  for (size_t a = 0; a < animations.size(); ++a) {
    std::string at = PointerChild("/animations", a);
    const Json& channels = r.ArrayOrEmpty(r.Object(animations[a], at), at, "channels");
    for (size_t c = 0; c < channels.size(); ++c) {
      const Json* target = JsonReader::Find(channels[c], "target");
      const Json* ext = target ? JsonReader::Find(*target, "extensions") : nullptr;
      const Json* ap = ext ? JsonReader::Find(*ext, "KHR_animation_pointer") : nullptr;
      const Json* pointer = ap ? JsonReader::Find(*ap, "pointer") : nullptr;
      if (pointer && pointer->is_string()) out.insert(pointer->get<std::string>());
    }
  }
  return out;
}

std::string MaterialLabel(const Json& m, const std::string& at) {
  const Json* name = JsonReader::Find(m, "name");
  if (name && name->is_string() && !name->get<std::string>().empty())
    return "'" + name->get<std::string>() + "' (" + at + ")";
  return at;
}

}  // namespace

Scene ReadGltfDocument(const Json& doc, const std::string& path, const std::string& format) {
  JsonReader r{path};
  r.Object(doc, "");
  CheckVersion(doc, r);
  Scene scene;
  scene.path = path;
  scene.format = format;

  const Json& materials = r.ArrayOrEmpty(doc, "", "materials");
  const Json& textures = r.ArrayOrEmpty(doc, "", "textures");
  for (size_t i = 0; i < materials.size(); ++i) {
    std::string at = PointerChild("/materials", i);
    CheckTextureInfos(r.Object(materials[i], at), at, textures.size(), r);
  }
  CheckTextures(doc, r);

  // Which materials the meshes use (all of them for an asset without meshes).
  const Json& meshes = r.ArrayOrEmpty(doc, "", "meshes");
  std::vector<bool> used(materials.size(), meshes.empty());
  std::string defaultUser;  // a primitive without a material: glTF's default material
  for (size_t m = 0; m < meshes.size(); ++m) {
    std::string at = PointerChild("/meshes", m);
    const Json& primitives = r.ArrayOrEmpty(r.Object(meshes[m], at), at, "primitives");
    for (size_t p = 0; p < primitives.size(); ++p) {
      std::string pat = PointerChild(PointerChild(at, "primitives"), p);
      const Json& prim = r.Object(primitives[p], pat);
      if (const Json* mat = JsonReader::Find(prim, "material"))
        used[r.Index(*mat, PointerChild(pat, "material"), materials.size(), "material")] = true;
      else if (defaultUser.empty())
        defaultUser = pat;
      const Json* ext = JsonReader::Find(prim, "extensions");
      const Json* variants = ext ? JsonReader::Find(*ext, "KHR_materials_variants") : nullptr;
      if (variants) {
        std::string vat = PointerChild(PointerChild(pat, "extensions"), "KHR_materials_variants");
        const Json& mappings = r.ArrayOrEmpty(r.Object(*variants, vat), vat, "mappings");
        for (size_t k = 0; k < mappings.size(); ++k) {
          std::string mat = PointerChild(PointerChild(vat, "mappings"), k);
          const Json* index = JsonReader::Find(r.Object(mappings[k], mat), "material");
          if (index)
            used[r.Index(*index, PointerChild(mat, "material"), materials.size(), "material")] =
                true;
        }
      }
    }
  }

  std::set<std::string> animated = AnimatedPointers(doc, r);
  for (size_t i = 0; i < materials.size(); ++i) {
    std::string at = PointerChild("/materials", i);
    std::string label = MaterialLabel(materials[i], at);
    if (!used[i]) {
      scene.notes.push_back(
          {SceneNote::Kind::Unused, "unused material", "no mesh primitive uses it", label});
      continue;
    }
    ++scene.materialCount;
    AddGltfMaterial(materials[i], at, label, animated, r, scene);
  }
  if (!defaultUser.empty()) {
    ++scene.materialCount;
    AddGltfMaterial(Json::object(), "", "default material (" + defaultUser + " has none)", animated,
                    r, scene);
  }

  // Extensions: the file-level ones that are not about materials, and unknown ones.
  std::set<std::string> onMaterials;
  for (const SceneNote& n : scene.notes)
    if (n.kind == SceneNote::Kind::Unknown) onMaterials.insert(n.topic);
  const Json& usedExt = r.ArrayOrEmpty(doc, "", "extensionsUsed");
  for (size_t i = 0; i < usedExt.size(); ++i) {
    std::string name = r.String(usedExt[i], PointerChild("/extensionsUsed", i));
    if (IsNonMaterialExtension(name))
      scene.notes.push_back({SceneNote::Kind::NoTable, name, "not a material extension", ""});
    else if (!IsKnownMaterialExtension(name) && !onMaterials.count(name))
      scene.notes.push_back({SceneNote::Kind::Unknown, name, "unknown extension: ignored", ""});
  }
  const Json& required = r.ArrayOrEmpty(doc, "", "extensionsRequired");
  for (size_t i = 0; i < required.size(); ++i) {
    std::string name = r.String(required[i], PointerChild("/extensionsRequired", i));
    if (!IsKnownMaterialExtension(name) && !IsNonMaterialExtension(name))
      scene.warnings.push_back(
          path + ": /extensionsRequired/" + std::to_string(i) + ": '" + name +
          "' is required but unknown to kiln: the plan covers what kiln understands "
          "and may miss tables this extension needs");
  }
  return scene;
}

Scene ReadGltf(const std::string& path, const std::string& bytes) {
  bool glbName = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  if (IsGlb(bytes) || glbName)
    return ReadGltfDocument(ParseSceneJson(GlbJsonChunk(bytes, path), path, "JSON chunk, "), path,
                            "glb");
  return ReadGltfDocument(ParseSceneJson(bytes, path), path, "glTF");
}

}  // namespace kiln
