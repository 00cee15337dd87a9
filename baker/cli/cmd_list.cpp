// kiln list: every model id, one per line, with its parameters.
#include <cstdio>

#include "baker/cli/commands.h"

namespace kiln::cli {

void RegisterList(CLI::App& app) {
  auto* sub = app.add_subcommand("list", "print every model id with its parameters");
  sub->callback([] {
    std::vector<ModelInfo> all = AllModels();
    all.insert(all.end(), AllBsdfModels().begin(), AllBsdfModels().end());
    for (const ModelInfo& m : all) {
      std::string line = m.id;
      for (const ParamInfo& p : m.params)
        line += " " + p.name + "=" + FullPrecision(p.def) + "[" + FullPrecision(p.lo) + "," +
                FullPrecision(p.hi) + "]";
      line += "  # " + std::string(m.bsdf ? "BSDF (reflection + transmission): " : "") + m.summary +
              "; roughness: " + m.roughness;
      std::printf("%s\n", line.c_str());
    }
  });
}

}  // namespace kiln::cli
