#include "baker/bake/bake.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "baker/bake/lookup_error.h"
#include "baker/io/atomic_write.h"
#include "baker/io/bounded_json.h"
#include "baker/io/texture_readers.h"
#include "baker/io/table_json.h"
#include "baker/io/cpp_header_writer.h"
#include "baker/io/exr_writer.h"
#include "baker/io/test_hooks.h"
#include "baker/io/texture_writers.h"
#include "baker/tables/engine_layout.h"
#include "baker/util/threads.h"
#include "kiln/exr_loader.h"

namespace kiln {
namespace {

constexpr const char* kGenerator = "kiln 0.1.0";

/// Redraws a one-line progress bar on stderr every 100 ms while the bake runs; Stop() (or the
/// destructor) wakes the drawing thread at once, joins it and clears the line.
class ProgressBar {
 public:
  ProgressBar(const std::string& label, size_t total, bool enabled)
      : label_(label), total_(total), enabled_(enabled) {
    if (!enabled_) return;
    Draw();  // at once: even a table baked in less than a redraw shows its bar
    thread_ = std::thread([this] { Run(); });
  }
  ~ProgressBar() { Stop(); }
  void Stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopped_) return;
      stopped_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    if (enabled_) {
      std::fprintf(stderr, "\r%*s\r", Width(), "");  // the per-table line takes its place
      std::fflush(stderr);
    }
  }
  std::atomic<size_t> done{0};

 private:
  static constexpr int kBar = 30;
  int Width() const { return 32 + 3 + kBar + 2 + 2 * 20 + 1; }
  void Run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stopped_; }))
      Draw();
  }
  void Draw() {
    size_t d = done.load();
    int filled = total_ ? static_cast<int>(kBar * d / total_) : kBar;
    std::fprintf(stderr, "\r%-32s [%s%s] %zu/%zu", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(kBar - filled, '.').c_str(), d, total_);
    std::fflush(stderr);
  }
  std::string label_;
  size_t total_;
  bool enabled_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopped_ = false;
  std::thread thread_;
};

}  // namespace

namespace {

/// The spec `spec` derives its texels from (QuantityInfo::derivedFrom), or false.
bool DerivationSource(const TableSpec& spec, TableSpec& source) {
  const QuantityInfo& q = Describe(spec.quantity);
  return q.derivedFrom && q.derive && q.derivedFrom(spec, source);
}

/// The search reuse of a table derived from one whose search evaluated `memo`
/// (QuantityInfo::searchDerivesFromSource): at a point off the smooth limit (where the two kinds'
/// limits differ) that the source's search evaluated, `derive` of the source's reference and its
/// stats. `spec` and `memo` must outlive the search.
SearchReuse ReuseFromSource(const TableSpec& spec, const SearchMemo& memo) {
  const QuantityInfo& q = Describe(spec.quantity);
  return [&spec, &memo, &q](const double* x, std::vector<double>& exact, IntegrationStats& st) {
    std::vector<double> smooth;
    if (q.smoothLimit && q.smoothLimit(spec, x, smooth)) return false;
    const SearchMemo::Entry* e = memo.Find(x);
    if (!e) return false;
    exact.assign(spec.channels.size(), 0.0);
    q.derive(spec, e->values.data(), exact.data());
    st.evals = e->evals;
    st.errorEstimate = e->errorEstimate;
    return true;
  };
}

}  // namespace

NodeValueCache::NodeValueCache(const std::vector<TableSpec>& specs) {
  for (const TableSpec& spec : specs) {
    TableSpec source;
    if (!DerivationSource(spec, source)) continue;
    NodeValues& kept = kept_[source.Hash()];
    const QuantityInfo& q = Describe(spec.quantity);
    if (q.searchDerivesFromSource && q.searchDerivesFromSource(spec)) kept.keepSearchMemo = true;
  }
}

NodeValues* NodeValueCache::KeepFor(const TableSpec& spec) {
  auto it = kept_.find(spec.Hash());
  return it == kept_.end() ? nullptr : &it->second;
}

const NodeValues* NodeValueCache::SourceFor(const TableSpec& spec) const {
  TableSpec source;
  if (!DerivationSource(spec, source)) return nullptr;
  auto it = kept_.find(source.Hash());
  return it == kept_.end() || it->second.values.empty() ? nullptr : &it->second;
}

