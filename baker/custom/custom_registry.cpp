#include "baker/custom/custom_registry.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>

namespace kiln {
namespace {

/// The current lobe of every registered custom model, by id. The lobes themselves live in
/// Lobes() for the process's lifetime: models built from a replaced lobe point into it.
std::map<std::string, const CustomLobe*>& Current() {
  static std::map<std::string, const CustomLobe*> current;
  return current;
}

std::deque<CustomLobe>& Lobes() {
  static std::deque<CustomLobe> lobes;
  return lobes;
}

/// The value of the lobe's parameter `p` in `a` (given, or the parameter's default).
double ArgValue(const ModelArgs& a, const ParamInfo& p) {
  static const std::map<std::string, double ModelArgs::*> kNumbers = {{"rho", &ModelArgs::rho},
                                                                      {"f0", &ModelArgs::f0},
                                                                      {"rs", &ModelArgs::rs},
                                                                      {"eta", &ModelArgs::eta},
                                                                      {"k", &ModelArgs::k}};
  if (auto it = kNumbers.find(p.name); it != kNumbers.end()) return a.*(it->second);
  if (p.name == "nu") return a.nu.value_or(p.def);
  if (p.name == "nv") return a.nv.value_or(p.def);
  throw std::invalid_argument("custom parameter '" + p.name + "' has no value");
}

/// Builds the value type of `lobe` from checked arguments (the descriptor's factory).
AnyModel MakeCustom(const CustomLobe* lobe, const std::vector<ParamInfo>& params,
                    const ModelArgs& a) {
  CustomModelBase base;
  base.lobe = lobe;
  base.roughness = a.roughness;
  int extra = 0;
  for (const ParamInfo& p : params)
    if (&p != &params.front()) base.params[extra++] = ArgValue(a, p);  // the first: roughness
  if (!lobe->specular) return CustomDiffuseModel{base};
  CustomSpecularModel m;
  static_cast<CustomModelBase&>(m) = base;
  double alpha = lobe->importanceAlpha ? lobe->importanceAlpha(base.roughness)
                                       : std::max(Sqr(base.roughness), kDefaultImportanceAlphaMin);
  if (!(alpha > 0) || !std::isfinite(alpha))
    throw CustomModelError("model '" + lobe->id + "': kiln_model_importance_alpha(" +
                           std::to_string(base.roughness) + ") is not a positive number");
  m.importance.alpha = std::max(alpha, MinAlpha);
  m.horizonMu = std::min(kHorizonMu, kHorizonMuPerAlpha * m.importance.alpha);
  return m;
}

/// The descriptor of `lobe` (stored in Lobes()) with its parameters, roughness first.
ModelInfo DescriptorOf(const CustomLobe* lobe, std::vector<ParamInfo> params) {
  ModelInfo m;
  m.id = lobe->id;
  m.summary = "custom model from " + lobe->origin + " (hash " + lobe->hash + ")";
  m.roughness = "as the lobe defines it, r in [0, 1]";
  m.params = std::move(params);
  m.reciprocal = false;  // not claimed
  m.energyConserving = lobe->energyConserving;
  m.nonNegative = true;  // every value is checked
  m.hasRho2 = false;
  m.domain = lobe->specular ? IntegrationDomain::HalfVector : IntegrationDomain::Light;
  m.rule = RuleFamily::None;  // adaptive quadrature: no fixed rule is tuned for a user's lobe
  m.codeHash = lobe->hash;
  m.tablesByName = true;
  m.make = [lobe, ps = m.params](const ModelArgs& a) { return MakeCustom(lobe, ps, a); };
  return m;
}

}  // namespace

const ModelInfo& RegisterCustomLobe(const CustomLobe& lobe, std::vector<ParamInfo> params) {
  auto it = Current().find(lobe.id);
  if (it != Current().end()) {
    if (it->second->hash == lobe.hash) return *FindModel(lobe.id);
    UnregisterModel(lobe.id);  // replaced: the old lobe stays in Lobes()
  }
  Lobes().push_back(lobe);
  const CustomLobe* stored = &Lobes().back();
  const ModelInfo& info = RegisterModel(DescriptorOf(stored, std::move(params)));
  Current()[lobe.id] = stored;
  return info;
}

const ModelInfo* FindCustomModel(const std::string& id) {
  return Current().count(id) ? FindModel(id) : nullptr;
}

std::vector<std::string> CustomModelIds() {
  std::vector<std::string> ids;
  for (const auto& [id, lobe] : Current()) ids.push_back(id);
  return ids;
}

const CustomLobe* FindCustomLobe(const std::string& id) {
  auto it = Current().find(id);
  return it == Current().end() ? nullptr : it->second;
}

}  // namespace kiln
