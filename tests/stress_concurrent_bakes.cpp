// Stress (issue #17, item 1): two bakes into one --out folder. Each write goes to a temporary
// file of its own (baker/io/atomic_write.h) and each table lands with its manifest entry under
// the folder's lock (CommitBakedTable), so whatever the interleaving the folder holds complete
// tables and a manifest whose entries describe them. The interleavings are forced with the test
// pause points (baker/io/test_hooks.h): a bake announces on stderr that it stopped at an exact
// moment and waits for SIGUSR1, so nothing depends on scheduling. The [long] case runs the
// issue's reproduction (two free-running bakes, sizes 96 and 97) 12 times.
#include <signal.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "baker/bake/bake.h"
#include "kiln/exr_loader.h"
#include "stress_child.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;

namespace {

/// `kiln bake --only TABLE --size SIZE -j 1 --out DIR` to completion; returns the result.
kiln::test::CommandResult Bake(const std::string& dir, const std::string& table, int size) {
  return RunKilnFor(300, "bake --only " + table + " --size " + std::to_string(size) +
                             " -j 1 --out " + Quote(dir));
}

/// Starts the same bake paused before the rename of `pauseFile`; returns once it announced it.
std::unique_ptr<KilnChild> StartPaused(const std::string& dir, const std::string& table, int size,
                                       const std::string& pauseFile) {
  auto child = std::make_unique<KilnChild>(
      std::vector<std::string>{"bake", "--only", table, "--size", std::to_string(size), "-j", "1",
                               "--out", dir},
      std::vector<std::string>{"KILN_TEST_PAUSE_BEFORE_RENAME=" + pauseFile});
  REQUIRE(child->Started());
  std::string pause = child->WaitForPause();
  INFO(child->err);
  REQUIRE(!pause.empty());
  return child;
}

/// The bytes a bake of `table` at `size` writes (bakes are deterministic), baked in `scratch`.
std::string ReferenceBytes(const ScratchDir& scratch, const std::string& table, int size) {
  std::string dir = scratch / ("ref-" + table + "-" + std::to_string(size));
  auto r = Bake(dir, table, size);
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  return ReadFile(dir + "/" + table + ".exr");
}

/// Every name in `dir` is a table, a header or manifest.json: no temporary file is left.
void CheckNoTemporaries(const std::string& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    INFO(name);
    CHECK(name.size() > 4);
    CHECK(name.compare(name.size() - 4, 4, ".tmp") != 0);
  }
}

/// The table loads, and its manifest entry has the spec hash stored in it.
void CheckConsistent(const std::string& dir, const std::string& table) {
  std::string exr = dir + "/" + table + ".exr";
  kiln::Table t;
  std::string error;
  INFO(table << ": " << error);
  REQUIRE(kiln::loadTable(exr, t, error));
  CHECK(ManifestSpecHash(dir, table) == t.specHash);
}

}  // namespace

TEST_CASE("Two bakes into one --out: the one that renames last wins whole, the other's file intact",
          "[stress][concurrent][cli]") {
  ScratchDir root("concurrent");
  std::string dir = root / "out", table = "ggx-dfg";
  std::string bytesA = ReferenceBytes(root, table, 9), bytesB = ReferenceBytes(root, table, 10);
  REQUIRE(bytesA != bytesB);
  // A stops with its table complete in its temporary file, B bakes the same table from start to
  // end, then A goes on. With one shared temporary name B wrote over A's temporary file.
  auto a = StartPaused(dir, table, 9, table + ".exr");
  auto b = Bake(dir, table, 10);
  INFO(b.err);
  REQUIRE(b.exitCode == 0);
  CHECK(ReadFile(dir + "/" + table + ".exr") == bytesB);
  CheckConsistent(dir, table);
  a->Signal(SIGUSR1);
  int status = a->Wait();
  INFO(a->err);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(ReadFile(dir + "/" + table + ".exr") == bytesA);
  CheckConsistent(dir, table);
  CheckNoTemporaries(dir);
}

TEST_CASE("A second bake into one --out waits for the first's manifest update and loses no entry",
          "[stress][concurrent][cli]") {
  ScratchDir root("concurrent_lock");
  std::string dir = root / "out";
  // A holds the folder lock with its manifest written but not renamed; B bakes another table and
  // must wait for the lock. Without it, B's manifest (read before A's rename) would lack A's
  // entry, or A's rename would drop B's.
  auto a = StartPaused(dir, "ggx-dfg", 9, "manifest.json");
  KilnChild b({"bake", "--only", "burley-albedo-avg", "--size", "9", "-j", "1", "--out", dir},
              {"KILN_TEST_NOTES=1"});
  REQUIRE(b.Started());
  std::string note = b.WaitForLine("kiln: test note: waiting for the lock");
  INFO(b.err);
  REQUIRE(!note.empty());  // B found the folder locked by A (it would have run into A otherwise)
  a->Signal(SIGUSR1);
  int statusA = a->Wait(), statusB = b.Wait();
  INFO(a->err << b.err);
  REQUIRE(WIFEXITED(statusA));
  REQUIRE(WIFEXITED(statusB));
  CHECK(WEXITSTATUS(statusA) == 0);
  CHECK(WEXITSTATUS(statusB) == 0);
  CheckConsistent(dir, "ggx-dfg");
  CheckConsistent(dir, "burley-albedo-avg");
  CheckNoTemporaries(dir);
}

TEST_CASE("Two bakes into one --out, the issue's reproduction 12 times: every run consistent",
          "[stress][concurrent][cli][long]") {
  ScratchDir root("concurrent_long");
  int clean = 0;
  for (int run = 0; run < 12; ++run) {
    std::string dir = root / ("run" + std::to_string(run));
    // The command: kiln bake --only ggx-dfg --size 96 -j1 --out D & ... --size 97 ...
    KilnChild a({"bake", "--only", "ggx-dfg", "--size", "96", "-j1", "--out", dir}, {});
    KilnChild b({"bake", "--only", "ggx-dfg", "--size", "97", "-j1", "--out", dir}, {});
    int statusA = a.Wait(), statusB = b.Wait();
    INFO("run " << run << ": " << a.err << b.err);
    bool ok = WIFEXITED(statusA) && WEXITSTATUS(statusA) == 0 && WIFEXITED(statusB) &&
              WEXITSTATUS(statusB) == 0;
    CHECK(ok);
    CheckConsistent(dir, "ggx-dfg");
    CheckNoTemporaries(dir);
    kiln::Table t;
    std::string error;
    clean += ok && kiln::loadTable(dir + "/ggx-dfg.exr", t, error) &&
             ManifestSpecHash(dir, "ggx-dfg") == t.specHash;
  }
  std::printf("stress long: concurrent bakes, %d of 12 runs clean\n", clean);
}
