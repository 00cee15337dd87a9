// kiln bake (catalogue): up-to-date tables are skipped untouched, --force rebakes, a line per
// table and a summary on stderr whether or not there is a terminal, --quiet silences them.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_util.h"

using kiln::test::ReadFile;
using kiln::test::RemoveTree;
using kiln::test::RunKiln;
using kiln::test::TempDir;

namespace {

/// The file's inode and modification time: a rename of a new file changes the inode, a write
/// the time.
std::string Identity(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return "missing";
  return std::to_string(st.st_ino) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("kiln bake skips up-to-date catalogue tables and --force rebakes them",
          "[cli][bake][skip]") {
  std::string dir = TempDir("bake_skip");
  const std::string only = " --only fresnel-dielectric-avg,lambert-albedo --size 6 -j 2";
  auto first = RunKiln("bake --out " + dir + only);
  INFO(first.err);
  REQUIRE(first.exitCode == 0);
  // Not on a terminal: stdout stays empty, stderr has a line per table and a summary, no bar.
  CHECK(first.out.empty());
  CHECK(Has(first.err, "baked   fresnel-dielectric-avg "));
  CHECK(Has(first.err, " 6 texels "));
  CHECK(Has(first.err, " bake error "));
  CHECK(Has(first.err, " lookup error "));
  CHECK(Has(first.err, "baked   lambert-albedo "));
  CHECK(Has(first.err, "2 baked, 0 skipped (up to date) in "));
  CHECK_FALSE(Has(first.err, "\r"));
  CHECK(kiln::test::CountLines(first.err) == 3);
  std::string exr = dir + "/fresnel-dielectric-avg.exr", manifest = dir + "/manifest.json";
  std::string id = Identity(exr), idManifest = Identity(manifest),
              manifestText = ReadFile(manifest);

  auto second = RunKiln("bake --out " + dir + only);
  INFO(second.err);
  REQUIRE(second.exitCode == 0);
  CHECK(second.out.empty());
  CHECK(Has(second.err, "skipped fresnel-dielectric-avg "));
  CHECK(Has(second.err, "skipped lambert-albedo "));
  CHECK(Has(second.err, " up to date\n"));
  CHECK(Has(second.err, "0 baked, 2 skipped (up to date) in "));
  CHECK(Identity(exr) == id);  // not opened for writing
  CHECK(Identity(manifest) == idManifest);
  CHECK(ReadFile(manifest) == manifestText);

  // --quiet: nothing on stderr (and nothing rebaked).
  auto quiet = RunKiln("bake --quiet --out " + dir + only);
  CHECK(quiet.exitCode == 0);
  CHECK(quiet.err.empty());
  CHECK(quiet.out.empty());
  CHECK(Identity(exr) == id);

  // --force: both rebaked (a new file renamed into place), same bytes (the bake is deterministic).
  std::string bytes = ReadFile(exr);
  auto forced = RunKiln("bake --force --out " + dir + only);
  CHECK(forced.exitCode == 0);
  CHECK(Has(forced.err, "2 baked, 0 skipped"));
  CHECK(Identity(exr) != id);
  CHECK(ReadFile(exr) == bytes);
  RemoveTree(dir);
}

TEST_CASE("kiln bake rebakes a table whose file or manifest entry is not what it would write",
          "[cli][bake][skip]") {
  std::string dir = TempDir("bake_stale");
  const std::string table = " --only fresnel-dielectric-avg -j 2";
  REQUIRE(RunKiln("bake --out " + dir + table + " --size 6").exitCode == 0);
  // Another size: another spec hash, stale.
  auto resized = RunKiln("bake --out " + dir + table + " --size 7");
  CHECK(Has(resized.err, "1 baked, 0 skipped"));
  // Half floats where float32 was stored, and back.
  CHECK(Has(RunKiln("bake --half --out " + dir + table + " --size 7").err, "1 baked, 0 skipped"));
  CHECK(Has(RunKiln("bake --half --out " + dir + table + " --size 7").err, "0 baked, 1 skipped"));
  CHECK(Has(RunKiln("bake --out " + dir + table + " --size 7").err, "1 baked, 0 skipped"));
  // A file that declares a lookup error serves a bake that asks for none; one that declares
  // none is stale for a bake that asks for it.
  CHECK(Has(RunKiln("bake --no-lookup-error --out " + dir + table + " --size 7").err,
            "0 baked, 1 skipped"));
  std::filesystem::remove(dir + "/fresnel-dielectric-avg.exr");
  CHECK(Has(RunKiln("bake --no-lookup-error --out " + dir + table + " --size 7").err,
            "1 baked, 0 skipped"));
  CHECK(Has(RunKiln("bake --out " + dir + table + " --size 7").err, "1 baked, 0 skipped"));
  // The manifest lost the entry (or the whole manifest is gone): baked again, entry back.
  std::filesystem::remove(dir + "/manifest.json");
  auto noManifest = RunKiln("bake --out " + dir + table + " --size 7");
  CHECK(Has(noManifest.err, "1 baked, 0 skipped"));
  auto m = nlohmann::json::parse(ReadFile(dir + "/manifest.json"));
  REQUIRE(m["tables"].size() == 1);
  CHECK(m["tables"][0]["name"] == "fresnel-dielectric-avg");
  // A header asked for later is written from the up-to-date file, which is not rebaked.
  auto header = RunKiln("bake --header --out " + dir + table + " --size 7");
  CHECK(Has(header.err, "skipped fresnel-dielectric-avg "));
  CHECK(Has(header.err, "up to date (header written)"));
  CHECK(!ReadFile(dir + "/fresnel-dielectric-avg.h").empty());
  RemoveTree(dir);
}

TEST_CASE("kiln bake --scene reports on stderr, --quiet silences it", "[cli][bake][skip]") {
  std::string dir = TempDir("bake_scene_report");
  std::string scene = std::string(KILN_SOURCE_DIR) + "/tests/scenes/merge.gltf";
  auto first = RunKiln("bake --scene " + scene + " --size 4 -j 2 --out " + dir);
  INFO(first.err);
  REQUIRE(first.exitCode == 0);
  CHECK(first.out.empty());
  CHECK(Has(first.err, "baked   ggx-dfg-r0.3-0.6 "));
  CHECK(Has(first.err, ": 3 baked, 0 skipped (up to date) in "));
  auto second = RunKiln("bake --scene " + scene + " --size 4 -j 2 --out " + dir);
  CHECK(Has(second.err, "skipped ggx-dfg-r0.3-0.6 "));
  CHECK(Has(second.err, ": 0 baked, 3 skipped (up to date) in "));
  auto forced = RunKiln("bake --force --quiet --scene " + scene + " --size 4 -j 2 --out " + dir);
  CHECK(forced.exitCode == 0);
  CHECK(forced.err.empty());
  CHECK(forced.out.empty());
  RemoveTree(dir);
}

TEST_CASE("On a terminal the bar is drawn on stderr, and --quiet prints nothing there either",
          "[cli][bake][skip]") {
  if (std::system("command -v script >/dev/null 2>&1") != 0) {
    WARN("util-linux `script` (a pseudo-terminal) is not installed: skipped");
    return;
  }
  std::string dir = TempDir("bake_tty"), log = dir + ".log";
  // `script` runs the bake on a pseudo-terminal (stdout and stderr) and copies what it printed.
  auto onTerminal = [&](const std::string& args) {
    std::string cmd = "script -qec \"" + std::string(KILN_BINARY) + " bake " + args + " --out " +
                      dir + "\" /dev/null >" + log + " 2>&1 </dev/null";
    CHECK(std::system(cmd.c_str()) == 0);
    return ReadFile(log);
  };
  std::string shown = onTerminal("--only lambert-albedo --size 4 -j 1");
  CHECK(Has(shown, "\rlambert-albedo"));  // the bar, drawn when the table starts
  CHECK(Has(shown, "] 0/8"));
  CHECK(Has(shown, "baked   lambert-albedo "));
  CHECK(Has(shown, "1 baked, 0 skipped"));
  std::string quiet = onTerminal("--quiet --force --only lambert-albedo --size 4 -j 1");
  CHECK(quiet.empty());
  RemoveTree(dir);
  RemoveTree(log);
}
