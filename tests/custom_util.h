// Custom models for the tests (baker/custom/): lobe sources written into one temp folder per
// test process, compiled once into a cache shared by every test of a ctest run (compiling a lobe
// takes about a second), and the example lobes of examples/models.
#pragma once
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>

#include "baker/custom/loader.h"
#include "baker/models/registry.h"

namespace kiln::test {

/// The folder of this process's lobe sources (and, outside ctest, its compile cache).
inline std::string CustomDirPath() { return "/tmp/kiln_test_custom_" + std::to_string(getpid()); }

/// Removes CustomDirPath() when the process exits (std::atexit), so that runs leave no folder.
inline void RemoveCustomDir() {
  std::error_code ignored;
  std::filesystem::remove_all(CustomDirPath(), ignored);
}

/// The folder of this process's lobe sources, made on first use and removed at exit.
inline const std::string& CustomDir() {
  static const std::string dir = [] {
    std::string d = CustomDirPath();
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    std::atexit(RemoveCustomDir);
    return d;
  }();
  return dir;
}

/// "PID_STARTTIME" of the ctest process that started this one, "" when the parent is not ctest.
inline std::string CtestRunStamp() {
  const std::string parent = "/proc/" + std::to_string(getppid());
  std::ifstream comm(parent + "/comm");
  std::string name;
  if (!std::getline(comm, name) || name != "ctest") return "";
  std::ifstream statFile(parent + "/stat");
  std::string stat((std::istreambuf_iterator<char>(statFile)), std::istreambuf_iterator<char>());
  const size_t close = stat.rfind(')');
  if (close == std::string::npos) return "";
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  for (int k = 3; k <= 22 && fields >> field; ++k) {  // field 22: the start time
  }
  return std::to_string(getppid()) + "_" + field;
}

/// The folder whose kiln/ is the lobes' compile cache: one per ctest run, shared by its test
/// processes (a lobe several tests load compiles once per run, not once per test), else this
/// process's own. Sharing is safe: the cache is keyed by the source's bytes, the compiler and
/// its flags (baker/custom/compiler.cpp), and a library enters it by rename.
inline const std::string& CacheHome() {
  static const std::string dir = [] {
    const std::string run = CtestRunStamp();
    std::string d = run.empty() ? CustomDir() + "/cache" : "/tmp/kiln_test_lobes_" + run;
    std::filesystem::create_directories(d + "/kiln");
    return d;
  }();
  return dir;
}

/// The compile cache of CacheHome(); the CLI tests hand it to kiln as XDG_CACHE_HOME/kiln.
inline std::string CustomCache() { return CacheHome() + "/kiln"; }

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