Table BakeTable(const TableSpec& spec, const BakeOptions& opt, BakeStats* stats,
                const NodeValues* from, NodeValues* keep) {
  if (spec.axes.empty() || spec.axes.size() > 3)
    throw std::invalid_argument("table '" + spec.name + "': needs 1 to 3 axes");
  for (const AxisSpec& a : spec.axes) {
    std::string problem = axisProblem(a.ToAxis());
    if (!problem.empty())
      throw std::invalid_argument("table '" + spec.name + "': axis " + a.name + ": " + problem);
    if (a.size > 65536)
      throw std::invalid_argument("table '" + spec.name + "': axis " + a.name + " size " +
                                  std::to_string(a.size) + " is absurd (at most 65536)");
  }
  if (spec.TexelCount() > (size_t(1) << 26))
    throw std::invalid_argument("table '" + spec.name + "': " + std::to_string(spec.TexelCount()) +
                                " texels is too many (at most 2^26)");
  Table t = TableShell(spec, kGenerator, spec.Method());
  t.tolerance = spec.tol;
  t.specHash = spec.Hash();
  size_t n = spec.TexelCount(), nc = spec.channels.size();
  std::vector<long long> evals(n, 0);
  std::vector<double> errors(n, 0);
  if (from && (from->values.size() != n * from->channels || from->errors.size() != n))
    throw std::logic_error("table '" + spec.name + "': the node values of '" + from->name +
                           "' do not match its nodes");
  if (keep) {
    keep->name = spec.name;
    keep->specHash = t.specHash;
    keep->channels = nc;
    keep->values.assign(n * nc, 0.0);
  }
  std::chrono::steady_clock::time_point t0, t1;
  {
    ProgressBar bar(spec.name, n, opt.progress);
    t0 = std::chrono::steady_clock::now();             // after the bar's thread started
    const size_t pauseAfter = TestPauseAfterTexels();  // 0 unless a test set it
    const int threads = ThreadCount(opt.threads);
    tbb::task_arena arena(threads);
    arena.execute([&] {
      // A fit (ltc) fills the whole table at once, in its own fixed order
      // (QuantityInfo::bakeTable).
      if (auto bakeAll = Describe(spec.quantity).bakeTable) {
        bakeAll(spec, threads, t, evals, errors);
        if (keep) keep->values.clear();  // a fit keeps no node values to derive from
        bar.done = n;
        return;
      }
      // Derived texels (QuantityInfo::derive): no integration, the source's error estimates.
      if (from) {
        const auto derive = Describe(spec.quantity).derive;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256),
                          [&](const tbb::blocked_range<size_t>& r) {
                            std::vector<double> v(nc);
                            for (size_t i = r.begin(); i != r.end(); ++i) {
                              derive(spec, &from->values[i * from->channels], v.data());
                              for (size_t c = 0; c < nc; ++c)
                                t.data[i * nc + c] = static_cast<float>(v[c]);
                              errors[i] = from->errors[i];
                            }
                          });
        bar.done = n;
        return;
      }
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i != r.end(); ++i) {
                            double x[3];
                            NodeEvaluationPoint(spec, i, x);
                            IntegrationStats st;
                            std::vector<double> v = EvaluateSpec(spec, x, st);
                            for (size_t c = 0; c < nc; ++c)
                              t.data[i * nc + c] = static_cast<float>(v[c]);
                            if (keep) std::copy(v.begin(), v.end(), keep->values.begin() + i * nc);
                            evals[i] = st.evals;
                            errors[i] = st.errorEstimate;
                            if (++bar.done == pauseAfter)
                              TestPause(std::to_string(pauseAfter) + " of " + std::to_string(n) +
                                        " texels of " + spec.name);
                          }
                        });
    });
    t1 = std::chrono::steady_clock::now();  // the texels only: not the bar's thread
    bar.Stop();
  }
  // Bake error, relative to max(1, |value|): ten times the integrator's own estimate (QUADPACK's
  // estimate of the nested rule can be low by a few times; tests/bake_tables.cpp checks the
  // bound by re-integrating texels), never below the tolerance, plus float32 rounding (2^-24).
  if (keep) keep->errors = errors;
  double estimate = 0;
  for (size_t i = 0; i < n; ++i) estimate = std::max(estimate, errors[i]);
  // A fixed-rule table declares its rule's bound, which each texel reports as its estimate
  // (spec.h, kFixedRuleBound for GGX; fixed_rule_diffuse.h, kDiffuseRuleBound; ...).
  bool integrated = spec.Method().rfind("closed form", 0) != 0;
  if (UsesFixedRule(spec))
    t.bakeError = estimate + 0x1p-24;
  else
    t.bakeError = (integrated ? 10 * std::max(estimate, spec.tol) : 0.0) + 0x1p-24;
  long long lookupPoints = 0, lookupReused = 0;
  if (opt.measureLookupError) {
    // A derived table with its source's texels and search reference: the source's report
    // (QuantityInfo::sharesSourceLookupError), else its own search, which reads its source's
    // search references where it may (QuantityInfo::searchDerivesFromSource).
    const QuantityInfo& q = Describe(spec.quantity);
    if (from && from->hasLookupError && q.sharesSourceLookupError &&
        q.sharesSourceLookupError(spec)) {
      t.lookupError = from->lookupError;
    } else {
      SearchReuse reuse;
      if (from && from->searchMemo && q.searchDerivesFromSource && q.searchDerivesFromSource(spec))
        reuse = ReuseFromSource(spec, *from->searchMemo);
      std::shared_ptr<SearchMemo> record;
      if (keep && keep->keepSearchMemo) record = std::make_shared<SearchMemo>();
      lookupPoints = MeasureLookupError(spec, t, opt.lookupBudget, opt.threads, reuse, record.get(),
                                        &lookupReused);
      if (keep) keep->searchMemo = record;
    }
    if (keep) {
      keep->hasLookupError = true;
      keep->lookupError = t.lookupError;
    }
  }
  auto t2 = std::chrono::steady_clock::now();
  if (stats) {
    stats->evals = 0;
    for (long long e : evals) stats->evals += e;
    stats->derivedFrom = from ? from->name : "";
    stats->seconds = std::chrono::duration<double>(t1 - t0).count();
    stats->lookupSeconds = std::chrono::duration<double>(t2 - t1).count();
    stats->lookupPoints = lookupPoints;
    stats->lookupReused = lookupReused;
  }
  return t;
}

