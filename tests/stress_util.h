// Helpers the stress suite (tests/stress_*.cpp) shares: the edge values every sweep visits, the
// parameter configurations of each model (its edges exactly included), scratch folders, and
// running the CLI with a check that it answered instead of crashing.
#pragma once
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "baker/models/registry.h"
#include "cli_util.h"

namespace kiln::stress {

/// cos(theta) values every sweep visits: the horizon, just above it, and normal incidence.
inline const std::vector<double>& EdgeMus() {
  static const std::vector<double> v = {0.0, 1e-12, 1e-6, 1e-3, 0.5, 1 - 1e-9, 1.0};
  return v;
}

/// Azimuth differences: forward (0), side (pi/2), backward (pi), and a full turn (2 pi).
inline const std::vector<double>& EdgePhis() {
  static const std::vector<double> v = {0.0, 1e-9, 1.0, Pi / 2, 2.5, Pi, 2 * Pi};
  return v;
}

/// The model's roughness parameter, or nullptr when it takes none.
inline const ParamInfo* RoughnessParam(const ModelInfo& m) {
  for (const ParamInfo& p : m.params)
    if (p.name == "roughness") return &p;
  return nullptr;
}

inline bool Takes(const ModelInfo& m, const char* name) {
  for (const ParamInfo& p : m.params)
    if (p.name == name) return true;
  return false;
}

/// Roughness edges of a model: 0, 1e-12, 1e-6, the middle and its own hi (pi/2 for the Oren-Nayar
/// family). {} for a model without roughness.
inline std::vector<double> EdgeRoughness(const ModelInfo& m) {
  const ParamInfo* r = RoughnessParam(m);
  if (!r) return {};
  return {r->lo, r->lo + 1e-12, r->lo + 1e-6, 0.5, r->hi};  // lo: 0, or a sheen lobe's 0.045
}

/// A number as a label shows it (%.10g: 1 + 1e-9 stays distinct from 1).
inline std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

/// One set of non-roughness parameters of a model, with a label for failure messages.
struct Variant {
  std::string label;
  ModelParams params;
};

/// The coupling and Fresnel edges a model takes: rs and a diffuse f0 at 0 and 1; for specular
/// models F = 1, Schlick f0 = 0 and 1, dielectric eta = 1, 1 + 1e-9, below 1 (total internal
/// reflection), the lowest 0.01 and 100, and conductors with k = 0, tiny and 100; the
/// Ashikhmin-Shirley exponents at 0 and 1e7.
inline std::vector<Variant> EdgeVariants(const ModelInfo& m) {
  std::vector<Variant> out = {{"defaults", {}}};
  auto add = [&](const std::string& label, auto set) {
    Variant v{label, {}};
    set(v.params);
    out.push_back(v);
  };
  if (m.specular() && Takes(m, "f0")) {
    add("f0=0", [](ModelParams& p) { p.f0 = 0.0; });
    add("f0=1", [](ModelParams& p) { p.f0 = 1.0; });
  }
  if (m.specular() && Takes(m, "eta")) {
    for (double eta : {1.0, 1 + 1e-9, 0.5, 0.01, 100.0})
      add("eta=" + Num(eta), [eta](ModelParams& p) { p.eta = eta; });
    const double nk[][2] = {{1.5, 0}, {1.5, 1e-12}, {1, 1e-9}, {0.2, 100}, {100, 100}, {0.01, 100}};
    for (const auto& c : nk)
      add("eta=" + Num(c[0]) + ",k=" + Num(c[1]), [c](ModelParams& p) {
        p.eta = c[0];
        p.k = c[1];
      });
  } else if (Takes(m, "f0")) {
    add("f0=1", [](ModelParams& p) { p.f0 = 1.0; });
  }
  if (Takes(m, "rs")) {
    add("rs=0", [](ModelParams& p) { p.rs = 0.0; });
    add("rs=1", [](ModelParams& p) { p.rs = 1.0; });
  }
  if (Takes(m, "nu")) {
    const double e[][2] = {{0, 0}, {1e7, 0}, {0, 1e7}, {1e7, 1e7}};
    for (const auto& c : e)
      add("nu=" + Num(c[0]) + ",nv=" + Num(c[1]), [c](ModelParams& p) {
        p.nu = c[0];
        p.nv = c[1];
      });
  }
  return out;
}

/// `params` with the roughness set (when the model takes one).
inline ModelParams WithRoughness(const ModelInfo& m, ModelParams params, double r) {
  if (RoughnessParam(m)) params.roughness = r;
  return params;
}

/// Whether `model` holds the same bytes as one of `seen` (then appended to it when not): the same
/// parameters after the model's own clamping, as roughness 0 and 1e-6 are for a microfacet lobe
/// (alpha = max(r^2, 1e-12)) and for Unity's a = max(r^2, 0.002), so each of its integrals is
/// the earlier one's, bit for bit, and a sweep computes it once. Conservative: padding or a
/// pointer that differs only makes two models count as different.
inline bool SeenModel(const AnyModel& model, std::vector<AnyModel>& seen) {
  for (const AnyModel& s : seen)
    if (std::memcmp(&s, &model, sizeof(AnyModel)) == 0) return true;
  seen.push_back(model);
  return false;
}

/// |a - b| relative to max(1, |a|, |b|): absolute for values below 1, relative above.
inline double Diff(double a, double b) {
  if (a == b) return 0;  // also equal infinities
  return std::abs(a - b) / std::max({1.0, std::abs(a), std::abs(b)});
}

/// A fresh, empty folder under /tmp, removed at the end of the scope.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& tag)
      : path("/tmp/kiln_stress_" + tag + "_" + std::to_string(getpid())) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  /// File names in the folder, sorted.
  std::vector<std::string> Entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

inline void WriteFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// Runs `kiln ARGS` like test::RunKiln, killed (SIGKILL, reported as exit 137) after `seconds`:
/// a hostile argument that makes kiln run on is a failure, not a hung test run. Directly
/// (test::SpawnToFiles, its own process group killed at the limit) when ARGS holds only words
/// and quotes, else through /bin/sh and `timeout -s KILL`. `shellPrefix` runs first in the same
/// shell (e.g. "ulimit -v 1048576;"). A kiln ended by signal n reports 128 + n (or -1).
inline test::CommandResult RunKilnFor(int seconds, const std::string& args,
                                      const std::string& shellPrefix = "") {
  static int counter = 0;
  std::string base =
      "/tmp/kiln_stress_run_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  test::CommandResult r;
  std::vector<std::string> argv;
  if (!shellPrefix.empty() || !test::SplitShellWords(args, argv) ||
      (argv.insert(argv.begin(), KILN_BINARY),
       !test::SpawnToFiles(argv, base, seconds, 128, r.exitCode))) {
    std::string cmd = shellPrefix + " timeout -s KILL " + std::to_string(seconds) + " " +
                      std::string(KILN_BINARY) + " " + args + " </dev/null >" + base + ".out 2>" +
                      base + ".err";
    int status = std::system(cmd.c_str());
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  test::TakeOutput(base, r);
  return r;
}

/// True when a CLI run answered like kiln should refuse something: a non-zero exit that is not a
/// signal (RunKiln reports a signal as -1, RunKilnFor as 128 + n), nothing on stdout, and exactly
/// one line on stderr starting "kiln: error:" (a sanitizer report or an uncaught exception would
/// be several lines, or none).
inline bool IsCleanRefusal(const test::CommandResult& r, bool allowStdout = false) {
  return r.exitCode > 0 && r.exitCode < 128 && (allowStdout || r.out.empty()) &&
         test::CountLines(r.err) == 1 && r.err.rfind("kiln: error: ", 0) == 0;
}

/// Single-quotes `s` for the shell RunKiln uses.
inline std::string Quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace kiln::stress
