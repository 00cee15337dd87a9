#include "baker/scene/gltf_materials.h"

#include <algorithm>
#include <limits>

#include "baker/models/sheen.h"

namespace kiln {
namespace {

using Kind = SceneNote::Kind;

const char* const kMaterialExtensions[] = {"KHR_materials_anisotropy",
                                           "KHR_materials_clearcoat",
                                           "KHR_materials_diffuse_transmission",
                                           "KHR_materials_dispersion",
                                           "KHR_materials_emissive_strength",
                                           "KHR_materials_ior",
                                           "KHR_materials_iridescence",
                                           "KHR_materials_pbrSpecularGlossiness",
                                           "KHR_materials_sheen",
                                           "KHR_materials_specular",
                                           "KHR_materials_transmission",
                                           "KHR_materials_unlit",
                                           "KHR_materials_volume"};

const char* const kNonMaterialExtensions[] = {
    "KHR_animation_pointer",   "KHR_draco_mesh_compression", "KHR_interactivity",
    "KHR_lights_punctual",     "KHR_materials_variants",     "KHR_mesh_quantization",
    "KHR_node_visibility",     "KHR_texture_basisu",         "KHR_texture_transform",
    "KHR_xmp_json_ld",         "EXT_lights_image_based",     "EXT_mesh_gpu_instancing",
    "EXT_meshopt_compression", "EXT_texture_avif",           "EXT_texture_webp"};

/// Reads one material: the helpers below share its pointer, label and the scene to fill.
class MaterialReader {
 public:
  MaterialReader(const Json& m, const std::string& at, const std::string& label,
                 const std::set<std::string>& animated, const JsonReader& r, Scene& scene)
      : m_(m), at_(at), label_(label), animated_(animated), r_(r), scene_(scene) {}

  void Read();

 private:
  /// The base lobe's roughness values, how they were read, and whether the material is fully
  /// metallic (no dielectric layer at all).
  struct BaseLobe {
    ValueRange rough;
    std::string roughWhat;
    bool fullyMetallic = false;
  };
  bool ReadUnlit(const std::vector<std::string>& present);
  BaseLobe ReadBaseLobe();
  void ReadClearcoat();
  void ReadDielectricLayer(const BaseLobe& b);
  void ReadSpecularAndSheen(const BaseLobe& b);
  void ReadTablelessExtensions();
  const Json* Ext(const std::string& name) const {
    const Json* ext = JsonReader::Find(m_, "extensions");
    const Json* e = ext ? JsonReader::Find(*ext, name) : nullptr;
    if (e) r_.Object(*e, ExtAt(name));
    return e;
  }
  std::string ExtAt(const std::string& name) const {
    return PointerChild(PointerChild(at_, "extensions"), name);
  }
  bool Animated(const std::string& at, const std::string& key) const {
    return animated_.count(PointerChild(at, key)) > 0;
  }
  void Note(Kind kind, const std::string& topic, const std::string& why) {
    scene_.notes.push_back({kind, topic, why, label_});
  }
  void Need(Quantity kind, std::map<std::string, ValueRange> ranges, const std::string& why) {
    NeedModel(kind, "ggx", std::move(ranges), why);
  }
  void NeedModel(Quantity kind, const std::string& model, std::map<std::string, ValueRange> ranges,
                 const std::string& why) {
    scene_.needs.push_back({kind, model, std::move(ranges), label_ + ": " + why, label_});
  }
  /// A factor in [lo, hi] multiplied by an optional texture: one value without a texture,
  /// [0, f] with one (the texture multiplies the factor), the whole axis when animated. `what`
  /// describes it for reasons.
  ValueRange Factor(const Json& obj, const std::string& at, const std::string& key, double def,
                    const std::string& textureKey, std::string& what) const {
    double f = r_.NumberIn(obj, at, key, def, 0, 1);
    bool textured = !textureKey.empty() && JsonReader::Find(obj, textureKey);
    if (Animated(at, key)) {
      what = key + " animated (KHR_animation_pointer): whole axis";
      return ValueRange::Whole();
    }
    if (textured) {
      what = textureKey + " x " + key + " " + ExactNumber(f) + ": 0.." + ExactNumber(f);
      return ValueRange::Between(0, f);
    }
    what = key + " " + ExactNumber(f);
    return ValueRange::Exactly(f);
  }