long long MeasureLookupError(const TableSpec& spec, Table& table, long long budget, int threads,
                             const SearchReuse& reuse, SearchMemo* record, long long* reused) {
  // The search kiln verify repeats (lookup_error.h), against the bake's own method.
  LookupSearchOptions opt;
  opt.budget = budget;
  opt.threads = threads;
  opt.alsoCubic = true;
  opt.reuse = reuse;
  opt.record = record;
  LookupErrorReport rep = MeasureLookupError(spec, table.view(), opt);
  if (reused) *reused = rep.reused;
  // A bound made mostly of the search reference's distance from the bake's rule says little of
  // the table (a smooth average's 3e-8 declared as 3e-6): search again with the bake's rule.
  if (rep.referenceError > rep.max) {
    opt.bakeRule = true;
    rep = MeasureLookupError(spec, table.view(), opt);
  }
  table.lookupError.max = (rep.max + rep.referenceError) * kDeclaredBoundMargin;
  table.lookupError.rms = rep.rms;
  table.lookupError.filter = "linear";
  table.lookupError.cubicMax = rep.cubicMax;
  table.lookupError.cubicRms = rep.cubicRms;
  // The bound's formula: "max", or "(max + D)" with D the search reference's distance from the
  // bake's method (a verification-grade rule, QuantityInfo::searchRule).
  char term[96] = "max";
  if (rep.referenceError > 0)
    std::snprintf(term, sizeof term, "(max + %.2g, its reference's distance from the bake rule)",
                  rep.referenceError);
  char buf[384];
  std::snprintf(buf, sizeof buf,
                "max %.3g at %s, %.3g outside the first cell of axis 1; bound = %.2g x %s of a "
                "search of %lld of %lld cells (%lld climbed), %lld points",
                rep.max, rep.WhereText(spec).c_str(), rep.maxOutsideCorner, kDeclaredBoundMargin,
                term, rep.cells, rep.allCells, rep.climbed, rep.points);
  table.lookupError.where = buf;
  return rep.points;
}

void WriteBakedTable(const std::string& dir, const Table& table, bool half, bool header,
                     int threads) {
  threads = ThreadCount(threads);
  writeTable(dir + "/" + table.name + ".exr", table, half, threads);
  if (header) writeCppHeader(dir + "/" + table.name + ".h", table);
}

std::string StoredSpecHash(const std::string& exrPath) {
  Table t;
  std::string error;
  if (access(exrPath.c_str(), R_OK) != 0) return "";
  return loadTable(exrPath, t, error) ? t.specHash : "";
}

