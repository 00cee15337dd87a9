// kiln: bakes BRDFs and their hemispherical integrals into OpenEXR lookup tables.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "baker/cli/bench_commands.h"
#include "baker/cli/commands.h"
#include "baker/cli/scene_commands.h"

int main(int argc, char** argv) {
  CLI::App app{"kiln: BRDF integral lookup tables, baked exactly"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");
  app.set_version_flag("--version", "kiln " KILN_VERSION);
  kiln::cli::RegisterList(app);
  kiln::cli::RegisterEval(app);
  kiln::cli::RegisterIntegrate(app);
  kiln::cli::RegisterBake(app);
  kiln::cli::RegisterInspect(app);
  kiln::cli::RegisterSample(app);
  kiln::cli::RegisterVerify(app);
  kiln::cli::RegisterPlan(app);
  kiln::cli::RegisterBench(app);
  kiln::cli::RegisterAtlas(app);
  kiln::cli::RegisterFit(app);
  kiln::cli::AddCustomModelOptions(app);
  kiln::cli::RefuseNonNumbers(app);
  kiln::cli::CheckThreadOptions(app);
  // -j above the number of cores is allowed (up to kMaxThreads): without this oneTBB would print
  // a warning and run fewer threads. Under an address-space limit (ulimit -v) fewer: oneTBB
  // aborts the process when pthread_create fails.
  tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(kiln::cli::ThreadLimit()));
  std::vector<std::string> args = kiln::cli::NumbersAsPositionals(argc, argv);
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "kiln: error: %s%s\n", e.what(),
                 kiln::cli::SuggestArgument(app, args).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (what.rfind("kiln: ", 0) == 0) what = what.substr(6);  // the runtime's own prefix
    std::fprintf(stderr, "kiln: error: %s\n", what.c_str());
    return 1;
  }
  return 0;
}
