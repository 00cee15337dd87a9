// Stress: a bake killed half-way (SIGKILL: no handler runs) leaves the previous table intact.
// `kiln bake --only beckmann-dfg --size 16` is stopped at an exact moment by a test pause point
// (baker/io/test_hooks.h): KILN_TEST_PAUSE_AFTER_TEXELS=128 (half of the 256 texels done) and
// KILN_TEST_PAUSE_BEFORE_RENAME=beckmann-dfg.exr (the temporary file complete, not yet renamed).
// The process announces the pause on stderr and blocks; the test reads that line from a pipe and
// kills it. Each time DIR/beckmann-dfg.exr holds the previous bytes and the manifest is
// unchanged; only a killed write leaves a temporary file, and the next bake leaves none.
// Nothing depends on timing or scheduling: the moment to kill is the process's own report.
// The [long] case repeats both interruptions 50 times.
#include <signal.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "baker/io/atomic_write.h"
#include "kiln/exr_loader.h"
#include "stress_child.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;

namespace {

const std::string kTable = "beckmann-dfg";
const char* kSize = "16";  // 256 texels

/// Runs the same bake to completion in `dir`, through the CLI.
void BakeToCompletion(const std::string& dir, const char* size) {
  auto r =
      RunKilnFor(300, "bake --only " + kTable + " --size " + size + " -j 2 --out " + Quote(dir));
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
}

/// Starts the bake of kTable at kSize into `dir` with the test pause `env`, waits for its pause
/// line, sends `sig` and returns the wait status.
int InterruptBake(const std::string& dir, const std::string& env, int sig) {
  KilnChild bake({"bake", "--only", kTable, "--size", kSize, "--out", dir, "-j", "2"}, {env});
  REQUIRE(bake.Started());
  std::string pause = bake.WaitForPause();
  INFO(bake.err);
  REQUIRE(!pause.empty());
  bake.Signal(sig);
  return bake.Wait();
}

/// The names in `dir`, sorted.
std::vector<std::string> Names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// A temporary file of kTable's write: "beckmann-dfg.exr" ... ".tmp".
bool IsTableTemporary(const std::string& name) {
  std::string prefix = kTable + ".exr";
  return name.size() >= prefix.size() + 4 && name.rfind(prefix, 0) == 0 &&
         name.compare(name.size() - 4, 4, ".tmp") == 0;
}

struct Fixture {
  ScratchDir root{"interrupt"};
  std::string dir = root / "out", exr = dir + "/" + kTable + ".exr",
              manifest = dir + "/manifest.json";
  std::string newBytes, oldBytes, oldManifest;
  Fixture() {
    BakeToCompletion(root / "reference", kSize);  // what a completed bake writes (deterministic)
    newBytes = ReadFile(root / "reference" + "/" + kTable + ".exr");
    BakeToCompletion(dir, "5");  // the previous table: the same name, other bytes
    oldBytes = ReadFile(exr);
    oldManifest = ReadFile(manifest);
    REQUIRE(!oldBytes.empty());
    REQUIRE(oldBytes != newBytes);
  }
  /// Puts the previous table and manifest back (a completed bake replaced them).
  void Restore() const {
    WriteFile(exr, oldBytes);
    WriteFile(manifest, oldManifest);
  }
};

/// Killed while the texels are computed: nothing changes, nothing is left behind.
void KillWhileComputing(const Fixture& f) {
  f.Restore();
  int status = InterruptBake(f.dir, "KILN_TEST_PAUSE_AFTER_TEXELS=128", SIGKILL);
  REQUIRE(EndedBySignal(status, SIGKILL));
  CHECK(ReadFile(f.exr) == f.oldBytes);
  CHECK(ReadFile(f.manifest) == f.oldManifest);
  CHECK(Names(f.dir) == std::vector<std::string>{kTable + ".exr", "manifest.json"});
}

/// Killed with the temporary file complete and not yet renamed: the old table and manifest stay,
/// the temporary file is the only thing left, and the next bake removes it.
void KillWhileWriting(const Fixture& f) {
  f.Restore();
  int status = InterruptBake(f.dir, "KILN_TEST_PAUSE_BEFORE_RENAME=" + kTable + ".exr", SIGKILL);
  REQUIRE(EndedBySignal(status, SIGKILL));
  CHECK(ReadFile(f.exr) == f.oldBytes);
  CHECK(ReadFile(f.manifest) == f.oldManifest);
  std::vector<std::string> names = Names(f.dir);
  REQUIRE(names.size() == 3);
  CHECK(names[0] == kTable + ".exr");
  CHECK(IsTableTemporary(names[1]));
  CHECK(names[2] == "manifest.json");
  BakeToCompletion(f.dir, kSize);
  CHECK(Names(f.dir) == std::vector<std::string>{kTable + ".exr", "manifest.json"});
  CHECK(ReadFile(f.exr) == f.newBytes);
  kiln::Table t;
  std::string error;
  CHECK(kiln::loadTable(f.exr, t, error));
}

}  // namespace