namespace {

using nlohmann::ordered_json;

/// A manifest entry's key: (name, file). One entry per file, so a table baked in two formats into
/// one folder has two entries; sorted by name first, as the manifest lists them.
using EntryKey = std::pair<std::string, std::string>;

/// The key of a manifest entry; an entry without "file" (older kiln) describes NAME.exr.
EntryKey KeyOf(const ordered_json& e) {
  std::string name = e["name"].get<std::string>();
  std::string file =
      e.contains("file") && e["file"].is_string() ? e["file"].get<std::string>() : name + ".exr";
  return {name, file};
}

/// The entries of a manifest by (name, file), pointing into the parsed document they keep alive.
struct ManifestEntryMap {
  std::shared_ptr<const ordered_json> doc;  ///< null when there is no manifest
  std::map<EntryKey, const ordered_json*> entries;
};

/// The entries of the manifest `doc` (at `path`) by (name, file); throws as CheckManifest.
std::shared_ptr<const ManifestEntryMap> IndexManifest(const std::string& path,
                                                      std::shared_ptr<const ordered_json> doc) {
  auto map = std::make_shared<ManifestEntryMap>();
  map->doc = std::move(doc);
  const ordered_json& old = *map->doc;
  auto notOurs = [&](const std::string& why) {
    return std::runtime_error(path + " is not a kiln manifest (" + why +
                              "); move it aside or delete it");
  };
  if (!old.is_object() || !old.contains("tables") || !old["tables"].is_array())
    throw notOurs("no \"tables\" array");
  for (const ordered_json& e : old["tables"]) {
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string())
      throw notOurs("an entry without a \"name\"");
    map->entries[KeyOf(e)] = &e;
  }
  return map;
}

/// The entries of DIR/manifest.json ({} when it is missing), parsed (ReadJsonFileCached) and
/// indexed once per version of the file; throws as CheckManifest.
std::shared_ptr<const ManifestEntryMap> ManifestEntries(const std::string& dir) {
  static std::mutex mutex;
  static std::shared_ptr<const ManifestEntryMap> last;  // the index of the last document read
  const std::string path = dir + "/manifest.json";
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return std::make_shared<ManifestEntryMap>();
    throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  }
  CheckWritableTarget(path);  // a link, FIFO or device is refused before it is read
  std::shared_ptr<const ordered_json> doc;
  try {
    doc = ReadJsonFileCached(path);
  } catch (const JsonTextError& e) {
    throw std::runtime_error(path + " is " + e.what() + "; move it aside or delete it");
  }
  std::lock_guard<std::mutex> lock(mutex);
  if (!last || last->doc != doc) last = IndexManifest(path, std::move(doc));
  return last;
}

/// DIR/manifest.json with the entries of `tables` added or replaced.
ordered_json ManifestDocument(const std::string& dir, const std::vector<Table>& tables,
                              const std::vector<long long>& evals, OutputFormat format, bool half,
                              const std::string& texelsFrom) {
  const std::shared_ptr<const ManifestEntryMap> old = ManifestEntries(dir);
  std::map<EntryKey, ordered_json> added;
  for (size_t i = 0; i < tables.size(); ++i) {
    const Table& t = tables[i];
    ordered_json e;
    e["name"] = t.name;
    const std::string file = t.name + FormatExtension(format);
    const int parts = tablePartCount(t.channels.size());
    e["file"] = tablePartPath(file, 1, parts);
    if (parts > 1) {
      ordered_json files = ordered_json::array();
      for (int p = 1; p <= parts; ++p) files.push_back(tablePartPath(file, p, parts));
      e["files"] = files;
    }
    e["layout"] = kLayoutVersion;
    if (format != OutputFormat::Exr) {
      e["format"] = FormatName(format);
      e["pixel_type"] = IsPng16(format) ? "unorm16" : half ? "float16" : "float32";
      if (IsPng16(format)) {
        ordered_json scale = ordered_json::array(), offset = ordered_json::array();
        for (const Png16Channel& c : Png16Quantisation(t, format == OutputFormat::Png16Scaled)) {
          scale.push_back(c.scale);
          offset.push_back(c.offset);
        }
        e["png16"] = {{"scale", scale},
                      {"offset", offset},
                      {"encoding", format == OutputFormat::Png16Scaled ? "scaled" : "unit"},
                      {"decode", "value = stored / 65535 * scale + offset"}};
      }
    }
    AppendTableDescription(e, t);
    if (t.lookupError.cubicMax >= 0)
      e["lookup_error_cubic"] = {{"max", t.lookupError.cubicMax}, {"rms", t.lookupError.cubicRms}};
    e["integrand_evaluations"] = i < evals.size() ? evals[i] : 0;
    if (!texelsFrom.empty()) e["texels_from"] = texelsFrom;  // derived: its evaluations are there
    e["bytes_float32"] = t.data.size() * 4;
    e["spec_hash"] = t.specHash;
    const EntryKey key = KeyOf(e);
    added[key] = std::move(e);
  }
  std::map<EntryKey, const ordered_json*> entries = old->entries;
  const std::string ext = FormatExtension(format);
  for (const auto& [key, e] : added) {
    // The table's entry of another file name in this format (a layout-1 NAME.exr of a table now
    // in parts, or the reverse) describes a file this bake does not write: dropped.
    for (auto it = entries.begin(); it != entries.end();) {
      const std::string& other = it->first.second;
      const bool sameFormat = other.size() >= ext.size() &&
                              other.compare(other.size() - ext.size(), ext.size(), ext) == 0;
      if (it->first.first == key.first && sameFormat && it->first != key)
        it = entries.erase(it);
      else
        ++it;
    }
    entries[key] = &e;
  }
  ordered_json doc;
  doc["generator"] = kGenerator;
  doc["format"] = kFormatVersion;
  doc["tables"] = ordered_json::array();
  for (const auto& [key, e] : entries) doc["tables"].push_back(*e);
  return doc;
}

}  // namespace

