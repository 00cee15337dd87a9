// Stress: every command that reads a file, given a hostile one, answers with one clear line on
// stderr and a non-zero exit, never a crash: `kiln inspect`, `kiln sample`, `kiln verify` (a
// file, and a folder mixing good and bad files), `kiln plan` and `kiln bake --scene` with a bad
// scene. A hostile table where a good one is expected in the output folder is "stale" to
// `kiln plan` and replaced by `kiln bake --scene`. The loader's own refusals (and their messages)
// are specified in tests/io_exr_roundtrip.cpp; here the point is the commands around it.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "baker/io/exr_writer.h"
#include "kiln/exr_loader.h"
#include "scene_util.h"
#include "stress_util.h"
#include "test_util.h"

using namespace kiln;
using namespace kiln::stress;
using kiln::test::CountLines;
using kiln::test::ReadFile;

namespace {

/// Writes `t`'s texels as FLOAT channels with the header `h` (kiln attributes as edited by the
/// caller); `extra` more channels of zeros are added after the table's own.
void WriteRaw(const std::string& path, Imf::Header h, const Table& t, int extra = 0) {
  int width = t.imageWidth(), height = t.imageHeight();
  size_t nc = t.channels.size(), pixels = size_t(width) * height;
  std::vector<std::vector<float>> planes(nc + extra, std::vector<float>(pixels, 0.0f));
  for (size_t p = 0; p < pixels; ++p)
    for (size_t c = 0; c < nc; ++c) planes[c][p] = t.data[p * nc + c];
  Imf::FrameBuffer fb;
  for (size_t c = 0; c < nc + extra; ++c) {
    std::string name = c < nc ? t.channels[c] : "extra" + std::to_string(c);
    h.channels().insert(name, Imf::Channel(Imf::FLOAT));
    fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()), sizeof(float),
                               sizeof(float) * width));
  }
  Imf::OutputFile file(path.c_str(), h);
  file.setFrameBuffer(fb);
  file.writePixels(height);
}

/// A header carrying `t`'s kiln attributes, sized to its image.
Imf::Header KilnHeader(const Table& t) {
  Imf::Header h(t.imageWidth(), t.imageHeight());
  setKilnAttributes(h, t);
  return h;
}

/// Pseudo-random bytes (a fixed LCG).
std::string RandomBytes(size_t n, uint32_t seed) {
  std::string b(n, '\0');
  for (char& c : b) c = static_cast<char>((seed = seed * 1103515245u + 12345u) >> 16);
  return b;
}

struct Hostile {
  std::string name;  ///< what is wrong
  std::string path;
};

/// A good kiln table (fresnel-dielectric at 5 x 5, baked by the CLI) and hostile variants of it:
/// broken files the loader refuses, and loadable kiln tables whose metadata make no sense.
struct Fixture {
  ScratchDir dir{"hostile_files"};
  std::string good;
  Table table;
  std::vector<Hostile> refused;  ///< the loader refuses these
  std::vector<Hostile> absurd;   ///< these load, but their spec cannot be evaluated as declared
  Hostile wide;                  ///< loads; 12 channels where the quantity has 1 (see below)

