// Stress: what a KTX2, DDS or 16-bit PNG table file declares. The readers (baker/io/
// texture_readers.h) put every header through the checks of the EXR loader (kiln/
// table_checks.h: format version, axes, sizes, channels; integers read as integers), and compare
// the size a header declares with the bytes the file holds before they allocate anything.
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>

#include "baker/io/texture_readers.h"
#include "stress_table_files.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;

namespace {

enum class Kind { Ktx2, Dds, Png16 };
const char* Name(Kind k) { return k == Kind::Ktx2 ? "ktx2" : k == Kind::Dds ? "dds" : "png16"; }

/// `width` x `height` one-channel float texels, all 0.5, as the file format stores them.
std::string Texels(Kind kind, std::uint32_t width, std::uint32_t height) {
  std::string bytes;
  if (kind == Kind::Png16) {
    for (std::uint32_t y = 0; y < height; ++y) {
      bytes += '\0';  // filter: none
      for (std::uint32_t x = 0; x < width; ++x) bytes += std::string("\x80\0", 2);
    }
    return bytes;
  }
  const float half = 0.5f;
  for (std::uint32_t i = 0; i < width * height; ++i)
    bytes.append(reinterpret_cast<const char*>(&half), 4);
  return bytes;
}

/// Writes DIR/hand.<ext> (and DIR/manifest.json for a DDS) declaring `width` x `height` texels of
/// one channel, described by `description`, holding `texels`; returns its path.
std::string WriteHandTable(const std::string& dir, Kind kind, const ordered_json& description,
                           std::uint32_t width, std::uint32_t height, const std::string& texels) {
  const std::string path = dir + "/hand." + (kind == Kind::Png16 ? "png" : Name(kind));
  if (kind == Kind::Ktx2)
    WriteFile(path,
              HandKtx2(description, width, height, 1, texels, std::uint64_t{width} * height * 4));
  else if (kind == Kind::Png16)
    WriteFile(path, HandPng16(description, width, height, 1, texels));
  else {
    WriteFile(path, HandDds(width, height, 1, texels));
    WriteFile(dir + "/manifest.json", HandManifest(description, "hand.dds"));
  }
  return path;
}

}  // namespace

TEST_CASE("Hand-made KTX2, DDS and PNG16 tables load: the files of the other tests are valid",
          "[stress][hostile][ktx2][dds][png16]") {
  ScratchDir dir("hand_tables");
  for (Kind kind : {Kind::Ktx2, Kind::Dds, Kind::Png16}) {
    INFO(Name(kind));
    const std::string path =
        WriteHandTable(dir.path.string(), kind, HandDescription(4, 2, 1), 4, 2, Texels(kind, 4, 2));
    const kiln::Table t = kiln::LoadAnyTable(path);
    CHECK(t.size(0) == 4);
    CHECK(t.size(1) == 2);
    REQUIRE(t.data.size() == 8);
    CHECK(t.data[7] == Approx(0.5).margin(1e-4));
  }
}

