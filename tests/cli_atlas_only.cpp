// kiln atlas --only: each pair once (a,a runs a once), and a mistyped pair gets a suggestion.
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;

TEST_CASE("atlas --only runs a repeated pair once and suggests a mistyped one",
          "[atlas][cli][did-you-mean]") {
  ScratchDir dir("atlas_only");
  auto r = RunKilnFor(120, "atlas --out " + Quote(dir.path.string()) +
                               " --only lambert,lambert,lambert --grid 4 -j 2");
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exitCode == 0);
  size_t first = r.out.find("lambert: done");
  REQUIRE(first != std::string::npos);
  CHECK(r.out.find("lambert: done", first + 1) == std::string::npos);
  auto typo = RunKilnFor(60, "atlas --out " + Quote(dir.path.string()) + " --only lambret");
  CHECK(IsCleanRefusal(typo));
  CHECK(typo.err.find("unknown pair 'lambret' (did you mean 'lambert'?)") != std::string::npos);
}
