// Every numeric option and argument takes plain decimal only: CLI11 2.1 read "0x10" as 16, the
// integer "010" as 8 and "0x1p-1" as 0.5. One check (RefuseNonNumbers) covers every command.
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;

TEST_CASE("Hexadecimal and leading-zero numbers are refused by every command", "[cli][numbers]") {
  ScratchDir dir("numbers_decimal");
  REQUIRE(
      RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::string table = Quote(dir / "fresnel-dielectric.exr");
  std::string scene =
      Quote(std::string(KILN_SOURCE_DIR) + "/tests/scenes/metal_rough_factors.gltf");
  std::string out = " --out " + Quote(dir / "out");
  const std::pair<std::string, std::string> cases[] = {
      {"bake --only lambert-albedo -j 0x10" + out,
       "--threads: needs a decimal integer, got '0x10'"},
      {"bake --only lambert-albedo --size 0x10" + out,
       "--size: needs a decimal integer, got '0x10'"},
      {"bake --only lambert-albedo --size 010" + out, "got '010'"},
      {"bake --only lambert-albedo --roughness 0x1p-1" + out,
       "--roughness: needs a decimal number"},
      {"verify " + table + " --points 0x10", "--points: needs a decimal integer"},
      {"verify " + table + " -j 0X2", "needs a decimal integer, got '0X2'"},
      {"sample " + table + " 0x1p-1", "needs a decimal number, got '0x1p-1'"},
      {"plan " + scene + " --size 0x20", "--size: needs a decimal integer"},
      {"integrate albedo --model ggx --mu 0x.8 --roughness 0.5", "--mu: needs a decimal number"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --phi 0x0", "needs a decimal number"},
  };
  for (const auto& [args, expected] : cases) {
    auto r = RunKilnFor(60, args);
    INFO("kiln " << args << "\n  exit " << r.exitCode << "\n  stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(expected) != std::string::npos);
  }
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}

TEST_CASE("Plain decimal numbers in every form are still read", "[cli][numbers]") {
  for (const std::string mu : {"0.5", ".5", "5e-1", "+0.5", "5.E-1", "0.50"}) {
    auto r = RunKilnFor(60, "integrate albedo --model ggx --mu " + mu + " --roughness 0.5");
    INFO("--mu " << mu << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(r.exitCode == 0);
  }
  auto zero = RunKilnFor(60, "integrate albedo --model ggx --mu 0 --roughness 0");
  CHECK(zero.exitCode == 0);
}
