// Specification of kiln's reader of its own texture files (issue #14, baker/io/texture_readers.h):
// a KTX2, a DDS and a 16-bit PNG of a table come back through kiln's loader with the same
// metadata and texels within the format's precision (float32 exactly, float16 to half rounding,
// PNG16 to scale / 131070); `kiln sample` and `kiln inspect` read them like the EXR; a second
// bake in the same format skips the table; one folder keeps a manifest entry per file; damaged
// files are refused with one line.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/io/texture_readers.h"
#include "baker/io/texture_writers.h"
#include "baker/tables/engine_layout.h"
#include "cli_util.h"
#include "io_texture_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {

void CheckSameDescription(const Table& got, const Table& want) {
  CHECK(got.name == want.name);
  CHECK(got.model == want.model);
  CHECK(got.quantity == want.quantity);
  CHECK(got.channels == want.channels);
  CHECK(got.channelMeanings == want.channelMeanings);
  REQUIRE(got.dims() == want.dims());
  for (int d = 0; d < got.dims(); ++d) {
    CHECK(got.axes[d].name == want.axes[d].name);
    CHECK(got.axes[d].axis.lo == want.axes[d].axis.lo);
    CHECK(got.axes[d].axis.hi == want.axes[d].axis.hi);
    CHECK(got.axes[d].axis.size == want.axes[d].axis.size);
    CHECK(got.axes[d].axis.warp == want.axes[d].axis.warp);
  }
  CHECK(got.params == want.params);
  CHECK(got.specHash == want.specHash);
  CHECK(got.bakeError == want.bakeError);
  CHECK(got.lookupError.max == want.lookupError.max);
  REQUIRE(got.data.size() == want.data.size());
}

/// The largest |got - want| over the texels.
double MaxDifference(const Table& got, const Table& want) {
  double worst = 0;
  for (size_t i = 0; i < got.data.size(); ++i)
    worst = std::max(worst, std::fabs(double(got.data[i]) - want.data[i]));
  return worst;
}

}  // namespace

TEST_CASE("a KTX2 file decodes to the table it was written from", "[io][ktx2][roundtrip]") {
  Table t = SmallGgxDfg(9);
  t.specHash = "0123456789abcdef";
  SECTION("float32: every texel bit for bit") {
    Table back = DecodeKtx2(EncodeKtx2(t, false));
    CheckSameDescription(back, t);
    CHECK(back.data == t.data);
  }
  SECTION("float16: every texel is the half it was rounded to") {
    Table back = DecodeKtx2(EncodeKtx2(t, true));
    CheckSameDescription(back, t);
    for (size_t i = 0; i < t.data.size(); ++i) CHECK(WithinHalf(back.data[i], t.data[i]));
  }
  SECTION("a 3D table keeps its slices in order") {
    Table cube = Small3D();
    Table back = DecodeKtx2(EncodeKtx2(cube, false));
    CHECK(back.data == cube.data);
  }
  SECTION("rows written flipped (--flip-y) come back in kiln order") {
    Table flipped = t;
    flipped.params = "flip_y=1";
    Table back = DecodeKtx2(EncodeKtx2(flipped, false));
    CHECK(FlipsY(back));
    CHECK(back.data == t.data);
  }
}

TEST_CASE("a DDS file decodes with its manifest entry as description", "[io][dds][roundtrip]") {
  Table t = SmallGgxDfg(9);
  t.specHash = "0123456789abcdef";
  nlohmann::ordered_json entry;
  entry["name"] = t.name;
  entry["file"] = t.name + ".dds";
  entry["generator"] = t.generator;
  // The keys the manifest writes (bake.cpp ManifestText): AppendTableDescription + spec_hash.
  nlohmann::ordered_json full = nlohmann::ordered_json::parse(
      R"({"model":"","quantity":"","channels":[],"channel_meanings":[],"axes":[],"params":"",
          "method":"","tolerance":0,"bake_error":0,"spec_hash":""})");
  full["name"] = t.name;
  full["model"] = t.model;
  full["quantity"] = t.quantity;
  full["channels"] = t.channels;
  full["channel_meanings"] = t.channelMeanings;
  for (const TableAxis& a : t.axes)
    full["axes"].push_back({{"name", a.name},
                            {"lo", a.axis.lo},
                            {"hi", a.axis.hi},
                            {"size", a.axis.size},
                            {"warp", warpName(a.axis.warp)}});
  full["params"] = t.params;
  full["method"] = t.method;
  full["tolerance"] = t.tolerance;
  full["bake_error"] = t.bakeError;
  full["spec_hash"] = t.specHash;
  SECTION("float32 exactly, float16 to half rounding") {
    CHECK(DecodeDds(EncodeDds(t, false), full).data == t.data);
    Table half = DecodeDds(EncodeDds(t, true), full);
    for (size_t i = 0; i < t.data.size(); ++i) CHECK(WithinHalf(half.data[i], t.data[i]));
  }
  SECTION("a description whose axes disagree with the file is refused") {
    full["axes"][0]["size"] = 10;
    CHECK_THROWS_WITH(DecodeDds(EncodeDds(t, false), full), Catch::Contains("9 x 9 x 1"));
  }
}

