#include "baker/custom/loader.h"

#include <cstdio>
#include <cstdint>
#include <dlfcn.h>
#include <fstream>
#include <set>
#include <stdexcept>

#include "baker/custom/compiler.h"
#include "baker/custom/custom_registry.h"
#include "kiln/model_abi.h"

namespace kiln {
namespace {

/// The parameter names a custom model may declare: kiln's own parameter options.
const std::set<std::string>& ParamNames() {
  static const std::set<std::string> names = {"rho", "f0", "rs", "eta", "k", "nu", "nv"};
  return names;
}

bool ValidId(const std::string& id) {
  if (id.empty() || id.size() > 64 || id.front() == '-' || id.back() == '-') return false;
  for (char c : id)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-')) return false;
  return true;
}

/// The symbol `name` of `handle` as a function pointer of type F, or nullptr.
template <class F>
F Symbol(void* handle, const char* name) {
  return reinterpret_cast<F>(dlsym(handle, name));
}

/// The declared parameters after the roughness, checked; throws naming the library.
std::vector<ParamInfo> ReadParams(void* handle, const std::string& where, CustomLobe& lobe) {
  std::vector<ParamInfo> params = {
      {"roughness", 0, 1, 0.5, "roughness r in [0, 1], as the lobe defines it"}};
  auto count = Symbol<int (*)()>(handle, "kiln_model_param_count");
  if (!count) return params;
  int n = count();
  auto name = Symbol<const char* (*)(int)>(handle, "kiln_model_param_name");
  auto range = Symbol<void (*)(int, double*, double*, double*)>(handle, "kiln_model_param_range");
  lobe.evalParams = Symbol<decltype(lobe.evalParams)>(handle, "kiln_model_eval_params");
  if (n < 0 || n > kMaxCustomParams)
    throw std::invalid_argument(where + ": kiln_model_param_count() = " + std::to_string(n) +
                                " is outside [0, " + std::to_string(kMaxCustomParams) + "]");
  if (n > 0 && (!name || !range || !lobe.evalParams))
    throw std::invalid_argument(where +
                                ": declares parameters but lacks kiln_model_param_name, "
                                "kiln_model_param_range or kiln_model_eval_params");
  for (int i = 0; i < n; ++i) {
    const char* text = name(i);
    std::string pname = text ? text : "";
    ParamInfo p{pname, 0, 0, 0, "custom parameter"};
    range(i, &p.lo, &p.hi, &p.def);
    if (!ParamNames().count(pname))
      throw std::invalid_argument(where + ": parameter '" + pname +
                                  "' is not one of rho, f0, rs, eta, k, nu, nv");
    for (const ParamInfo& q : params)
      if (q.name == pname)
        throw std::invalid_argument(where + ": parameter '" + pname + "' is declared twice");
    if (!(std::isfinite(p.lo) && std::isfinite(p.hi) && p.lo <= p.def && p.def <= p.hi))
      throw std::invalid_argument(where + ": parameter '" + pname +
                                  "' needs finite lo <= default <= hi");
    params.push_back(p);
  }
  lobe.paramCount = n;
  return params;
}

}  // namespace

std::string FileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("cannot read '" + path + "'");
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i)
      h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
    if (!in) break;
  }
  char out[20];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

/// LoadModelLibrary, with `origin` the file messages name (the source a library came from).
static const ModelInfo& LoadAs(const std::string& path, const std::string& hash,
                               const std::string& origin) {
  const std::string where = "model library " + path;
  std::string fileHash = hash.empty() ? FileHash(path) : hash;
  // A path with no '/' would be searched on the library path: name the file itself.
  std::string openPath = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(openPath.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::invalid_argument("cannot load " + where + ": " + dlerror());
  auto version = Symbol<int (*)()>(handle, "kiln_model_abi_version");
  auto id = Symbol<const char* (*)()>(handle, "kiln_model_id");
  auto specular = Symbol<int (*)()>(handle, "kiln_model_is_specular");
  CustomLobe lobe;
  lobe.eval = Symbol<decltype(lobe.eval)>(handle, "kiln_model_eval");
  const std::pair<const char*, bool> required[] = {{"kiln_model_abi_version", version != nullptr},
                                                   {"kiln_model_id", id != nullptr},
                                                   {"kiln_model_is_specular", specular != nullptr},
                                                   {"kiln_model_eval", lobe.eval != nullptr}};
  for (const auto& [name, found] : required)
    if (!found)
      throw std::invalid_argument(where + " lacks " + name + " (extern \"C\", kiln/model_abi.h)");
  if (version() != KILN_MODEL_ABI_VERSION)
    throw std::invalid_argument(where +
                                ": kiln_model_abi_version() = " + std::to_string(version()) +
                                ", kiln reads version " + std::to_string(KILN_MODEL_ABI_VERSION));
  const char* idText = id();
  lobe.id = idText ? idText : "";
  if (!ValidId(lobe.id))
    throw std::invalid_argument(where + ": id '" + lobe.id +
                                "' must be lower-case letters, digits and '-'");
  if ((FindModel(lobe.id) && !FindCustomModel(lobe.id)) || FindBsdfModel(lobe.id))
    throw std::invalid_argument(where + ": id '" + lobe.id + "' is a built-in model's");
  lobe.hash = fileHash;
  lobe.origin = origin;
  lobe.specular = specular() != 0;
  if (auto ec = Symbol<int (*)()>(handle, "kiln_model_energy_conserving"))
    lobe.energyConserving = ec() != 0;
  lobe.importanceAlpha = Symbol<double (*)(double)>(handle, "kiln_model_importance_alpha");
  if (lobe.specular)
    lobe.evalHalf = Symbol<decltype(lobe.evalHalf)>(handle, "kiln_model_eval_half");
  std::vector<ParamInfo> params = ReadParams(handle, where, lobe);
  return RegisterCustomLobe(lobe, std::move(params));
}

const ModelInfo& LoadModelLibrary(const std::string& path, const std::string& hash) {
  return LoadAs(path, hash, path);
}

const ModelInfo& LoadModelSource(const std::string& path, const std::string& cacheDir) {
  const std::string hash = FileHash(path);
  std::string library =
      CompileModelSource(path, cacheDir.empty() ? DefaultModelCacheDir() : cacheDir);
  return LoadAs(library, hash, path);  // messages name the source, not the cached library
}

}  // namespace kiln
