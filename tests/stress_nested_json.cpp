// Stress: JSON nested without end. Every JSON file kiln reads (manifest.json, the manifest entry
// describing a DDS table, kiln.json inside KTX2 and PNG tables, scene files and glTF) goes
// through one parser with a nesting limit of 64 levels (baker/io/bounded_json.h): a value nested
// 100,000 deep is refused with one line naming the file, instead of crashing the process in the
// recursion of the parser, a copy or a dump.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "baker/io/bounded_json.h"
#include "stress_util.h"

using namespace kiln::stress;
using kiln::test::ReadFile;
namespace fs = std::filesystem;

namespace {

/// A JSON array nested `depth` levels deep: [[[...0...]]].
std::string NestedArray(std::size_t depth) {
  return std::string(depth, '[') + "0" + std::string(depth, ']');
}

/// DIR/manifest.json with `nested` added as the value of "extra" in the entry of `name`.
void NestInManifest(const std::string& dir, const std::string& name, const std::string& nested) {
  std::string text = ReadFile(dir + "/manifest.json");
  const std::string key = "\"name\": \"" + name + "\",";
  const std::size_t at = text.find(key);
  REQUIRE(at != std::string::npos);
  text.insert(at + key.size(), " \"extra\": " + nested + ",");
  WriteFile(dir + "/manifest.json", text);
}

}  // namespace

TEST_CASE("ParseBoundedJson reads 64 levels and refuses 65, wherever the brackets are",
          "[stress][json]") {
  CHECK(kiln::ParseBoundedJson(NestedArray(kiln::kMaxJsonDepth)).is_array());
  CHECK(kiln::JsonTooDeepAt(NestedArray(kiln::kMaxJsonDepth)) == std::string::npos);
  CHECK(kiln::JsonTooDeepAt(NestedArray(kiln::kMaxJsonDepth + 1)) == kiln::kMaxJsonDepth);
  CHECK_THROWS_WITH(kiln::ParseBoundedJson(NestedArray(kiln::kMaxJsonDepth + 1)),
                    "nested deeper than 64 levels (line 1, column 65)");
  // Objects count as levels too; brackets inside strings (escaped quotes included) do not.
  std::string objects;
  for (int i = 0; i < 65; ++i) objects += "{\"k\":";
  objects += "0" + std::string(65, '}');
  CHECK_THROWS_WITH(kiln::ParseBoundedJson(objects), Catch::StartsWith("nested deeper than 64"));
  const std::string inString = "{\"s\": \"\\\"" + std::string(1000, '[') + "\"}";
  CHECK(kiln::ParseBoundedJson(inString)["s"].get<std::string>().size() == 1001);
  // 100,000 levels: refused at once, without the parser's recursion.
  CHECK_THROWS_WITH(kiln::ParseBoundedJson(NestedArray(100000)),
                    Catch::StartsWith("nested deeper than 64 levels"));
  CHECK_THROWS_WITH(kiln::ParseBoundedJson("{\"a\": [1, 2"), Catch::StartsWith("not valid JSON ("));
}

TEST_CASE("kiln bake refuses a manifest entry nested 100,000 deep, with and without --force",
          "[stress][json][manifest][cli]") {
  ScratchDir root("nested_manifest");
  const std::string dir = root / "D", manifest = dir + "/manifest.json";
  auto first = RunKilnFor(120, "bake --only ggx-dfg --size 5 -j 1 --out " + Quote(dir));
  INFO(first.err);
  REQUIRE(first.exitCode == 0);
  NestInManifest(dir, "ggx-dfg", NestedArray(100000));  // about 200 KB
  const std::string before = ReadFile(manifest);
  for (const char* force : {"", " --force"}) {
    auto r = RunKilnFor(120, "bake --only ggx-dfg --size 5 -j 1 --out " + Quote(dir) + force);
    INFO("bake" << force << ": " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK_THAT(r.err, Catch::StartsWith("kiln: error: " + manifest +
                                        " is nested deeper than 64 levels (line "));
    CHECK(ReadFile(manifest) == before);
  }
}

TEST_CASE("kiln inspect and kiln sample refuse a DDS whose manifest is nested 200,000 deep",
          "[stress][json][dds][cli]") {
  ScratchDir root("nested_dds_manifest");
  const std::string dir = root / "D", dds = dir + "/ggx-dfg.dds";
  auto bake = RunKilnFor(
      120, "bake --only ggx-dfg --size 5 -j 1 --no-lookup-error --format dds --out " + Quote(dir));
  INFO(bake.err);
  REQUIRE(bake.exitCode == 0);
  REQUIRE(RunKilnFor(60, "inspect " + Quote(dds)).exitCode == 0);
  NestInManifest(dir, "ggx-dfg", NestedArray(200000));
  for (const std::string& command :
       {"inspect " + Quote(dds), "sample " + Quote(dds) + " 0.5 0.5"}) {
    auto r = RunKilnFor(60, command);
    INFO(command << ": " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK_THAT(r.err, Catch::Contains(dds) &&
                          Catch::Contains(dir + "/manifest.json is nested deeper than 64 levels"));
  }
}

TEST_CASE("kiln.json nested 100,000 deep inside a KTX2 table is refused naming the file",
          "[stress][json][ktx2][cli]") {
  ScratchDir root("nested_kiln_json");
  const std::string dir = root / "D";
  auto bake = RunKilnFor(
      120, "bake --only ggx-dfg --size 5 -j 1 --no-lookup-error --format ktx2 --out " + Quote(dir));
  INFO(bake.err);
  REQUIRE(bake.exitCode == 0);
  // The description's closing brace becomes a key nested 100,000 deep, padded to keep the
  // key/value entries 4-byte aligned; the KTX2 lengths are fixed by hand: only the JSON changes.
  std::string deep = ",\"extra\":" + NestedArray(100000) + "}";
  while ((deep.size() - 1) % 4 != 0) deep.insert(deep.size() - 1, " ");
  {
    std::string bytes = ReadFile(dir + "/ggx-dfg.ktx2");
    const std::size_t key = bytes.find(std::string("kiln.json") + '\0');
    REQUIRE(key != std::string::npos);
    const std::size_t close = bytes.find('}' + std::string(1, '\0'), key);  // the JSON's end
    REQUIRE(close != std::string::npos);
    // Only the key/value data's own lengths matter to the reader before it parses the JSON.
    bytes.replace(close, 1, deep);
    const std::uint32_t grow = static_cast<std::uint32_t>(deep.size() - 1);
    auto addLe32 = [&](std::size_t at, std::uint32_t add) {
      std::uint32_t v = 0;
      for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
      v += add;
      for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
    };
    addLe32(key - 4, grow);  // this entry's length
    addLe32(60, grow);       // kvdByteLength
    WriteFile(dir + "/ggx-dfg.ktx2", bytes);
  }
  auto r = RunKilnFor(60, "inspect " + Quote(dir + "/ggx-dfg.ktx2"));
  INFO(r.err);
  CHECK(IsCleanRefusal(r));
  CHECK_THAT(r.err, Catch::Contains("ggx-dfg.ktx2") &&
                        Catch::Contains("kiln.json is nested deeper than 64 levels"));
}
