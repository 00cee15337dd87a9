// Stress (issue #17, items 9, 10 and 12): the manifest and the output folder. A corrupt
// manifest.json is an error naming it (never silently replaced, which dropped every other
// table's entry); the manifest is updated after each table, so a bake killed after table k
// leaves one that describes the files; --out with missing parents is created, and one that
// cannot be says why.
#include <signal.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "baker/bake/bake.h"
#include "stress_child.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;
namespace fs = std::filesystem;

namespace {

kiln::test::CommandResult Bake(const std::string& dir, const std::string& tables, int size) {
  return RunKilnFor(300, "bake --only " + tables + " --size " + std::to_string(size) +
                             " -j 1 --out " + Quote(dir));
}

}  // namespace

TEST_CASE("A corrupt manifest.json is an error naming it, and is left as it was",
          "[stress][manifest][cli]") {
  ScratchDir root("corrupt_manifest");
  std::string dir = root / "D", manifest = dir + "/manifest.json";
  fs::create_directories(dir);
  struct Case {
    const char* bytes;
    const char* says;
  };
  for (const Case& c :
       {Case{"{\"tables\": [ {\"name\": \"ggx-dfg\"", "is not valid JSON ("},
        Case{"", "is not valid JSON ("},
        Case{"[1, 2, 3]\n", "is not a kiln manifest (no \"tables\" array)"},
        Case{"{\"tables\": [ {\"file\": \"x.exr\"} ]}\n", "is not a kiln manifest (an entry"}}) {
    INFO("manifest: " << c.bytes);
    WriteFile(manifest, c.bytes);
    auto r = Bake(dir, "burley-albedo-avg", 9);
    INFO(r.err);
    CHECK(IsCleanRefusal(r));
    CHECK_THAT(r.err, Catch::StartsWith("kiln: error: " + manifest + " " + c.says) &&
                          Catch::EndsWith("; move it aside or delete it\n"));
    CHECK(ReadFile(manifest) == c.bytes);
    CHECK(root.Entries() == std::vector<std::string>{"D"});
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) ==
          1);  // nothing baked
  }
  // The scene bake refuses it too.
  WriteFile(manifest, "not json");
  auto r = RunKilnFor(
      300, "bake --scene " +
               Quote(std::string(KILN_SOURCE_DIR) + "/tests/scenes/lambert_only.kiln.json") +
               " --out " + Quote(dir));
  INFO(r.err);
  CHECK(IsCleanRefusal(r));
  CHECK_THAT(r.err, Catch::Contains(manifest + " is not valid JSON"));
  CHECK(ReadFile(manifest) == "not json");
}

TEST_CASE("A bake killed after its first table leaves a manifest describing the files",
          "[stress][manifest][interrupt][cli]") {
  ScratchDir root("killed_after_first");
  std::string dir = root / "D";
  const std::string first = "burley-albedo-avg", second = "ggx-dfg";
  auto old = Bake(dir, first + "," + second, 5);
  INFO(old.err);
  REQUIRE(old.exitCode == 0);
  std::string oldSecond = kiln::StoredSpecHash(dir + "/" + second + ".exr");
  std::string oldFirst = kiln::StoredSpecHash(dir + "/" + first + ".exr");
  // The second table's temporary file is complete: the first table is committed, the second not.
  KilnChild bake({"bake", "--only", first + "," + second, "--size", "9", "-j", "1", "--out", dir},
                 {"KILN_TEST_PAUSE_BEFORE_RENAME=" + second + ".exr"});
  REQUIRE(bake.Started());
  REQUIRE(!bake.WaitForPause().empty());
  bake.Signal(SIGKILL);
  REQUIRE(EndedBySignal(bake.Wait(), SIGKILL));
  std::string newFirst = kiln::StoredSpecHash(dir + "/" + first + ".exr");
  CHECK(newFirst != oldFirst);                      // table 1 replaced ...
  CHECK(ManifestSpecHash(dir, first) == newFirst);  // ... and its entry with it
  CHECK(kiln::StoredSpecHash(dir + "/" + second + ".exr") == oldSecond);  // table 2 untouched
  CHECK(ManifestSpecHash(dir, second) == oldSecond);
}

TEST_CASE("bake --out with missing parents creates them, one that cannot be made says why",
          "[stress][manifest][cli]") {
  ScratchDir root("out_parents");
  auto ok = Bake(root / "a/b/c", "burley-albedo-avg", 9);
  INFO(ok.err);
  CHECK(ok.exitCode == 0);
  CHECK(fs::exists(root / "a/b/c/burley-albedo-avg.exr"));
  CHECK(fs::exists(root / "a/b/c/manifest.json"));
  WriteFile(root / "file", "a regular file");
  auto under = Bake(root / "file/x/y", "burley-albedo-avg", 9);
  INFO(under.err);
  CHECK(IsCleanRefusal(under));
  CHECK_THAT(under.err, Catch::Contains("cannot create folder '" + root / "file/x/y" + "': "));
  auto onFile = Bake(root / "file", "burley-albedo-avg", 9);
  INFO(onFile.err);
  CHECK(IsCleanRefusal(onFile));
  CHECK_THAT(onFile.err, Catch::Contains("'" + root / "file" + "' exists and is not a folder"));
  CHECK(ReadFile(root / "file") == "a regular file");
}
