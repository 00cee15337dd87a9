// kiln bake gives the same bytes on a CPU without AVX-512F: with KILN_NO_AVX512=1 (the portable
// paths from the start) the glass tables that the AVX-512F paths bake (the exit E pair, whose
// walk fuses multiply-adds and sums in eight lanes; the exit average; an entering column table)
// are the bytes of a bake that takes them; so are the tables whose fixed rules (Beckmann and
// Blinn-Phong nodes, sheen rows) and LTC fits (the objective's sums) take AVX-512F lanes.
#include <catch2/catch.hpp>

#include "baker/integrate/dielectric_simd.h"
#include "stress_util.h"

using namespace kiln::stress;

namespace {

/// Bakes `tables` (a comma-separated --only list) at `size` twice on one thread, with
/// KILN_NO_AVX512=0 and =1, into two scratch folders named after `scratch`, and requires the
/// same folder entries and, for each of the `files` .exr files, the same bytes.
void RequireSameBytesWithoutAvx512(const std::string& tables, int size, int files,
                                   const std::string& scratch) {
  kiln::dielectric_simd::SetEnabled(true);
  if (!kiln::dielectric_simd::Enabled())
    WARN("no AVX-512F on this CPU: both bakes take the portable paths (compared with themselves)");
  ScratchDir fast(scratch + "_avx512"), portable(scratch + "_no_avx512");
  const std::string args = "bake --size " + std::to_string(size) +
                           " -j 1 --no-lookup-error -q --only " + tables + " --out ";
  const auto a = RunKilnFor(120, args + Quote(fast.path.string()), "KILN_NO_AVX512=0");
  const auto b = RunKilnFor(120, args + Quote(portable.path.string()), "KILN_NO_AVX512=1");
  INFO("stderr: " << a.err << " / " << b.err);
  REQUIRE(a.exitCode == 0);
  REQUIRE(b.exitCode == 0);
  REQUIRE(fast.Entries() == portable.Entries());
  int compared = 0;
  for (const std::string& name : fast.Entries()) {
    if (name.size() < 4 || name.substr(name.size() - 4) != ".exr") continue;
    INFO(name);
    CHECK(kiln::test::ReadFile(fast / name) == kiln::test::ReadFile(portable / name));
    ++compared;
  }
  CHECK(compared == files);
}

}  // namespace

TEST_CASE("a bake with KILN_NO_AVX512=1 gives the glass tables' bytes", "[cli][bake][glass-rule]") {
  RequireSameBytesWithoutAvx512(
      "ggx-dielectric-albedo-r-exit,ggx-dielectric-albedo-t-exit,"
      "ggx-dielectric-albedo-r-exit-avg,ggx-dielectric-albedo-r",
      8, 4, "bake");
}

TEST_CASE(
    "a bake with KILN_NO_AVX512=1 gives the bytes of the tables whose fixed rules and LTC fits "
    "take AVX-512F lanes",
    "[cli][bake][fixed-rule]") {
  // Beckmann and Blinn-Phong nodes, sheen rows (Charlie, charlie-smith, velvet), the LTC
  // objective's sums (ltc-beckmann: its norm by the Beckmann nodes too); the LTC tables are two
  // files each.
  RequireSameBytesWithoutAvx512(
      "beckmann-dfg,blinn-phong-dfg,beckmann-separable-dfg,charlie-dfg,charlie-smith-dfg,"
      "ashikhmin-velvet-albedo,ltc-beckmann,ltc-charlie-smith",
      12, 10, "bake_rules");
}
