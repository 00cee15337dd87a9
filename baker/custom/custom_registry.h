// The custom models of this process (kiln/model_abi.h lobes loaded by baker/custom/loader.h),
// registered in the model registry (models/registry.h RegisterModel) with a descriptor of rule
// family None: a loaded lobe's id works wherever a built-in id does, and its tables are baked by
// adaptive quadrature.
#pragma once
#include <string>
#include <vector>

#include "baker/models/registry.h"

namespace kiln {

/// Registers a loaded lobe with its parameters (roughness first) through RegisterModel and
/// returns its descriptor: rule family None, a factory building CustomDiffuseModel or
/// CustomSpecularModel (models/custom_lobe.h), codeHash = the lobe's hash, tablesByName set.
/// Registering an id again replaces the model when the hash differs (the previous lobe's
/// functions stay loaded, for models built from it) and keeps it otherwise. Not thread-safe:
/// call it before any work that looks models up.
const ModelInfo& RegisterCustomLobe(const CustomLobe& lobe, std::vector<ParamInfo> params);

/// The registered custom model `id`, or nullptr (a built-in id gives nullptr).
const ModelInfo* FindCustomModel(const std::string& id);

/// The ids of the registered custom models, sorted.
std::vector<std::string> CustomModelIds();

/// The loaded lobe behind custom model `id`, or nullptr.
const CustomLobe* FindCustomLobe(const std::string& id);

}  // namespace kiln
