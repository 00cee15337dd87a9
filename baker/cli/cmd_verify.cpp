// kiln verify: re-measures each table's lookup error against direct evaluation.
#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "baker/bake/lookup_error.h"
#include "baker/cli/commands.h"
#include "kiln/exr_loader.h"

namespace kiln::cli {
namespace {

/// The most cell centres and the most random points verify takes per table.
constexpr long long kMaxVerifyPoints = 10000000;

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
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".exr") == 0) out.push_back(path + "/" + n);
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
      "re-measure each table's lookup error at every cell centre and random points; "
      "exit 1 when one exceeds its declared bound");
  struct Args {
    std::vector<std::string> paths;
    long long points = 100000, cells = 0;
    double tol = 1e-7;
    int threads = 0;
    std::string filter;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("paths", args->paths, "tables or folders of tables")->required();
  sub->add_option("--points", args->points, "random points per table, besides every cell centre")
      ->capture_default_str();
  sub->add_option("--cells", args->cells, "check at most this many cell centres, strided (0: all)")
      ->capture_default_str();
  sub->add_option("--tol", args->tol, "tolerance of the direct evaluation")->capture_default_str();
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->add_option("--filter", args->filter,
                  "measure with this filter instead of the declared one (then only reported, "
                  "not checked against the bound)")
      ->check(CLI::IsMember({"linear", "cubic"}));
  sub->add_flag("--json", args->json,
                "print the results as one JSON object on stdout (keys: README, Command line)");
  sub->callback([args] {
    // Caps on the work (each point is one integral, and 17 bytes of bookkeeping).
    if (args->cells < 0 || args->cells > kMaxVerifyPoints)
      throw std::invalid_argument("verify: --cells " + std::to_string(args->cells) +
                                  " must be in [0, 1e7]");
    if (args->points < 0 || args->points > kMaxVerifyPoints)
      throw std::invalid_argument("verify: --points " + std::to_string(args->points) +
                                  " must be in [0, 1e7]");
    if (!(args->tol >= 1e-12 && args->tol <= 1e-4))
      throw std::invalid_argument("verify: --tol " + FullPrecision(args->tol) +
                                  " must be in [1e-12, 1e-4]");
    CheckThreads("verify", args->threads);
    std::vector<std::string> files;
    for (const std::string& p : args->paths)
      for (const std::string& f : ExrFiles(p)) files.push_back(f);
    if (files.empty()) throw std::invalid_argument("verify: no .exr files found");
    int failed = 0;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    if (!args->json)
      std::printf("%-40s %11s %11s %11s %11s  %s\n", "file", "max", "rms", "declared", "off-corner",
                  "where (max)");
    for (const std::string& f : files) {
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
      Table t;
      std::string error;
      if (!loadTable(f, t, error)) {
        fail(error);
        continue;
      }
      TableSpec spec;
      try {
        spec = SpecFromTable(t);
      } catch (const std::exception& e) {
        fail(e.what());  // an unknown quantity, or unreadable params (SpecFromTable says which)
        continue;
      }
      std::string filter = args->filter.empty() ? t.lookupError.filter : args->filter;
      bool checked = filter == t.lookupError.filter;
      LookupErrorReport rep;
      try {
        double lo[3] = {0, 0, 0};
        for (size_t d = 0; d < spec.axes.size() && d < 3; ++d) lo[d] = spec.axes[d].lo;
        IntegrationStats stats;
        size_t channels = EvaluateSpec(spec, lo, args->tol, stats).size();
        if (channels != t.channels.size()) {
          fail(std::to_string(t.channels.size()) + " channel(s), but quantity '" + t.quantity +
               "' has " + std::to_string(channels));
          continue;
        }
        rep = MeasureLookupError(spec, t.view(), args->points, args->tol, args->threads,
                                 filter == "cubic" ? Filter::Cubic : Filter::Linear, args->cells);
      } catch (const std::exception& e) {
        fail(e.what());
        continue;
      }
      // The direct evaluation itself is only good to tol: allow that much on top of the bound.
      bool ok = !checked ||
                (t.lookupError.max >= 0 && rep.max <= t.lookupError.max + args->tol + t.bakeError);
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
                        {"points", rep.points}});
      else
        std::printf("%-40s %11.3e %11.3e %11.3e %11.3e  %s%s\n", f.c_str(), rep.max, rep.rms,
                    t.lookupError.max, rep.maxOutsideCorner, rep.WhereText(spec).c_str(),
                    ok ? "" : "  EXCEEDS BOUND");
      if (!ok) ++failed;
    }
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
