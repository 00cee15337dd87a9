// The kiln command line: one Register* function per subcommand (each in its own cmd_*.cpp).
#pragma once
#include <CLI/CLI.hpp>

#include "baker/models/registry.h"

namespace kiln::cli {

/// The model parameter options every model-taking command shares (--roughness, --rho, --f0,
/// --eta, --k, --rs, --nu, --nv); Params() gives only those the user set.
struct ModelParamOptions {
  double roughness = 0, rho = 0, f0 = 0, eta = 0, k = 0, rs = 0, nu = 0, nv = 0;
  CLI::Option *oRoughness = nullptr, *oRho = nullptr, *oF0 = nullptr, *oEta = nullptr,
              *oK = nullptr, *oRs = nullptr, *oNu = nullptr, *oNv = nullptr;
  void Add(CLI::App* app);
  ModelParams Params() const;
};

/// Prints a double with %.17g (round-trips exactly).
std::string FullPrecision(double x);

/// Makes every numeric option and argument of every subcommand of `app` (those CLI11 types INT,
/// UINT or FLOAT) refuse an empty or non-numeric value with a one-line error naming it: CLI11 2.1
/// would read '' as 0. main() calls it once, after every subcommand is registered.
void RefuseNonNumbers(CLI::App& app);

/// The most threads -j takes; main() raises oneTBB's limit to it (by default oneTBB allows the
/// cores' count and warns on stderr at any larger arena).
constexpr int kMaxThreads = 1024;

/// The -j/--threads check of every command that takes it: 0 (all cores) or [1, kMaxThreads];
/// throws std::invalid_argument "COMMAND: -j N must be in [1, 1024]" otherwise.
void CheckThreads(const std::string& command, int threads);

/// Makes every --threads option of every subcommand of `app` refuse a value outside
/// [1, kMaxThreads] when given (-j 0 included; 0 stays the default meaning all cores).
void CheckThreadOptions(CLI::App& app);

/// argv[1..] for CLI11, with the numbers CLI11 2.1 would take for options ("-inf", "-nan", "-.5")
/// kept as values: each gets a leading space, which strtod skips.
std::vector<std::string> NumbersAsPositionals(int argc, char** argv);

void RegisterList(CLI::App& app);
void RegisterEval(CLI::App& app);
void RegisterIntegrate(CLI::App& app);
void RegisterBake(CLI::App& app);
void RegisterInspect(CLI::App& app);
void RegisterSample(CLI::App& app);
void RegisterVerify(CLI::App& app);
/// kiln atlas [--out DIR] [--only a,b] [--grid N] [-j N]: the error atlas (baker/atlas/atlas.h).
void RegisterAtlas(CLI::App& app);

}  // namespace kiln::cli