TEST_CASE("KTX2, DDS and PNG16 headers go through the EXR loader's checks",
          "[stress][hostile][ktx2][dds][png16]") {
  ScratchDir dir("table_headers");
  struct Case {
    const char* what;
    void (*edit)(ordered_json&);
    const char* says;
  };
  const Case cases[] = {
      {"an axis of [-1e308, 1e308]",
       [](ordered_json& j) {
         j["axes"][0]["lo"] = -1e308;
         j["axes"][0]["hi"] = 1e308;
       },
       "axis 0 ('mu'): lo -1e+308 or hi 1e+308 is beyond +-1e6, where no kiln axis reaches"},
      {"format 2", [](ordered_json& j) { j["format"] = 2; },
       "format version 2, this runtime reads 1"},
      {"format \"1\"", [](ordered_json& j) { j["format"] = "1"; },
       "no integer \"format\" (the format version)"},
      {"no format", [](ordered_json& j) { j.erase("format"); },
       "no integer \"format\" (the format version)"},
      {"a size of 2^32 + 4", [](ordered_json& j) { j["axes"][0]["size"] = 4294967300ull; },
       "description's \"size\" is 4294967300, out of range"},
      {"a size of 4.5", [](ordered_json& j) { j["axes"][0]["size"] = 4.5; },
       "description's \"size\" is 4.5, not an integer"},
      {"a size of -4", [](ordered_json& j) { j["axes"][0]["size"] = -4; },
       "axis 0 ('mu'): size is -4, must be >= 1"},
      {"a duplicate channel",
       [](ordered_json& j) {
         j["channels"] = {"E0", "E0"};
       },
       "channel name 'E0' appears twice"},
      {"a layer warp on a 1D table",
       [](ordered_json& j) {
         j["axes"].erase(1);
         j["axes"][0]["warp"] = "root4-layer";
       },
       "the root4-layer warp couples axis 0 to axis 1"},
  };
  for (Kind kind : {Kind::Ktx2, Kind::Dds, Kind::Png16})
    for (const Case& c : cases) {
      INFO(Name(kind) << ", " << c.what);
      ordered_json description = HandDescription(4, 2, 1);
      c.edit(description);
      const std::string path =
          WriteHandTable(dir.path.string(), kind, description, 4, 2, Texels(kind, 4, 2));
      CHECK_THROWS_WITH(
          kiln::LoadAnyTable(path),
          Catch::StartsWith("cannot read '" + path + "': ") && Catch::Contains(c.says));
    }
}

TEST_CASE("kiln inspect --axes of a KTX2 with an axis of [-1e308, 1e308] refuses it in one line",
          "[stress][hostile][ktx2][cli]") {
  ScratchDir dir("huge_axis_cli");
  ordered_json description = HandDescription(4, 2, 1);
  description["axes"][0]["lo"] = -1e308;
  description["axes"][0]["hi"] = 1e308;
  const std::string path =
      WriteHandTable(dir.path.string(), Kind::Ktx2, description, 4, 2, Texels(Kind::Ktx2, 4, 2));
  auto r = RunKilnFor(30, "inspect --axes " + Quote(path));
  INFO(r.out << r.err);
  CHECK(IsCleanRefusal(r));
  CHECK_THAT(r.err, Catch::Contains("beyond +-1e6"));
  CHECK(r.out.find("inf") == std::string::npos);
}

// A header declaring 16384 x 16384 texels (2^28 values, the readers' cap) in a file of about a
// kilobyte: refused from the sizes alone, before the 1 GiB of floats (and for PNG the 512 MiB of
// inflated rows) is allocated, so that even under a 1 GiB address-space limit the answer is the
// reason, not std::bad_alloc.
TEST_CASE("A KTX2, DDS or PNG16 declaring 16384 x 16384 texels it does not hold allocates nothing",
          "[stress][hostile][ktx2][dds][png16][cli]") {
  ScratchDir dir("declared_sizes");
  const std::uint32_t n = 16384;
  struct Case {
    Kind kind;
    const char* says;
  };
  for (const Case& c :
       {Case{Kind::Ktx2, "truncated texel data (1073741824 bytes expected, 16 in level 0)"},
        Case{Kind::Dds, "truncated texel data (1073741824 bytes expected, 16 after the header)"},
        Case{Kind::Png16, "at most from the compressed image data)"}}) {
    INFO(Name(c.kind));
    // Four texels (PNG: two rows of four) where 2^28 are declared.
    const std::string texels = c.kind == Kind::Png16 ? Texels(c.kind, n, 2) : Texels(c.kind, 2, 2);
    const std::string path =
        WriteHandTable(dir.path.string(), c.kind, HandDescription(n, n, 1), n, n, texels);
    CHECK(std::filesystem::file_size(path) < 4096);
    CHECK_THROWS_WITH(kiln::LoadAnyTable(path), Catch::Contains(c.says));
    auto r = RunKilnFor(30, "inspect " + Quote(path), "ulimit -v 1048576;");
    INFO(r.err);
    CHECK(IsCleanRefusal(r));
    CHECK_THAT(r.err, Catch::Contains(c.says));
  }
}
