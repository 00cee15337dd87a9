#include "baker/scene/kiln_scene_reader.h"

#include <algorithm>

#include "baker/models/model_names.h"
#include "baker/models/registry.h"

namespace kiln {
namespace {

using Kind = SceneNote::Kind;

const ParamInfo* FindParam(const ModelInfo& m, const std::string& name) {
  for (const ParamInfo& p : m.params)
    if (p.name == name) return &p;
  return nullptr;
}

/// Why model `m` has no table of `kind` ("" when it has one).
std::string KindProblem(const ModelInfo& m, Quantity kind) {
  const QuantityInfo& q = Describe(kind);
  return q.sceneProblem ? q.sceneProblem(m) : "";
}

std::string Join(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

/// One parameter value: a number, [lo, hi] or "any", inside the model's range.
ValueRange ReadValue(const Json& v, const std::string& at, const ParamInfo& p,
                     const JsonReader& r) {
  auto inRange = [&](double x, const std::string& where) {
    if (x < p.lo || x > p.hi)
      r.Fail(where, p.name + " " + ExactNumber(x) + " is outside [" + ExactNumber(p.lo) + ", " +
                        ExactNumber(p.hi) + "]");
    return x;
  };
  if (v.is_number()) return ValueRange::Exactly(inRange(r.Number(v, at), at));
  if (v.is_string() && v.get<std::string>() == "any") return ValueRange::Whole();
  if (v.is_array()) {
    if (v.size() != 2)
      r.Fail(at, "an interval is [lo, hi], got " + std::to_string(v.size()) + " values");
    double lo = inRange(r.Number(v[0], PointerChild(at, 0)), PointerChild(at, 0));
    double hi = inRange(r.Number(v[1], PointerChild(at, 1)), PointerChild(at, 1));
    if (lo > hi)
      r.Fail(at, "interval [" + ExactNumber(lo) + ", " + ExactNumber(hi) + "] has lo > hi");
    return ValueRange::Between(lo, hi);
  }
  r.Fail(at, "expected a number, an interval [lo, hi] or \"any\", got " + JsonKind(v));
}

void ReadMaterial(const Json& m, const std::string& at, const JsonReader& r, Scene& scene) {
  r.Object(m, at);
  std::string label = at;
  if (const Json* name = JsonReader::Find(m, "name"))
    label = "'" + r.String(*name, PointerChild(at, "name")) + "' (" + at + ")";
  const Json* modelJson = JsonReader::Find(m, "model");
  if (!modelJson) r.Fail(at, "missing \"model\" (a kiln model id, see `kiln list`)");
  std::string id = r.String(*modelJson, PointerChild(at, "model"));
  const ModelInfo* info = FindModel(id);
  if (!info) r.Fail(PointerChild(at, "model"), UnknownModelMessage(id));

  std::map<std::string, ValueRange> values;
  std::vector<Quantity> kinds;
  bool kindsGiven = false;
  for (auto it = m.begin(); it != m.end(); ++it) {
    const std::string& key = it.key();
    std::string kat = PointerChild(at, key);
    if (key == "name" || key == "model") continue;
    if (key == "tables") {
      kindsGiven = true;
      r.Array(*it, kat);
      for (size_t j = 0; j < it->size(); ++j) {
        std::string jat = PointerChild(kat, j);
        std::string name = r.String((*it)[j], jat);
        const QuantityInfo* q = FindQuantity(name);
        if (!q || !q->sceneKind)
          r.Fail(jat,
                 "unknown table kind '" + name + "' (one of: " + Join(SceneTableKinds()) + ")");
        std::string problem = KindProblem(*info, q->id);
        if (!problem.empty())
          r.Fail(jat, "model '" + id + "' has no " + name + " table: " + problem);
        if (std::find(kinds.begin(), kinds.end(), q->id) == kinds.end()) kinds.push_back(q->id);
      }
      continue;
    }
    const ParamInfo* p = FindParam(*info, key);
    if (!p) {
      std::vector<std::string> names;
      for (const ParamInfo& q : info->params) names.push_back(q.name);
      r.Fail(kat, "model '" + id + "' takes no parameter '" + key + "' (keys: name, model, tables" +
                      (names.empty() ? "" : ", " + Join(names)) + ")");
    }
    values[key] = ReadValue(*it, kat, *p, r);
  }
  if (values.count("f0") && values.count("eta"))
    r.Fail(at, "give either f0 (Schlick) or eta, not both");
  if (values.count("k") && !values.count("eta")) r.Fail(PointerChild(at, "k"), "k needs eta");
  bool conductor = values.count("k") && (values["k"].whole || values["k"].hi > 0);

  if (!kindsGiven) {
    if (info->albedoIsRho) {
      scene.notes.push_back({Kind::NoTable, "Lambert diffuse", "its albedo is rho exactly", label});
    } else if (info->specular()) {
      kinds = {Quantity::Dfg, Quantity::Albedo, Quantity::AlbedoAvg};
      if (conductor)
        kinds.push_back(Quantity::FresnelConductor);
      else if (values.count("eta") && KindProblem(*info, Quantity::FresnelAlbedo).empty())
        kinds.push_back(Quantity::FresnelAlbedo);
      else if (values.count("eta"))
        scene.notes.push_back(
            {Kind::NotYet, "eta", "exact-Fresnel albedo tables are baked for ggx only", label});
    } else {
      kinds = {Quantity::Albedo, Quantity::AlbedoAvg};
    }
  } else if (kinds.empty()) {
    scene.notes.push_back({Kind::NoTable, "tables: []", "the material asks for no table", label});
  }

  // Parameters with no table axis.
  if (values.count("rho"))
    scene.notes.push_back(
        {Kind::NoTable, "rho",
         "tables are baked at rho = 1: scale by rho (rho^2 channel where the model has one)",
         label});
  if (values.count("f0")) {
    if (info->specular())
      scene.notes.push_back({Kind::NoTable, "f0",
                             "Schlick F0 is applied at run time: F0 A + B from the dfg table",
                             label});
    else
      scene.notes.push_back({Kind::NotYet, "f0",
                             "the " + id + " tables are baked at its default f0 (no f0 axis yet)",
                             label});
  }
  if (values.count("rs"))
    scene.notes.push_back({Kind::NotYet, "rs",
                           "the " + id + " tables are baked at its default rs (no rs axis yet)",
                           label});
  if (values.count("nu") || values.count("nv"))
    scene.notes.push_back({Kind::NotYet, "nu, nv",
                           "tables use n_u = n_v from roughness (no anisotropy axis yet)", label});

  auto value = [&](const std::string& name) {
    auto found = values.find(name);
    return found == values.end() ? ValueRange::Whole() : found->second;
  };
  std::string what = "model " + id;
  for (const auto& [name, v] : values) what += ", " + name + " " + v.Text();
  for (Quantity kind : kinds) {
    const QuantityInfo& q = Describe(kind);
    TableNeed need;
    need.kind = kind;
    need.reason = label + ": " + what;
    need.material = label;
    need.named = kindsGiven;
    need.model = q.sceneModel ? q.sceneModel : id;
    for (const auto& [axis, param] : q.sceneAxes)
      if (FindParam(*info, param)) need.ranges[axis] = value(param);
    scene.needs.push_back(need);
  }
}

}  // namespace

const std::vector<std::string>& SceneTableKinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> v;
    for (const QuantityInfo* q : AllQuantities())
      if (q->sceneKind) v.push_back(q->name);
    return v;
  }();
  return kinds;
}