void CheckManifest(const std::string& dir) { ManifestEntries(dir); }

void CommitBakedTable(const std::string& dir, const Table& table, long long evals, bool half,
                      bool header, int threads, OutputFormat format,
                      const std::string& texelsFrom) {
  threads = ThreadCount(threads);
  if (format == OutputFormat::Exr && FlipsY(table))
    throw std::runtime_error("kiln: cannot write '" + dir + "/" + table.name +
                             ".exr': --flip-y applies to ktx2, dds and png16 (kiln's EXR loader "
                             "reads row 0 as the first node)");
  // The long part (compressing, writing) outside the lock; then the short critical section.
  // A table of more than 4 channels is one file per part (tablePart, tablePartPath).
  const int parts = tablePartCount(table.channels.size());
  std::vector<std::unique_ptr<PendingFile>> tableFiles;
  for (int p = 1; p <= parts; ++p) {
    tableFiles.push_back(std::make_unique<PendingFile>(
        tablePartPath(dir + "/" + table.name + FormatExtension(format), p, parts)));
    const Table part = parts > 1 ? tablePart(table, p) : Table();
    const Table& written = parts > 1 ? part : table;
    if (format == OutputFormat::Exr)
      writeTable(*tableFiles.back(), written, half, threads);
    else
      WriteTextureTable(*tableFiles.back(), written, format, half);
  }
  std::unique_ptr<PendingFile> h;
  if (header) {
    h = std::make_unique<PendingFile>(dir + "/" + table.name + ".h");
    writeCppHeader(*h, table);
  }
  FolderLock lock(dir);
  RemoveStaleTemporaries(dir);
  PendingFile manifest(dir + "/manifest.json");
  auto doc = std::make_shared<const ordered_json>(
      ManifestDocument(dir, {table}, {evals}, format, half, texelsFrom));
  const std::string text = doc->dump(2) + "\n";
  manifest.WriteBytes(text);
  std::vector<PendingFile*> files;
  for (auto& f : tableFiles) files.push_back(f.get());
  if (h) files.push_back(h.get());
  files.push_back(&manifest);
  PendingFile::CommitAll(files);
  RememberJsonFile(manifest.Path(), text, std::move(doc));  // under the lock: what was written
}

namespace {

/// Whether every channel of the EXR file at `path` (a loadable kiln table) is HALF.
bool StoredAsHalf(const std::string& path) {
  Imf::InputFile in(path.c_str(), 1);
  const Imf::ChannelList& channels = in.header().channels();
  for (auto it = channels.begin(); it != channels.end(); ++it)
    if (it.channel().type != Imf::HALF) return false;
  return channels.begin() != channels.end();
}

/// The kiln.layout of the EXR file at `path` (1 when absent: files written before it).
int StoredLayout(const std::string& path) {
  Imf::InputFile in(path.c_str(), 1);
  const auto* layout = in.header().findTypedAttribute<Imf::IntAttribute>("kiln.layout");
  return layout != nullptr ? layout->value() : 1;
}

}  // namespace

