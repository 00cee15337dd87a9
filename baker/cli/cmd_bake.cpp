// kiln bake: the default catalogue (or a part of it) into self-describing EXR files.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "baker/bake/bake.h"
#include "baker/io/atomic_write.h"
#include "baker/io/engine_module_writer.h"
#include "baker/io/engine_png_writer.h"
#include "baker/io/texture_readers.h"
#include "baker/cli/commands.h"
#include "baker/scene/bake_scene.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/engine_layout.h"
#include "baker/tables/engine_presets.h"

namespace kiln::cli {
namespace {

/// Creates the folder `dir` with its missing parents; throws std::runtime_error naming the folder
/// and the reason when it cannot, or when `dir` exists and is not a folder. Then checks that its
/// manifest can be updated (CheckManifest), before any table is baked.
void PrepareOutputFolder(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    if (std::filesystem::exists(std::filesystem::symlink_status(dir, ec)))
      throw std::runtime_error("bake: --out '" + dir + "' exists and is not a folder");
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("bake: cannot create folder '" + dir + "': " + ec.message());
  }
  CheckManifest(dir);
}

/// Writes the preset's engine files of each baked table in `dir`, from the table file just
/// written in `format` (LoadAnyTable): its engine source file (EnginePreset::moduleExtension)
/// and its engine 8-bit PNG (PresetTable::pngChannels), all renamed into place together; logs
/// how many values a PNG clamped above 1. Nothing for a preset without either.
void WriteEngineModules(const EnginePreset& preset, const std::vector<TableSpec>& specs,
                        const std::string& dir, OutputFormat format, std::FILE* log) {
  std::vector<std::unique_ptr<PendingFile>> files;
  std::vector<std::string> notes;
  for (const TableSpec& spec : specs) {
    const PresetTable* t = PresetTableOf(preset, spec.name);
    const bool png = t && !t->pngChannels.empty();
    if (preset.moduleExtension.empty() && !png) continue;
    const OutputFormat written = t && t->exrOnly ? OutputFormat::Exr : format;
    // A table of more than 4 channels is written as parts; loading part 1 joins them.
    const Table table = LoadAnyTable(tablePartPath(dir + "/" + spec.name + FormatExtension(written),
                                                   1, tablePartCount(spec.channels.size())));
    if (!preset.moduleExtension.empty()) {
      files.push_back(
          std::make_unique<PendingFile>(dir + "/" + spec.name + preset.moduleExtension));
      files.back()->WriteBytes(EngineModuleText(table, preset.moduleExtension));
    }
    if (!png) continue;
    long long clipped = 0;
    files.push_back(std::make_unique<PendingFile>(dir + "/" + t->engineName + ".png"));
    files.back()->WriteBytes(EnginePng8(table, t->pngChannels, &clipped));
    if (clipped > 0)
      notes.push_back(t->engineName + ".png: " + std::to_string(clipped) +
                      " values above 1 stored as 1 (8-bit)");
  }
  std::vector<PendingFile*> commit;
  for (auto& f : files) commit.push_back(f.get());
  PendingFile::CommitAll(commit);
  if (!log) return;
  for (const PendingFile* f : commit) std::fprintf(log, "wrote   %s\n", f->Path().c_str());
  for (const std::string& n : notes) std::fprintf(log, "note    %s\n", n.c_str());
}

/// BakeSpecs of a preset's specs: the tables marked exrOnly (PresetTable) as EXR, the others in
/// run.format. The counts and times of the two runs added up.
BakeRunResult BakePresetSpecs(const EnginePreset& preset, const std::vector<TableSpec>& specs,
                              const std::string& dir, const BakeRunOptions& run) {
  std::vector<TableSpec> texture, exr;
  for (const TableSpec& spec : specs) {
    const PresetTable* t = PresetTableOf(preset, spec.name);
    (t && t->exrOnly && run.format != OutputFormat::Exr ? exr : texture).push_back(spec);
  }
  BakeRunResult done = BakeSpecs(texture, dir, run);
  if (exr.empty()) return done;
  BakeRunOptions exrRun = run;
  exrRun.format = OutputFormat::Exr;
  BakeRunResult more = BakeSpecs(exr, dir, exrRun);
  done.baked.insert(done.baked.end(), more.baked.begin(), more.baked.end());
  done.skipped.insert(done.skipped.end(), more.skipped.begin(), more.skipped.end());
  done.seconds += more.seconds;
  return done;
}

/// What `kiln bake --scene` does to each planned table: the preset's form
/// (ApplyPresetToPlanned) with --preset, else --layout/--grid/--flip-y
/// (ApplyEngineOptionsToPlanned), `size` (--size, 0: none) texels per engine axis.
SpecAdapter SceneAdapter(const EnginePreset* preset, const EngineOptions& engine, int size) {
  return [preset, engine, size](TableSpec& spec) {
    if (preset)
      ApplyPresetToPlanned(*preset, size, spec);
    else
      ApplyEngineOptionsToPlanned(spec, engine, size, size);
  };
}

/// The specs of a catalogue bake: the preset's tables (those named in `only`, when given), else
/// the `only` tables or the default catalogue with the engine options applied. Throws for an
/// unknown table or an option a table refuses.
std::vector<TableSpec> CatalogueSpecs(const EnginePreset* preset, const EngineOptions& engine,
                                      const CatalogueOptions& copt,
                                      const std::vector<std::string>& only) {
  if (preset) return PresetSpecs(*preset, copt.size, only);
  std::vector<TableSpec> specs;
  if (only.empty()) specs = DefaultCatalogue(copt);
  for (const std::string& name : only) specs.push_back(CatalogueTable(name, copt));
  for (TableSpec& spec : specs) ApplyEngineOptions(spec, engine);
  return specs;
}

}  // namespace

