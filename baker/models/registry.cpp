#include "baker/models/registry.h"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include "baker/models/model_list.h"
#include "baker/models/model_names.h"
#include "baker/util/did_you_mean.h"

namespace kiln {
namespace {

/// The models in order (a deque: pointers stay valid as run-time ones are added) and the map
/// from id to descriptor: the one place an id is looked up.
struct Registry {
  std::deque<ModelInfo> models;
  std::unordered_map<std::string, const ModelInfo*> byId;
  size_t builtIn = 0;
};

Registry& TheRegistry() {
  static Registry r = [] {
    Registry reg;
#define KILN_MODEL(F) reg.models.push_back(model_list::F());
#include "baker/models/model_list.inc"
#undef KILN_MODEL
    for (const ModelInfo& m : reg.models) reg.byId[m.id] = &m;
    reg.builtIn = reg.models.size();
    return reg;
  }();
  return r;
}

std::string Format(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The given parameters by name, in ParamInfo's order of names.
std::vector<std::pair<const char*, const std::optional<double>*>> Given(const ModelParams& p) {
  return {{"roughness", &p.roughness},
          {"rho", &p.rho},
          {"f0", &p.f0},
          {"eta", &p.eta},
          {"k", &p.k},
          {"rs", &p.rs},
          {"nu", &p.nu},
          {"nv", &p.nv}};
}

/// The value of parameter `name`: given, else the model's default, 0 when it takes none.
double Get(const ModelInfo& info, const ModelParams& p, const std::string& name) {
  for (const ParamInfo& pi : info.params) {
    if (pi.name != name) continue;
    for (const auto& [n, value] : Given(p))
      if (name == n && *value) return **value;
    return pi.def;
  }
  return 0;
}

/// Throws when a given parameter is one the model does not take or outside its range.
void CheckParams(const ModelInfo& info, const ModelParams& p) {
  const std::string& id = info.id;
  for (const auto& [name, value] : Given(p)) {
    if (!*value) continue;
    const ParamInfo* pi = nullptr;
    for (const ParamInfo& q : info.params)
      if (q.name == name) pi = &q;
    if (!pi) throw std::invalid_argument("model '" + id + "' takes no parameter '" + name + "'");
    double x = **value;
    if (!(x >= pi->lo && x <= pi->hi))
      throw std::invalid_argument("model '" + id + "': " + name + " = " + Format(x) +
                                  " is outside [" + Format(pi->lo) + ", " + Format(pi->hi) + "]");
  }
  if (p.f0 && p.eta)
    throw std::invalid_argument("model '" + id + "': give either f0 (Schlick) or eta, not both");
  if (p.k && !p.eta) throw std::invalid_argument("model '" + id + "': k needs eta");
}

}  // namespace

const std::deque<ModelInfo>& AllModels() { return TheRegistry().models; }

const ModelInfo* FindModel(const std::string& id) {
  const Registry& r = TheRegistry();
  auto it = r.byId.find(id);
  return it == r.byId.end() ? nullptr : it->second;
}

bool IsSheen(const std::string& id) {
  const ModelInfo* m = FindModel(id);
  return m && m->rule == RuleFamily::Sheen;
}

const ModelInfo& RegisterModel(ModelInfo descriptor) {
  Registry& r = TheRegistry();
  if (descriptor.id.empty()) throw std::invalid_argument("RegisterModel: a model needs an id");
  if (FindModel(descriptor.id) || FindBsdfModel(descriptor.id))
    throw std::invalid_argument("RegisterModel: model '" + descriptor.id + "' exists already");
  if (!descriptor.make)
    throw std::invalid_argument("RegisterModel: model '" + descriptor.id + "' has no factory");
  if (descriptor.bsdf)
    throw std::invalid_argument("RegisterModel: model '" + descriptor.id +
                                "' is a BSDF (only BRDFs are registered at run time)");
  r.models.push_back(std::move(descriptor));
  const ModelInfo& m = r.models.back();
  r.byId[m.id] = &m;
  return m;
}

bool UnregisterModel(const std::string& id) {
  Registry& r = TheRegistry();
  for (size_t i = r.builtIn; i < r.models.size(); ++i) {
    if (r.models[i].id != id) continue;
    r.models.erase(r.models.begin() + static_cast<std::ptrdiff_t>(i));
    r.byId.clear();
    for (const ModelInfo& m : r.models) r.byId[m.id] = &m;
    return true;
  }
  return false;
}

std::vector<std::string> AllModelIds() {
  std::vector<std::string> ids;
  for (const ModelInfo& m : AllModels()) ids.push_back(m.id);
  for (const ModelInfo& m : AllBsdfModels()) ids.push_back(m.id);
  return ids;
}

std::string UnknownModelMessage(const std::string& id) {
  return "unknown model '" + id + "'" + DidYouMean(id, AllModelIds()) + " (see `kiln list`)";
}

Fresnel FresnelFromParams(const ModelParams& p) {
  Fresnel F;
  if (p.f0) {
    F.kind = Fresnel::Kind::Schlick;
    F.f0 = *p.f0;
  } else if (p.eta) {
    F.eta = *p.eta;
    F.k = p.k.value_or(0);
    F.kind = F.k > 0 ? Fresnel::Kind::Conductor : Fresnel::Kind::Dielectric;
  }
  return F;
}

AnyModel MakeModel(const std::string& id, const ModelParams& p) {
  const ModelInfo* info = FindModel(id);
  if (!info) throw std::invalid_argument(UnknownModelMessage(id));
  return MakeModel(*info, p);
}

AnyModel MakeModel(const ModelInfo& info, const ModelParams& p) {
  CheckParams(info, p);
  ModelArgs a;
  a.roughness = Get(info, p, "roughness");
  a.rho = Get(info, p, "rho");
  a.f0 = Get(info, p, "f0");
  a.rs = Get(info, p, "rs");
  a.eta = Get(info, p, "eta");
  a.k = Get(info, p, "k");
  a.alpha = std::max(AlphaFromPerceptual(a.roughness), MinAlpha);
  a.fresnel = FresnelFromParams(p);
  a.nu = p.nu;
  a.nv = p.nv;
  if (!info.make) throw std::invalid_argument("model '" + info.id + "' has no factory");
  return info.make(a);
}

double Evaluate(const AnyModel& model, Vec3 wo, Vec3 wi) {
  return std::visit([&](const auto& m) { return m.f(wo, wi); }, model);
}

RhoParts EvaluateParts(const AnyModel& model, Vec3 wo, Vec3 wi) {
  return std::visit([&](const auto& m) { return m.Parts(wo, wi); }, model);
}

void SetFresnel(AnyModel& model, const Fresnel& fresnel) {
  std::visit(
      [&](auto& m) {
        if constexpr (std::decay_t<decltype(m)>::kDomain == IntegrationDomain::HalfVector)
          m.fresnel = fresnel;
      },
      model);
}

}  // namespace kiln
