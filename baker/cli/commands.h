// The kiln command line: one Register* function per subcommand (each in its own cmd_*.cpp).
#pragma once
#include <CLI/CLI.hpp>

#include "baker/models/registry.h"
#include "baker/tables/spec.h"

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

/// Adds --model-source FILE.cpp and --model-library FILE.so (each may repeat) to the commands
/// that take a model (eval, integrate, bake, verify, plan) and to list: the user's lobe
/// (kiln/model_abi.h, baker/custom/) is loaded and registered while the line is parsed. main()
/// calls it once.
void AddCustomModelOptions(CLI::App& app);

/// The comma-separated names in `list`, each once, in the order of their first appearance
/// ("a,b,a" -> a, b).
std::vector<std::string> UniqueNames(const std::string& list);

/// Prints a double with %.17g (round-trips exactly).
std::string FullPrecision(double x);

/// Makes every numeric option and argument of every subcommand of `app` (those CLI11 types INT,
/// UINT or FLOAT) refuse an empty, non-numeric or not plain decimal value with a one-line error
/// naming it: CLI11 2.1 would read '' as 0, "0x10" as 16 and the integer "010" as 8. Integers:
/// [+-]digits without leading zeros; numbers: [+-]digits[.digits][e[+-]digits], inf or nan. main()
/// calls it once, after every subcommand is registered.
void RefuseNonNumbers(CLI::App& app);

/// The most threads -j takes; main() raises oneTBB's limit to it (by default oneTBB allows the
/// cores' count and warns on stderr at any larger arena).
constexpr int kMaxThreads = 1024;

/// The -j/--threads check of every command that takes it: 0 (all cores) or [1, kMaxThreads];
/// throws std::invalid_argument "COMMAND: -j N must be in [1, 1024]" otherwise.
void CheckThreads(const std::string& command, int threads);

/// The most threads this process can run: kMaxThreads, or fewer under a finite address-space
/// limit (ulimit -v): half of the unmapped room, at 72 MiB per thread (a malloc arena and a
/// stack), at least 1. main() gives it to oneTBB as its limit.
int ThreadLimit();

/// `requested` when it is at most `limit`; else prints one warning line on stderr ("kiln:
/// warning: -j N: running M threads ...") and returns `limit`.
int ThreadsToRun(int requested, int limit);

/// Makes every --threads option of every subcommand of `app` refuse a value outside
/// [1, kMaxThreads] when given (-j 0 included; 0 stays the default meaning all cores).
void CheckThreadOptions(CLI::App& app);

/// argv[1..] for CLI11, with the numbers CLI11 2.1 would take for options ("-inf", "-nan", "-.5")
/// kept as values: each gets a leading space, which strtod skips.
std::vector<std::string> NumbersAsPositionals(int argc, char** argv);

/// One table `kiln list --tables` shows: its catalogue spec and whether the default catalogue
/// (`kiln bake` without --only) bakes it; the others are baked on request (--only, a scene).
struct ListedTable {
  TableSpec spec;
  bool inDefaultCatalogue = true;
  bool customModel = false;  ///< a table of a user's lobe (loaded by --model-source / -library)
};

/// Every table kiln can bake by name: the default catalogue in its order, then the on-request
/// tables, then the tables of the user's lobes loaded in this process (albedo, albedo-avg and,
/// for a specular lobe, dfg), each name once.
std::vector<ListedTable> AllListedTables();

/// One line per table ("NAME  [default|on request]  AXES[ at P = V, ...]  # MEANING", AXES as
/// kiln plan prints them: "mu 0..1 (32, sqrt) x roughness ...", then the model parameters the
/// table is baked at, if any; a user's lobe's table adds "; method: ..." after the meaning), or
/// (json) a JSON array of objects with keys name, model, quantity, channels, axes (name, lo, hi,
/// size, warp), params, default_catalogue, custom_model, method, description.
std::string FormatTableList(const std::vector<ListedTable>& tables, bool json);

/// kiln list [--tables [--json]]: the models, or every table kiln can bake.
void RegisterList(CLI::App& app);

/// For a command line CLI11 refused (`args`: argv[1..]): " (did you mean 'NAME'?)" for the first
/// word that is no subcommand of `app` (in the subcommand's place) or option that neither `app`
/// nor the subcommand given takes, NAME the closest such name (DidYouMean); "" when there is
/// none close enough.
std::string SuggestArgument(CLI::App& app, const std::vector<std::string>& args);
void RegisterEval(CLI::App& app);
void RegisterIntegrate(CLI::App& app);
void RegisterBake(CLI::App& app);
void RegisterInspect(CLI::App& app);
void RegisterSample(CLI::App& app);
void RegisterVerify(CLI::App& app);
/// kiln atlas [--out DIR] [--only a,b] [--grid N] [-j N]: the error atlas (baker/atlas/atlas.h).
void RegisterAtlas(CLI::App& app);
/// kiln fit TABLE [--max-error E | --terms N] [--out DIR]: a closed form (baker/fit/fit.h).
void RegisterFit(CLI::App& app);

}  // namespace kiln::cli
