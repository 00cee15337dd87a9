// kiln plan: the tables a scene needs, and which of them the output folder already has.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "baker/cli/scene_commands.h"
#include "baker/scene/plan_report.h"

namespace kiln::cli {

void RegisterPlan(CLI::App& app) {
  auto* sub = app.add_subcommand("plan",
                                 "print the tables a scene (glTF 2.0 .gltf/.glb, or a kiln scene) "
                                 "needs and whether DIR has them");
  struct Args {
    std::string scene, out = "luts";
    int size = 0;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("scene", args->scene, "glTF 2.0 (.gltf, .glb) or kiln scene (.json) file")
      ->required();
  sub->add_option("--out,-o", args->out, "folder the tables are baked into")->capture_default_str();
  CLI::Option* oSize =
      sub->add_option("--size", args->size,
                      "nodes on every catalogue axis before narrowing (default: the catalogue's)");
  sub->callback([args, oSize] {
    if (oSize->count() && (args->size < 2 || args->size > 4096))
      throw std::invalid_argument("plan: --size " + std::to_string(args->size) +
                                  " must be in [2, 4096]");
    PlanOptions opt;
    opt.size = args->size;
    Plan plan = PlanSceneFile(args->scene, opt);
    for (const std::string& w : plan.warnings)
      std::fprintf(stderr, "kiln: warning: %s\n", w.c_str());
    std::fputs(FormatPlan(plan, args->out).c_str(), stdout);
  });
}

}  // namespace kiln::cli