bool IsUpToDate(const TableSpec& spec, const std::string& dir, bool half, bool lookupError,
                OutputFormat format) {
  const std::string base = spec.name + FormatExtension(format);
  const int parts = tablePartCount(spec.channels.size());
  const std::string file = tablePartPath(base, 1, parts), path = dir + "/" + file;
  const std::string hash = spec.Hash();
  for (int p = 1; p <= parts; ++p)
    if (access((dir + "/" + tablePartPath(base, p, parts)).c_str(), R_OK) != 0) return false;
  const std::shared_ptr<const ManifestEntryMap> manifest = ManifestEntries(dir);
  auto it = manifest->entries.find({spec.name, file});
  if (it == manifest->entries.end()) return false;
  const ordered_json& entry = *it->second;
  if (!entry.contains("spec_hash") || entry["spec_hash"] != hash) return false;
  // A file of another layout (kLayoutVersion: the EXR channel names, the parts) is rewritten.
  if (entry.value("layout", 1) != kLayoutVersion) return false;
  Table stored;
  try {
    if (format == OutputFormat::Exr && StoredLayout(path) != kLayoutVersion) return false;
    stored = LoadAnyTable(path);
    if (format == OutputFormat::Exr) {
      if (StoredAsHalf(path) != half) return false;
    } else {
      // The manifest says how the texels are stored ("float16", "float32", "unorm16").
      std::string pixel = entry.value("pixel_type", "");
      if (pixel != (IsPng16(format) ? "unorm16" : half ? "float16" : "float32")) return false;
      // png16 and png16-scaled share the file name: the manifest says which one it is.
      if (entry.value("format", "") != FormatName(format)) return false;
    }
  } catch (const std::exception&) {
    return false;
  }
  return stored.specHash == hash && !(lookupError && stored.lookupError.max < 0);
}

BakeRunResult BakeSpecs(const std::vector<TableSpec>& specs, const std::string& dir,
                        const BakeRunOptions& opt) {
  auto t0 = std::chrono::steady_clock::now();
  BakeRunResult result;
  {
    // The temporary files of a killed bake go on every bake, also one with nothing to bake
    // (CommitBakedTable sweeps again under the lock each time it commits).
    FolderLock lock(dir);
    RemoveStaleTemporaries(dir);
  }
  NodeValueCache nodeValues(specs);
  for (const TableSpec& spec : specs) {
    if (!opt.force && IsUpToDate(spec, dir, opt.half, opt.bake.measureLookupError, opt.format)) {
      result.skipped.push_back(spec.name);
      std::string h = dir + "/" + spec.name + ".h";
      bool wroteHeader = opt.header && access(h.c_str(), F_OK) != 0;
      if (wroteHeader)
        writeCppHeader(h, LoadAnyTable(dir + "/" + spec.name + FormatExtension(opt.format)));
      if (opt.log) {
        std::fprintf(opt.log, "skipped %-36s up to date%s\n", spec.name.c_str(),
                     wroteHeader ? " (header written)" : "");
        std::fflush(opt.log);
      }
      continue;
    }
    BakeStats stats;
    Table table =
        BakeTable(spec, opt.bake, &stats, nodeValues.SourceFor(spec), nodeValues.KeepFor(spec));
    // Table and manifest entry land together, table by table: a bake killed after table k
    // leaves a manifest that describes tables 1..k (and the older files) correctly.
    CommitBakedTable(dir, table, stats.evals, opt.half, opt.header, opt.bake.threads, opt.format,
                     stats.derivedFrom);
    if (opt.log) {
      std::fprintf(opt.log, "baked   %-36s %8zu texels %8.2f s  bake error %.1e", spec.name.c_str(),
                   spec.TexelCount(), stats.seconds, table.bakeError);
      if (table.lookupError.max >= 0)
        std::fprintf(opt.log, "  lookup error %.1e (checked in %.2f s)", table.lookupError.max,
                     stats.lookupSeconds);
      if (!stats.derivedFrom.empty())
        std::fprintf(opt.log, "  texels from %s", stats.derivedFrom.c_str());
      std::fprintf(opt.log, "\n");
      std::fflush(opt.log);
    }
    result.baked.push_back(spec.name);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace kiln