  Fixture() {
    auto r = RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir / "good"));
    REQUIRE(r.exitCode == 0);
    good = dir / "good/fresnel-dielectric.exr";
    table = loadTable(good);
    std::string bytes = ReadFile(good);
    auto file = [&](const std::string& name, const std::function<void(const std::string&)>& make) {
      std::string path = dir / (name + ".exr");
      make(path);
      return Hostile{name, path};
    };
    auto edited = [&](const std::string& name, const std::function<void(Imf::Header&)>& edit,
                      int extra = 0) {
      return file(name, [&](const std::string& p) {
        Imf::Header h = KilnHeader(table);
        edit(h);
        WriteRaw(p, h, table, extra);
      });
    };
    auto withTable = [&](const std::string& name, const std::function<void(Table&)>& edit) {
      return file(name, [&](const std::string& p) {
        Table t = table;
        edit(t);
        WriteRaw(p, KilnHeader(t), t);
      });
    };
    refused = {
        {"missing file", dir / "no-such.exr"},
        file("a folder", [](const std::string& p) { std::filesystem::create_directory(p); }),
        file("empty", [](const std::string& p) { WriteFile(p, ""); }),
        file("truncated header", [&](const std::string& p) { WriteFile(p, bytes.substr(0, 60)); }),
        file("truncated in half",
             [&](const std::string& p) { WriteFile(p, bytes.substr(0, bytes.size() / 2)); }),
        file("truncated pixels",
             [&](const std::string& p) { WriteFile(p, bytes.substr(0, bytes.size() - 16)); }),
        file("random bytes", [](const std::string& p) { WriteFile(p, RandomBytes(4096, 7)); }),
        file("EXR magic, then random",
             [](const std::string& p) {
               WriteFile(p, std::string("\x76\x2f\x31\x01\x02\0\0\0", 8) + RandomBytes(4096, 8));
             }),
        file("a PNG",
             [](const std::string& p) { WriteFile(p, "\x89PNG\r\n\x1a\n" + RandomBytes(100, 9)); }),
        file("plain EXR without kiln attributes",
             [&](const std::string& p) {
               WriteRaw(p, Imf::Header(table.imageWidth(), table.imageHeight()), table);
             }),
        edited("format version 2",
               [](Imf::Header& h) { h.insert("kiln.format", Imf::IntAttribute(2)); }),
        edited("format version -1",
               [](Imf::Header& h) { h.insert("kiln.format", Imf::IntAttribute(-1)); }),
        edited(
            "an extra channel", [](Imf::Header&) {}, 1),
        edited("kiln.channels names two channels, the image has one",
               [](Imf::Header& h) { h.insert("kiln.channels", Imf::StringAttribute("F,G")); }),
        edited("axis size 2^30",
               [](Imf::Header& h) { h.insert("kiln.axis0.size", Imf::IntAttribute(1 << 30)); }),
        edited("axis size -5",
               [](Imf::Header& h) { h.insert("kiln.axis1.size", Imf::IntAttribute(-5)); }),
        edited("dims 1000", [](Imf::Header& h) { h.insert("kiln.dims", Imf::IntAttribute(1000)); }),
        withTable("NaN texel",
                  [](Table& t) { t.data[3] = std::numeric_limits<float>::quiet_NaN(); }),
        withTable("infinite texel",
                  [](Table& t) { t.data[0] = std::numeric_limits<float>::infinity(); }),
        // Issue #17: these loaded, and verify reported its worst point at mu = inf.
        withTable("axis lo -1e308, hi 1e308",
                  [](Table& t) {
                    t.axes[0].axis = {-1e308, 1e308, 5, Warp::Linear};
                  }),
        withTable("axis hi 1e7", [](Table& t) { t.axes[1].axis.hi = 1e7; }),
    };
    absurd = {
        withTable("unknown quantity", [](Table& t) { t.quantity = "volume"; }),
        withTable("unknown model",
                  [](Table& t) {
                    t.model = "phong-ish";
                    t.quantity = "albedo";
                    t.axes[1].name = "roughness";
                    t.axes[1].axis = {0, 1, 5, Warp::Linear};
                  }),
        withTable("unparseable params", [](Table& t) { t.params = "roughness=abc"; }),
        withTable("params without '='", [](Table& t) { t.params = "roughness"; }),
        withTable("a 2-axis quantity with 1 axis",
                  [](Table& t) {
                    t.quantity = "dfg";
                    t.model = "ggx";
                    t.axes.resize(1);
                    t.data.resize(5);
                    t.axes[0].axis.size = 5;
                    // (the good table's layer-eta mu axis needs a second axis to load at all)
                    t.axes[0].axis.warp = Warp::Root4;
                  }),
        withTable("out-of-range roughness axis",
                  [](Table& t) {
                    t.model = "ggx";
                    t.quantity = "albedo";
                    t.axes[1] = {"roughness", {0, 7, 5, Warp::Linear}};
                  }),
    };
    wide = withTable("more channels than the quantity has (12)", [](Table& t) {
      std::vector<float> data;
      t.channels.clear();
      t.channelMeanings.clear();
      for (int c = 0; c < 12; ++c) t.channels.push_back("c" + std::to_string(c));
      for (size_t i = 0; i < 25; ++i)
        for (int c = 0; c < 12; ++c) data.push_back(0.5f);
      t.data = data;
    });
    absurd.push_back(wide);
    // Each absurd file must load: the test is about what the commands do with it.
    for (const Hostile& h : absurd) {
      Table t;
      std::string error;
      bool loaded = loadTable(h.path, t, error);
      INFO(h.name << ": " << error);
      REQUIRE(loaded);
    }
  }
};

