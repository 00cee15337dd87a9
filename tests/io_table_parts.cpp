// Specification of tables of more than 4 channels (the ltc tables' 6: minv_a..d, norm, fresnel)
// in files: every format stores them as two RGBA-style textures, NAME-1 (channels 0-3, the
// published ltc_1: M^-1's a, b, c, d as R, G, B, A) and NAME-2 (channels 4-5, ltc_2's x, y),
// each self-describing (its own channels, which part of how many, the whole table's channels);
// kiln's readers load the whole table from either file; the manifest has one entry listing both.
#include <catch2/catch.hpp>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/io/exr_writer.h"
#include "baker/io/texture_readers.h"
#include "baker/io/texture_writers.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"

namespace fs = std::filesystem;

namespace {

std::string scratch(const std::string& tag) {
  fs::path dir =
      fs::temp_directory_path() / ("kiln-io-parts-" + tag + "-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

/// A 6-channel table shaped like an ltc table (3 x 2 nodes), values 0.01 (texel + 7 channel).
kiln::Table sixChannels() {
  kiln::Table t;
  t.generator = "kiln test";
  t.name = "ltc-test";
  t.model = "ggx";
  t.quantity = "ltc";
  t.channels = {"minv_a", "minv_b", "minv_c", "minv_d", "norm", "fresnel"};
  t.channelMeanings = {"a", "b", "c", "d", "n", "f"};
  t.axes = {{"roughness", {0, 1, 3, kiln::Warp::Linear}},
            {"sqrt_one_minus_mu", {0, 1, 2, kiln::Warp::Linear}}};
  t.specHash = "0123456789abcdef";
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 6; ++c) t.data.push_back(0.01f * float(i + 7 * c));
  return t;
}

std::vector<std::string> exrChannels(const std::string& path) {
  Imf::InputFile in(path.c_str());
  std::vector<std::string> names;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it)
    names.push_back(it.name());
  return names;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("a 6-channel table is two EXRs, NAME-1 (R, G, B, A) and NAME-2 (R, G, B unused)",
          "[io][exr][parts]") {
  const std::string dir = scratch("exr");
  const kiln::Table t = sixChannels();
  kiln::CommitBakedTable(dir, t, 0, /*half=*/false, /*header=*/false);
  CHECK_FALSE(fs::exists(dir + "/ltc-test.exr"));
  CHECK(exrChannels(dir + "/ltc-test-1.exr") == std::vector<std::string>{"A", "B", "G", "R"});
  CHECK(exrChannels(dir + "/ltc-test-2.exr") == std::vector<std::string>{"B", "G", "R"});
  {
    Imf::InputFile in((dir + "/ltc-test-2.exr").c_str());
    const Imf::Header& h = in.header();
    CHECK(h.typedAttribute<Imf::IntAttribute>("kiln.part").value() == 2);
    CHECK(h.typedAttribute<Imf::IntAttribute>("kiln.parts").value() == 2);
    CHECK(h.typedAttribute<Imf::StringAttribute>("kiln.channels").value() == "norm,fresnel");
    CHECK(h.typedAttribute<Imf::StringAttribute>("kiln.table_channels").value() ==
          "minv_a,minv_b,minv_c,minv_d,norm,fresnel");
    CHECK(h.typedAttribute<Imf::StringAttribute>("kiln.unused_channels").value() == "B");
  }
  // Either file gives the whole table.
  for (const char* file : {"/ltc-test-1.exr", "/ltc-test-2.exr"}) {
    INFO(file);
    const kiln::Table back = kiln::loadTable(dir + file);
    CHECK(back.channels == t.channels);
    CHECK(back.channelMeanings == t.channelMeanings);
    CHECK(back.data == t.data);
    CHECK(back.view().channels == 6);
  }
  // The manifest: one entry for the table, its "file" part 1 and "files" both.
  const nlohmann::json m = readJson(dir + "/manifest.json");
  REQUIRE(m["tables"].size() == 1);
  CHECK(m["tables"][0]["file"] == "ltc-test-1.exr");
  CHECK(m["tables"][0]["files"] == nlohmann::json::array({"ltc-test-1.exr", "ltc-test-2.exr"}));
  CHECK(m["tables"][0]["layout"] == kiln::kLayoutVersion);

  // A part missing or of another table: refused in one line naming the other part.
  fs::rename(dir + "/ltc-test-2.exr", dir + "/moved.exr");
  kiln::Table unused;
  std::string error;
  CHECK_FALSE(kiln::loadTable(dir + "/ltc-test-1.exr", unused, error));
  CHECK_THAT(error, Catch::Contains("part 2") && Catch::Contains("ltc-test-2.exr"));
  CHECK(error.find('\n') == std::string::npos);
  kiln::Table other = sixChannels();
  other.specHash = "fedcba9876543210";
  kiln::writeTable(dir + "/other.exr", other, false);
  fs::rename(dir + "/other-2.exr", dir + "/ltc-test-2.exr");
  CHECK_FALSE(kiln::loadTable(dir + "/ltc-test-1.exr", unused, error));
  CHECK_THAT(error, Catch::Contains("spec hash"));
  fs::remove_all(dir);
}

TEST_CASE("a 6-channel table loads from either file of its KTX2, DDS and PNG16 pairs",
          "[io][parts][ktx2][dds][png16]") {
  const kiln::Table t = sixChannels();
  for (kiln::OutputFormat format :
       {kiln::OutputFormat::Ktx2, kiln::OutputFormat::Dds, kiln::OutputFormat::Png16}) {
    INFO(kiln::FormatName(format));
    const std::string dir = scratch(kiln::FormatName(format));
    const std::string ext = kiln::FormatExtension(format);
    kiln::CommitBakedTable(dir, t, 0, false, false, 1, format);
    CHECK_FALSE(fs::exists(dir + "/ltc-test" + ext));
    for (const std::string& file : {"/ltc-test-1" + ext, "/ltc-test-2" + ext}) {
      INFO(file);
      const kiln::Table back = kiln::LoadAnyTable(dir + file);
      REQUIRE(back.channels == t.channels);
      REQUIRE(back.data.size() == t.data.size());
      for (std::size_t i = 0; i < t.data.size(); ++i)
        CHECK(std::fabs(back.data[i] - t.data[i]) <= 0.5 / 65535);  // exact but for PNG16
    }
    // Part 1 alone is an RGBA texture of channels 0-3 (the published ltc_1).
    kiln::Table first = kiln::tablePart(t, 1);
    CHECK(first.channels == std::vector<std::string>{"minv_a", "minv_b", "minv_c", "minv_d"});
    const nlohmann::json m = readJson(dir + "/manifest.json");
    CHECK(m["tables"][0]["files"].size() == 2);
    fs::remove_all(dir);
  }
}

TEST_CASE("kiln sample, inspect and verify take either file of an ltc pair, in EXR and KTX2",
          "[io][parts][cli]") {
  const std::string dir = kiln::test::TempDir("ltc_pair");
  for (const char* format : {"exr", "ktx2"}) {
    kiln::test::CommandResult bake = kiln::test::RunKiln(
        std::string("bake --quiet --only ltc-ggx --size 6 -j 1 --format ") +
        format + " --out " + dir);
    INFO(bake.err);
    REQUIRE(bake.exitCode == 0);
  }
  const std::string exr1 = kiln::test::RunKiln("sample " + dir + "/ltc-ggx-1.exr 0.4 0.6").out;
  REQUIRE(std::count(exr1.begin(), exr1.end(), ' ') == 5);  // six channels
  for (const char* file : {"/ltc-ggx-2.exr", "/ltc-ggx-1.ktx2", "/ltc-ggx-2.ktx2"}) {
    INFO(file);
    CHECK(kiln::test::RunKiln("sample " + dir + file + " 0.4 0.6").out == exr1);
  }
  const kiln::test::CommandResult inspect =
      kiln::test::RunKiln("inspect " + dir + "/ltc-ggx-2.exr");
  CHECK(inspect.exitCode == 0);
  CHECK(inspect.out.find("channel R = minv_a") != std::string::npos);
  CHECK(inspect.out.find("channel 2:G = fresnel") != std::string::npos);
  // A folder lists the pair once (part 1); naming part 2 checks the same table.
  const kiln::test::CommandResult folder =
      kiln::test::RunKiln("verify " + dir + " -j 1 --points 4");
  INFO(folder.out << folder.err);
  CHECK(folder.exitCode == 0);
  CHECK(folder.out.find("1 tables, 0 over their bound") != std::string::npos);
  CHECK(kiln::test::RunKiln("verify " + dir + "/ltc-ggx-2.exr -j 1 --points 4").exitCode == 0);
  fs::remove_all(dir);
}
