// kiln: bakes BRDFs and their hemispherical integrals into OpenEXR lookup tables.
#include <cstdio>
#include <exception>

#include "baker/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"kiln: BRDF integral lookup tables, baked exactly"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every subcommand");
  kiln::cli::RegisterList(app);
  kiln::cli::RegisterEval(app);
  kiln::cli::RegisterIntegrate(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "kiln: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kiln: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
