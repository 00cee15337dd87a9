// Loading a user's lobe (kiln/model_abi.h): from a shared library, or from a C++ source that
// kiln compiles into a cached one (baker/custom/compiler.h). A loaded lobe is registered
// (custom_registry.h): its id then works wherever a built-in model's does.
#pragma once
#include <string>

#include "baker/models/registry.h"

namespace kiln {

/// Loads the shared library at `path` (dlopen), checks its ABI (version 1, the required
/// functions, an id of lower-case letters, digits and '-' that no built-in model has, parameters
/// kiln can name) and registers it under `hash` (empty: the FNV-1a 64 of the library's bytes).
/// Throws std::invalid_argument with one line naming the library and the problem.
const ModelInfo& LoadModelLibrary(const std::string& path, const std::string& hash = "");

/// Compiles the C++ source at `path` (CompileModelSource, into `cacheDir`; empty: the default
/// cache folder) and loads the library, registered under the source's hash. Throws
/// std::invalid_argument for a source that does not compile (with the compiler's lines) or a
/// library LoadModelLibrary refuses.
const ModelInfo& LoadModelSource(const std::string& path, const std::string& cacheDir = "");

/// Hex FNV-1a 64 of a file's bytes; throws std::invalid_argument when it cannot be read.
std::string FileHash(const std::string& path);

}  // namespace kiln