/// INFO text for a run.
std::string Describe(const std::string& args, const test::CommandResult& r) {
  return "kiln " + args + "\n  exit " + std::to_string(r.exitCode) + "\n  stdout: " + r.out +
         "\n  stderr: " + r.err;
}

}  // namespace

TEST_CASE("kiln inspect and kiln sample refuse every hostile file with one line naming it",
          "[stress][hostile][cli]") {
  Fixture fx;
  for (const Hostile& h : fx.refused) {
    for (const std::string& args :
         {"inspect " + Quote(h.path),
          "inspect " + Quote(h.path) + " --png " + Quote(fx.dir / "x.png"),
          "sample " + Quote(h.path) + " 0.5 1.5", "sample " + Quote(h.path) + " 0.5 1.5 --cubic"}) {
      auto r = RunKilnFor(60, args);
      INFO(h.name << ": " << Describe(args, r));
      CHECK(IsCleanRefusal(r));
      CHECK(r.err.find(h.path) != std::string::npos);
    }
  }
  CHECK_FALSE(std::filesystem::exists(fx.dir / "x.png"));
}

TEST_CASE("kiln inspect and kiln sample handle loadable tables with absurd metadata",
          "[stress][hostile][cli]") {
  Fixture fx;
  for (const Hostile& h : fx.absurd) {
    // inspect only prints the attributes; sample --clamp only interpolates (a point outside the
    // absurd axes is clamped to them): both work on any valid table.
    auto i = RunKilnFor(60, "inspect " + Quote(h.path));
    INFO(h.name << ": " << Describe("inspect", i));
    CHECK(i.exitCode == 0);
    int dims = loadTable(h.path).dims();
    std::string coords = dims == 1 ? "0.5" : "0.5 1.5";
    auto s = RunKilnFor(60, "sample " + Quote(h.path) + " " + coords + " --clamp");
    INFO(Describe("sample " + coords, s));
    CHECK(s.exitCode == 0);
    CHECK(CountLines(s.out) == 1);
  }
}

TEST_CASE("kiln sample refuses NaN, infinite and missing coordinates", "[stress][hostile][cli]") {
  Fixture fx;
  for (const char* coords :
       {"nan 1.5", "0.5 inf", "-inf 1", "0.5", "0.5 1.5 2", "abc 1", "1e999 1"}) {
    std::string args = "sample " + Quote(fx.good) + " " + coords;
    auto r = RunKilnFor(60, args);
    INFO(Describe(args, r));
    CHECK(IsCleanRefusal(r));
  }
}

TEST_CASE("kiln verify refuses every hostile file, and checks the good ones in the same folder",
          "[stress][hostile][cli]") {
  Fixture fx;
  for (const Hostile& h : fx.refused) {
    std::string args = "verify " + Quote(h.path) + " --points 20 -j 2 --quiet";
    auto r = RunKilnFor(60, args);
    INFO(h.name << ": " << Describe(args, r));
    CHECK(IsCleanRefusal(r, /*allowStdout=*/true));  // the report table goes to stdout
    if (h.name != "missing file" && h.name != "a folder")
      CHECK(r.out.find("FAILED") != std::string::npos);
  }
  // (the absurd-but-valid files: the next test, which checks more of the same runs)
  // A folder of good and bad tables: every file is reported, the good one passes, exit 1.
  ScratchDir mixed("hostile_mixed");
  std::filesystem::copy_file(fx.good, mixed / "a-good.exr");
  for (const Hostile& h : fx.refused)
    if (std::filesystem::is_regular_file(h.path))
      std::filesystem::copy_file(
          h.path, mixed / ("z-" + std::filesystem::path(h.path).filename().string()));
  auto r = RunKilnFor(60, "verify " + Quote(mixed.path.string()) + " --points 20 -j 2 --quiet");
  INFO(Describe("verify <mixed folder>", r));
  CHECK(IsCleanRefusal(r, true));
  CHECK(r.out.find(mixed / "a-good.exr") != std::string::npos);
  CHECK(r.out.find("a-good.exr FAILED") == std::string::npos);
  CHECK(CountLines(r.out) >= 3);
}

