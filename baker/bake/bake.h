// The bake: evaluate a table spec at every node with oneTBB, measure its errors, write it.
#pragma once
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "baker/bake/lookup_error.h"
#include "baker/io/texture_writers.h"
#include "baker/tables/spec.h"
#include "kiln/table.h"

namespace kiln {

struct BakeOptions {
  int threads = 0;                 ///< 0: all cores
  bool progress = false;           ///< redraw a progress bar on stderr (meant for a terminal)
  bool measureLookupError = true;  ///< search the lookup error (lookup_error.h) and declare it
  long long lookupBudget = 0;      ///< reference evaluations of that search (0: its default)
};

struct BakeStats {
  long long evals = 0;         ///< integrand evaluations of the texels (0 for derived texels)
  std::string derivedFrom;     ///< the table whose node values gave the texels, or
  double seconds = 0;          ///< wall time of the texels only (no lookup check, no progress bar)
  double lookupSeconds = 0;    ///< wall time of the lookup-error check
  long long lookupPoints = 0;  ///< its reference evaluations (0: none, or its source's report)
  long long lookupReused = 0;  ///< of those, read from its source's search (SearchMemo)
};

/// The node values of one baked table in double (before the float32 store) with each node's
/// error estimate: what a table derived from it needs (QuantityInfo::derivedFrom).
struct NodeValues {
  std::string name, specHash;
  size_t channels = 0;
  std::vector<double> values;  ///< texel after texel, `channels` values each
  std::vector<double> errors;  ///< per texel
  /// The table's lookup-error report, when the bake measured it (hasLookupError): a table
  /// derived from this one with the same texels and the same search reference takes it
  /// (QuantityInfo::sharesSourceLookupError) instead of repeating the search.
  bool hasLookupError = false;
  LookupError lookupError;
  /// The references its lookup-error search evaluated, by point, when a table derived from it
  /// reads them (QuantityInfo::searchDerivesFromSource); null otherwise.
  std::shared_ptr<SearchMemo> searchMemo;
  bool keepSearchMemo = false;  ///< a table derived from it reads searchMemo (NodeValueCache)
};

/// The node values a run of bakes keeps for the tables derived from them: built from the run's
/// specs, it keeps exactly the tables some later spec derives from.
class NodeValueCache {
 public:
  explicit NodeValueCache(const std::vector<TableSpec>& specs);
  /// Where BakeTable should keep `spec`'s node values (null: no later spec needs them).
  NodeValues* KeepFor(const TableSpec& spec);
  /// The kept node values `spec` derives from (null: none kept, bake it by its own rule).
  const NodeValues* SourceFor(const TableSpec& spec) const;