void RegisterBake(CLI::App& app) {
  auto* sub =
      app.add_subcommand("bake", "bake the default catalogue (or --only some tables) into DIR");
  struct Args {
    std::string out = "luts", only, scene;
    int size = 0, threads = 0;
    bool half = false, header = false, noLookup = false, force = false, quiet = false;
    double roughness = 0.5;
    std::string format = "exr", layout = "kiln", grid = "kiln";  // issue #14: engine output
    bool flipY = false;
    std::string preset;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("--out,-o", args->out, "output folder")->capture_default_str();
  auto* oOnly = sub->add_option("--only", args->only, "comma-separated table names (default: all)");
  auto* oSize =
      sub->add_option("--size", args->size, "nodes on every axis (default: each table's own)");
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->add_flag("--half", args->half, "store half floats instead of float32");
  sub->add_flag("--header", args->header, "also write a C++ header per table");
  sub->add_option("--roughness", args->roughness, "roughness of the *-brdf tables")
      ->capture_default_str();
  auto* oScene = sub->add_option(
      "--scene", args->scene, "bake only what this glTF/.glb or kiln scene needs (see kiln plan)");
  sub->add_flag("--no-lookup-error", args->noLookup,
                "skip measuring the lookup error (the file then declares none)");
  sub->add_flag("--force", args->force,
                "bake every table, also those whose file in DIR is up to date (same spec hash)");
  sub->add_flag("-q,--quiet", args->quiet,
                "print nothing but errors (no line per table on stderr, no progress bar)");
  auto* oFormat = sub->add_option("--format", args->format,
                                  "file format: exr, ktx2, dds, png16 (16-bit unorm, plain [0, 1] "
                                  "values) or png16-scaled (16-bit unorm, scale and offset per "
                                  "channel)")
                      ->capture_default_str();
  auto* oLayout = sub->add_option("--layout", args->layout,
                                  "dfg channel layout: kiln, ue4, filament or filament-cloth")
                      ->capture_default_str();
  auto* oGrid = sub->add_option("--grid", args->grid,
                                "kiln (the table's own axes) or engine (texel-centred, uniform in "
                                "(mu, roughness): sample with texture(lut, vec2(NoV, roughness)))")
                    ->capture_default_str();
  auto* oFlip = sub->add_flag("--flip-y", args->flipY,
                              "reverse the rows (row 0 = last roughness node); not with exr");
  auto* oPreset = sub->add_option(
      "--preset", args->preset,
      "an engine's tables in its layout, grid, size and format (docs/engines.md): filament, "
      "gltf-viewer, three, ue4 or bevy; --preset help lists them");
  sub->callback([args, oSize, oOnly, oScene, oFormat, oLayout, oGrid, oFlip, oPreset] {
    if (oPreset->count() && args->preset == "help") {
      std::fputs(EnginePresetHelp().c_str(), stdout);
      return;
    }
    const EnginePreset* preset = oPreset->count() ? &FindEnginePreset(args->preset) : nullptr;
    if (preset && (oLayout->count() || oGrid->count() || oFlip->count()))
      throw std::invalid_argument(
          "bake: --preset " + preset->name +
          " sets the layout, grid and orientation; give --format and --size only");
    // Engine output (#14): checked before anything is baked or written.
    const OutputFormat format =
        preset && !oFormat->count() ? preset->format : ParseOutputFormat(args->format);
    EngineOptions engine;
    engine.layout = ParseDfgLayout(args->layout);
    if (args->grid != "kiln" && args->grid != "engine")
      throw std::invalid_argument("unknown --grid '" + args->grid + "' (kiln or engine)");
    engine.engineGrid = args->grid == "engine";
    engine.flipY = args->flipY;
    if (engine.flipY && format == OutputFormat::Exr)
      throw std::invalid_argument(
          "bake: --flip-y applies to --format ktx2, dds or png16 (kiln's EXR loader reads row 0 "
          "as the first node)");
    // A preset whose engine texture is 16-bit float stores halves in every float format.
    const bool half = args->half || (preset && preset->half && !IsPng16(format));
    if (IsPng16(format) && args->half)
      throw std::invalid_argument("bake: --half does not apply to --format png16");
    if (oSize->count() && (args->size < 2 || args->size > 4096))
      throw std::invalid_argument("bake: --size " + std::to_string(args->size) +
                                  " must be in [2, 4096]");
    CheckThreads("bake", args->threads);
    if (!(args->roughness >= 0 && args->roughness <= 1))
      throw std::invalid_argument("bake: --roughness must be in [0, 1]");
    // Given but empty is an error, never "not given": --only '' would bake the whole catalogue.
    if (oOnly->count() && args->only.empty())
      throw std::invalid_argument("bake: --only '' names no table");
    if (oScene->count() && args->scene.empty())
      throw std::invalid_argument("bake: --scene '' names no file");
    // A line per table and a summary on stderr, terminal or not (build logs, CI); the redrawn
    // bar only on a terminal. --quiet: neither.
    BakeRunOptions run;
    run.bake.threads = args->threads;
    run.bake.progress = !args->quiet && isatty(STDERR_FILENO);
    run.bake.measureLookupError = !args->noLookup;
    run.half = half;
    run.header = args->header;
    run.force = args->force;
    run.log = args->quiet ? nullptr : stderr;
    run.format = format;
    if (oScene->count()) {
      if (oOnly->count()) throw std::invalid_argument("bake: give --scene or --only, not both");
      PrepareOutputFolder(args->out);
      PlanOptions popt;
      popt.size = args->size;
      int code =
          BakeScene(args->scene, args->out, run, popt, SceneAdapter(preset, engine, args->size));
      if (code != 0) std::exit(code);
      return;
    }
    CatalogueOptions copt;
    copt.size = args->size;
    copt.brdfRoughness = args->roughness;
    const std::vector<std::string> only =
        oOnly->count() ? UniqueNames(args->only) : std::vector<std::string>{};  // a,a bakes a once
    const std::vector<TableSpec> specs = CatalogueSpecs(preset, engine, copt, only);
    PrepareOutputFolder(args->out);
    BakeRunResult done;
    if (preset) {
      done = BakePresetSpecs(*preset, specs, args->out, run);
      WriteEngineModules(*preset, specs, args->out, format, run.log);
    } else {
      done = BakeSpecs(specs, args->out, run);
    }
    if (run.log)
      std::fprintf(run.log, "%zu baked, %zu skipped (up to date) in %.2f s -> %s\n",
                   done.baked.size(), done.skipped.size(), done.seconds, args->out.c_str());
  });
}

}  // namespace kiln::cli
