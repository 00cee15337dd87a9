#include "baker/scene/bake_scene.h"

#include <unistd.h>

#include <chrono>
#include <exception>
#include <filesystem>

#include "baker/io/cpp_header_writer.h"
#include "baker/scene/plan_report.h"
#include "kiln/exr_loader.h"

namespace kiln {

SceneBakeResult BakePlan(const Plan& plan, const std::string& dir, const BakeOptions& opt,
                         bool half, bool header, std::FILE* log) {
  auto t0 = std::chrono::steady_clock::now();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("bake: cannot create folder '" + dir + "': " + ec.message());
  CheckManifest(dir);  // refuse a corrupt manifest before baking anything
  SceneBakeResult result;
  for (const PlannedTable& t : plan.tables) {
    const TableSpec& spec = t.spec;
    if (StateOf(spec, dir) == TableState::UpToDate) {
      result.skipped.push_back(spec.name);
      std::string h = dir + "/" + spec.name + ".h";
      bool wroteHeader = header && access(h.c_str(), F_OK) != 0;
      if (wroteHeader) writeCppHeader(h, loadTable(dir + "/" + spec.name + ".exr"));
      if (log)
        std::fprintf(log, "skipped %-36s up to date%s\n", spec.name.c_str(),
                     wroteHeader ? " (header written)" : "");
      continue;
    }
    BakeStats stats;
    Table table = BakeTable(spec, opt, &stats);
    // Table and manifest entry land together (CommitBakedTable), table by table.
    CommitBakedTable(dir, table, stats.evals, half, header, opt.threads);
    if (log) {
      std::fprintf(log, "baked   %-36s %8zu texels %8.2f s", spec.name.c_str(), spec.TexelCount(),
                   stats.seconds + stats.lookupSeconds);
      if (table.lookupError.max >= 0)
        std::fprintf(log, "  lookup error %.1e", table.lookupError.max);
      std::fprintf(log, "\n");
    }
    result.baked.push_back(spec.name);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (log)
    std::fprintf(log, "scene %s: %zu baked, %zu skipped (up to date) in %.2f s -> %s\n",
                 plan.scenePath.c_str(), result.baked.size(), result.skipped.size(), result.seconds,
                 dir.c_str());
  return result;
}

int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header, const PlanOptions& planOpt) {
  try {
    Plan plan = PlanSceneFile(scenePath, planOpt);
    for (const std::string& w : plan.warnings)
      std::fprintf(stderr, "kiln: warning: %s\n", w.c_str());
    BakePlan(plan, outDir, opt, half, header, stdout);
    std::fflush(stdout);
    return 0;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "kiln: error: %s\n", e.what());
    return 1;
  }
}

int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header) {
  return BakeScene(scenePath, outDir, opt, half, header, PlanOptions{});
}

}  // namespace kiln
