// kiln atlas: the error atlas of the cheap approximations (issue #16, baker/atlas/).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <thread>

#include "baker/atlas/atlas.h"
#include "baker/cli/commands.h"
#include "baker/io/atomic_write.h"
#include "baker/util/did_you_mean.h"

namespace kiln::cli {

void RegisterAtlas(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "atlas",
      "error atlas of the cheap approximations: per pair DIR/<pair>.csv and DIR/<pair>.png "
      "(albedo difference and max cosine-weighted BRDF difference over (mu, roughness)) and "
      "DIR/README.md");
  struct Args {
    std::string out = "docs/atlas";
    std::string only;
    int threads = 0;
    int grid = 32;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("--out,-o", args->out, "output folder (created if missing)")
      ->capture_default_str();
  auto* oOnly =
      sub->add_option("--only", args->only, "comma-separated pair names (default: every pair)");
  sub->add_option("--grid", args->grid, "nodes per axis of the (mu, roughness) grid")
      ->capture_default_str();
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->callback([args, oOnly] {
    CheckThreads("atlas", args->threads);
    if (args->out.empty()) throw std::invalid_argument("atlas: --out '' names no folder");
    if (args->grid < 2 || args->grid > 256)
      throw std::invalid_argument("atlas: --grid must be in [2, 256]");
    std::vector<AtlasPair> pairs;
    if (oOnly->count()) {
      std::vector<std::string> known;
      for (const AtlasPair& p : AtlasPairs()) known.push_back(p.name);
      for (const std::string& name : UniqueNames(args->only)) {  // a,a runs a once
        const AtlasPair* found = nullptr;
        for (const AtlasPair& p : AtlasPairs())
          if (p.name == name) found = &p;
        if (!found)
          throw std::invalid_argument("atlas: unknown pair '" + name + "'" +
                                      DidYouMean(name, known));
        pairs.push_back(*found);
      }
      if (pairs.empty()) throw std::invalid_argument("atlas: --only '' names no pair");
    } else {
      pairs = AtlasPairs();
    }
    for (const AtlasPair& p : pairs) CheckAtlasPair(p);
    std::error_code ec;
    std::filesystem::create_directories(args->out, ec);
    if (ec || !std::filesystem::is_directory(args->out))
      throw std::invalid_argument("atlas: cannot use --out '" + args->out + "' as a folder" +
                                  (ec ? ": " + ec.message() : ""));
    AtlasOptions opt;
    opt.muNodes = opt.roughnessNodes = args->grid;
    opt.threads =
        args->threads > 0 ? args->threads : static_cast<int>(std::thread::hardware_concurrency());
    std::vector<AtlasResult> results;
    for (const AtlasPair& p : pairs) {
      results.push_back(ComputeAtlas(p, opt));
      std::printf("%s: done\n", p.name.c_str());
      std::fflush(stdout);
    }
    std::string command = "kiln atlas --out " + args->out;
    if (args->grid != 32) command += " --grid " + std::to_string(args->grid);
    if (oOnly->count()) command += " --only " + args->only;
    // Every file is written to a temporary file first and all are renamed together.
    std::vector<std::unique_ptr<PendingFile>> files;
    auto add = [&](const std::string& name, const std::string& bytes) {
      files.push_back(std::make_unique<PendingFile>(args->out + "/" + name));
      files.back()->WriteBytes(bytes);
    };
    for (const AtlasResult& r : results) {
      add(r.pair.name + ".csv", AtlasCsv(r));
      add(r.pair.name + ".png", AtlasPng(r));
    }
    add("README.md", AtlasReadme(results, opt, command));
    std::vector<PendingFile*> raw;
    for (auto& f : files) raw.push_back(f.get());
    PendingFile::CommitAll(raw);
    std::printf("wrote %zu files to %s\n", files.size(), args->out.c_str());
  });
}

}  // namespace kiln::cli
