// Specification of the EXR channel names (file layout 2, kiln::kLayoutVersion): kiln writes a
// 1-channel table as `Y`, 2 to 4 channels as R, G, B(, A) in storage order with a 2-channel
// table's B an unused channel of zeros, so that OpenEXR's own RGBA reader and three.js's
// EXRLoader (which opens R, G, B(, A) or Y, nothing else) see a table's values; the kiln names stay
// in kiln.channels. The loader still reads the older namings: R, G (layout 1) and the
// kiln.channels names (before that).
#include <catch2/catch.hpp>

#include <Imath/half.h>
#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/io/exr_writer.h"
#include "baker/tables/catalogue.h"
#include "exr_rgba.h"
#include "kiln/exr_loader.h"

using kiln::test::ReadRgba;

namespace fs = std::filesystem;

namespace {

/// A fresh folder of this test process under the system temporary folder.
std::string scratch(const std::string& tag) {
  fs::path dir =
      fs::temp_directory_path() / ("kiln-io-exr-channels-" + tag + "-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

/// ggx-dfg baked at 8 x 8 nodes (no lookup-error measurement: quick).
kiln::Table smallGgxDfg() {
  kiln::CatalogueOptions copt;
  copt.size = 8;
  kiln::BakeOptions opt;
  opt.threads = 1;
  opt.measureLookupError = false;
  return kiln::BakeTable(kiln::CatalogueTable("ggx-dfg", copt), opt);
}

/// A one-channel 1D table "E" with values 0.1 .. 0.9.
kiln::Table oneChannel() {
  kiln::Table t;
  t.generator = "kiln test";
  t.name = "one";
  t.model = "none";
  t.quantity = "albedo";
  t.channels = {"E"};
  t.channelMeanings = {"directional albedo"};
  t.axes = {{"mu", {0.0, 1.0, 5, kiln::Warp::Linear}}};
  t.data = {0.1f, 0.3f, 0.5f, 0.7f, 0.9f};
  return t;
}

std::vector<std::string> exrChannelList(const std::string& path) {
  Imf::InputFile in(path.c_str());
  std::vector<std::string> names;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it)
    names.push_back(it.name());
  return names;
}


}  // namespace

TEST_CASE(
    "a baked ggx-dfg EXR has channels R, G, B and reads as (A, B, 0, 1) through RgbaInputFile",
    "[io][exr][channels]") {
  const std::string dir = scratch("dfg");
  const kiln::Table t = smallGgxDfg();
  REQUIRE(t.channels == std::vector<std::string>{"A", "B"});
  const std::string path = dir + "/ggx-dfg.exr";
  kiln::writeTable(path, t, /*half=*/false);
  CHECK(exrChannelList(path) == std::vector<std::string>{"B", "G", "R"});  // OpenEXR sorts them
  {
    Imf::InputFile in(path.c_str());
    const auto* unused =
        in.header().findTypedAttribute<Imf::StringAttribute>("kiln.unused_channels");
    REQUIRE(unused != nullptr);
    CHECK(unused->value() == "B");
    const auto* layout = in.header().findTypedAttribute<Imf::IntAttribute>("kiln.layout");
    REQUIRE(layout != nullptr);
    CHECK(layout->value() == kiln::kLayoutVersion);
  }

  int width = 0, height = 0;
  const std::vector<Imf::Rgba> px = ReadRgba(path, width, height);
  REQUIRE(width == 8);
  REQUIRE(height == 8);
  for (std::size_t i = 0; i < px.size(); ++i) {
    INFO("texel " << i);
    // RgbaInputFile converts to half: the same rounding as half(value).
    CHECK(float(px[i].r) == float(half(t.data[2 * i])));
    CHECK(float(px[i].g) == float(half(t.data[2 * i + 1])));
    CHECK(float(px[i].b) == 0.0f);  // the unused channel, stored as zeros
    CHECK(float(px[i].a) == 1.0f);
  }
  // Not a trivially constant image: scale spans most of [0, 1].
  CHECK(float(px.front().r) != float(px.back().r));

  // kiln's loader gives back the kiln names, 2 channels and the exact floats.
  kiln::Table back = kiln::loadTable(path);
  CHECK(back.channels == t.channels);
  CHECK(back.channelMeanings == t.channelMeanings);
  CHECK(back.data == t.data);
  CHECK(back.view().channels == 2);
  fs::remove_all(dir);
}

TEST_CASE("a one-channel table is the luminance channel Y: (E, E, E, 1) through RgbaInputFile",
          "[io][exr][channels]") {
  const std::string dir = scratch("one");
  const kiln::Table t = oneChannel();
  const std::string path = dir + "/one.exr";
  kiln::writeTable(path, t, /*half=*/true);
  CHECK(exrChannelList(path) == std::vector<std::string>{"Y"});
  int width = 0, height = 0;
  const std::vector<Imf::Rgba> px = ReadRgba(path, width, height);
  REQUIRE(px.size() == 5);
  for (std::size_t i = 0; i < px.size(); ++i) {
    INFO("texel " << i);
    // What RgbaInputFile does with a lone Y: grey, R = G = B = Y, A = 1.
    CHECK(float(px[i].r) == float(half(t.data[i])));
    CHECK(float(px[i].g) == float(half(t.data[i])));
    CHECK(float(px[i].b) == float(half(t.data[i])));
    CHECK(float(px[i].a) == 1.0f);
  }
  const kiln::Table back = kiln::loadTable(path);
  CHECK(back.channels == t.channels);
  CHECK(back.data.size() == 5);
  fs::remove_all(dir);
}

TEST_CASE("channels map to Y or R, G, B, A in storage order, more than 4 make parts",
          "[io][exr][channels]") {
  CHECK(kiln::exrChannelNames(1) == std::vector<std::string>{"Y"});
  CHECK(kiln::exrChannelNames(2) == std::vector<std::string>{"R", "G"});
  CHECK(kiln::exrFileChannels(2) == std::vector<std::string>{"R", "G", "B"});
  CHECK(kiln::exrChannelNames(3) == std::vector<std::string>{"R", "G", "B"});
  CHECK(kiln::exrFileChannels(3) == std::vector<std::string>{"R", "G", "B"});
  CHECK(kiln::exrChannelNames(4) == std::vector<std::string>{"R", "G", "B", "A"});
  CHECK(kiln::exrChannelNames(0).empty());
  CHECK(kiln::exrChannelNames(5).empty());
  CHECK(kiln::tablePartCount(4) == 1);
  CHECK(kiln::tablePartCount(5) == 2);
  CHECK(kiln::tablePartCount(6) == 2);
  CHECK(kiln::tablePartPath("luts/ltc-ggx.exr", 2, 2) == "luts/ltc-ggx-2.exr");
  CHECK(kiln::tablePartPath("luts/ggx-dfg.exr", 1, 1) == "luts/ggx-dfg.exr");
  CHECK(kiln::tableSiblingPartPath("a.b/ltc-1.exr", 1, 2) == "a.b/ltc-2.exr");

  const std::string dir = scratch("wide");
  kiln::Table t = oneChannel();
  t.channels = {"a", "b", "c", "d", "e"};
  t.channelMeanings = {"ma", "mb", "mc", "md", "me"};
  t.data.assign(5 * 5, 0.5f);
  t.data[3] = 0.25f;
  t.data[24] = 0.75f;
  // More than 4 channels: two files, wide-1.exr (a..d as R, G, B, A) and wide-2.exr (e as Y).
  kiln::writeTable(dir + "/wide.exr", t, false);
  CHECK_FALSE(fs::exists(dir + "/wide.exr"));
  CHECK(exrChannelList(dir + "/wide-1.exr") == std::vector<std::string>{"A", "B", "G", "R"});
  CHECK(exrChannelList(dir + "/wide-2.exr") == std::vector<std::string>{"Y"});
  for (const char* file : {"/wide-1.exr", "/wide-2.exr"}) {
    INFO(file);
    kiln::Table back;
    std::string error;
    REQUIRE(kiln::loadTable(dir + file, back, error));
    CHECK(back.channels == t.channels);
    CHECK(back.channelMeanings == t.channelMeanings);
    CHECK(back.data == t.data);
    CHECK(back.part.count == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("the loader reads an old file whose EXR channels are named after kiln.channels",
          "[io][exr][channels]") {
  const std::string dir = scratch("old");
  const kiln::Table t = smallGgxDfg();
  // The pre-#14 layout: EXR channels "A" and "B" (the kiln names), FLOAT.
  Imf::Header header(t.imageWidth(), t.imageHeight());
  kiln::setKilnAttributes(header, t);
  header.channels().insert("A", Imf::Channel(Imf::FLOAT));
  header.channels().insert("B", Imf::Channel(Imf::FLOAT));
  const Imath::Box2i window = header.dataWindow();
  Imf::FrameBuffer fb;
  const std::size_t xs = 2 * sizeof(float), ys = xs * std::size_t(t.imageWidth());
  fb.insert("A", Imf::Slice::Make(Imf::FLOAT, t.data.data(), window, xs, ys));
  fb.insert("B", Imf::Slice::Make(Imf::FLOAT, t.data.data() + 1, window, xs, ys));
  const std::string path = dir + "/old.exr";
  {
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(t.imageHeight());
  }
  kiln::Table back = kiln::loadTable(path);
  CHECK(back.channels == t.channels);
  CHECK(back.data == t.data);

  // Layout 1: the channels as R, G (no B), and a one-channel table as R.
  Imf::Header rg(t.imageWidth(), t.imageHeight());
  kiln::setKilnAttributes(rg, t);
  rg.erase("kiln.layout");
  rg.erase("kiln.unused_channels");
  rg.channels().insert("R", Imf::Channel(Imf::FLOAT));
  rg.channels().insert("G", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fbRg;
  fbRg.insert("R", Imf::Slice::Make(Imf::FLOAT, t.data.data(), window, xs, ys));
  fbRg.insert("G", Imf::Slice::Make(Imf::FLOAT, t.data.data() + 1, window, xs, ys));
  const std::string rgPath = dir + "/layout1.exr";
  {
    Imf::OutputFile out(rgPath.c_str(), rg);
    out.setFrameBuffer(fbRg);
    out.writePixels(t.imageHeight());
  }
  back = kiln::loadTable(rgPath);
  CHECK(back.channels == t.channels);
  CHECK(back.data == t.data);

  const kiln::Table e = oneChannel();
  Imf::Header r(e.imageWidth(), e.imageHeight());
  kiln::setKilnAttributes(r, e);
  r.channels().insert("R", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fbR;
  fbR.insert("R", Imf::Slice::Make(Imf::FLOAT, e.data.data(), r.dataWindow(), sizeof(float),
                                   sizeof(float) * std::size_t(e.imageWidth())));
  const std::string rPath = dir + "/one-r.exr";
  {
    Imf::OutputFile out(rPath.c_str(), r);
    out.setFrameBuffer(fbR);
    out.writePixels(e.imageHeight());
  }
  back = kiln::loadTable(rPath);
  CHECK(back.channels == e.channels);
  CHECK(back.data == e.data);

  // Neither the R, G names nor the kiln names: refused.
  Imf::Header bad(t.imageWidth(), t.imageHeight());
  kiln::setKilnAttributes(bad, t);
  bad.channels().insert("R", Imf::Channel(Imf::FLOAT));
  bad.channels().insert("B", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fb2;
  fb2.insert("R", Imf::Slice::Make(Imf::FLOAT, t.data.data(), window, xs, ys));
  fb2.insert("B", Imf::Slice::Make(Imf::FLOAT, t.data.data() + 1, window, xs, ys));
  const std::string badPath = dir + "/bad.exr";
  {
    Imf::OutputFile out(badPath.c_str(), bad);
    out.setFrameBuffer(fb2);
    out.writePixels(t.imageHeight());
  }
  kiln::Table unused;
  std::string error;
  CHECK_FALSE(kiln::loadTable(badPath, unused, error));
  CHECK_THAT(error, Catch::Contains("channel mismatch"));
  fs::remove_all(dir);
}