 private:
  std::map<std::string, NodeValues> kept_;  ///< by spec hash: the needed ones, filled or not
};

/// Bakes `spec` into a table (metadata and texels). Bit-identical for any thread count. With
/// `from` (the node values of the table spec derives from, NodeValueCache::SourceFor) the texels
/// come from them by QuantityInfo::derive, the same float32 texels as its own rule; with `keep`
/// the double node values are kept there.
Table BakeTable(const TableSpec& spec, const BakeOptions& opt, BakeStats* stats = nullptr,
                const NodeValues* from = nullptr, NodeValues* keep = nullptr);

/// Searches a table's lookup error (linear filter) against EvaluateSpec (lookup_error.h, at
/// most `budget` reference evaluations, 0: the search's default) and fills table.lookupError
/// with the declared bound (kDeclaredBoundMargin x the max found), the rms over the probe
/// points and the cubic filter's max and rms at the same points. Returns the search's reference
/// evaluations (LookupErrorReport::points).
/// `reuse` and `record` as LookupSearchOptions' (lookup_error.h); `reused` (optional) gets the
/// points reuse supplied.
long long MeasureLookupError(const TableSpec& spec, Table& table, long long budget, int threads,
                             const SearchReuse& reuse = {}, SearchMemo* record = nullptr,
                             long long* reused = nullptr);

/// Writes `table` as DIR/<name>.exr (and DIR/<name>.h with header), atomically; the EXR's
/// blocks are compressed on `threads` threads (0: all cores; same bytes for any count).
void WriteBakedTable(const std::string& dir, const Table& table, bool half, bool header,
                     int threads = 1);

/// The spec hash stored in DIR/<name>.exr, or "" when the file is missing or not a kiln table.
std::string StoredSpecHash(const std::string& exrPath);

/// Throws std::runtime_error when DIR/manifest.json exists and cannot be updated: not a regular
/// file, not valid JSON ("DIR/manifest.json is not valid JSON (<reason>); move it aside or
/// delete it"), or not a kiln manifest (not an object with a "tables" array of entries with a
/// "name"). A missing manifest passes. Never changes the file.
void CheckManifest(const std::string& dir);

/// Writes `table` as DIR/<name>.exr (DIR/<name><FormatExtension(format)> for another `format`,
/// texture_writers.h; and DIR/<name>.h with `header`) to temporary files of their own, then,
/// holding DIR's FolderLock: removes the temporary files of dead processes
/// (RemoveStaleTemporaries), adds the table's entry (with `evals`) to DIR/manifest.json, and
/// renames table, header and manifest into place together (PendingFile::CommitAll). A bake that
/// commits each table so, when killed, leaves a manifest that describes the files in DIR, and
/// two bakes into one DIR leave the files and the entries of whichever committed last. Throws
/// std::runtime_error (one line); DIR's files are then unchanged. The manifest entry of an EXR
/// is as before #14; another format adds "format" (its --format name) and "pixel_type"
/// ("float32", "float16" or "unorm16"), and png16 the per-channel "png16" scale and offset. A
/// table whose texels were derived from another's (`texelsFrom`, BakeStats::derivedFrom) has
/// "texels_from" (that table's name) after its "integrand_evaluations" (then 0).
/// EXR rows cannot be flipped (kiln's loader reads row 0 as the first node): a table with
/// flip_y (tables/engine_layout.h ApplyFlipY) is refused in EXR.
void CommitBakedTable(const std::string& dir, const Table& table, long long evals, bool half,
                      bool header, int threads = 1, OutputFormat format = OutputFormat::Exr,
                      const std::string& texelsFrom = "");

/// Whether DIR/<spec.name><extension of format> already is what a bake of `spec` would write, so
/// that the bake can leave it alone: the file (read by LoadAnyTable, any format) stores the spec
/// hash spec.Hash(), its pixels are half exactly when `half` (EXR: the channel type; KTX2/DDS:
/// the manifest's pixel_type; PNG16 never), it declares a lookup error when `lookupError` (a
/// bake with --no-lookup-error writes none), and DIR/manifest.json has an entry for that file
/// with the same spec hash (a skipped table keeps its manifest entry; without one the table is
/// baked again so the entry is whole). Throws as CheckManifest for a manifest that is not one.
bool IsUpToDate(const TableSpec& spec, const std::string& dir, bool half, bool lookupError,
                OutputFormat format = OutputFormat::Exr);

/// How BakeSpecs bakes.
struct BakeRunOptions {
  BakeOptions bake;     ///< threads, progress bar, lookup-error measurement
  bool half = false;    ///< store half floats
  bool header = false;  ///< also write DIR/<name>.h
  bool force = false;   ///< bake every table, even when up to date
  /// The file format (every format is checked for being up to date, IsUpToDate).
  OutputFormat format = OutputFormat::Exr;
  std::FILE* log = nullptr;  ///< one line per table (nullptr: silent)
};

/// What BakeSpecs did.
struct BakeRunResult {
  std::vector<std::string> baked, skipped;  ///< table names, in order
  double seconds = 0;                       ///< wall time of the whole run
};

/// Bakes each of `specs` into `dir` (which must exist; CheckManifest first), first removing the
/// temporary files of killed bakes from it (RemoveStaleTemporaries, under the folder's lock; also
/// when every table is up to date), deriving a table's
/// texels from a table baked before it in the same run where its kind says so (NodeValueCache:
/// the same bytes as baking it alone), and commits it with
/// its manifest entry (CommitBakedTable), table by table, except those IsUpToDate finds (unless
/// opt.force): they are left untouched (same bytes, same mtime; with opt.header a missing
/// DIR/<name>.h is written from the file). Logs, per table, either
///   "baked   NAME  TEXELS texels  S s  bake error E  lookup error L" (S: the texels only;
///   "  texels from SOURCE" appended when they were derived, NodeValueCache) or
///   "skipped NAME  up to date".
/// Throws what BakeTable and CommitBakedTable throw; the tables committed before stay.
BakeRunResult BakeSpecs(const std::vector<TableSpec>& specs, const std::string& dir,
                        const BakeRunOptions& opt);

}  // namespace kiln
