// Stress: hostile scene files (issue #17). The scene readers cap what they read before they
// parse it: at most 64 MiB (a bounded read, so /dev/zero or a pipe that never ends is refused at
// the cap; a larger glb is read from its JSON chunk), at most 64 levels of nesting (checked
// before the parser builds anything), and CheckTextureInfos walks the materials without
// recursion. Every refusal is one line naming the file; a seeded mutation loop over the committed
// scenes checks that every mutant is planned or refused with one line, never a crash.
#include <sys/resource.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "baker/scene/glb.h"
#include "baker/scene/plan.h"
#include "baker/scene/scene_error.h"
#include "baker/scene/scene_json.h"
#include "scene_util.h"
#include "stress_util.h"
#include "test_util.h"

using namespace kiln;
using namespace kiln::stress;

namespace {

/// A glTF asset whose first material holds `inner` under the key "deep".
std::string GltfWithMaterialValue(const std::string& inner) {
  return R"({"asset":{"version":"2.0"},"materials":[{"name":"m","deep":)" + inner + "}]}";
}

/// `levels` nested arrays.
std::string NestedArrays(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }

/// The message of the SceneError ReadScene(path) throws, or "" when it reads the file.
std::string SceneErrorOf(const std::string& path) {
  try {
    ReadScene(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

/// The peak resident set of this process, in MiB.
double PeakRssMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace

TEST_CASE("Deeply nested glTF: kiln plan refuses 30,000 levels with one line instead of crashing",
          "[stress][hostile][scene][cli]") {
  ScratchDir dir("hostile_scenes_deep");
  const std::string deep = GltfWithMaterialValue(NestedArrays(30000));  // about 60 KB
  WriteFile(dir / "deep.gltf", deep);
  WriteFile(dir / "deep.glb", MakeGlb(deep, ""));
  WriteFile(dir / "deep.kiln.json",
            R"({"kiln_scene":1,"materials":[{"model":"ggx","x":)" + NestedArrays(30000) + "}]}");
  for (const std::string name : {"deep.gltf", "deep.glb", "deep.kiln.json"}) {
    auto r = RunKilnFor(60, "plan " + Quote(dir / name));
    INFO(name << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(name) != std::string::npos);
    CHECK(r.err.find("nested deeper than 64 levels") != std::string::npos);
  }
  // The place is the bracket that opens level 65 ("line 1, column C"; the glb's in its JSON chunk):
  // the document, "materials" and the material are levels 1 to 3, the nested arrays 4 onwards.
  std::string message = SceneErrorOf(dir / "deep.gltf");
  size_t column = deep.find("[[") + 61 + 1;
  CHECK(message.find("line 1, column " + std::to_string(column) + ": nested deeper") !=
        std::string::npos);
  CHECK(SceneErrorOf(dir / "deep.glb").find("JSON chunk, line 1") != std::string::npos);
}

TEST_CASE("Brackets inside strings do not count as nesting, and 64 levels are read",
          "[stress][hostile][scene]") {
  ScratchDir dir("hostile_scenes_depth_edge");
  // 61 levels inside the material (+ the document, "materials" and the material = 64): read.
  WriteFile(dir / "edge.gltf", GltfWithMaterialValue(NestedArrays(61)));
  CHECK(SceneErrorOf(dir / "edge.gltf").empty());
  WriteFile(dir / "over.gltf", GltfWithMaterialValue(NestedArrays(62)));
  CHECK(SceneErrorOf(dir / "over.gltf").find("nested deeper than 64 levels") != std::string::npos);
  // 10,000 brackets and an escaped quote in a string are text, not nesting.
  WriteFile(dir / "string.gltf", GltfWithMaterialValue("\"\\\"" + std::string(10000, '[') + "\""));
  CHECK(SceneErrorOf(dir / "string.gltf").empty());
}

// CheckTextureInfos (baker/scene/gltf_reader.cpp) walks every material value for textureInfos;
// it recursed per level and built a JSON pointer per value. Now iterative: the pointer of a
// textureInfo found 50 levels down, through objects and arrays, must still be exact.
TEST_CASE("A bad textureInfo deep in a material is named by its exact JSON pointer",
          "[stress][hostile][scene]") {
  ScratchDir dir("hostile_scenes_texinfo");
  std::string inner = R"({"normalTexture":{"texCoord":0}})";
  std::string pointer = "/normalTexture";
  for (int level = 0; level < 25; ++level) {
    inner = R"({"extras":{"aTexture":{}},"a/b":[0,)" + inner + "]}";
    pointer = "/a~1b/1" + pointer;
  }
  WriteFile(dir / "texinfo.gltf", GltfWithMaterialValue(inner));
  std::string message = SceneErrorOf(dir / "texinfo.gltf");
  INFO(message);
  CHECK(message.find(": /materials/0/deep" + pointer + ": textureInfo without \"index\"") !=
        std::string::npos);
  // The same textureInfo with a texture that exists: read.
  std::string good = inner;
  good.replace(good.find(R"({"texCoord":0})"), 14, R"({"index":0})");
  WriteFile(dir / "good.gltf",
            R"({"asset":{"version":"2.0"},"textures":[{}],"materials":[{"deep":)" + good + "}]}");
  CHECK(SceneErrorOf(dir / "good.gltf").empty());
  std::string bad = inner;
  bad.replace(bad.find(R"({"texCoord":0})"), 14, R"({"index":3})");
  WriteFile(dir / "bad.gltf",
            R"({"asset":{"version":"2.0"},"textures":[{}],"materials":[{"deep":)" + bad + "}]}");
  CHECK(
      SceneErrorOf(dir / "bad.gltf").find("deep" + pointer + "/index: texture 3 does not exist") !=
      std::string::npos);
}

TEST_CASE("kiln plan /dev/zero and an endless pipe are refused at 64 MiB with one line",
          "[stress][hostile][scene][cli]") {
  ScratchDir dir("hostile_scenes_zero");
  auto r = RunKilnFor(60, "plan /dev/zero");
  INFO("plan /dev/zero: exit " << r.exitCode << ", stderr: " << r.err);
  CHECK(IsCleanRefusal(r));
  CHECK(r.err.find("/dev/zero: larger than 64 MiB") != std::string::npos);
  std::string fifo = dir / "endless.gltf";
  auto p = RunKilnFor(
      60, "plan " + Quote(fifo),
      "mkfifo " + Quote(fifo) + " && (cat /dev/zero > " + Quote(fifo) + " 2>/dev/null &);");
  INFO("plan FIFO: exit " << p.exitCode << ", stderr: " << p.err);
  CHECK(IsCleanRefusal(p));
  CHECK(p.err.find("larger than 64 MiB") != std::string::npos);
}

TEST_CASE("A scene file over 64 MiB is refused, a glb over 64 MiB is read from its JSON chunk",
          "[stress][hostile][scene]") {
  ScratchDir dir("hostile_scenes_large");
  const std::string scene = test::ReadFile(test::ScenePath("metal_rough_factors.gltf"));
  // The 65 MiB tails below are zeros left unwritten (a sparse file): the size is what is tested.
  constexpr uintmax_t kTail = 65u << 20;
  auto writeWithZeroTail = [](const std::filesystem::path& path, const std::string& head) {
    WriteFile(path, head);
    std::filesystem::resize_file(path, head.size() + kTail);
  };
  // JSON with 65 MiB after it: refused by its size before it is parsed (parsed, its NULs would
  // be a syntax error, not this one).
  writeWithZeroTail(dir / "large.gltf", scene);
  CHECK(SceneErrorOf(dir / "large.gltf").find("larger than 64 MiB") != std::string::npos);
  // A glb with a 65 MiB binary chunk (meshes, images; its data last in the file) plans like its
  // JSON alone. Its head is MakeGlb's with a 4-byte chunk whose two lengths (the file's at byte
  // 8, the chunk's before its type) are raised to the 65 MiB chunk's: the bytes MakeGlb writes
  // for that chunk, without building 65 MiB of zeros in memory.
  std::string head = MakeGlb(scene, std::string(4, '\0'));
  head.resize(head.size() - 4);
  auto putU32 = [&head](size_t at, uint32_t value) {
    for (int k = 0; k < 4; ++k) head[at + k] = static_cast<char>((value >> (8 * k)) & 0xff);
  };
  putU32(8, static_cast<uint32_t>(head.size() + kTail));
  putU32(head.size() - 8, static_cast<uint32_t>(kTail));
  writeWithZeroTail(dir / "large.glb", head);
  WriteFile(dir / "small.glb", MakeGlb(scene, ""));
  Plan large = PlanSceneFile(dir / "large.glb"), small = PlanSceneFile(dir / "small.glb");
  CHECK(test::TableNames(large) == test::TableNames(small));
  CHECK_FALSE(large.tables.empty());
}

// Issue #17: a file in a folder that cannot be searched was reported as "no such file". Tests
// run as root here (permissions do not apply), so the case is a loop of symbolic links, which
// fails the same way with another errno.
TEST_CASE("A path that cannot be resolved is reported with its reason, not as a missing file",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_scenes_loop");
  std::filesystem::create_symlink(dir / "loop.exr", dir / "loop.exr");
  std::filesystem::create_symlink(dir / "loop.gltf", dir / "loop.gltf");
  for (const std::string& args :
       {"inspect " + Quote(dir / "loop.exr"), "verify " + Quote(dir / "loop.exr"),
        "sample " + Quote(dir / "loop.exr") + " 0.5", "plan " + Quote(dir / "loop.gltf")}) {
    auto r = RunKilnFor(60, args);
    INFO("kiln " << args << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find("symbolic links") != std::string::npos);
    CHECK(r.err.find("no such file") == std::string::npos);
  }
}

namespace {

/// The committed scenes: the seeds of the mutation loop.
std::vector<std::string> SceneSeeds() {
  std::vector<std::string> files;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(KILN_SOURCE_DIR) + "/tests/scenes"))
    if (e.is_regular_file()) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// One random mutation of a scene's bytes: byte-level ones and JSON-aware ones (brackets, deep
/// nesting, absurd numbers, duplicated and removed spans).
void MutateScene(std::string& b, test::Rng& rng) {
  auto below = [&](size_t n) {
    return n == 0 ? size_t(0) : static_cast<size_t>(rng.Uniform() * n) % n;
  };
  if (b.empty()) {
    b = "{";
    return;
  }
  static const char* kTokens[] = {"[",           "]",          "{",
                                  "}",           ",",          ":",
                                  "\"",          "\\",         "null",
                                  "true",        "-0",         "1e999",
                                  "-1e308",      "4294967296", "18446744073709551616",
                                  "-1",          "0.5",        "1e-320",
                                  "\"\\u0000\"", "\"index\":", "\"Texture\":{",
                                  "\"extras\":", "\"asset\":{"};
  switch (below(10)) {
    case 0:
      b[below(b.size())] ^= static_cast<char>(1 << below(8));
      break;
    case 1:
      b[below(b.size())] = static_cast<char>(below(256));
      break;
    case 2:
    case 3:
      b.insert(below(b.size() + 1), kTokens[below(sizeof kTokens / sizeof kTokens[0])]);
      break;
    case 4: {  // a deep or a nearly too deep run of brackets
      size_t n = rng.Uniform() < 0.5 ? 50 + below(30) : 1 + below(5000);
      b.insert(below(b.size() + 1), std::string(n, rng.Uniform() < 0.5 ? '[' : '{'));
      break;
    }
    case 5: {  // replace a number by an absurd one
      size_t p = b.find_first_of("0123456789", below(b.size()));
      if (p == std::string::npos) break;
      size_t e = b.find_first_not_of("0123456789.eE+-", p);
      b.replace(p, (e == std::string::npos ? b.size() : e) - p, kTokens[10 + below(8)]);
      break;
    }
    case 6: {  // duplicate a span
      size_t p = below(b.size()), n = std::min(b.size() - p, 1 + below(200));
      b.insert(below(b.size() + 1), b.substr(p, n));
      break;
    }
    case 7: {  // remove a span
      size_t p = below(b.size());
      b.erase(p, std::min(b.size() - p, 1 + below(64)));
      break;
    }
    case 8:
      b.resize(below(b.size()));
      break;
    default: {  // an int32 in the glb header and chunk headers
      static const uint32_t kInts[] = {0,           1,  0xFFFFFFFFu, 0x7FFFFFFF,
                                       0x80000000u, 12, 20,          0x4E4F534A};
      size_t p = below(std::min<size_t>(b.size(), 28));
      uint32_t v = kInts[below(8)];
      for (int k = 0; k < 4 && p + k < b.size(); ++k) b[p + k] = static_cast<char>(v >> (8 * k));
    }
  }
}

/// Plans `count` mutants (1 to 4 mutations each) of the committed scenes: each must be planned
/// or refused with a one-line std::exception (a crash ends the test run). Prints a summary.
void SceneMutationLoop(int count, uint64_t seed) {
  std::vector<std::string> seeds = SceneSeeds(), seedBytes;
  REQUIRE(seeds.size() >= 5);
  for (const std::string& s : seeds) seedBytes.push_back(test::ReadFile(s));
  ScratchDir dir("scene_fuzz_" + std::to_string(seed));
  test::Rng rng(seed);
  int planned = 0, refused = 0, failures = 0;
  double rssBefore = PeakRssMiB();
  for (int i = 0; i < count; ++i) {
    size_t k = static_cast<size_t>(rng.Uniform() * seeds.size()) % seeds.size();
    std::string bytes = seedBytes[k];
    int n = 1 + static_cast<int>(rng.Uniform() * 4);
    for (int m = 0; m < n; ++m) MutateScene(bytes, rng);
    std::string ext = std::filesystem::path(seeds[k]).extension().string();
    std::string path = dir / ("mutant" + ext);
    WriteFile(path, bytes);
    std::string problem;
    try {
      PlanSceneFile(path);
      ++planned;
    } catch (const std::exception& e) {
      std::string what = e.what();
      if (what.empty() || what.find('\n') != std::string::npos)
        problem = "bad message: " + what;
      else
        ++refused;
    }
    if (!problem.empty()) {
      WriteFile(
          "/tmp/kiln-scene-fuzz-failure-" + std::to_string(seed) + "-" + std::to_string(i) + ext,
          bytes);
      if (failures++ < 5) FAIL_CHECK("mutation " << i << " of " << seeds[k] << ": " << problem);
    }
  }
  double rssAfter = PeakRssMiB();
  std::printf(
      "stress fuzz: %d scene mutants planned (seed %llu): %d planned, %d refused with one line, "
      "%d failures; peak RSS %.0f MiB (%.0f before)\n",
      count, static_cast<unsigned long long>(seed), planned, refused, failures, rssAfter,
      rssBefore);
  CHECK(failures == 0);
  // No mutant may cost more than 256 MB (a bound on the growth of this process's peak).
  CHECK(rssAfter - rssBefore < 256);
}

}  // namespace

TEST_CASE("2000 mutations of the committed scenes: planned or refused with one line, never a crash",
          "[stress][hostile][scene][fuzz]") {
  SceneMutationLoop(2000, 20261201);
}

TEST_CASE("100000 mutations of the committed scenes", "[stress][hostile][scene][fuzz][long]") {
  SceneMutationLoop(100000, 1717);
}
