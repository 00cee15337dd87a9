// kiln: bakes BRDFs and their hemispherical integrals into OpenEXR lookup tables.
#include <cstdio>
#include <exception>
#include <string>

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
  kiln::cli::RefuseNonNumbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "kiln: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (what.rfind("kiln: ", 0) == 0) what = what.substr(6);  // the runtime's own prefix
    std::fprintf(stderr, "kiln: error: %s\n", what.c_str());
    return 1;
  }
  return 0;
}
