// Specification: a bake's up-to-date check (IsUpToDate, which lets `kiln bake` skip a table)
// compares the file layout (kiln::kLayoutVersion: the EXR's kiln.layout attribute and the
// manifest entry's "layout") besides the spec hash, so a folder baked before layout 2 (EXR
// channels R, G or the kiln names) is re-baked into files every RGBA reader opens, while the
// spec hashes stay what they were. png16 and png16-scaled share a file name; the manifest's
// "format" tells them apart.
#include <catch2/catch.hpp>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/bake/bake.h"
#include "baker/io/exr_writer.h"
#include "baker/tables/catalogue.h"
#include "kiln/exr_loader.h"

namespace fs = std::filesystem;

namespace {

std::string scratch(const std::string& tag) {
  fs::path dir =
      fs::temp_directory_path() / ("kiln-layout-stale-" + tag + "-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

kiln::TableSpec smallSpec() {
  kiln::CatalogueOptions copt;
  copt.size = 6;
  return kiln::CatalogueTable("fresnel-dielectric-avg", copt);
}

kiln::BakeRunOptions quietRun(kiln::OutputFormat format) {
  kiln::BakeRunOptions opt;
  opt.bake.threads = 1;
  opt.bake.measureLookupError = false;
  opt.format = format;
  return opt;
}

/// Rewrites the 1-channel table in `path` as layout 1 wrote it: its channel named R, no
/// kiln.layout attribute.
void rewriteAsLayout1(const std::string& path) {
  const kiln::Table t = kiln::loadTable(path);
  REQUIRE(t.channels.size() == 1);
  Imf::Header header(t.imageWidth(), t.imageHeight());
  kiln::setKilnAttributes(header, t);
  header.erase("kiln.layout");
  header.channels().insert("R", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice::Make(Imf::FLOAT, t.data.data(), header.dataWindow(), sizeof(float),
                                  sizeof(float) * std::size_t(t.imageWidth())));
  fs::remove(path);
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(fb);
  out.writePixels(t.imageHeight());
}

/// Removes "layout" from every entry of DIR/manifest.json (a manifest written before it).
void dropManifestLayout(const std::string& dir) {
  nlohmann::ordered_json m;
  {
    std::ifstream in(dir + "/manifest.json");
    m = nlohmann::ordered_json::parse(in);
  }
  for (auto& e : m["tables"]) e.erase("layout");
  std::ofstream(dir + "/manifest.json") << m.dump(2) << "\n";
}

}  // namespace

TEST_CASE("a table of an older file layout is stale for the bake, its spec hash unchanged",
          "[bake][skip][layout]") {
  const std::string dir = scratch("exr");
  const kiln::TableSpec spec = smallSpec();
  const std::string hash = spec.Hash();
  const kiln::BakeRunOptions opt = quietRun(kiln::OutputFormat::Exr);
  REQUIRE(kiln::BakeSpecs({spec}, dir, opt).baked.size() == 1);
  const std::string path = dir + "/" + spec.name + ".exr";
  CHECK(kiln::IsUpToDate(spec, dir, false, false));

  // The file of layout 1 (channel R, no kiln.layout), the manifest of today: stale.
  rewriteAsLayout1(path);
  CHECK(kiln::loadTable(path).specHash == hash);  // still loads, same spec hash
  CHECK_FALSE(kiln::IsUpToDate(spec, dir, false, false));
  // Both of layout 1 (a folder baked before): stale, and the bake rewrites it.
  dropManifestLayout(dir);
  CHECK_FALSE(kiln::IsUpToDate(spec, dir, false, false));
  const kiln::BakeRunResult again = kiln::BakeSpecs({spec}, dir, opt);
  CHECK(again.baked.size() == 1);
  CHECK(kiln::IsUpToDate(spec, dir, false, false));
  CHECK(kiln::loadTable(path).specHash == hash);
  // A manifest without "layout" beside a file of today: stale too (the entry is rewritten).
  dropManifestLayout(dir);
  CHECK_FALSE(kiln::IsUpToDate(spec, dir, false, false));
  fs::remove_all(dir);
}

TEST_CASE("png16 and png16-scaled are not up to date for each other", "[bake][skip][png16]") {
  const std::string dir = scratch("png");
  const kiln::TableSpec spec = smallSpec();
  REQUIRE(kiln::BakeSpecs({spec}, dir, quietRun(kiln::OutputFormat::Png16Scaled)).baked.size() ==
          1);
  CHECK(kiln::IsUpToDate(spec, dir, false, false, kiln::OutputFormat::Png16Scaled));
  CHECK_FALSE(kiln::IsUpToDate(spec, dir, false, false, kiln::OutputFormat::Png16));
  REQUIRE(kiln::BakeSpecs({spec}, dir, quietRun(kiln::OutputFormat::Png16)).baked.size() == 1);
  CHECK(kiln::IsUpToDate(spec, dir, false, false, kiln::OutputFormat::Png16));
  fs::remove_all(dir);
}