TEST_CASE("A bake killed half-way leaves the previous table intact, and the next bake cleans up",
          "[stress][interrupt][cli]") {
  Fixture f;
  KillWhileComputing(f);
  KillWhileWriting(f);
}

TEST_CASE("A bake killed half-way, 50 times over: the previous table intact every time",
          "[stress][interrupt][cli][long]") {
  Fixture f;
  for (int i = 0; i < 50; ++i) {
    INFO("round " << i);
    KillWhileComputing(f);
    KillWhileWriting(f);
  }
}

TEST_CASE("SIGINT, SIGTERM and SIGHUP remove the temporary file and end the bake by that signal",
          "[stress][interrupt][cli]") {
  Fixture f;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    for (const std::string& env : {std::string("KILN_TEST_PAUSE_AFTER_TEXELS=128"),
                                   "KILN_TEST_PAUSE_BEFORE_RENAME=" + kTable + ".exr"}) {
      INFO("signal " << sig << ", " << env);
      int status = InterruptBake(f.dir, env, sig);
      CHECK(EndedBySignal(status, sig));
      CHECK(ReadFile(f.exr) == f.oldBytes);
      CHECK(ReadFile(f.manifest) == f.oldManifest);
      CHECK(Names(f.dir) == std::vector<std::string>{kTable + ".exr", "manifest.json"});
    }
  }
}

TEST_CASE("SIGXFSZ (a file size limit) removes the temporary file", "[stress][interrupt][cli]") {
  Fixture f;
  // 1 KiB (dash counts 512-byte blocks): the table's header alone is larger.
  auto r =
      RunKilnFor(300, "bake --only " + kTable + " --size " + kSize + " -j 2 --out " + Quote(f.dir),
                 "ulimit -f 2;");
  INFO(r.err);
  CHECK(r.exitCode != 0);
  CHECK(ReadFile(f.exr) == f.oldBytes);
  CHECK(ReadFile(f.manifest) == f.oldManifest);
  CHECK(Names(f.dir) == std::vector<std::string>{kTable + ".exr", "manifest.json"});
}

// CommitBakedTable (baker/bake/bake.cpp) writes manifest.json through a temporary file like the
// tables, so a bake killed while it writes the manifest leaves the old one, never a truncated
// one. Renamed into place, the file gets a new inode: a hard link made beforehand keeps the old
// bytes, which shows it deterministically.
TEST_CASE("The manifest, like every table, is replaced by a rename, never rewritten in place",
          "[stress][interrupt][cli]") {
  ScratchDir dir("interrupt_manifest");
  BakeToCompletion(dir.path.string(), "5");
  std::string exr = dir / (kTable + ".exr"), manifest = dir / "manifest.json";
  std::filesystem::create_hard_link(exr, dir / "table.link");
  std::filesystem::create_hard_link(manifest, dir / "manifest.link");
  std::string oldExr = ReadFile(exr), oldManifest = ReadFile(manifest);
  BakeToCompletion(dir.path.string(), "6");
  REQUIRE(ReadFile(exr) != oldExr);
  REQUIRE(ReadFile(manifest) != oldManifest);
  CHECK(ReadFile(dir / "table.link") == oldExr);          // the table: replaced by a rename
  CHECK(ReadFile(dir / "manifest.link") == oldManifest);  // the manifest: replaced by a rename too
}

// RemoveStaleTemporaries (baker/io/atomic_write.h), called by each bake under the folder lock:
// a temporary file whose process is gone is removed; one of a living process (this one: a bake
// in progress) and every name outside the pattern are kept. The dead pid is a reaped child's.
TEST_CASE("Stale temporary files of dead processes are removed, those of living ones kept",
          "[stress][interrupt]") {
  ScratchDir dir("stale_temporaries");
  pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) _exit(0);
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  const std::string hex = ".0123456789abcdef.tmp";
  const std::string dead = "a.exr." + std::to_string(child) + hex;
  const std::string alive = "b.exr." + std::to_string(getpid()) + hex;
  const std::vector<std::string> others = {
      "c.exr.tmp", "d.exr." + std::to_string(child) + ".0123.tmp", "e.exr", "manifest.json"};
  for (const std::string& name : others) WriteFile(dir / name, "x");
  WriteFile(dir / dead, "x");
  WriteFile(dir / alive, "x");
  CHECK(kiln::RemoveStaleTemporaries(dir.path.string()) == 1);
  std::vector<std::string> expected = others;
  expected.push_back(alive);
  std::sort(expected.begin(), expected.end());
  CHECK(dir.Entries() == expected);
}
