// kiln atlas: the error atlas of the cheap approximations (issue #16, baker/atlas/).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "baker/atlas/atlas.h"
#include "baker/atlas/atlas_tables.h"
#include "baker/cli/commands.h"
#include "baker/io/atomic_write.h"
#include "baker/util/did_you_mean.h"
#include "baker/util/threads.h"

namespace kiln::cli {

void RegisterAtlas(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "atlas",
      "error atlas of the cheap approximations: per pair DIR/<pair>.csv and DIR/<pair>.png "
      "(albedo difference and max cosine-weighted BRDF difference over (mu, roughness)) and "
      "DIR/README.md; the approximations engines ship in place of a table against kiln's exact "
      "integrals: DIR/<name>.csv, DIR/<name>.png and DIR/tables.md");
  struct Args {
    std::string out = "docs/atlas";
    std::string only;
    std::string section = "all";
    int threads = 0;
    int grid = 32;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("--out,-o", args->out, "output folder (created if missing)")
      ->capture_default_str();
  auto* oOnly = sub->add_option(
      "--only", args->only,
      "comma-separated pair or table-approximation names (default: every one of the sections)");
  sub->add_option("--section", args->section, "pairs (README.md), tables (tables.md) or all")
      ->capture_default_str();
  sub->add_option("--grid", args->grid, "nodes per axis of the (mu, roughness) grid")
      ->capture_default_str();
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->callback([args, oOnly] {
    CheckThreads("atlas", args->threads);
    if (args->out.empty()) throw std::invalid_argument("atlas: --out '' names no folder");
    if (args->grid < 2 || args->grid > 256)
      throw std::invalid_argument("atlas: --grid must be in [2, 256]");
    if (args->section != "all" && args->section != "pairs" && args->section != "tables")
      throw std::invalid_argument("atlas: --section must be pairs, tables or all, not '" +
                                  args->section + "'");
    const bool doPairs = args->section != "tables", doTables = args->section != "pairs";
    std::vector<AtlasPair> pairs;
    std::vector<TableApproximation> approxs;
    if (oOnly->count()) {
      std::vector<std::string> known;
      if (doPairs)
        for (const AtlasPair& p : AtlasPairs()) known.push_back(p.name);
      if (doTables)
        for (const TableApproximation& t : TableApproximations()) known.push_back(t.name);
      for (const std::string& name : UniqueNames(args->only)) {  // a,a runs a once
        bool found = false;
        for (const AtlasPair& p : AtlasPairs())
          if (doPairs && p.name == name) pairs.push_back(p), found = true;
        for (const TableApproximation& t : TableApproximations())
          if (doTables && t.name == name) approxs.push_back(t), found = true;
        if (!found)
          // "pair" unless only table approximations are searched.
          throw std::invalid_argument(std::string("atlas: unknown ") +
                                      (doPairs ? "pair" : "approximation") + " '" + name + "'" +
                                      DidYouMean(name, known));
      }
      if (pairs.empty() && approxs.empty())
        throw std::invalid_argument("atlas: --only '' names no pair");
    } else {
      if (doPairs) pairs = AtlasPairs();
      if (doTables) approxs = TableApproximations();
    }
    for (const AtlasPair& p : pairs) CheckAtlasPair(p);
    std::error_code ec;
    std::filesystem::create_directories(args->out, ec);
    if (ec || !std::filesystem::is_directory(args->out))
      throw std::invalid_argument("atlas: cannot use --out '" + args->out + "' as a folder" +
                                  (ec ? ": " + ec.message() : ""));
    AtlasOptions opt;
    opt.muNodes = opt.roughnessNodes = args->grid;
    opt.threads = ThreadCount(args->threads);
    std::vector<AtlasResult> results;
    for (const AtlasPair& p : pairs) {
      results.push_back(ComputeAtlas(p, opt));
      std::printf("%s: done\n", p.name.c_str());
      std::fflush(stdout);
    }
    std::vector<TableApproximationResult> tables;
    for (const TableApproximation& t : approxs) {
      tables.push_back(ComputeTableApproximation(t, opt));
      std::printf("%s: done\n", t.name.c_str());
      std::fflush(stdout);
    }
    std::string command = "kiln atlas --out " + args->out;
    if (args->grid != 32) command += " --grid " + std::to_string(args->grid);
    if (args->section != "all") command += " --section " + args->section;
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
    if (!results.empty()) add("README.md", AtlasReadme(results, opt, command));
    for (const TableApproximationResult& r : tables) {
      add(r.approx.name + ".csv", TableApproximationCsv(r));
      add(r.approx.name + ".png", TableApproximationPng(r));
    }
    if (!tables.empty()) add("tables.md", TableApproximationsReadme(tables, opt, command));
    std::vector<PendingFile*> raw;
    for (auto& f : files) raw.push_back(f.get());
    PendingFile::CommitAll(raw);
    std::printf("wrote %zu files to %s\n", files.size(), args->out.c_str());
  });
}

}  // namespace kiln::cli