  const Json& m_;
  std::string at_, label_;
  const std::set<std::string>& animated_;
  const JsonReader& r_;
  Scene& scene_;
};

/// Notes on the extensions kiln does not know; for an unlit material the notes that it needs
/// no table, and true (nothing more to read).
bool MaterialReader::ReadUnlit(const std::vector<std::string>& present) {
  for (const std::string& name : present)
    if (!IsKnownMaterialExtension(name))
      Note(Kind::Unknown, name,
           IsNonMaterialExtension(name)
               ? "not a material extension here: ignored"
               : "unknown material extension: ignored (the plan covers what kiln knows)");

  if (Ext("KHR_materials_unlit")) {
    Note(Kind::NoTable, "KHR_materials_unlit", "unlit: no BRDF, so no table");
    for (const std::string& name : present)
      if (name != "KHR_materials_unlit" && IsKnownMaterialExtension(name))
        Note(Kind::NoEffect, name, "ignored on an unlit material");
    return true;
  }

  return false;
}

/// The base GGX lobe (metallic-roughness or specular-glossiness): its tables and what the
/// layers above it need of it.
MaterialReader::BaseLobe MaterialReader::ReadBaseLobe() {
  BaseLobe b;
  if (const Json* sg = Ext("KHR_materials_pbrSpecularGlossiness")) {
    std::string at = ExtAt("KHR_materials_pbrSpecularGlossiness"), what;
    ValueRange gloss = Factor(*sg, at, "glossinessFactor", 1, "specularGlossinessTexture", what);
    b.rough = gloss.whole ? gloss : ValueRange::Between(1 - gloss.hi, 1 - gloss.lo);
    b.roughWhat = "roughness 1 - glossiness (" + what + ")";
  } else {
    static const Json kDefaults = Json::object();
    const Json* pbr = JsonReader::Find(m_, "pbrMetallicRoughness");
    std::string at = PointerChild(at_, "pbrMetallicRoughness");
    if (pbr) r_.Object(*pbr, at);
    const Json& p = pbr ? *pbr : kDefaults;
    b.rough = Factor(p, at, "roughnessFactor", 1, "metallicRoughnessTexture", b.roughWhat);
    std::string metalWhat;
    ValueRange metal = Factor(p, at, "metallicFactor", 1, "metallicRoughnessTexture", metalWhat);
    b.fullyMetallic = metal.Single() && metal.lo == 1;
  }
  Need(Quantity::Dfg, {{"roughness", b.rough}}, "base GGX lobe, " + b.roughWhat);
  Need(Quantity::Albedo, {{"roughness", b.rough}}, "base GGX lobe, " + b.roughWhat);
  Need(Quantity::AlbedoAvg, {{"roughness", b.rough}}, "base GGX lobe, " + b.roughWhat);
  if (!b.fullyMetallic) Note(Kind::NoTable, "Lambert diffuse", "its albedo is rho exactly");

  return b;
}

/// KHR_materials_clearcoat: the coat's GGX lobe.
void MaterialReader::ReadClearcoat() {
  if (const Json* cc = Ext("KHR_materials_clearcoat")) {
    std::string at = ExtAt("KHR_materials_clearcoat"), what;
    ValueRange coat = Factor(*cc, at, "clearcoatFactor", 0, "clearcoatTexture", what);
    if (!coat.whole && coat.hi == 0) {
      Note(Kind::NoEffect, "KHR_materials_clearcoat", "clearcoatFactor 0: no coat");
    } else {
      std::string rWhat;
      ValueRange cr =
          Factor(*cc, at, "clearcoatRoughnessFactor", 0, "clearcoatRoughnessTexture", rWhat);
      Need(Quantity::Dfg, {{"roughness", cr}}, "clearcoat GGX lobe, " + rWhat);
    }
  }
}

/// The dielectric layer (KHR_materials_ior, _transmission, _volume, _dispersion) over the base
/// lobe `b`: its Fresnel albedo and, when it transmits, the rough glass interface's tables.
void MaterialReader::ReadDielectricLayer(const BaseLobe& b) {
  const ValueRange& rough = b.rough;
  const std::string& roughWhat = b.roughWhat;
  const bool fullyMetallic = b.fullyMetallic;
  const Json* iorExt = Ext("KHR_materials_ior");
  const Json* tr = Ext("KHR_materials_transmission");
  const Json* vol = Ext("KHR_materials_volume");
  const Json* disp = Ext("KHR_materials_dispersion");
  double ior = 1.5;
  bool iorAnimated = false;
  if (iorExt) {
    std::string at = ExtAt("KHR_materials_ior");
    ior = r_.NumberIn(*iorExt, at, "ior", 1.5, 0, std::numeric_limits<double>::infinity());
    if (ior > 0 && ior < 1)
      r_.Fail(PointerChild(at, "ior"),
              ExactNumber(ior) + " is not a valid IOR (>= 1, or exactly 0)");
    iorAnimated = Animated(at, "ior");
  }
  bool transmits = false;
  std::string trWhat;
  if (tr) {
    ValueRange t = Factor(*tr, ExtAt("KHR_materials_transmission"), "transmissionFactor", 0,
                          "transmissionTexture", trWhat);
    transmits = t.whole || t.hi > 0;
    if (!transmits)
      Note(Kind::NoEffect, "KHR_materials_transmission", "transmissionFactor 0: no transmission");
  }
  if (vol && !transmits)
    Note(Kind::NoEffect, "KHR_materials_volume",
         "no effect without transmission (transmissionFactor > 0)");
  double dispersion = 0;
  if (disp) {
    dispersion = r_.NumberIn(*disp, ExtAt("KHR_materials_dispersion"), "dispersion", 0, 0,
                             std::numeric_limits<double>::infinity());
    if (!transmits)
      Note(Kind::NoEffect, "KHR_materials_dispersion",
           "no effect without transmission (transmissionFactor > 0)");
    else if (dispersion == 0)
      Note(Kind::NoEffect, "KHR_materials_dispersion", "dispersion 0: no dispersion");
  }
  if (iorExt || transmits) {
    std::string what = iorExt ? "KHR_materials_ior ior " + ExactNumber(ior) : "ior 1.5 (default)";
    if (transmits) what += ", KHR_materials_transmission (" + trWhat + ")";
    if (fullyMetallic) {
      for (const char* name : {"KHR_materials_ior", "KHR_materials_transmission"})
        if (Ext(name))
          Note(
              Kind::NoEffect, name,
              "the material is fully metallic (metallicFactor 1, no texture): no dielectric layer");
    } else if (ior == 0 && !iorAnimated) {
      Note(Kind::NoTable, "KHR_materials_ior",
           "ior 0 (specular-glossiness compatibility): F = 1, the dielectric albedo is "
           "ggx-albedo's");
    } else if (ior == 1 && !iorAnimated) {
      Note(Kind::NoTable, "KHR_materials_ior",
           "ior 1 (no interface): F = 0, the dielectric layer reflects nothing");
    } else {
      // ggx-fresnel-albedo covers eta in [1.3, 3], the glass tables [1.1, 3] (their
      // sceneDomain): the planner plans each table the ior falls in and notes the others.
      ValueRange eta = ValueRange::Exactly(ior);
      if (iorAnimated) {
        eta = ValueRange::Whole();
        what += " animated (KHR_animation_pointer): whole IOR axis";
      } else if (transmits && dispersion > 0) {
        // KHR_materials_dispersion: per-channel IORs ior -+ (ior - 1) 0.025 dispersion.
        double half = (ior - 1) * 0.025 * dispersion;
        eta = ValueRange::Between(std::max(1.0, ior - half), ior + half);
        what += ", KHR_materials_dispersion " + ExactNumber(dispersion) + ": ior " + eta.Text();
      }
      if (transmits && vol) what += ", KHR_materials_volume";
      Need(Quantity::FresnelAlbedo, {{"roughness", rough}, {"eta", eta}},
           "dielectric layer (" + what + "), " + roughWhat);
      if (transmits) {
        // The rough glass interface (ggx-dielectric): the energy it reflects and transmits
        // entering at eta = ior, and, with a volume (light leaves it through the back), the exit
        // side at eta' = 1 / ior.
        std::string why = "rough dielectric interface (" + what + "), " + roughWhat;
        // A multiple-scattering compensation (Turquin 2019, as Cycles applies it to glass)
        // reads E(mu) and its average E_avg of each side: the averages come with the E tables.
        for (Quantity q : {Quantity::DielectricAlbedoR, Quantity::DielectricAlbedoT,
                           Quantity::DielectricAlbedoRAvg, Quantity::DielectricAlbedoTAvg})
          NeedModel(q, "ggx-dielectric", {{"roughness", rough}, {"eta", eta}}, why);
        if (vol) {
          ValueRange inv = eta.whole ? eta : ValueRange::Between(1 / eta.hi, 1 / eta.lo);
          for (Quantity q :
               {Quantity::DielectricAlbedoRExit, Quantity::DielectricAlbedoTExit,
                Quantity::DielectricAlbedoRExitAvg, Quantity::DielectricAlbedoTExitAvg})
            NeedModel(q, "ggx-dielectric", {{"roughness", rough}, {"eta", inv}},
                      why + ", exit side eta = 1/ior " + inv.Text());
        }
        // Image-based refraction (entering side): the split-sum BTDF pair an engine multiplies
        // its prefiltered environment, sampled along the refracted ray, by (T_lobe - s T_F).
        NeedModel(Quantity::DielectricBtdfSplitSum, "ggx-dielectric",
                  {{"roughness", rough}, {"eta", eta}}, why + ", image-based refraction");
      }
      if (transmits && vol)
        Note(Kind::NoTable, "KHR_materials_volume",
             "attenuation is Beer-Lambert (closed form); refraction uses the dielectric table");
    }
  }
}

/// KHR_materials_specular (over the base lobe `b`) and KHR_materials_sheen.
void MaterialReader::ReadSpecularAndSheen(const BaseLobe& b) {
  const bool fullyMetallic = b.fullyMetallic;
  if (Ext("KHR_materials_specular")) {
    if (fullyMetallic)
      Note(Kind::NoEffect, "KHR_materials_specular",
           "the material is fully metallic: no dielectric layer");
    else
      Note(Kind::NoTable, "KHR_materials_specular",
           "scales the dielectric Fresnel (F0 x specularColor, F90 x specular): F0 A + F90 B from "
           "ggx-dfg");
  }
  if (const Json* sh = Ext("KHR_materials_sheen")) {
    std::string at = ExtAt("KHR_materials_sheen");
    bool on = Animated(at, "sheenColorFactor");
    if (const Json* c = JsonReader::Find(*sh, "sheenColorFactor")) {
      r_.Array(*c, PointerChild(at, "sheenColorFactor"));
      // A color factor, in [0, 1] like every other factor.
      for (size_t i = 0; i < c->size(); ++i) {
        std::string p = PointerChild(PointerChild(at, "sheenColorFactor"), i);
        double x = r_.Number((*c)[i], p);
        if (x < 0 || x > 1) r_.Fail(p, ExactNumber(x) + " is outside [0, 1]");
        on |= x > 0;
      }
    }
    if (!on)
      Note(Kind::NoEffect, "KHR_materials_sheen", "sheenColorFactor 0: no sheen");
    else {
      // KHR_materials_sheen's lobe is charlie-smith (the glTF sample viewer's V_Sheen). The
      // spec's albedo scaling dims the layers below by 1 - max(sheenColor) E(mu), E the lobe's
      // directional albedo: charlie-smith-albedo (the same integral as charlie-smith-dfg, the
      // split-sum term for image-based light; docs/models.md "Sheen tables").
      // The tables start at sheenRoughness 0.045 (Filament's clamp, models/sheen.h): a smaller
      // value is clamped there, with a note.
      std::string what;
      ValueRange sr = Factor(*sh, at, "sheenRoughnessFactor", 0, "sheenRoughnessTexture", what);
      if (!sr.whole && sr.lo < kSheenTableMinRoughness) {
        Note(Kind::NoEffect, "KHR_materials_sheen",
             "sheenRoughness below 0.045 is clamped to 0.045 (the charlie-smith tables start "
             "there, as Filament's sheen roughness)");
        sr = ValueRange::Between(kSheenTableMinRoughness, std::max(sr.hi, kSheenTableMinRoughness));
      }
      NeedModel(Quantity::Albedo, "charlie-smith", {{"roughness", sr}},
                "sheen albedo scaling (charlie-smith E; its dfg is the same integral), " + what);
    }
  }
}

/// The extensions that need no table of their own: iridescence, anisotropy, emissive
/// strength, diffuse transmission.
void MaterialReader::ReadTablelessExtensions() {
  if (const Json* ir = Ext("KHR_materials_iridescence")) {
    std::string what;
    ValueRange f = Factor(*ir, ExtAt("KHR_materials_iridescence"), "iridescenceFactor", 0,
                          "iridescenceTexture", what);
    if (!f.whole && f.hi == 0)
      Note(Kind::NoEffect, "KHR_materials_iridescence", "iridescenceFactor 0: no thin film");
    else
      Note(Kind::NotYet, "KHR_materials_iridescence",
           "thin-film Fresnel (Belcour-Barla 2017) has no kiln table yet");
  }
  if (const Json* an = Ext("KHR_materials_anisotropy")) {
    std::string at = ExtAt("KHR_materials_anisotropy");
    double s = r_.NumberIn(*an, at, "anisotropyStrength", 0, 0, 1);
    if (s == 0 && !Animated(at, "anisotropyStrength") &&
        !JsonReader::Find(*an, "anisotropyTexture"))
      Note(Kind::NoEffect, "KHR_materials_anisotropy", "anisotropyStrength 0: isotropic");
    else
      Note(Kind::NotYet, "KHR_materials_anisotropy",
           "anisotropic GGX albedo needs an anisotropy axis; kiln's GGX tables are isotropic");
  }
  if (Ext("KHR_materials_emissive_strength"))
    Note(Kind::NoTable, "KHR_materials_emissive_strength", "emission is not a BRDF");
  if (const Json* dt = Ext("KHR_materials_diffuse_transmission")) {
    std::string what;
    ValueRange f = Factor(*dt, ExtAt("KHR_materials_diffuse_transmission"),
                          "diffuseTransmissionFactor", 0, "diffuseTransmissionTexture", what);
    if (!f.whole && f.hi == 0)
      Note(Kind::NoEffect, "KHR_materials_diffuse_transmission", "diffuseTransmissionFactor 0");
    else
      Note(Kind::NoTable, "KHR_materials_diffuse_transmission",
           "Lambertian transmission: its albedo is the color exactly");
  }
}

void MaterialReader::Read() {
  r_.Object(m_, at_);
  const Json* extensions = JsonReader::Find(m_, "extensions");
  if (extensions) r_.Object(*extensions, PointerChild(at_, "extensions"));
  std::vector<std::string> present;
  if (extensions)
    for (auto it = extensions->begin(); it != extensions->end(); ++it) present.push_back(it.key());

  if (ReadUnlit(present)) return;
  const BaseLobe b = ReadBaseLobe();
  ReadClearcoat();
  ReadDielectricLayer(b);
  ReadSpecularAndSheen(b);
  ReadTablelessExtensions();
}

}  // namespace

void AddGltfMaterial(const Json& material, const std::string& at, const std::string& label,
                     const std::set<std::string>& animated, const JsonReader& reader,
                     Scene& scene) {
  MaterialReader(material, at, label, animated, reader, scene).Read();
}

bool IsKnownMaterialExtension(const std::string& name) {
  return std::find(std::begin(kMaterialExtensions), std::end(kMaterialExtensions), name) !=
         std::end(kMaterialExtensions);
}

bool IsNonMaterialExtension(const std::string& name) {
  return std::find(std::begin(kNonMaterialExtensions), std::end(kNonMaterialExtensions), name) !=
         std::end(kNonMaterialExtensions);
}

}  // namespace kiln
