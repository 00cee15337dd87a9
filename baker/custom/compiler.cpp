#include "baker/custom/compiler.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "baker/custom/loader.h"
#include "kiln/model_abi.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;

/// The flags every lobe is compiled with (part of the cache key).
constexpr const char* kCompileFlags = "-std=c++17 -O2 -shared -fPIC";

/// `text` in single quotes for /bin/sh.
std::string ShellQuote(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs `command` through /bin/sh with stderr joined to stdout; returns the exit status and
/// fills `output`.
int RunCapturing(const std::string& command, std::string& output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw std::invalid_argument("cannot run '" + command + "'");
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) output.append(buf, n);
  return pclose(pipe);
}

/// The folders holding kiln/model_abi.h: next to an installed kiln (<prefix>/include) and the
/// source tree kiln was built from.
std::vector<std::string> AbiIncludeDirs() {
  std::vector<std::string> dirs;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path installed = exe.parent_path().parent_path() / "include";
    if (fs::exists(installed / "kiln" / "model_abi.h", ec)) dirs.push_back(installed.string());
  }
#ifdef KILN_MODEL_ABI_INCLUDE
  dirs.push_back(KILN_MODEL_ABI_INCLUDE);
#endif
  return dirs;
}

/// The first line the compiler prints for --version (its identity in the cache key).
std::string CompilerIdentity(const std::string& compiler) {
  std::string out;
  if (RunCapturing(compiler + " --version", out) != 0)
    throw std::invalid_argument("cannot run the compiler '" + compiler + "' (" +
                                out.substr(0, out.find('\n')) + ")");
  return out.substr(0, out.find('\n'));
}

}  // namespace

std::string ModelCompiler() {
  const char* cxx = std::getenv("KILN_CXX");
  return cxx && *cxx ? cxx : "c++";
}

std::string DefaultModelCacheDir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "kiln").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "kiln").string();
  return "/tmp/kiln-cache";
}

std::string CompileModelSource(const std::string& sourcePath, const std::string& cacheDir) {
  const std::string compiler = ModelCompiler();
  const std::string key = FileHash(sourcePath) + "-" + [&] {
    // The compiler, the flags and the ABI version, hashed into one more word.
    std::string id = CompilerIdentity(compiler) + "|" + kCompileFlags + "|abi" +
                     std::to_string(KILN_MODEL_ABI_VERSION);
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : id) h = (h ^ c) * 1099511628211ull;
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return std::string(buf);
  }();
  std::error_code ec;
  fs::create_directories(cacheDir, ec);
  if (ec)
    throw std::invalid_argument("cannot create the model cache '" + cacheDir +
                                "': " + ec.message());
  const fs::path library = fs::path(cacheDir) / ("model-" + key + ".so");
  if (fs::exists(library, ec)) return library.string();
  const std::string temp = library.string() + ".tmp." + std::to_string(getpid());
  std::string command = ShellQuote(compiler) + " " + kCompileFlags;
  for (const std::string& dir : AbiIncludeDirs()) command += " -I" + ShellQuote(dir);
  command += " " + ShellQuote(sourcePath) + " -o " + ShellQuote(temp);
  std::string output;
  if (RunCapturing(command, output) != 0) {
    fs::remove(temp, ec);
    while (!output.empty() && output.back() == '\n') output.pop_back();
    throw std::invalid_argument("cannot compile " + sourcePath + " (" + compiler + " " +
                                kCompileFlags + "):\n" + output);
  }
  fs::rename(temp, library, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw std::invalid_argument("cannot store the compiled model in '" + cacheDir + "'");
  }
  return library.string();
}

}  // namespace kiln