// A table of any channel count is measured without overflowing a buffer (the lookup error once
// sampled into `float got[8]`), and a table whose metadata cannot be evaluated (unreadable
// params, unknown model or quantity, more or fewer channels than its quantity) is reported as
// "FILE FAILED: reason" on its own line, the files after it still checked, exit 1.
TEST_CASE(
    "kiln verify survives a table with more than 8 channels, and names the file when a "
    "table's metadata cannot be evaluated",
    "[stress][hostile][cli]") {
  Fixture fx;
  for (const Hostile& h : fx.absurd) {
    std::string args = "verify " + Quote(h.path) + " --points 20 -j 2 --quiet";
    auto r = RunKilnFor(60, args);
    INFO(h.name << ": " << Describe(args, r));
    CHECK(IsCleanRefusal(r, true));
    CHECK((r.err.find(h.path) != std::string::npos ||
           r.out.find(h.path + " FAILED") != std::string::npos ||
           r.out.find("EXCEEDS BOUND") != std::string::npos));
  }
  // All of them in one folder, with the good table last: each is reported, the good one passes.
  ScratchDir mixed("hostile_absurd_mixed");
  for (const Hostile& h : fx.absurd)
    std::filesystem::copy_file(h.path, mixed / std::filesystem::path(h.path).filename().string());
  std::filesystem::copy_file(fx.good, mixed / "zz-good.exr");
  auto r = RunKilnFor(120, "verify " + Quote(mixed.path.string()) + " --points 20 -j 2 --quiet");
  INFO(Describe("verify <absurd folder>", r));
  CHECK(IsCleanRefusal(r, true));
  for (const Hostile& h : fx.absurd)
    CHECK(r.out.find(mixed / std::filesystem::path(h.path).filename().string()) !=
          std::string::npos);
  CHECK(r.out.find(mixed / "zz-good.exr") != std::string::npos);
  CHECK(r.out.find("zz-good.exr FAILED") == std::string::npos);
  CHECK(r.out.find("FAILED: 12 channel(s)") != std::string::npos);
}

