// kiln bake --only lists each table once: a name repeated (a,a,a) is baked once, in the order of
// its first appearance (10,000 copies of one name had run 10,000 bakes).
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;

TEST_CASE("bake --only a,b,a,a --force bakes a and b once each, in first order", "[cli][bake]") {
  ScratchDir dir("bake_only_repeat");
  auto r = RunKilnFor(120,
                      "bake --force --size 5 --no-lookup-error --only "
                      "fresnel-dielectric,lambert-albedo,fresnel-dielectric,fresnel-dielectric "
                      "--out " +
                          Quote(dir.path.string()));
  INFO("stderr: " << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.find("2 baked, 0 skipped") != std::string::npos);
  size_t first = r.err.find("fresnel-dielectric"), second = r.err.find("lambert-albedo");
  CHECK(first < second);
  CHECK(r.err.find("fresnel-dielectric", first + 1) > second);
}
