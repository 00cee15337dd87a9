// kiln bake --scene: bake only the tables a scene needs, skipping those already up to date.
#pragma once
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/scene/plan.h"

namespace kiln {

/// What a scene bake did.
struct SceneBakeResult {
  std::vector<std::string> baked, skipped;  ///< table names
  double seconds = 0;                       ///< wall time of the whole run
};

/// Changes a planned table's spec before it is baked: `kiln bake --scene` with --preset
/// (ApplyPresetToPlanned) or --layout/--grid/--flip-y (ApplyEngineOptionsToPlanned). Null: none.
using SpecAdapter = std::function<void(TableSpec&)>;

/// Bakes every table of `plan`, each changed by `adapt` when given, into `dir` (created when
/// missing) in run.format with BakeSpecs, as the overload below does with run's options; a
/// table whose adapted name an earlier one already has is baked once.
SceneBakeResult BakePlan(const Plan& plan, const std::string& dir, const BakeRunOptions& run,
                         const SpecAdapter& adapt = nullptr);

/// Bakes every table of `plan` into `dir` (created when missing) with BakeSpecs: a table whose
/// file is up to date (IsUpToDate: the stored spec hash is spec.Hash(), and its manifest entry
/// too) is left untouched (same bytes, same mtime; with `header`, a missing DIR/<name>.h is
/// written from the file) unless `force`. Adds the baked tables to DIR/manifest.json. Prints
/// one line per table and a summary to `log` (nullptr: silent). Throws what BakeTable and
/// CommitBakedTable throw.
SceneBakeResult BakePlan(const Plan& plan, const std::string& dir, const BakeOptions& opt,
                         bool half, bool header, std::FILE* log, bool force = false);

/// `kiln bake --scene SCENE --out DIR`: reads and plans the scene, bakes it (BakePlan; its
/// report goes to run.log, nullptr for --quiet). Returns the process exit code: 0, or 1 after
/// printing "kiln: error: ..." on stderr for a bad scene file or a failed bake. Warnings (e.g. an
/// unknown required extension) go to stderr and do not fail the run. `adapt` (when given)
/// changes each planned spec before the bake (an error it throws is reported the same way).
int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeRunOptions& run,
              const PlanOptions& planOpt, const SpecAdapter& adapt = nullptr);

/// Same, reporting on stderr, not forced, with plan options (the axis size override of tests).
int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header, const PlanOptions& planOpt);

/// Same, with the catalogue's sizes.
int BakeScene(const std::string& scenePath, const std::string& outDir, const BakeOptions& opt,
              bool half, bool header);

}  // namespace kiln