TEST_CASE("kiln plan and kiln bake --scene refuse a hostile scene file and write nothing",
          "[stress][hostile][cli][scene]") {
  ScratchDir dir("hostile_scene");
  std::string good = ReadFile(test::ScenePath("metal_rough_factors.gltf"));
  std::string glb = ReadFile(test::ScenePath("box.glb"));
  REQUIRE(!good.empty());
  REQUIRE(glb.size() > 20);
  auto u32 = [](uint32_t v) {
    return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
  };
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"empty.gltf", ""},
      {"random.gltf", RandomBytes(3000, 11)},
      {"random.glb", RandomBytes(3000, 12)},
      {"zeros.gltf", std::string(1000, '\0')},
      {"truncated.gltf", good.substr(0, good.size() / 2)},
      {"truncated.glb", glb.substr(0, glb.size() / 2)},
      {"glb-chunk-past-end.glb",
       "glTF" + u32(2) + u32(28) + u32(0xFFFFFFF0u) + "JSON" + std::string(8, ' ')},
      {"glb-length-zero.glb", "glTF" + u32(2) + u32(0) + u32(0)},
      {"deep.gltf", std::string(200000, '[') + std::string(200000, ']')},
      {"deep-objects.gltf",
       [] {
         std::string s;
         for (int i = 0; i < 100000; ++i) s += "{\"a\":";
         return s + "1" + std::string(100000, '}');
       }()},
      {"huge-number.gltf",
       R"({"asset":{"version":"2.0"},"materials":[{"pbrMetallicRoughness":{"roughnessFactor":1e999}}]})"},
      {"nan-roughness.gltf",
       R"({"asset":{"version":"2.0"},"materials":[{"pbrMetallicRoughness":{"roughnessFactor":NaN}}]})"},
      {"string-roughness.gltf",
       R"({"asset":{"version":"2.0"},"materials":[{"pbrMetallicRoughness":{"roughnessFactor":"0.5"}}]})"},
      {"negative-ior.gltf",
       R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_ior"],"materials":[{"extensions":{"KHR_materials_ior":{"ior":-1e308}}}]})"},
      {"materials-not-array.gltf", R"({"asset":{"version":"2.0"},"materials":{"a":1}})"},
      {"not-utf8.kiln.json", "{\"kiln_scene\": \"\xff\xfe\xfd\"}"},
      {"manifest-nan.kiln.json",
       R"({"kiln_scene":1,"materials":[{"model":"ggx","roughness":[0,1e400]}]})"},
  };
  for (const auto& [name, bytes] : scenes) {
    std::string path = dir / name;
    WriteFile(path, bytes);
    for (const std::string& args :
         {"plan " + Quote(path) + " --out " + Quote(dir / "plan-out"),
          "bake --scene " + Quote(path) + " --out " + Quote(dir / ("out-" + name))}) {
      auto r = RunKilnFor(60, args);
      INFO(name << ": " << Describe(args, r));
      CHECK(IsCleanRefusal(r));
      CHECK(r.err.find(path) != std::string::npos);
    }
    std::string out = dir / ("out-" + name);
    CHECK((!std::filesystem::exists(out) || std::filesystem::is_empty(out)));
  }
  for (const std::string& path : {dir / "no-such.gltf", dir.path.string(), dir / ""}) {
    auto r = RunKilnFor(60, "plan " + Quote(path));
    INFO(Describe("plan " + path, r));
    CHECK(IsCleanRefusal(r));
  }
}

