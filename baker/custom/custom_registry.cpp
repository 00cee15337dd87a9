#include "baker/custom/custom_registry.h"

#include <cstdio>
#include <map>
#include <memory>

namespace kiln {
namespace {

struct Entry {
  CustomLobe lobe;
  ModelInfo info;
};

std::map<std::string, std::unique_ptr<Entry>>& Entries() {
  static std::map<std::string, std::unique_ptr<Entry>> entries;
  return entries;
}

/// The value of parameter `p` in `params` (the CLI's fixed set of names), if given.
std::optional<double> GivenValue(const ModelParams& params, const std::string& name) {
  if (name == "roughness") return params.roughness;
  if (name == "rho") return params.rho;
  if (name == "f0") return params.f0;
  if (name == "eta") return params.eta;
  if (name == "k") return params.k;
  if (name == "rs") return params.rs;
  if (name == "nu") return params.nu;
  if (name == "nv") return params.nv;
  return std::nullopt;
}

}  // namespace

void ThrowBadCustomValue(const CustomLobe& lobe, double f, Vec3 wo, Vec3 wi, double roughness) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "model '%s' (%s): f = %g at wo = (%.17g, %.17g, %.17g), wi = (%.17g, %.17g, "
                "%.17g), roughness %.17g: f must be finite and >= 0",
                lobe.id.c_str(), lobe.origin.c_str(), f, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z,
                roughness);
  throw CustomModelError(buf);
}

const ModelInfo& RegisterCustomLobe(const CustomLobe& lobe, std::vector<ParamInfo> params) {
  std::unique_ptr<Entry>& slot = Entries()[lobe.id];
  if (slot && slot->lobe.hash == lobe.hash) return slot->info;
  // A replaced entry stays alive: models built from it hold pointers to its lobe.
  static std::vector<std::unique_ptr<Entry>> retired;
  if (slot) retired.push_back(std::move(slot));
  slot = std::make_unique<Entry>();
  slot->lobe = lobe;
  ModelInfo& m = slot->info;
  m.id = lobe.id;
  m.summary = "custom model from " + lobe.origin + " (hash " + lobe.hash + ")";
  m.roughness = "as the lobe defines it, r in [0, 1]";
  m.params = std::move(params);
  m.reciprocal = false;  // not claimed
  m.energyConserving = lobe.energyConserving;
  m.nonNegative = true;  // every value is checked
  m.hasRho2 = false;
  m.domain = lobe.specular ? IntegrationDomain::HalfVector : IntegrationDomain::Light;
  return m;
}

const ModelInfo* FindCustomModel(const std::string& id) {
  auto it = Entries().find(id);
  return it == Entries().end() ? nullptr : &it->second->info;
}

std::vector<std::string> CustomModelIds() {
  std::vector<std::string> ids;
  for (const auto& [id, entry] : Entries()) ids.push_back(id);
  return ids;
}

const CustomLobe* FindCustomLobe(const std::string& id) {
  auto it = Entries().find(id);
  return it == Entries().end() ? nullptr : &it->second->lobe;
}

std::string CustomModelHash(const std::string& id) {
  const CustomLobe* lobe = FindCustomLobe(id);
  return lobe ? lobe->hash : "";
}

AnyModel MakeCustomModel(const ModelInfo& info, const ModelParams& params) {
  const CustomLobe* lobe = FindCustomLobe(info.id);
  if (!lobe) throw std::invalid_argument("model '" + info.id + "' is not a custom model");
  CustomModelBase base;
  base.lobe = lobe;
  int extra = 0;
  for (const ParamInfo& p : info.params) {
    double v = GivenValue(params, p.name).value_or(p.def);
    if (p.name == "roughness")
      base.roughness = v;
    else
      base.params[extra++] = v;
  }
  if (!lobe->specular) return CustomDiffuseModel{base};
  CustomSpecularModel m;
  static_cast<CustomModelBase&>(m) = base;
  double alpha = lobe->importanceAlpha ? lobe->importanceAlpha(base.roughness)
                                       : std::max(Sqr(base.roughness), kDefaultImportanceAlphaMin);
  if (!(alpha > 0) || !std::isfinite(alpha))
    throw CustomModelError("model '" + info.id + "': kiln_model_importance_alpha(" +
                           std::to_string(base.roughness) + ") is not a positive number");
  m.importance.alpha = std::max(alpha, MinAlpha);
  return m;
}

}  // namespace kiln
