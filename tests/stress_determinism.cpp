// Stress: the same bake gives the same bytes. `kiln bake` with -j 1, -j 2 and more threads than
// cores, and a repeated run, write byte-identical files (EXR, C++ header, manifest) for a 2D
// table with an adaptive integral per texel and for a 3D table (tests/bake_tables.cpp compares
// the in-memory texels; this is the whole CLI path down to the file bytes).
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;
using kiln::test::RunKiln;

namespace {

const char* kTables[] = {"ggx-dfg", "oren-nayar-albedo", "fresnel-conductor"};
const char* kOnly = "ggx-dfg,oren-nayar-albedo,fresnel-conductor";

/// Bakes the tables into DIR with `threads` threads (and the extra flags); returns the bytes of
/// every file written, in a fixed order.
std::vector<std::string> Bake(const ScratchDir& root, const std::string& name, int threads,
                              const std::string& flags) {
  std::string dir = root / name;
  auto r = RunKiln("bake --out " + Quote(dir) + " --only " + kOnly + " --size 7 --header -j " +
                   std::to_string(threads) + " " + flags);
  INFO("kiln bake -j " << threads << " " << flags << ": " << r.err);
  REQUIRE(r.exitCode == 0);
  std::vector<std::string> files;
  for (const char* t : kTables) {
    files.push_back(ReadFile(dir + "/" + t + ".exr"));
    files.push_back(ReadFile(dir + "/" + t + ".h"));
  }
  files.push_back(ReadFile(dir + "/manifest.json"));
  for (const std::string& f : files) REQUIRE(!f.empty());
  return files;
}

}  // namespace

TEST_CASE("kiln bake writes the same bytes for -j 1, -j 2, -j 7 and across runs",
          "[stress][determinism][cli]") {
  ScratchDir root("determinism");
  for (const char* flags : {"", "--half"}) {
    INFO("flags: '" << flags << "'");
    std::vector<std::string> one = Bake(root, std::string("j1") + flags, 1, flags);
    std::vector<std::string> two = Bake(root, std::string("j2") + flags, 2, flags);
    std::vector<std::string> seven = Bake(root, std::string("j7") + flags, 7, flags);
    std::vector<std::string> again = Bake(root, std::string("j2-again") + flags, 2, flags);
    for (size_t i = 0; i < one.size(); ++i) {
      INFO("file " << i << " (table " << kTables[std::min(i / 2, size_t(2))] << ", "
                   << (i % 2 ? ".h" : ".exr") << "; the last is manifest.json)");
      CHECK(one[i] == two[i]);
      CHECK(one[i] == seven[i]);
      CHECK(two[i] == again[i]);
    }
  }
}

TEST_CASE("Re-baking over existing files gives the same bytes as a fresh bake",
          "[stress][determinism][cli]") {
  ScratchDir root("rebake");
  std::vector<std::string> fresh = Bake(root, "d", 2, "");
  std::vector<std::string> over = Bake(root, "d", 2, "");  // same folder: replaces, manifest merges
  CHECK(fresh == over);
}
