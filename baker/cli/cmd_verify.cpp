// kiln verify: options and output; the checks are in baker/verify/ (verify.h).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/fit/fit_verify.h"
#include "baker/verify/verify.h"

namespace kiln::cli {
namespace {

/// The most reference evaluations, cells and random points verify takes per table.
constexpr long long kMaxVerifyPoints = 10000000;
/// The most sampled nodes of the bake-error check.
constexpr int kMaxBakeNodes = 100000;

/// The one-line bar on a terminal: tables done of all, and the one being searched.
void DrawBar(size_t done, size_t total, const std::string& name) {
  constexpr int kBar = 30;
  int filled = total ? static_cast<int>(kBar * done / total) : kBar;
  std::fprintf(stderr, "\r%-32s [%s%s] %zu/%zu", name.c_str(), std::string(filled, '#').c_str(),
               std::string(kBar - filled, '.').c_str(), done, total);
  std::fflush(stderr);
}
void ClearBar() {
  std::fprintf(stderr, "\r%*s\r", 32 + 3 + 30 + 2 + 2 * 20 + 1, "");
  std::fflush(stderr);
}

/// The verdict as one JSON object (keys: docs/cli.md).
nlohmann::ordered_json VerdictJson(const verify::TableVerdict& v) {
  if (!v.error.empty()) return {{"file", v.file}, {"ok", false}, {"error", v.error}};
  return {{"file", v.file},
          {"ok", v.ok},
          {"name", v.name},
          {"filter", v.filter},
          {"checked", v.checked},
          {"max", v.lookup.max},
          {"rms", v.lookup.rms},
          {"declared", v.declaredLookup},
          {"off_corner", v.lookup.maxOutsideCorner},
          {"where", v.lookupWhere},
          {"points", v.lookup.points},
          {"cells", v.lookup.cells},
          {"climbed", v.lookup.climbed},
          {"budget", v.lookup.budget},
          {"bake_max", v.bake.max},
          {"bake_declared", v.bake.declared},
          {"bake_where", v.bakeWhere},
          {"bake_nodes", v.bake.nodes},
          {"bake_ok", v.bake.ok},
          {"bake_evals", v.bake.evals},
          {"bake_seconds", v.bakeSeconds},
          {"seconds", v.seconds}};
}

/// The verdict's row on stdout: the columns of PrintHeader, then why it failed.
void PrintRow(const verify::TableVerdict& v) {
  if (!v.error.empty()) {
    std::printf("%-40s FAILED: %s\n", v.file.c_str(), v.error.c_str());
    return;
  }
  std::printf("%-40s %11.3e %11.3e %11.3e %11.3e %11.3e %11.3e  %s%s%s%s\n", v.file.c_str(),
              v.lookup.max, v.lookup.rms, v.declaredLookup, v.lookup.maxOutsideCorner, v.bake.max,
              v.bake.declared, v.lookupWhere.c_str(), v.lookupOk ? "" : "  EXCEEDS BOUND",
              v.bake.ok ? "" : ("  EXCEEDS BAKE ERROR at " + v.bakeWhere).c_str(),
              v.fitProblem.empty() ? "" : "  FIT CHECK FAILED");
}

void PrintHeader() {
  std::printf("%-40s %11s %11s %11s %11s %11s %11s  %s\n", "file", "max", "rms", "declared",
              "off-corner", "bake-max", "bake-decl", "where (max)");
}

/// The progress line of one table on `log`.
void LogVerdict(FILE* log, const verify::TableVerdict& v) {
  if (!v.fitSummary.empty()) std::fprintf(log, "%-36s %s\n", v.name.c_str(), v.fitSummary.c_str());
  std::fprintf(log, "%-36s max %.3e  declared %.3e  bake %.3e of %.3e  %6.2f s  %s\n",
               v.name.c_str(), v.lookup.max, v.declaredLookup, v.bake.max, v.bake.declared,
               v.seconds,
               !v.ok        ? "EXCEEDS"
               : !v.checked ? "(not checked)"
                            : "ok");
  std::fflush(log);
}

}  // namespace

void RegisterVerify(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "verify",
      "check every claim of each table: repeat the bake's lookup-error search (corner and edge "
      "cells, the cells the node values rank worst, a climb to the local maximum in each) and "
      "compare texels at sampled nodes with an independent reference (the bake error); exit 1 "
      "when one exceeds its declared bound");
  struct Args {
    std::vector<std::string> paths;
    long long budget = 0, points = 0, cells = 0;
    double tol = 0;
    int threads = 0;
    std::string filter;
    bool json = false, quiet = false, outerReference = false, allNodes = false;
    int bakeNodes = verify::kBakeSampleNodes;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("paths", args->paths, "tables or folders of tables")->required();
  sub->add_option("--budget", args->budget,
                  "reference evaluations of the search per table (0: the bake's budget, fewer "
                  "for a costly reference; docs/accuracy.md)")
      ->capture_default_str();
  sub->add_option("--points", args->points, "random points per table, besides the search")
      ->capture_default_str();
  sub->add_option("--cells", args->cells,
                  "search at most this many cells (0: as the budget allows)")
      ->capture_default_str();
  auto* oTol =
      sub->add_option("--tol", args->tol,
                      "reference by adaptive quadrature to this tolerance (default: the bake's own "
                      "method, its fixed rule where it has one)");
  sub->add_flag("--outer-reference", args->outerReference,
                "with --tol: an average's search cells and random points take the bake-error "
                "check's reference (adaptive quadrature over mu of E by its 3D table's rule); "
                "the declared worst point keeps adaptive quadrature of the whole integral");
  auto* oBakeNodes =
      sub->add_option("--bake-nodes", args->bakeNodes,
                      "bake-error check: sampled nodes per table besides the corners and the nodes "
                      "that depart most from their neighbours (reference: adaptive quadrature or a "
                      "closed form, never the bake's rule)")
          ->capture_default_str();
  sub->add_flag("--all-nodes", args->allNodes,
                "bake-error check: every node of each table, whatever the reference costs "
                "(minutes for a 3D glass table; docs/accuracy.md)")
      ->excludes(oBakeNodes);
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->add_option("--filter", args->filter,
                  "measure with this filter instead of the declared one (then only reported, "
                  "not checked against the bound)")
      ->check(CLI::IsMember({"linear", "cubic"}));
  sub->add_flag("--json", args->json,
                "print the results as one JSON object on stdout (keys: docs/cli.md); "
                "no progress on stderr");
  sub->add_flag("-q,--quiet", args->quiet,
                "no progress line per table on stderr and no bar (errors only)");
  sub->callback([args, oTol] {
    // Caps on the work (each point is one integral).
    if (args->budget < 0 || args->budget > kMaxVerifyPoints)
      throw std::invalid_argument("verify: --budget " + std::to_string(args->budget) +
                                  " must be in [0, 1e7]");
    if (args->cells < 0 || args->cells > kMaxVerifyPoints)
      throw std::invalid_argument("verify: --cells " + std::to_string(args->cells) +
                                  " must be in [0, 1e7]");
    if (args->points < 0 || args->points > kMaxVerifyPoints)
      throw std::invalid_argument("verify: --points " + std::to_string(args->points) +
                                  " must be in [0, 1e7]");
    if (args->bakeNodes < 0 || args->bakeNodes > kMaxBakeNodes)
      throw std::invalid_argument("verify: --bake-nodes " + std::to_string(args->bakeNodes) +
                                  " must be in [0, 1e5]");
    if (oTol->count() && !(args->tol >= 1e-12 && args->tol <= 1e-4))
      throw std::invalid_argument("verify: --tol " + FullPrecision(args->tol) +
                                  " must be in [1e-12, 1e-4]");
    if (args->outerReference && !oTol->count())
      throw std::invalid_argument("verify: --outer-reference needs --tol");
    CheckThreads("verify", args->threads);
    // A closed-form fit (DIR/TABLE-fit.h, `kiln fit`): its own check (baker/fit/fit_verify.h).
    if (args->paths.size() == 1 && IsFitHeaderPath(args->paths[0])) {
      FitVerifyResult r = VerifyFitHeader(args->paths[0], args->threads);
      std::printf("%-40s max %.3e (off the jump %.3e)  median %.3e  stated %.3e (%.3e)  %s\n",
                  args->paths[0].c_str(), r.measured.max, r.measured.maxOffJump, r.measured.median,
                  r.fit.statedMax, r.fit.statedOffJump, r.ok ? "ok" : "EXCEEDS");
      if (!r.note.empty()) std::fprintf(stderr, "kiln: note: %s\n", r.note.c_str());
      if (!r.ok) throw std::runtime_error("verify: " + args->paths[0] + ": " + r.problem);
      return;
    }
    std::vector<std::string> files;
    for (const std::string& p : args->paths)
      for (const std::string& f : verify::VerifyInputs(p)) files.push_back(f);
    if (files.empty()) throw std::invalid_argument("verify: no .exr files found");
    verify::VerifyOptions opt;
    opt.budget = args->budget;
    opt.points = args->points;
    opt.cells = args->cells;
    opt.tol = args->tol;
    opt.outerReference = args->outerReference;
    opt.threads = args->threads;
    opt.filter = args->filter;
    opt.bakeNodes = args->allNodes ? verify::kBakeAllNodes : args->bakeNodes;
    // A line per table on stderr (terminal or not), the redrawn bar only on a terminal;
    // --quiet and --json (stdout is then one JSON object with the same numbers): neither.
    FILE* log = args->quiet || args->json ? nullptr : stderr;
    const bool bar = log && isatty(STDERR_FILENO);
    int failed = 0;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    if (!args->json) PrintHeader();
    auto start = std::chrono::steady_clock::now();
    for (size_t fi = 0; fi < files.size(); ++fi) {
      if (bar) DrawBar(fi, files.size(), files[fi]);
      verify::TableVerdict v = verify::VerifyTableFile(files[fi], opt);
      if (bar) ClearBar();
      if (!v.fitProblem.empty())
        std::fprintf(stderr, "%s: %s\n", v.file.c_str(), v.fitProblem.c_str());
      if (log && v.error.empty()) LogVerdict(log, v);
      if (args->json)
        rows.push_back(VerdictJson(v));
      else
        PrintRow(v);
      std::fflush(stdout);
      if (!v.ok) ++failed;
    }
    double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (log) std::fprintf(log, "%zu tables in %.1f s\n", files.size(), total);
    if (args->json) {
      nlohmann::ordered_json doc;
      doc["tables"] = rows;
      doc["count"] = files.size();
      doc["failed"] = failed;
      std::fputs((doc.dump(2) + "\n").c_str(), stdout);
      std::fflush(stdout);
    } else {
      std::printf("%zu tables, %d over their bound\n", files.size(), failed);
    }
    if (failed) throw std::runtime_error("verify: " + std::to_string(failed) + " table(s) failed");
  });
}

}  // namespace kiln::cli