Scene ReadKilnScene(const Json& doc, const std::string& path) {
  JsonReader r{path};
  r.Object(doc, "");
  const Json* version = JsonReader::Find(doc, "kiln_scene");
  if (!version) r.Fail("/kiln_scene", "missing (a kiln scene starts with \"kiln_scene\": 1)");
  if (!version->is_number_integer() && !version->is_number_unsigned())
    r.Fail("/kiln_scene", "expected the integer 1, got " + JsonKind(*version));
  if (version->get<long long>() != 1)
    r.Fail("/kiln_scene",
           "version " + std::to_string(version->get<long long>()) + ", kiln reads version 1");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "kiln_scene" && it.key() != "materials" && it.key() != "description") {
      // The key as JSON writes it (control characters escaped): the message stays one line.
      std::string key = Json(it.key()).dump(-1, ' ', true, Json::error_handler_t::replace);
      key = key.substr(1, key.size() - 2);
      r.Fail(PointerChild("", key),
             "unknown key '" + key + "' (keys: kiln_scene, materials, description)");
    }
  const Json* materials = JsonReader::Find(doc, "materials");
  if (!materials) r.Fail("/materials", "missing (an array of materials)");
  r.Array(*materials, "/materials");
  Scene scene;
  scene.path = path;
  scene.format = "kiln scene";
  for (size_t i = 0; i < materials->size(); ++i) {
    ReadMaterial((*materials)[i], PointerChild("/materials", i), r, scene);
    ++scene.materialCount;
  }
  return scene;
}

}  // namespace kiln
