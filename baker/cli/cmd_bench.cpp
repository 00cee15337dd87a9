// kiln bench: run time against error, side by side with the methods peers use.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "baker/bench/bench.h"
#include "baker/cli/bench_commands.h"
#include "baker/cli/commands.h"

namespace kiln::cli {

void RegisterBench(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "bench",
      "time kiln's bake against Monte Carlo and Gauss-Legendre bakes of the same tables, "
      "with bake and lookup errors; writes DIR/bench.csv and DIR/bench.svg");
  struct Args {
    std::string out = "bench";
    bool quick = false;
    int threads = 0;
  };
  auto args = std::make_shared<Args>();
  sub->add_flag("--quick", args->quick, "small tables and sweeps: under a minute (CI smoke run)");
  sub->add_option("--out,-o", args->out, "output folder")->capture_default_str();
  sub->add_option("-j,--threads", args->threads,
                  "threads of the bakes and references (default: all cores); the baker-issue "
                  "comparison always uses 2");
  sub->callback([args] {
    CheckThreads("bench", args->threads);
    BenchOptions opt;
    opt.scale = args->quick ? BenchScale::Quick : BenchScale::Full;
    opt.outDir = args->out;
    opt.threads = args->threads;
    RunBench(opt, stdout);
  });
}

}  // namespace kiln::cli
