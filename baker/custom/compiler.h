// Compiling a user's lobe (kiln/model_abi.h) with the system compiler into a shared library kept
// in a cache: `c++ -std=c++17 -O2 -shared -fPIC`, keyed by the source's bytes, the compiler's
// identity (its --version line) and the ABI version, so that the same source compiles once.
#pragma once
#include <string>

namespace kiln {

/// The compiler command (the environment's KILN_CXX when set, else "c++").
std::string ModelCompiler();

/// The default cache folder: $XDG_CACHE_HOME/kiln, else $HOME/.cache/kiln, else /tmp/kiln-cache.
std::string DefaultModelCacheDir();

/// The shared library compiled from the C++ source `sourcePath`, in `cacheDir` (created when
/// missing) as model-KEY.so; compiles only when that file is missing, through a temporary file
/// renamed into place (a concurrent compile of the same source is harmless). Throws
/// std::invalid_argument "cannot compile SOURCE:" followed by the compiler's lines when it fails.
std::string CompileModelSource(const std::string& sourcePath, const std::string& cacheDir);

}  // namespace kiln