TEST_CASE("a 16-bit PNG decodes within its quantisation step", "[io][png16][roundtrip]") {
  Table t = SmallGgxDfg(9);
  t.specHash = "0123456789abcdef";
  Table back = DecodePng16(EncodePng16(t));
  CheckSameDescription(back, t);
  // stored / 65535 * scale + offset: rounding errs by at most scale / 131070 (plus float).
  for (const Png16Channel& c : Png16Scales(t)) CHECK(c.scale <= 1.0);
  CHECK(MaxDifference(back, t) <= 1.0 / 131070 + 1e-7);
  CHECK(MaxDifference(back, t) > 0);  // quantised: not the float bits (the test can fail)
}

TEST_CASE("damaged texture files are refused with a reason", "[io][roundtrip][hostile]") {
  Table t = SmallGgxDfg(5);
  std::string ktx = EncodeKtx2(t, false);
  CHECK_THROWS_WITH(DecodeKtx2(ktx.substr(0, ktx.size() - 8)), Catch::Contains("truncated"));
  CHECK_THROWS_WITH(DecodeKtx2(ktx.substr(0, 40)), Catch::Contains("truncated"));
  std::string png = EncodePng16(t);
  std::string corrupt = png;
  corrupt[png.size() / 2] ^= 0x55;
  CHECK_THROWS_WITH(DecodePng16(corrupt), Catch::Contains("CRC"));
  CHECK_THROWS_WITH(DecodePng16(png.substr(0, png.size() - 12)), Catch::Contains("IEND"));
  CHECK_THROWS_WITH(DecodeKtx2(png), Catch::Contains("not a KTX2"));
  CHECK_THROWS_WITH(DecodeDds(std::string("DDS xxxx"), nlohmann::ordered_json::object()),
                    Catch::Contains("header size"));
}

TEST_CASE("kiln reads every format it bakes, skips it when up to date, and keeps an entry per file",
          "[io][roundtrip][cli]") {
  std::string dir = TempDir("cli");
  for (const char* format : {"exr", "ktx2", "dds", "png16"}) {
    CommandResult r = RunKiln(std::string("bake --only ggx-dfg --size 12 --no-lookup-error -j 1 ") +
                              "--format " + format + " --out " + dir);
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
  }
  // The manifest has one entry per file, all of the same table.
  auto m = nlohmann::json::parse(ReadFile(dir + "/manifest.json"));
  std::set<std::string> files;
  for (auto& e : m["tables"]) files.insert(e["file"].get<std::string>());
  CHECK(files ==
        std::set<std::string>{"ggx-dfg.dds", "ggx-dfg.exr", "ggx-dfg.ktx2", "ggx-dfg.png"});

  // sample reads each; the float32 formats give the EXR's answer bit for bit.
  std::string exr = RunKiln("sample " + dir + "/ggx-dfg.exr 0.3 0.4").out;
  REQUIRE(!exr.empty());
  CHECK(RunKiln("sample " + dir + "/ggx-dfg.ktx2 0.3 0.4").out == exr);
  CHECK(RunKiln("sample " + dir + "/ggx-dfg.dds 0.3 0.4").out == exr);
  CommandResult png = RunKiln("sample " + dir + "/ggx-dfg.png 0.3 0.4");
  REQUIRE(png.exitCode == 0);
  double a = 0, b = 0, pa = 0, pb = 0;
  REQUIRE(std::sscanf(exr.c_str(), "%lf %lf", &a, &b) == 2);
  REQUIRE(std::sscanf(png.out.c_str(), "%lf %lf", &pa, &pb) == 2);
  CHECK(std::fabs(pa - a) <= 1.0 / 131070 + 1e-7);
  CHECK(std::fabs(pb - b) <= 1.0 / 131070 + 1e-7);
  CommandResult inspect = RunKiln("inspect " + dir + "/ggx-dfg.ktx2");
  CHECK(inspect.exitCode == 0);
  CHECK(inspect.out.find("channel R = A") != std::string::npos);

  // A second bake in each format skips the table.
  for (const char* format : {"ktx2", "dds", "png16"}) {
    CommandResult r = RunKiln(std::string("bake --only ggx-dfg --size 12 --no-lookup-error -j 1 ") +
                              "--format " + format + " --out " + dir);
    INFO(format << ": " << r.err);
    CHECK(r.err.find("0 baked, 1 skipped") != std::string::npos);
  }
  // ... but not when the pixel type asked for differs from the file's.
  CommandResult half = RunKiln(
      "bake --only ggx-dfg --size 12 --no-lookup-error -j 1 --half "
      "--format ktx2 --out " +
      dir);
  CHECK(half.err.find("1 baked, 0 skipped") != std::string::npos);

  // A DDS without its manifest has no description: one line, exit 1.
  std::filesystem::copy_file(dir + "/ggx-dfg.dds", dir + "/lonely.dds");
  std::filesystem::create_directories(dir + "/alone");
  std::filesystem::rename(dir + "/lonely.dds", dir + "/alone/lonely.dds");
  CommandResult lonely = RunKiln("sample " + dir + "/alone/lonely.dds 0.3 0.4");
  CHECK(lonely.exitCode != 0);
  CHECK(lonely.err.find("manifest.json must be beside it") != std::string::npos);
  CHECK(CountLines(lonely.err) == 1);
  // A file shorter than the sniffed bytes is read to its end, and refused for what it is.
  {
    std::ofstream(dir + "/short.png", std::ios::binary) << std::string("\x89PNG\r\n\x1a\n", 8);
    CommandResult tiny = RunKiln("inspect " + dir + "/short.png");
    CHECK(tiny.exitCode != 0);
    CHECK(tiny.err.find("truncated PNG") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
