#include "baker/scene/bake_scene.h"

#include <chrono>
#include <exception>
#include <filesystem>

#include "baker/scene/plan_report.h"

namespace kiln {

SceneBakeResult BakePlan(const Plan& plan, const std::string& dir, const BakeOptions& opt,
                         bool half, bool header, std::FILE* log, bool force) {
  BakeRunOptions run;
  run.bake = opt;
  run.half = half;
  run.header = header;
  run.force = force;
  run.log = log;
  return BakePlan(plan, dir, run);
}

SceneBakeResult BakePlan(const Plan& plan, const std::string& dir, const BakeRunOptions& run,
                         const SpecAdapter& adapt) {
  std::vector<TableSpec> specs;
  for (const PlannedTable& t : plan.tables) {
    TableSpec spec = t.spec;
    if (adapt) adapt(spec);
    // Adapted tables of two materials may coincide (the engine grid spans every range): once.
    bool seen = false;
    for (const TableSpec& s : specs) seen = seen || s.name == spec.name;
    if (!seen) specs.push_back(spec);
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("bake: cannot create folder '" + dir + "': " + ec.message());
  CheckManifest(dir);  // refuse a corrupt manifest before baking anything
  std::FILE* log = run.log;
  BakeRunResult done = BakeSpecs(specs, dir, run);
  SceneBakeResult result;
  result.baked = done.baked;
  result.skipped = done.skipped;
  result.seconds = done.seconds;
  if (log)
    std::fprintf(log, "scene %s: %zu baked, %zu skipped (up to date) in %.2f s -> %s\n",
                 plan.scenePath.c_str(), result.baked.size(), result.skipped.size(), result.seconds,
                 dir.c_str());
  return result;
}

int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeRunOptions& run,
              const PlanOptions& planOpt, const SpecAdapter& adapt) {
  try {
    Plan plan = PlanSceneFile(scenePath, planOpt);
    for (const std::string& w : plan.warnings)
      std::fprintf(stderr, "kiln: warning: %s\n", w.c_str());
    BakePlan(plan, outDir, run, adapt);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kiln: error: %s\n", e.what());
    return 1;
  }
}

int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header, const PlanOptions& planOpt) {
  BakeRunOptions run;
  run.bake = opt;
  run.half = half;
  run.header = header;
  run.log = stderr;
  return BakeScene(scenePath, outDir, run, planOpt);
}

int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header) {
  return BakeScene(scenePath, outDir, opt, half, header, PlanOptions{});
}

}  // namespace kiln
