// kiln bench: run time against error, side by side with the methods peers use.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "baker/bench/bench.h"
#include "baker/bench/catalogue_report.h"
#include "baker/bench/custom_lobe_bench.h"
#include "baker/io/atomic_write.h"
#include "baker/cli/bench_commands.h"
#include "baker/cli/commands.h"

namespace kiln::cli {

void RegisterBench(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "bench",
      "time kiln's bake against Monte Carlo and Gauss-Legendre bakes of the same tables, "
      "with bake and lookup errors; writes DIR/bench.csv and DIR/bench.svg");
  struct Args {
    std::string out;
    bool quick = false;
    int threads = 0;
    bool catalogue = false;
    std::string only;
    int samples = 6;
    bool noReference = false;
    bool noLookupError = false;
    CustomLobeBenchOptions lobe;
  };
  auto args = std::make_shared<Args>();
  sub->add_flag("--quick", args->quick, "small tables and sweeps: under a minute (CI smoke run)");
  auto* oOut =
      sub->add_option("--out,-o", args->out,
                      "output folder (default: bench/ for the full run, bench/quick/ with --quick, "
                      "bench/catalogue/ with --catalogue)");
  sub->add_option("-j,--threads", args->threads,
                  "threads of the bakes and references (default: all cores); the baker-issue "
                  "comparison always uses 2");
  sub->add_flag("--catalogue", args->catalogue,
                "instead: bake every catalogue table as `kiln bake` does (texels and lookup-error "
                "search) and report per table and per table kind the seconds and rates of each, "
                "the total as a multiple of a yardstick timed in the same run (1024-sample Monte "
                "Carlo of a 128 x 128 GGX DFG), and the bake error at sampled texels against "
                "adaptive quadrature at 1e-10; writes DIR/catalogue.csv");
  auto* oOnly = sub->add_option("--only", args->only,
                                "with --catalogue: comma-separated table names (default: all)");
  sub->add_option("--samples", args->samples, "with --catalogue: texels re-integrated per table")
      ->capture_default_str();
  sub->add_flag("--no-reference", args->noReference,
                "with --catalogue: skip the adaptive references of the sampled texels (the "
                "slowest part: times only)");
  sub->add_flag("--no-lookup-error", args->noLookupError,
                "with --catalogue: bake the texels only, without the lookup-error searches");
  auto* oLobe = sub->add_option(
      "--custom-lobe", args->lobe.source,
      "instead: time the 128 x 128 albedo of a user's lobe (FILE.cpp or FILE.so) against "
      "--against's, both by adaptive quadrature to the same tolerance, in interleaved rounds: "
      "medians and their ratio (docs/benchmarks.md)");
  // The options only --custom-lobe takes.
  const std::vector<CLI::Option*> lobeOnly = {
      sub->add_option("--against", args->lobe.against, "with --custom-lobe: the built-in model")
          ->capture_default_str(),
      sub->add_option("--rounds", args->lobe.rounds, "with --custom-lobe: timed rounds")
          ->capture_default_str(),
      sub->add_option("--size", args->lobe.size, "with --custom-lobe: nodes per axis")
          ->capture_default_str()};
  sub->callback([args, oOnly, oOut, oLobe, lobeOnly] {
    CheckThreads("bench", args->threads);
    for (CLI::Option* o : lobeOnly)
      if (o->count() && !oLobe->count())
        throw std::invalid_argument("bench: " + o->get_name() + " needs --custom-lobe");
    if (oLobe->count()) {
      if (args->quick || args->catalogue)
        throw std::invalid_argument("bench: --custom-lobe takes neither --quick nor --catalogue");
      args->lobe.threads = args->threads > 0 ? args->threads : 2;
      RunCustomLobeBench(args->lobe, stdout);
      return;
    }
    if (oOut->count() && args->out.empty())
      throw std::invalid_argument("bench: --out '' names no folder");
    if (args->out.empty()) args->out = DefaultBenchFolder(args->quick, args->catalogue);
    if (args->catalogue) {
      if (args->quick) throw std::invalid_argument("bench: give --catalogue or --quick, not both");
      if (oOnly->count() && args->only.empty())
        throw std::invalid_argument("bench: --only '' names no table");
      if (args->samples < 1 || args->samples > 1000)
        throw std::invalid_argument("bench: --samples must be in [1, 1000]");
      CatalogueBenchOptions opt;
      opt.threads = args->threads > 0 ? args->threads : 2;
      opt.samples = args->samples;
      opt.reference = !args->noReference;
      opt.lookupError = !args->noLookupError;
      if (!args->only.empty()) opt.only = UniqueNames(args->only);
      std::string csv = CatalogueCsv(RunCatalogueBench(opt, stdout));
      std::filesystem::create_directories(args->out);
      writeAtomically(args->out + "/catalogue.csv",
                      [&](const std::string& tmp) { writeBytes(tmp, csv); });
      std::printf("wrote %s/catalogue.csv\n", args->out.c_str());
      return;
    }
    if (oOnly->count()) throw std::invalid_argument("bench: --only needs --catalogue");
    if (args->noReference || args->noLookupError)
      throw std::invalid_argument("bench: --no-reference and --no-lookup-error need --catalogue");
    BenchOptions opt;
    opt.scale = args->quick ? BenchScale::Quick : BenchScale::Full;
    opt.outDir = args->out;
    opt.threads = args->threads;
    RunBench(opt, stdout);
  });
}

}  // namespace kiln::cli
