// kiln integrate on the sheen models: the Charlie domain is refused below 0.045, and the cloth
// DFG prints the same integral as the albedo.
#include <catch2/catch.hpp>
#include <string>

#include "cli_util.h"

using kiln::test::RunKiln;

TEST_CASE("kiln integrate refuses a Charlie roughness below the domain", "[sheen][cli]") {
  auto r = RunKiln("integrate albedo --model charlie --mu 0.5 --roughness 0.01");
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("outside [0.044999999999999998, 1]") != std::string::npos);
  auto ok = RunKiln("integrate dfg --model charlie --mu 0.5 --roughness 0.3");
  CHECK(ok.exitCode == 0);
  auto albedo = RunKiln("integrate albedo --model charlie --mu 0.5 --roughness 0.3");
  CHECK(ok.out == albedo.out);
}
