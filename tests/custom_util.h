// Custom models for the tests (baker/custom/): lobe sources written into one temp folder per
// test process, compiled once into a cache there and shared by every test (compiling a lobe
// takes about a second), and the example lobes of examples/models.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "baker/custom/loader.h"
#include "baker/models/registry.h"

namespace kiln::test {

/// The folder of this process's lobe sources and compile cache.
inline const std::string& CustomDir() {
  static const std::string dir = [] {
    std::string d = "/tmp/kiln_test_custom_" + std::to_string(getpid());
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d + "/cache");
    return d;
  }();
  return dir;
}

/// The compile cache of CustomDir(); the CLI tests hand it to kiln as XDG_CACHE_HOME/kiln.
inline std::string CustomCache() { return CustomDir() + "/cache/kiln"; }

/// "XDG_CACHE_HOME=... " for a kiln command line: the same cache as the in-process loads.
inline std::string CustomCacheEnv() { return "XDG_CACHE_HOME=" + CustomDir() + "/cache "; }

/// Writes `body` (after the ABI header and the required functions for `id`) to
/// CustomDir()/NAME.cpp and returns its path. `eval` is the body of kiln_model_eval.
inline std::string WriteLobe(const std::string& name, const std::string& id, bool specular,
                             const std::string& eval, const std::string& extra = "") {
  std::string path = CustomDir() + "/" + name + ".cpp";
  std::ofstream out(path);
  out << "#include <kiln/model_abi.h>\n#include <cmath>\n"
      << extra << "extern \"C\" int kiln_model_abi_version() { return KILN_MODEL_ABI_VERSION; }\n"
      << "extern \"C\" const char* kiln_model_id() { return \"" << id << "\"; }\n"
      << "extern \"C\" int kiln_model_is_specular() { return " << (specular ? 1 : 0) << "; }\n"
      << "extern \"C\" double kiln_model_eval(const double wo[3], const double wi[3], double r) "
         "{\n"
      << eval << "\n}\n";
  return path;
}

/// Removes the model `id` from the registry when it goes out of scope: a lobe built to fail (NaN,
/// negative values) must not reach the later tests of the process that walk every model.
struct UnregisterAtExit {
  std::string id;
  ~UnregisterAtExit() { UnregisterModel(id); }
};

/// An example lobe of examples/models, loaded (compiled once per process).
inline const ModelInfo& ExampleLobe(const std::string& file) {
  return LoadModelSource(std::string(KILN_SOURCE_DIR) + "/examples/models/" + file, CustomCache());
}

}  // namespace kiln::test
