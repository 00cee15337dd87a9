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
    bool check = false, json = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("scene", args->scene, "glTF 2.0 (.gltf, .glb) or kiln scene (.json) file")
      ->required();
  sub->add_option("--out,-o", args->out, "folder the tables are baked into")->capture_default_str();
  CLI::Option* oSize =
      sub->add_option("--size", args->size,
                      "nodes on every catalogue axis before narrowing (default: the catalogue's)");
  sub->add_flag("--check", args->check,
                "exit 1 when a table is missing or stale in DIR (0 when all are up to date)");
  sub->add_flag("--json", args->json,
                "print the plan as one JSON object on stdout (keys: docs/cli.md)");
  sub->callback([args, oSize] {
    if (oSize->count() && (args->size < 2 || args->size > 4096))
      throw std::invalid_argument("plan: --size " + std::to_string(args->size) +
                                  " must be in [2, 4096]");
    PlanOptions opt;
    opt.size = args->size;
    Plan plan = PlanSceneFile(args->scene, opt);
    for (const std::string& w : plan.warnings)
      std::fprintf(stderr, "kiln: warning: %s\n", w.c_str());
    std::fputs((args->json ? FormatPlanJson(plan, args->out) : FormatPlan(plan, args->out)).c_str(),
               stdout);
    if (args->check) {
      size_t notReady = 0;
      for (TableState s : PlanStates(plan, args->out)) notReady += s != TableState::UpToDate;
      if (notReady) {
        std::fflush(stdout);
        throw std::runtime_error("plan --check: " + std::to_string(notReady) + " of " +
                                 std::to_string(plan.tables.size()) +
                                 " table(s) missing or stale in " + args->out);
      }
    }
  });
}

}  // namespace kiln::cli
