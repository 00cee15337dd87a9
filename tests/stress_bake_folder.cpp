// Stress: the output folder of a bake. manifest.json is parsed once per run however many tables
// the run checks or commits (a 100 MB manifest cost seconds per table); the temporary files of a
// killed bake are swept by every bake, also one with nothing to do; a full disk is reported with
// the system's reason ("No space left on device") for every file a bake writes; kiln verify reads
// every format kiln writes.
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <catch2/catch.hpp>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "baker/io/atomic_write.h"
#include "baker/io/bounded_json.h"
#include "baker/io/errno_ostream.h"
#include "stress_child.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;
namespace fs = std::filesystem;

namespace {

const std::string kTables = "burley-albedo-avg,ggx-dfg,fresnel-dielectric-avg";

std::string BakeArgs(const std::string& dir, const std::string& tables = kTables) {
  return "bake --only " + tables + " --size 5 -j 1 --no-lookup-error --out " + Quote(dir);
}

/// How many times the run's stderr says it parsed `path` (KILN_TEST_NOTES).
int Parses(const std::string& err, const std::string& path) {
  const std::string note = "kiln: test note: parsing '" + path + "'";
  int n = 0;
  for (std::size_t at = err.find(note); at != std::string::npos; at = err.find(note, at + 1)) ++n;
  return n;
}

/// A pid that belonged to a process now gone (a reaped child).
pid_t DeadPid() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  return child;
}

}  // namespace

TEST_CASE("ReadJsonFileCached parses a file once while it stays the same file",
          "[stress][json][manifest]") {
  ScratchDir dir("json_cache");
  const std::string path = dir / "m.json";
  WriteFile(path, "{\"a\": 1}");
  auto first = kiln::ReadJsonFileCached(path);
  CHECK((*first)["a"] == 1);
  CHECK(kiln::ReadJsonFileCached(path) == first);  // the same parsed document
  // Replaced by a rename (what every kiln writer does): read again.
  WriteFile(dir / "m.tmp", "{\"a\": 2}");
  fs::rename(dir / "m.tmp", path);
  auto second = kiln::ReadJsonFileCached(path);
  CHECK(second != first);
  CHECK((*second)["a"] == 2);
  // Rewritten in place with another size: read again.
  WriteFile(path, "{\"a\": 33}");
  CHECK((*kiln::ReadJsonFileCached(path))["a"] == 33);
  // Rewritten in place at once with the same size (the same times on a coarse clock): the bytes
  // of a recently modified file are compared, so the new contents are read.
  WriteFile(path, "{\"a\": 44}");
  CHECK((*kiln::ReadJsonFileCached(path))["a"] == 44);
  WriteFile(path, "{\"a\": 55}");
  CHECK((*kiln::ReadJsonFileCached(path))["a"] == 55);
  auto same = kiln::ReadJsonFileCached(path);
  CHECK(kiln::ReadJsonFileCached(path) == same);  // unchanged bytes: the same document
  // A writer that renamed a document into place tells the cache what it holds.
  WriteFile(dir / "m.tmp", "{\"a\": 4}");
  fs::rename(dir / "m.tmp", path);
  auto told = std::make_shared<const nlohmann::ordered_json>(nlohmann::ordered_json{{"a", 4}});
  kiln::RememberJsonFile(path, "{\"a\": 4}", told);
  CHECK(kiln::ReadJsonFileCached(path) == told);
  CHECK_THROWS_WITH(kiln::ReadJsonFileCached(dir / "missing.json"),
                    "cannot read " + (dir / "missing.json") + ": No such file or directory");
}

TEST_CASE("A bake parses manifest.json once, whether it skips or bakes its tables",
          "[stress][manifest][cli]") {
  ScratchDir root("manifest_once");
  const std::string dir = root / "D", manifest = dir + "/manifest.json";
  auto first = RunKilnFor(120, BakeArgs(dir), "export KILN_TEST_NOTES=1;");
  INFO(first.err);
  REQUIRE(first.exitCode == 0);
  CHECK(Parses(first.err, manifest) == 0);  // no manifest yet; each commit knows what it wrote
  auto noop = RunKilnFor(120, BakeArgs(dir), "export KILN_TEST_NOTES=1;");
  INFO(noop.err);
  REQUIRE(noop.exitCode == 0);
  CHECK(noop.err.find("0 baked, 3 skipped (up to date)") != std::string::npos);
  CHECK(Parses(noop.err, manifest) == 1);  // three tables checked
  auto forced = RunKilnFor(120, BakeArgs(dir) + " --force", "export KILN_TEST_NOTES=1;");
  INFO(forced.err);
  REQUIRE(forced.exitCode == 0);
  CHECK(Parses(forced.err, manifest) == 1);  // three tables committed
}

