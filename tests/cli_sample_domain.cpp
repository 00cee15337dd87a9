// kiln sample outside a table's axes: an error naming the axis, the value and its range, unless
// --clamp is given (then the point is clamped to the axes, with one warning line).
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;

namespace {
const std::string kDfg = Quote(std::string(KILN_SOURCE_DIR) + "/luts/ggx-dfg.exr");
}  // namespace

TEST_CASE("kiln sample refuses a point outside the table's axes", "[cli][sample]") {
  const std::pair<std::string, std::string> cases[] = {
      {"0.5 2.0", "roughness 2 is outside the domain of"},
      {"1.5 0.5", "mu 1.5 is outside the domain of"},
      {"-0.25 0.5", "mu -0.25 is outside"},
  };
  for (const auto& [point, expected] : cases) {
    auto r = RunKilnFor(60, "sample " + kDfg + " " + point);
    INFO("sample " << point << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK(r.err.find("in [0, 1]") != std::string::npos);
    CHECK(r.err.find("--clamp") != std::string::npos);
  }
}

TEST_CASE("kiln sample --clamp clamps to the axes with one warning line", "[cli][sample]") {
  auto edge = RunKilnFor(60, "sample " + kDfg + " 0.5 1");
  REQUIRE(edge.exitCode == 0);
  auto r = RunKilnFor(60, "sample " + kDfg + " 0.5 2.0 --clamp");
  INFO("stderr: " << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out == edge.out);
  CHECK(kiln::test::CountLines(r.err) == 1);
  CHECK(r.err.rfind("kiln: warning: sample: clamped roughness 2 to 1", 0) == 0);
  // Inside the axes: no warning, --clamp or not.
  auto inside = RunKilnFor(60, "sample " + kDfg + " 0.5 1 --clamp");
  CHECK(inside.exitCode == 0);
  CHECK(inside.err.empty());
  CHECK(inside.out == edge.out);
}

TEST_CASE("A table defined on its axes only refuses a point outside even with --clamp",
          "[cli][sample]") {
  std::string table = Quote(std::string(KILN_SOURCE_DIR) + "/luts/ggx-fresnel-albedo.exr");
  auto r = RunKilnFor(60, "sample " + table + " 0.5 0.5 1.2 --clamp");
  INFO("stderr: " << r.err);
  CHECK(IsCleanRefusal(r));
  CHECK(r.err.find("eta 1.2 is outside the domain") != std::string::npos);
}
