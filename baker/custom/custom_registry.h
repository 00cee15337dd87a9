// The custom models of this process (kiln/model_abi.h lobes loaded by baker/custom/loader.h):
// FindModel and MakeModel (models/registry.h) fall back to them, so a loaded lobe's id works
// wherever a built-in id does.
#pragma once
#include <string>
#include <vector>

#include "baker/models/registry.h"

namespace kiln {

/// Registers a loaded lobe with its parameters (roughness first) and returns its ModelInfo.
/// Registering an id again replaces the entry when the hash differs (the previous lobe's
/// functions stay loaded), and keeps it otherwise. Not thread-safe against lookups: call it
/// before any work that looks models up.
const ModelInfo& RegisterCustomLobe(const CustomLobe& lobe, std::vector<ParamInfo> params);

/// The registered custom model `id`, or nullptr.
const ModelInfo* FindCustomModel(const std::string& id);

/// The ids of the registered custom models, sorted.
std::vector<std::string> CustomModelIds();

/// The loaded lobe behind custom model `id`, or nullptr.
const CustomLobe* FindCustomLobe(const std::string& id);

/// The hash of custom model `id`'s source or library ("" for any other id): part of the spec
/// hash of its tables, so that an edited lobe makes them stale.
std::string CustomModelHash(const std::string& id);

/// Builds custom model `info` with `params` already checked against its ranges (MakeModel).
AnyModel MakeCustomModel(const ModelInfo& info, const ModelParams& params);

}  // namespace kiln
