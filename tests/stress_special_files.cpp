// Stress (issue #17, items 2 and 3): writes that a planted or special file could redirect.
// Temporary files get fresh names created with O_EXCL | O_NOFOLLOW, so a link planted under the
// old fixed name "<file>.tmp" is never followed; a destination that exists and is not a regular
// file (symbolic link, FIFO, device, folder) is refused with one line instead of being replaced
// by the rename. Every case checks what the planted file points to is untouched.
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "kiln/exr_loader.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;
namespace fs = std::filesystem;

namespace {

/// A small table, baked once per test into `dir` (returns its path).
std::string SmallTable(const std::string& dir) {
  auto r = RunKilnFor(120, "bake --only burley-albedo-avg --size 9 -j 1 --out " + Quote(dir));
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  return dir + "/burley-albedo-avg.exr";
}

}  // namespace

TEST_CASE("A planted symlink at the old temporary name redirects no write",
          "[stress][special-files][cli]") {
  ScratchDir root("planted_link");
  std::string dir = root / "D", victim = root / "victim";
  fs::create_directories(dir);
  WriteFile(victim, "the victim's bytes");
  fs::create_symlink("../victim", dir + "/burley-albedo-avg.exr.tmp");
  std::string exr = SmallTable(dir);
  CHECK(ReadFile(victim) == "the victim's bytes");
  CHECK(fs::is_symlink(dir + "/burley-albedo-avg.exr.tmp"));  // not ours: left alone
  kiln::Table t;
  std::string error;
  CHECK(kiln::loadTable(exr, t, error));
  CHECK_FALSE(fs::is_symlink(exr));
}

TEST_CASE("A symlink at a table's own name is refused, its target untouched",
          "[stress][special-files][cli]") {
  ScratchDir root("table_link");
  std::string dir = root / "D", victim = root / "victim";
  fs::create_directories(dir);
  WriteFile(victim, "the victim's bytes");
  fs::create_symlink("../victim", dir + "/burley-albedo-avg.exr");
  auto r = RunKilnFor(120, "bake --only burley-albedo-avg --size 9 -j 1 --out " + Quote(dir));
  INFO(r.err);
  CHECK(IsCleanRefusal(r, true));
  CHECK_THAT(r.err,
             Catch::Contains(dir + "/burley-albedo-avg.exr") && Catch::Contains("symbolic link"));
  CHECK(ReadFile(victim) == "the victim's bytes");
  CHECK(fs::is_symlink(dir + "/burley-albedo-avg.exr"));
  CHECK(root.Entries() == std::vector<std::string>{"D", "victim"});
  // The link only: no temporary file, no manifest.
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("A symlinked manifest is refused before anything is baked",
          "[stress][special-files][cli]") {
  ScratchDir root("manifest_link");
  std::string dir = root / "D", victim = root / "victim.json";
  fs::create_directories(dir);
  WriteFile(victim, "{\"tables\": []}\n");
  fs::create_symlink("../victim.json", dir + "/manifest.json");
  auto r = RunKilnFor(120, "bake --only burley-albedo-avg --size 9 -j 1 --out " + Quote(dir));
  INFO(r.err);
  CHECK(IsCleanRefusal(r, true));
  CHECK_THAT(r.err, Catch::Contains("manifest.json") && Catch::Contains("symbolic link"));
  CHECK(ReadFile(victim) == "{\"tables\": []}\n");
  CHECK_FALSE(fs::exists(dir + "/burley-albedo-avg.exr"));
}

TEST_CASE("inspect --png onto a FIFO, a device or a folder is refused, they stay what they were",
          "[stress][special-files][cli]") {
  ScratchDir root("png_special");
  std::string exr = SmallTable(root / "tables");
  SECTION("a FIFO") {
    std::string fifo = root / "fifo";
    REQUIRE(mkfifo(fifo.c_str(), 0644) == 0);
    auto r = RunKilnFor(60, "inspect " + Quote(exr) + " --png " + Quote(fifo));
    INFO(r.err);
    CHECK(IsCleanRefusal(r, true));
    CHECK_THAT(r.err, Catch::Contains(fifo) && Catch::Contains("a FIFO, not a regular file"));
    CHECK(fs::is_fifo(fifo));
  }
  SECTION("a character device (/dev/full's numbers, made in the scratch folder)") {
    std::string dev = root / "full";
    if (mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
      WARN("mknod not permitted here; using /dev/full itself, refused before it is touched");
      dev = "/dev/full";
    }
    auto r = RunKilnFor(60, "inspect " + Quote(exr) + " --png " + Quote(dev));
    INFO(r.err);
    CHECK(IsCleanRefusal(r, true));
    CHECK_THAT(r.err, Catch::Contains("a character device, not a regular file"));
    CHECK(fs::is_character_file(dev));
  }
  SECTION("a symlink to a regular file") {
    std::string target = root / "target.png", link = root / "link.png";
    WriteFile(target, "keep");
    fs::create_symlink("target.png", link);
    auto r = RunKilnFor(60, "inspect " + Quote(exr) + " --png " + Quote(link));
    INFO(r.err);
    CHECK(IsCleanRefusal(r, true));
    CHECK(ReadFile(target) == "keep");
    CHECK(fs::is_symlink(link));
  }
  SECTION("a folder") {
    std::string folder = root / "folder.png";
    fs::create_directories(folder);
    auto r = RunKilnFor(60, "inspect " + Quote(exr) + " --png " + Quote(folder));
    INFO(r.err);
    CHECK(IsCleanRefusal(r, true));
    CHECK_THAT(r.err, Catch::Contains("a folder, not a regular file"));
    CHECK(fs::is_directory(folder));
  }
  SECTION("a regular file is replaced, and no temporary file is left") {
    std::string png = root / "ok.png";
    WriteFile(png, "old");
    auto r = RunKilnFor(60, "inspect " + Quote(exr) + " --png " + Quote(png));
    INFO(r.err);
    CHECK(r.exitCode == 0);
    CHECK(ReadFile(png).substr(1, 3) == "PNG");
    CHECK(root.Entries() == std::vector<std::string>{"ok.png", "tables"});
  }
}
