// Stress: more threads than the address space holds. Under `ulimit -v 1048576` (1 GiB) oneTBB
// aborted in pthread_create at -j 16 (bake) and -j 64 (verify), and -j 12 failed with "Resource
// temporarily unavailable": kiln now runs as many threads as the limit leaves room for, says so
// in one warning line, and finishes.
#include <catch2/catch.hpp>

#include "stress_util.h"

using namespace kiln::stress;

namespace {
constexpr const char* kOneGiB = "ulimit -v 1048576;";

/// True when `err` is exactly one "kiln: warning: -j J: running N threads" line.
bool OneThreadWarning(const std::string& err, const std::string& j) {
  return kiln::test::CountLines(err) == 1 &&
         err.rfind("kiln: warning: -j " + j + ": running ", 0) == 0 &&
         err.find("ulimit -v") != std::string::npos;
}
}  // namespace

TEST_CASE("Under ulimit -v 1 GiB, -j above what fits runs fewer threads with one warning",
          "[stress][hostile][cli][threads]") {
  ScratchDir dir("thread_limit");
  for (const std::string j : {"12", "16", "64"}) {
    auto bake = RunKilnFor(
        120, "bake --quiet --only ggx-dfg --size 9 -j " + j + " --out " + Quote(dir.path.string()),
        kOneGiB);
    INFO("bake -j " << j << ": exit " << bake.exitCode << ", stderr: " << bake.err);
    CHECK(bake.exitCode == 0);
    CHECK(OneThreadWarning(bake.err, j));
    auto verify = RunKilnFor(
        120, "verify --quiet " + Quote(dir / "ggx-dfg.exr") + " --points 64 -j " + j, kOneGiB);
    INFO("verify -j " << j << ": exit " << verify.exitCode << ", stderr: " << verify.err);
    CHECK(verify.exitCode == 0);
    CHECK(OneThreadWarning(verify.err, j));
  }
}

TEST_CASE("Under ulimit -v 1 GiB, -j that fits runs as asked, silently",
          "[stress][hostile][cli][threads]") {
  ScratchDir dir("thread_limit_fits");
  auto bake = RunKilnFor(
      120, "bake --quiet --only ggx-dfg --size 9 -j 2 --out " + Quote(dir.path.string()), kOneGiB);
  INFO("stderr: " << bake.err);
  CHECK(bake.exitCode == 0);
  CHECK(bake.err.empty());
}