TEST_CASE("Every bake sweeps the temporary files of dead bakes, even one with nothing to do",
          "[stress][interrupt][cli]") {
  ScratchDir root("sweep_noop");
  const std::string dir = root / "D";
  REQUIRE(RunKilnFor(120, BakeArgs(dir, "ggx-dfg")).exitCode == 0);
  const std::string hex = ".0123456789abcdef.tmp";
  const std::string dead = std::to_string(DeadPid()), alive = std::to_string(getpid());
  const std::vector<std::string> stale = {"ggx-dfg.exr." + dead + hex,
                                          "manifest.json." + dead + hex};
  const std::string living = "ggx-dfg.exr." + alive + hex;
  for (const std::string& name : stale) WriteFile(dir + "/" + name, "x");
  WriteFile(dir + "/" + living, "x");
  auto r = RunKilnFor(120, BakeArgs(dir, "ggx-dfg"));
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.find("0 baked, 1 skipped (up to date)") != std::string::npos);  // nothing to do
  for (const std::string& name : stale) CHECK_FALSE(fs::exists(dir + "/" + name));
  CHECK(fs::exists(dir + "/" + living));
}

TEST_CASE("A full device is reported with the system's reason by every writer",
          "[stress][enospc]") {
  const std::string full = strerror(ENOSPC);  // "No space left on device"
  CHECK_THROWS_WITH(kiln::writeBytes("/dev/full", "a manifest"), full);
  // The EXR writer's stream: a full device fails the first write, or Close() says so.
  auto writeExr = [] {
    kiln::ErrnoOStream stream("/dev/full");
    {
      Imf::Header header(4, 4);
      header.channels().insert("R", Imf::Channel(Imf::FLOAT));
      std::vector<float> pixels(16, 0.5f);
      Imf::FrameBuffer frame;
      frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()),
                                   sizeof(float), 4 * sizeof(float)));
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame);
      file.writePixels(4);
    }
    stream.Close();
  };
  CHECK_THROWS_WITH(writeExr(), Catch::Contains(full));
}

// A real full file system: a 64 KiB tmpfs filled to the last page, either before the bake (the
// table's write fails) or while the bake waits between its table and its manifest (the
// manifest's write fails). Mounting needs root: skipped otherwise.
TEST_CASE("kiln bake on a full disk says \"No space left on device\" and leaves no temporary",
          "[stress][enospc][cli]") {
  ScratchDir root("enospc");
  const std::string mnt = root / "fs", dir = mnt + "/D";
  fs::create_directories(mnt);
  if (mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k") != 0) {
    WARN("skipped: cannot mount a tmpfs (" << strerror(errno) << "); it needs root");
    return;  // Catch2 2.x has no SKIP
  }
  struct Unmount {
    std::string at;
    ~Unmount() { umount2(at.c_str(), MNT_DETACH); }
  } unmount{mnt};
  fs::create_directories(dir);
  auto fill = [&] {
    return std::system(
        ("dd if=/dev/zero of=" + Quote(mnt + "/filler") + " bs=4096 2>/dev/null; sync").c_str());
  };
  const std::string full = strerror(ENOSPC);
  SECTION("the table's own write") {
    fill();
    auto r = RunKilnFor(120, BakeArgs(dir, "ggx-dfg"));
    INFO(r.err);
    CHECK(IsCleanRefusal(r));
    CHECK_THAT(r.err, Catch::Contains("cannot write '" + dir + "/ggx-dfg.exr'") &&
                          Catch::EndsWith(": " + full + "\n"));
  }
  SECTION("the manifest's write") {
    KilnChild bake(
        {"bake", "--only", "ggx-dfg", "--size", "5", "-j", "1", "--no-lookup-error", "--out", dir},
        {"KILN_TEST_PAUSE_BEFORE_RENAME=ggx-dfg.exr"});
    REQUIRE(bake.Started());
    REQUIRE(!bake.WaitForPause().empty());
    fill();
    bake.Signal(SIGUSR1);
    const int status = bake.Wait();
    INFO(bake.err);
    CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 1));
    CHECK_THAT(bake.err, Catch::Contains("kiln: error: cannot write '" + dir +
                                         "/manifest.json': " + full + "\n"));
  }
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  CHECK(left.empty());
}

TEST_CASE("kiln verify checks a KTX2 or DDS table as it checks an EXR one",
          "[stress][verify][ktx2][dds][cli]") {
  ScratchDir root("verify_formats");
  for (const char* format : {"ktx2", "dds"}) {
    const std::string dir = root / format;
    auto bake = RunKilnFor(120, "bake --only ggx-dfg --size 9 -j 1 --format " +
                                    std::string(format) + " --out " + Quote(dir));
    INFO(bake.err);
    REQUIRE(bake.exitCode == 0);
    const std::string file = dir + "/ggx-dfg." + format;
    auto r = RunKilnFor(120, "verify -j 1 -q " + Quote(file));
    INFO(r.out << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("FAILED") == std::string::npos);
    CHECK(r.out.find("1 tables, 0 over their bound") != std::string::npos);
  }
}
