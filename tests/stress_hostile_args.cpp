// Stress: hostile command-line arguments. Unknown models and tables, out-of-range values, sizes
// of 0 and absurd sizes, NaN and infinities, malformed numbers: every command answers with one
// clear line on stderr naming the problem, nothing on stdout and a non-zero exit that is not a
// signal. tests/cli_contract.cpp and tests/cli_bake.cpp hold the first few cases of each command;
// these are the edges around them.
#include <catch2/catch.hpp>

#include <filesystem>

#include "stress_util.h"

using namespace kiln::stress;

namespace {

struct Case {
  std::string args;
  std::string expected;  ///< a substring the one-line error must contain
};

void CheckRefused(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    auto r = RunKilnFor(60, c.args);
    INFO("kiln " << c.args << "\n  exit " << r.exitCode << "\n  stdout: " << r.out
                 << "\n  stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(c.expected) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("kiln eval refuses unknown models and NaN, infinite or out-of-range arguments",
          "[stress][hostile][cli]") {
  const std::string pair = " --mu-o 0.5 --mu-l 0.5";
  CheckRefused({
      {"eval --model nope" + pair, "unknown model 'nope'"},
      {"eval --model ''" + pair, "unknown model ''"},
      {"eval --model GGX" + pair, "unknown model 'GGX'"},
      {"eval --model ggx --mu-o nan --mu-l 0.5", "--mu-o"},
      {"eval --model ggx --mu-o 0.5 --mu-l inf", "--mu-l"},
      {"eval --model ggx --mu-o -1e-300 --mu-l 0.5", "--mu-o"},
      {"eval --model ggx --mu-o 1e999 --mu-l 0.5", "--mu-o"},
      {"eval --model ggx --mu-o 0x10 --mu-l 0.5", "--mu-o"},
      {"eval --model ggx --mu-o 0.5.5 --mu-l 0.5", "--mu-o"},
      {"eval --model ggx" + pair + " --phi nan", "--phi"},
      {"eval --model ggx" + pair + " --phi -inf", "--phi"},
      {"eval --model ggx" + pair + " --roughness nan", "roughness"},
      {"eval --model ggx" + pair + " --roughness -1e-9", "roughness"},
      {"eval --model oren-nayar" + pair + " --roughness 1.5708", "roughness"},  // just above pi/2
      {"eval --model lambert" + pair + " --rho nan", "rho"},
      {"eval --model lambert" + pair + " --rho 1.0000001", "rho"},
      {"eval --model ggx" + pair + " --eta 0", "eta"},
      {"eval --model ggx" + pair + " --eta inf", "eta"},
      {"eval --model ggx" + pair + " --eta 1.5 --k -1", "k"},
      {"eval --model ggx" + pair + " --eta 1.5 --k nan", "k"},
      {"eval --model ggx" + pair + " --k 3", "k needs eta"},
      {"eval --model ggx" + pair + " --f0 0.04 --eta 1.5", "not both"},
      {"eval --model ggx" + pair + " --f0 nan", "f0"},
      {"eval --model ashikhmin-shirley" + pair + " --nu 1e8", "nu"},
      {"eval --model ashikhmin-shirley" + pair + " --nv -1", "nv"},
      {"eval --model triace-lambert" + pair + " --rs inf", "rs"},
      {"eval --model ggx" + pair + " --nu 5", "takes no parameter 'nu'"},
      {"eval --model ggx" + pair + " --bogus 1", "--bogus"},
  });
}

TEST_CASE("kiln integrate refuses NaN, infinite and absurd tolerances, indices and angles",
          "[stress][hostile][cli]") {
  CheckRefused({
      {"integrate albedo --model ggx --mu nan", "--mu"},
      {"integrate albedo --model ggx --mu -inf", "--mu"},
      {"integrate dfg --model ggx --mu 1.0000001", "--mu"},
      {"integrate albedo --model ggx --mu 0.5 --tol nan", "--tol"},
      {"integrate albedo --model ggx --mu 0.5 --tol 0", "--tol"},
      {"integrate albedo --model ggx --mu 0.5 --tol -1e-9", "--tol"},
      {"integrate albedo --model ggx --mu 0.5 --tol inf", "--tol"},
      {"integrate albedo-avg --model burley --roughness nan", "roughness"},
      {"integrate albedo-avg --model nope", "unknown model 'nope'"},
      {"integrate fresnel-avg --eta nan", "--eta"},
      {"integrate fresnel-avg --eta 0", "--eta"},
      {"integrate fresnel-avg --eta -1.5", "--eta"},
      {"integrate fresnel-avg --eta inf", "--eta"},
      {"integrate fresnel-avg --eta 1e300", "--eta"},
      {"integrate fresnel-avg --eta 1.5 --k nan", "--k"},
      {"integrate fresnel-avg --eta 1.5 --k 1e300", "--k"},
      {"integrate fresnel-avg --eta 1.5 --model ggx", "takes no --model"},
      {"integrate ALBEDO --model ggx --mu 0.5", "ALBEDO"},
  });
}

TEST_CASE(
    "kiln bake refuses unknown tables, absurd sizes and thread counts, NaN roughness, and an "
    "output folder it cannot write",
    "[stress][hostile][cli][bake]") {
  ScratchDir dir("hostile_args");
  std::string out = " --out " + Quote(dir / "out");
  WriteFile(dir / "a-file", "not a folder");
  CheckRefused({
      {"bake --only ggx-dfg,,lambert-albedo --size 3" + out, "unknown table ''"},
      {"bake --only GGX-DFG" + out, "unknown table 'GGX-DFG'"},
      {"bake --only 'ggx-dfg;rm -rf /'" + out, "unknown table"},
      {"bake --only lambert-albedo --size 1" + out, "--size 1"},
      {"bake --only lambert-albedo --size -3" + out, "--size"},
      {"bake --only lambert-albedo --size 4097" + out, "--size 4097"},
      {"bake --only lambert-albedo --size 99999999999" + out, "--size"},
      {"bake --only lambert-albedo --size nan" + out, "--size"},
      {"bake --only lambert-albedo --size 2.5" + out, "--size"},
      // 4096^3 texels: refused before any work is done.
      {"bake --only ggx-fresnel-albedo --size 4096" + out, "too many"},
      {"bake --only lambert-albedo -j 1025" + out, "-j"},
      {"bake --only lambert-albedo -j nan" + out, "--threads"},
      {"bake --only oren-nayar-brdf --roughness nan" + out, "--roughness"},
      {"bake --only oren-nayar-brdf --roughness inf" + out, "--roughness"},
      {"bake --only oren-nayar-brdf --roughness -0.0001" + out, "--roughness"},
      {"bake --only lambert-albedo --size 3 --out " + Quote(dir / "a-file"), "a-file"},
      {"bake --only lambert-albedo --size 3 --out " + Quote(dir / "a-file/below"), "a-file/below"},
      {"bake --only lambert-albedo --size 3 --out /proc/kiln-cannot-write-here",
       "/proc/kiln-cannot-write-here"},
      {"bake --scene" + out, "not expected"},
      {"bake --scene x.gltf --only lambert-albedo" + out, "not both"},
  });
  // Nothing was written by any of them.
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}

TEST_CASE("kiln sample, verify and plan refuse absurd numbers", "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_tables");
  REQUIRE(
      RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::string table = Quote(dir / "fresnel-dielectric.exr");
  std::string scene =
      Quote(std::string(KILN_SOURCE_DIR) + "/tests/scenes/metal_rough_factors.gltf");
  CheckRefused({
      {"sample " + table, "coords"},
      {"sample " + table + " 0.5 nan", "finite"},
      {"sample " + table + " 0.5 1e999", "finite"},
      {"verify " + table + " --points -1", "--points"},
      {"verify " + table + " --points nan", "--points"},
      {"verify " + table + " --points 1e20", "--points"},
      {"verify " + table + " --cells -1", "--cells"},
      {"verify " + table + " --tol 0", "--tol"},
      {"verify " + table + " --tol nan", "--tol"},
      {"verify " + table + " --tol 1", "--tol"},
      {"verify", "paths"},
      {"plan " + scene + " --size 1", "--size 1"},
      {"plan " + scene + " --size 5000", "--size 5000"},
      {"plan " + scene + " --size nan", "--size"},
      {"plan", "scene"},
      {"frobnicate", "subcommand"},
      {"", "subcommand"},
      {"list --all-of-them", "--all-of-them"},
  });
}

// CLI11 2.1 would convert an empty string to 0 for a numeric option (`kiln eval --model ggx
// --mu-o ''` would print f at mu_o = 0): every numeric option and argument of every command
// refuses an empty or non-numeric value with one line naming it (RefuseNonNumbers in
// baker/cli/model_options.cpp).
TEST_CASE("An empty numeric argument is refused, not read as 0", "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_empty");
  REQUIRE(
      RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::string table = Quote(dir / "fresnel-dielectric.exr");
  std::string scene =
      Quote(std::string(KILN_SOURCE_DIR) + "/tests/scenes/metal_rough_factors.gltf");
  std::string out = " --out " + Quote(dir / "out");
  CheckRefused({
      {"eval --model ggx --mu-o '' --mu-l 0.5", "--mu-o"},
      {"eval --model ggx --mu-o 0.5 --mu-l ''", "--mu-l"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --phi ''", "--phi"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --roughness ''", "--roughness"},
      {"eval --model lambert --mu-o 0.5 --mu-l 0.5 --rho ''", "--rho"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --f0 ' '", "--f0"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --eta ''", "--eta"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --eta 1.5 --k ''", "--k"},
      {"eval --model triace-lambert --mu-o 0.5 --mu-l 0.5 --rs ''", "--rs"},
      {"eval --model ashikhmin-shirley --mu-o 0.5 --mu-l 0.5 --nu ''", "--nu"},
      {"eval --model ashikhmin-shirley --mu-o 0.5 --mu-l 0.5 --nv abc", "--nv"},
      {"integrate albedo --model ggx --mu ''", "--mu"},
      {"integrate albedo --model ggx --mu 0.5 --tol ''", "--tol"},
      {"integrate fresnel-avg --eta ''", "--eta"},
      {"bake --only lambert-albedo --size ''" + out, "--size"},
      {"bake --only lambert-albedo -j ''" + out, "--threads"},
      {"bake --only oren-nayar-brdf --roughness ''" + out, "--roughness"},
      {"sample " + table + " '' 1.5", "coords"},
      {"sample " + table + " 0.5 x", "coords"},
      {"verify " + table + " --points ''", "--points"},
      {"verify " + table + " --cells ''", "--cells"},
      {"verify " + table + " --tol ''", "--tol"},
      {"verify " + table + " -j ''", "--threads"},
      {"plan " + scene + " --size ''", "--size"},
      {"bench -j ''" + out, "--threads"},
  });
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}

// An empty --only ('') names no table, and an empty --scene no file: both are refused, never
// taken as not given (which would bake the whole catalogue, hours); each run is killed after 20 s.
TEST_CASE("kiln bake --only '' is refused, not the whole catalogue", "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_only");
  for (const std::string option : {"--only", "--scene"}) {
    auto r = RunKilnFor(20, "bake " + option + " '' --out " + Quote(dir / "out"));
    INFO("bake " << option << " '': exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(option) != std::string::npos);
  }
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}

// kiln verify checks -j like kiln bake and kiln bench ([1, 1024] when given; not given: all cores):
// -j 1000000000 would make tbb::task_arena crash the process, and -j -3 is no thread count.
TEST_CASE("kiln verify refuses absurd thread counts", "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_verify");
  REQUIRE(
      RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::string table = Quote(dir / "fresnel-dielectric.exr");
  CheckRefused({{"verify " + table + " --points 1 -j 1000000000", "-j"},
                {"verify " + table + " --points 1 -j -3", "-j"}});
}

// Issue #17: work without caps. Each option that sizes the work has a range, refused with one
// line naming the option and the range: --tol 1e-300 ran 143 M evaluations, verify --points 1e18
// printed "FAILED: std::bad_alloc" and counted the table as over its bound, -j 0 was accepted
// while the message said [1, 1024], plan --size 0 was taken as "not given".
TEST_CASE("Options that size the work are refused outside their ranges, -j 0 and --size 0 included",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_ranges");
  REQUIRE(
      RunKilnFor(60, "bake --only fresnel-dielectric --size 5 --out " + Quote(dir.path.string()))
          .exitCode == 0);
  std::string table = Quote(dir / "fresnel-dielectric.exr");
  std::string scene =
      Quote(std::string(KILN_SOURCE_DIR) + "/tests/scenes/metal_rough_factors.gltf");
  std::string out = " --out " + Quote(dir / "out");
  CheckRefused({
      {"integrate albedo --model ggx --mu 0.5 --roughness 0.5 --tol 1e-300",
       "--tol 1e-300 must be in [1e-13, 0.1]"},
      {"integrate albedo --model ggx --mu 0.5 --tol 1e-14", "[1e-13, 0.1]"},
      {"integrate albedo --model ggx --mu 0.5 --tol 0.5", "[1e-13, 0.1]"},
      {"verify " + table + " --points 1e18", "--points"},
      {"verify " + table + " --points 1000000000000000000",
       "--points 1000000000000000000 must be in [0, 1e7]"},
      {"verify " + table + " --points 10000001", "[0, 1e7]"},
      {"verify " + table + " --cells 1000000000000", "--cells 1000000000000 must be in [0, 1e7]"},
      {"verify " + table + " --tol 1e-300", "--tol 1e-300 must be in [1e-12, 1e-4]"},
      {"verify " + table + " -j 0", "-j 0 must be in [1, 1024]"},
      {"verify " + table + " -j 1025", "[1, 1024]"},
      {"bake --only lambert-albedo --size 3 -j 0" + out, "-j 0 must be in [1, 1024]"},
      {"bench -j 0" + out, "-j 0 must be in [1, 1024]"},
      {"plan " + scene + " --size 0", "--size 0 must be in [2, 4096]"},
  });
  CHECK((!std::filesystem::exists(dir / "out") || std::filesystem::is_empty(dir / "out")));
}

// oneTBB printed "TBB Warning: The number of workers is currently limited to 1" for any -j above
// the number of cores (issue #17 saw it at -j 256); main() raises oneTBB's limit to 1024.
TEST_CASE("A thread count above the number of cores runs without a oneTBB warning",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_threads");
  for (const std::string j : {"256", "1024"}) {
    auto r = RunKilnFor(120, "bake --quiet --only lambert-albedo --size 3 -j " + j + " --out " +
                                 Quote(dir.path.string()));
    INFO("bake -j " << j << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    auto v = RunKilnFor(
        120, "verify --quiet " + Quote(dir / "lambert-albedo.exr") + " --points 4 -j " + j);
    INFO("verify -j " << j << ": exit " << v.exitCode << ", stderr: " << v.err);
    CHECK(v.exitCode == 0);
    CHECK(v.err.empty());
  }
}

// CLI11 2.1 takes "-inf", "-nan" and "-.5" for short options (-i, -n, -.): `sample X -inf 0.3`
// said "-inf" was not expected. They are numbers now, refused or used as numbers.
TEST_CASE("Negative numbers that do not start with a digit are taken as numbers",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_negative");
  REQUIRE(
      RunKilnFor(60, "bake --only ggx-dfg --size 5 --out " + Quote(dir.path.string())).exitCode ==
      0);
  std::string table = Quote(dir / "ggx-dfg.exr");
  CheckRefused({
      {"sample " + table + " -inf 0.3", "coordinates must be finite"},
      {"sample " + table + " 0.5 -nan", "coordinates must be finite"},
      {"integrate albedo --model ggx --roughness 0.5 --mu -inf", "--mu = -inf is outside [0, 1]"},
      {"integrate albedo --model ggx --roughness 0.5 --mu -.5", "--mu = -0.5 is outside [0, 1]"},
      {"eval --model ggx --mu-o 0.5 --mu-l 0.5 --phi -inf", "--phi"},
  });
  // Below the axis: refused naming mu; with --clamp, -.5 and -1e-3 give the values at mu = 0.
  auto at0 = RunKilnFor(60, "sample " + table + " 0 0.3");
  for (const std::string x : {"-.5", "-1e-3", "-0.5"}) {
    auto refused = RunKilnFor(60, "sample " + table + " " + x + " 0.3");
    CHECK(IsCleanRefusal(refused));
    CHECK(refused.err.find("mu ") != std::string::npos);
    auto r = RunKilnFor(60, "sample " + table + " " + x + " 0.3 --clamp");
    INFO("sample " << x << " 0.3 --clamp: exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.out == at0.out);
  }
}

// `kiln integrate albedo --model ggx --mu 5e-324 --roughness 0.5` never returned: in
// baker/integrate/hemisphere.h the masking panels start at m = scale / 4 with scale = mu, which
// rounds to 0 at the smallest subnormals, and 0 * 4 never reaches the end. Killed after 60 s.
TEST_CASE("Integrals at the smallest subnormal mu return the mu = 0 value",
          "[stress][hostile][cli]") {
  for (const std::string q : {"albedo", "dfg"}) {
    auto zero = RunKilnFor(60, "integrate " + q + " --model ggx --mu 0 --roughness 0.5");
    REQUIRE(zero.exitCode == 0);
    for (const std::string mu : {"5e-324", "1e-320", "2.2250738585072014e-308", "1e-300"}) {
      auto r = RunKilnFor(60, "integrate " + q + " --model ggx --mu " + mu + " --roughness 0.5");
      INFO(q << " at mu " << mu << ": exit " << r.exitCode << ", stdout: " << r.out
             << ", stderr: " << r.err);
      REQUIRE(r.exitCode == 0);
      // Within 1e-8 of the mu = 0 value (the tolerance is 1e-9 per integral).
      double a0 = 0, b0 = 0, a = 0, b = 0;
      std::sscanf(zero.out.c_str(), "%lf %lf", &a0, &b0);
      std::sscanf(r.out.c_str(), "%lf %lf", &a, &b);
      CHECK(std::abs(a - a0) < 1e-8);
      CHECK(std::abs(b - b0) < 1e-8);
    }
  }
}

// RunKiln and RunKilnFor start kiln without a shell when the argument line holds only words and
// quotes (kiln::test::SplitShellWords): the words must be exactly those /bin/sh passes, and every
// line with something else the shell acts on must go through the shell.
TEST_CASE("The argument lines the CLI tests run without a shell split into /bin/sh's words",
          "[stress][hostile][cli]") {
  ScratchDir dir("hostile_args_words");
  const std::vector<std::string> lines = {
      "eval --model ggx --mu-o 0.5",
      "  two\tblanks   between\t\twords  ",
      "bake --only '' --out " + Quote(dir / "a folder/with 'quotes'"),
      "sample " + Quote("it's") + " -inf 0.3 -.5",
      "a\"b c\"'d e'f \"\" g\\ h\\'i",
      "unicode \xc3\xa9t\xc3\xa9 =x= -- --opt=value!",
  };
  for (const std::string& line : lines) {
    std::vector<std::string> words;
    INFO("line: " << line);
    REQUIRE(kiln::test::SplitShellWords(line, words));
    const std::string out = dir / "words";
    const std::string cmd = "printf '%s\\0' " + line + " > " + out;
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::string expected;
    for (const std::string& w : words) expected += w + '\0';
    CHECK(kiln::test::ReadFile(out) == expected);
  }
  for (const std::string line :
       {"a > b", "a 2>&1", "a | b", "a; b", "a && b", "$HOME", "a*", "a?", "[ab]", "~", "#c", "`x`",
        "\"$x\"", "'open", "a\\", "a\nb", "{a,b}", "(a)"}) {
    std::vector<std::string> words;
    INFO("line: " << line);
    CHECK_FALSE(kiln::test::SplitShellWords(line, words));
  }
}
