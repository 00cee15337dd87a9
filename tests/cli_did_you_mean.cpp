// "Did you mean": a mistyped table, model, option or subcommand gets the closest known name in
// its one-line error (one edit-distance function, baker/util/did_you_mean.h, for all of them).
#include <catch2/catch.hpp>

#include "baker/util/did_you_mean.h"
#include "stress_util.h"

using namespace kiln;
using namespace kiln::stress;

TEST_CASE("EditDistance counts insertions, deletions, substitutions and adjacent swaps",
          "[cli][did-you-mean]") {
  CHECK(EditDistance("", "") == 0);
  CHECK(EditDistance("abc", "") == 3);
  CHECK(EditDistance("", "ab") == 2);
  CHECK(EditDistance("ggx-dgf", "ggx-dfg") == 1);  // one swap
  CHECK(EditDistance("ca", "abc") == 3);           // optimal string alignment, not 2
  CHECK(EditDistance("kitten", "sitting") == 3);
  CHECK(EditDistance("--thread", "--threads") == 1);
  CHECK(EditDistance("ggx", "ggx") == 0);
}

TEST_CASE("ClosestName picks a typo's intended name, never an unrelated word",
          "[cli][did-you-mean]") {
  const std::vector<std::string> names = {"ggx-dfg", "ggx-albedo", "beckmann-dfg", "bake", "plan"};
  CHECK(ClosestName("ggx-dgf", names) == "ggx-dfg");
  CHECK(ClosestName("ggx-albdeo", names) == "ggx-albedo");
  CHECK(ClosestName("bkae", names) == "bake");
  CHECK(ClosestName("frobnicate", names).empty());
  CHECK(ClosestName("ggx-dfg", names).empty());  // not a typo
  CHECK(ClosestName("x", names).empty());
  CHECK(DidYouMean("plna", names) == " (did you mean 'plan'?)");
  CHECK(DidYouMean("zzzz", names).empty());
}

TEST_CASE("Unknown tables, models, options and subcommands suggest the closest name",
          "[cli][did-you-mean]") {
  ScratchDir dir("did_you_mean");
  const std::pair<std::string, std::string> cases[] = {
      {"bake --only ggx-dgf --out " + Quote(dir / "out"),
       "unknown table 'ggx-dgf' (did you mean 'ggx-dfg'?)"},
      {"eval --model ggxx --mu-o 0.5 --mu-l 0.5", "unknown model 'ggxx' (did you mean 'ggx'?)"},
      {"integrate albedo --model beckman --mu 0.5",
       "unknown model 'beckman' (did you mean 'beckmann'?)"},
      {"bake --thread 2 --out " + Quote(dir / "out"), "(did you mean '--threads'?)"},
      {"verify luts --pionts 4", "(did you mean '--points'?)"},
      {"bkae --only ggx-dfg", "(did you mean 'bake'?)"},
      {"sampel luts/ggx-dfg.exr 0.5 0.5", "(did you mean 'sample'?)"},
  };
  for (const auto& [args, expected] : cases) {
    auto r = RunKilnFor(60, args);
    INFO("kiln " << args << "\n  exit " << r.exitCode << "\n  stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(expected) != std::string::npos);
  }
  // Nothing close: no suggestion.
  auto far = RunKilnFor(60, "frobnicate");
  CHECK(IsCleanRefusal(far));
  CHECK(far.err.find("did you mean") == std::string::npos);
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}
