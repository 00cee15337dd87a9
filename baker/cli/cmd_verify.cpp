// kiln verify: repeats the bake's lookup-error search (lookup_error.h) on each table and checks
// the max it finds against the bound the table declares.
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "baker/bake/lookup_error.h"
#include "baker/cli/commands.h"
#include "baker/fit/fit_verify.h"
#include "baker/io/texture_readers.h"
#include "baker/models/registry.h"
#include "baker/tables/engine_layout.h"
#include "kiln/exr_loader.h"

namespace kiln::cli {
namespace {

/// The most reference evaluations, cells and random points verify takes per table.
constexpr long long kMaxVerifyPoints = 10000000;

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

/// Whether the EXR file at `path` is part 2 or later of a wider table (kiln.part > 1): loading
/// part 1 reads the whole table, so a folder's listing names the table once. False for a file
/// whose header does not read (its own line reports it).
bool IsLaterPart(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str(), 1);
    const auto* part = in.header().findTypedAttribute<Imf::IntAttribute>("kiln.part");
    return part != nullptr && part->value() > 1;
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> ExrFiles(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw std::invalid_argument("verify: no such file or folder '" + path + "'");
    throw std::invalid_argument("verify: cannot access '" + path + "' (" + std::strerror(errno) +
                                ")");
  }
  if (!S_ISDIR(st.st_mode)) return {path};
  std::vector<std::string> out;
  if (DIR* d = opendir(path.c_str())) {
    while (dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".exr") == 0 && !IsLaterPart(path + "/" + n))
        out.push_back(path + "/" + n);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void RegisterVerify(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "verify",
      "repeat the bake's lookup-error search on each table (corner and edge cells, the cells the "
      "node values rank worst, a climb to the local maximum in each); exit 1 when one exceeds "
      "its declared bound");
  struct Args {
    std::vector<std::string> paths;
    long long budget = 0, points = 0, cells = 0;
    double tol = 0;
    int threads = 0;
    std::string filter;
    bool json = false, quiet = false;
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
    if (oTol->count() && !(args->tol >= 1e-12 && args->tol <= 1e-4))
      throw std::invalid_argument("verify: --tol " + FullPrecision(args->tol) +
                                  " must be in [1e-12, 1e-4]");
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
      for (const std::string& f : ExrFiles(p)) files.push_back(f);
    if (files.empty()) throw std::invalid_argument("verify: no .exr files found");
    // A line per table on stderr (terminal or not), the redrawn bar only on a terminal;
    // --quiet and --json (stdout is then one JSON object with the same numbers): neither.
    FILE* log = args->quiet || args->json ? nullptr : stderr;
    const bool bar = log && isatty(STDERR_FILENO);
    int failed = 0;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    if (!args->json)
      std::printf("%-40s %11s %11s %11s %11s  %s\n", "file", "max", "rms", "declared", "off-corner",
                  "where (max)");
    auto start = std::chrono::steady_clock::now();
    for (size_t fi = 0; fi < files.size(); ++fi) {
      const std::string& f = files[fi];
      // A file that does not load, or whose metadata cannot be evaluated (unreadable params,
      // unknown model or quantity, channels the quantity does not have), fails on its own line;
      // the other files are still checked.
      auto fail = [&](const std::string& why) {
        if (args->json)
          rows.push_back({{"file", f}, {"ok", false}, {"error", why}});
        else
          std::printf("%-40s FAILED: %s\n", f.c_str(), why.c_str());
        ++failed;
      };
      // Any format kiln writes (EXR, KTX2, DDS with its manifest.json, 16-bit PNG): the texels
      // as stored, so a float16 or unorm16 file is measured with its rounding.
      Table t;
      try {
        t = LoadAnyTable(f);
      } catch (const std::exception& e) {
        fail(e.what());
        continue;
      }
      TableSpec spec;
      try {
        spec = SpecFromTable(t);
      } catch (const std::exception& e) {
        fail(e.what());  // an unknown quantity, or unreadable params (SpecFromTable says which)
        continue;
      }
      // An axis over a model parameter must stay inside its range (the evaluators clamp, so the
      // search would compare the texels with the clamped model), unless the file says that it
      // clamps there itself (an engine-grid sheen table: sheen_roughness_min, engine_layout.h).
      std::string outside;
      if (const ModelInfo* m = FindModel(spec.model))
        for (const AxisSpec& a : spec.axes)
          for (const ParamInfo& q : m->params)
            if (q.name == a.name &&
                ((a.name == "roughness" ? SheenRoughnessFor(spec, a.lo) : a.lo) < q.lo ||
                 a.hi > q.hi) &&
                outside.empty())
              outside = "axis " + a.name + " [" + FullPrecision(a.lo) + ", " + FullPrecision(a.hi) +
                        "] is outside model '" + spec.model + "''s range [" + FullPrecision(q.lo) +
                        ", " + FullPrecision(q.hi) + "]";
      if (!outside.empty()) {
        fail(outside);
        continue;
      }
      std::string filter = args->filter.empty() ? t.lookupError.filter : args->filter;
      bool checked = filter == t.lookupError.filter;
      LookupErrorReport rep;
      if (bar) DrawBar(fi, files.size(), t.name);
      auto t0 = std::chrono::steady_clock::now();
      try {
        double lo[3] = {0, 0, 0};
        for (size_t d = 0; d < spec.axes.size() && d < 3; ++d) lo[d] = spec.axes[d].lo;
        IntegrationStats stats;
        size_t channels = EvaluateSpec(spec, lo, stats).size();

        if (channels != t.channels.size()) {
          if (bar) ClearBar();
          fail(std::to_string(t.channels.size()) + " channel(s), but quantity '" + t.quantity +
               "' has " + std::to_string(channels));
          continue;
        }
        LookupSearchOptions opt;
        opt.budget = args->budget;
        opt.maxCells = args->cells;
        opt.randomPoints = args->points;
        opt.refTol = args->tol;
        opt.threads = args->threads;
        opt.filter = filter == "cubic" ? Filter::Cubic : Filter::Linear;
        rep = MeasureLookupError(spec, t.view(), opt);
      } catch (const std::exception& e) {
        if (bar) ClearBar();
        fail(e.what());
        continue;
      }
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      // The reference itself is only good to its tolerance (--tol, or the table's own, plus the
      // bake error the texels declare): allow that much on top of the bound.
      double refTol = args->tol > 0 ? args->tol : spec.tol;
      // A verification-grade search reference adds its distance from the bake's method.
      bool ok =
          !checked || (t.lookupError.max >= 0 &&
                       rep.max <= t.lookupError.max + refTol + t.bakeError + rep.referenceError);
      // A fitted table (ltc) also re-measures its declared fit error (QuantityInfo::verifyTable).
      std::string fitSummary, fitProblem;
      if (auto check = Describe(spec.quantity).verifyTable)
        fitProblem = check(t, args->threads, fitSummary);
      if (!fitProblem.empty()) ok = false;
      if (bar) ClearBar();
      if (log && !fitSummary.empty())
        std::fprintf(log, "%-36s %s\n", t.name.c_str(), fitSummary.c_str());
      if (!fitProblem.empty()) std::fprintf(stderr, "%s: %s\n", f.c_str(), fitProblem.c_str());
      if (log) {
        std::fprintf(log, "%-36s max %.3e  declared %.3e  %6.2f s  %s\n", t.name.c_str(), rep.max,
                     t.lookupError.max, seconds,
                     !checked ? "(not checked)"
                     : ok     ? "ok"
                              : "EXCEEDS");
        std::fflush(log);
      }
      if (args->json)
        rows.push_back({{"file", f},
                        {"ok", ok},
                        {"name", t.name},
                        {"filter", filter},
                        {"checked", checked},
                        {"max", rep.max},
                        {"rms", rep.rms},
                        {"declared", t.lookupError.max},
                        {"off_corner", rep.maxOutsideCorner},
                        {"where", rep.WhereText(spec)},
                        {"points", rep.points},
                        {"cells", rep.cells},
                        {"climbed", rep.climbed},
                        {"budget", rep.budget},
                        {"seconds", seconds}});
      else
        std::printf("%-40s %11.3e %11.3e %11.3e %11.3e  %s%s\n", f.c_str(), rep.max, rep.rms,
                    t.lookupError.max, rep.maxOutsideCorner, rep.WhereText(spec).c_str(),
                    ok ? "" : "  EXCEEDS BOUND");
      std::fflush(stdout);
      if (!ok) ++failed;
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