TEST_CASE(
    "A hostile file in the output folder is stale to kiln plan and replaced by kiln bake --scene",
    "[stress][hostile][cli][scene]") {
  ScratchDir dir("hostile_out");
  std::string scene = test::ScenePath("metal_rough_factors.gltf");
  REQUIRE(
      RunKilnFor(60, "bake --scene " + Quote(scene) + " --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::vector<std::string> exrs;
  for (const std::string& e : dir.Entries())
    if (e.size() > 4 && e.substr(e.size() - 4) == ".exr") exrs.push_back(e);
  REQUIRE(exrs.size() >= 2);
  std::string victim = dir / exrs[0], intact = ReadFile(victim);
  for (const std::string& bytes :
       {std::string(), RandomBytes(5000, 3), intact.substr(0, intact.size() / 2)}) {
    WriteFile(victim, bytes);
    WriteFile(dir / "manifest.json", "{\"tables\": [1, 2, {\"name\": 3}");  // a broken manifest too
    auto plan =
        RunKilnFor(60, "plan " + Quote(scene) + " --size 5 --out " + Quote(dir.path.string()));
    INFO(Describe("plan", plan));
    CHECK(plan.exitCode == 0);
    CHECK(plan.out.find("stale") != std::string::npos);
    // A broken manifest is refused, never silently replaced (#17 item 10); moved aside, the bake
    // runs.
    auto refused = RunKilnFor(
        60, "bake --scene " + Quote(scene) + " --size 5 --out " + Quote(dir.path.string()));
    INFO(Describe("bake --scene, broken manifest", refused));
    CHECK(IsCleanRefusal(refused));
    CHECK(refused.err.find("manifest.json is not valid JSON") != std::string::npos);
    std::filesystem::rename(dir / "manifest.json", dir / "manifest.json.bak");
    auto bake = RunKilnFor(
        60, "bake --scene " + Quote(scene) + " --size 5 --out " + Quote(dir.path.string()));
    INFO(Describe("bake --scene", bake));
    CHECK(bake.exitCode == 0);
    CHECK(ReadFile(victim) == intact);  // baked again, bit for bit
    Table t;
    std::string error;
    CHECK(loadTable(victim, t, error));
  }
}

// A number that overflows a double is valid JSON that nlohmann refuses with out_of_range.406
// rather than a parse_error: it is reported like a syntax error, one line naming the file and
// the place of the number.
TEST_CASE("A scene number that overflows a double is refused naming the file",
          "[stress][hostile][cli][scene]") {
  ScratchDir dir("hostile_overflow");
  std::string path = dir / "huge.gltf";
  WriteFile(
      path,
      R"({"asset":{"version":"2.0"},"materials":[{"pbrMetallicRoughness":{"roughnessFactor":1e999}}]})");
  auto r = RunKilnFor(60, "plan " + Quote(path));
  INFO(Describe("plan", r));
  CHECK(IsCleanRefusal(r));
  CHECK(r.err.find(path) != std::string::npos);
  CHECK(r.err.find("line 1, column 84") != std::string::npos);
  CHECK(r.err.find("1e999") != std::string::npos);
}

// Issue #17: a table whose mu axis ends at 1e-320 made `kiln verify` hang like `kiln integrate
// --mu 5e-324` (the masking panels of baker/integrate/hemisphere.h started at a step that rounds
// to 0). Killed after 120 s; it must report the table (its texels are not the integrals at those
// mu, so it may exceed its bound) and end.
TEST_CASE("kiln verify of a table whose mu axis ends at a subnormal terminates",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_subnormal_axis");
  REQUIRE(RunKilnFor(120, "bake --only ggx-albedo --size 5 --out " + Quote(dir.path.string()))
              .exitCode == 0);
  Table t = loadTable(dir / "ggx-albedo.exr");
  REQUIRE(t.axes[0].name == "mu");
  t.axes[0].axis.lo = 0;
  t.axes[0].axis.hi = 1e-320;
  WriteRaw(dir / "subnormal.exr", KilnHeader(t), t);
  std::string args = "verify " + Quote(dir / "subnormal.exr") + " --points 20 -j 2 --quiet";
  auto r = RunKilnFor(120, args);
  INFO(Describe(args, r));
  CHECK((r.exitCode == 0 || IsCleanRefusal(r, true)));
  CHECK(r.out.find("1 tables") != std::string::npos);
}

// Issue #17: the EXR loader allocated before it knew the data existed (a 9.8 KB file declaring a
// 32768 x 16384 x 2 data window cost 4 GiB and 22 s), and OpenEXR's header reading could be
// talked past the attribute-size check (a channel list or a box whose declared size disagrees
// with what OpenEXR reads, then a 1.77 GB string; a string vector or a preview declaring
// gigabytes inside a small attribute). The files are in tests/fuzz_corpus/ (oom-*, loaded by
// every test run, and by kiln inspect with 1 GB of memory in stress_fuzz_loader.cpp); here each
// is refused for its own reason.
TEST_CASE("Crafted headers and data windows are refused from the header, each for its reason",
          "[stress][hostile][io]") {
  const std::string corpus = std::string(KILN_SOURCE_DIR) + "/tests/fuzz_corpus/";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"oom-scanline-window-32768x16384.exr",
       "the data window (32768 x 16384) needs 1024 blocks of scan lines"},
      {"oom-chlist-size-disagrees.exr",
       "attribute 'channels' (chlist) declares 37 bytes but its list ends after 19"},
      {"oom-box2i-size-disagrees.exr",
       "attribute 'dataWindow' (box2i) declares 34 bytes, a box2i has 16"},
      {"fuzz-stringvector-2gb.exr", "a string declares 2000000000 bytes"},
      {"fuzz-preview-40000x40000.exr",
       "declares 8 bytes, its 40000 x 40000 pixels need 6400000008"},
      {"fuzz-axis-1e308.exr", "beyond +-1e6"},
  };
  for (const auto& [file, reason] : cases) {
    Table t;
    std::string error;
    CHECK_FALSE(loadTable(corpus + file, t, error));
    INFO(file << ": " << error);
    CHECK(error.find(reason) != std::string::npos);
    CHECK(error.find('\n') == std::string::npos);
  }
}
