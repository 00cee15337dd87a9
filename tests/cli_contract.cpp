// The command-line contract other tools rely on: kiln list, eval, integrate.
#include <catch2/catch.hpp>
#include <cmath>

#include "cli_util.h"

using kiln::test::CountLines;
using kiln::test::RunKiln;

TEST_CASE("kiln list prints every model id, one per line with its parameters", "[cli]") {
  auto r = RunKiln("list");
  REQUIRE(r.exitCode == 0);
  CHECK(CountLines(r.out) == 34);  // 33 BRDFs and the BSDF ggx-dielectric
  for (const char* id : {"lambert ", "ggx roughness=", "ggx-vcavity ", "oren-nayar-qualitative-ir ",
                         "ashikhmin-shirley roughness=", "ggx-dielectric roughness="})
    CHECK(("\n" + r.out).find(std::string("\n") + id) != std::string::npos);
}

TEST_CASE("kiln eval prints one value", "[cli]") {
  auto r = RunKiln("eval --model lambert --mu-o 0.5 --mu-l 0.3 --phi 1 --rho 0.5");
  REQUIRE(r.exitCode == 0);
  CHECK(std::stod(r.out) == Approx(0.5 / M_PI).epsilon(1e-15));
  CHECK(CountLines(r.out) == 1);
}

TEST_CASE("kiln integrate prints the channels on one line at full precision, nothing else",
          "[cli]") {
  auto a = RunKiln("integrate albedo --model ggx --mu 0.5 --roughness 1");
  REQUIRE(a.exitCode == 0);
  CHECK(CountLines(a.out) == 1);
  CHECK(std::stod(a.out) == Approx(1 - 0.5 * std::log(3.0)).margin(1e-12));
  auto d = RunKiln("integrate dfg --model ggx --mu 0.5 --roughness 0.5");
  REQUIRE(d.exitCode == 0);
  double A = 0, B = 0;
  REQUIRE(std::sscanf(d.out.c_str(), "%lf %lf", &A, &B) == 2);
  auto e = RunKiln("integrate albedo --model ggx --mu 0.5 --roughness 0.5");
  CHECK(A + B == Approx(std::stod(e.out)).margin(2e-9));
  auto avg = RunKiln("integrate albedo-avg --model lambert");
  CHECK(std::stod(avg.out) == Approx(1).margin(1e-12));
  auto f = RunKiln("integrate fresnel-avg --eta 0.34 --k 3.2");
  REQUIRE(f.exitCode == 0);
  CHECK(std::stod(f.out) > 0.8);
  CHECK(std::stod(f.out) < 1.0);
}

TEST_CASE("Bad input: one clear line on stderr and a non-zero exit", "[cli]") {
  const char* cases[][2] = {
      {"integrate albedo --model nope --mu 0.5", "unknown model 'nope'"},
      {"integrate albedo --model ggx --mu 0.5 --roughness 2", "roughness"},
      {"integrate albedo --model ggx --mu 1.5", "--mu"},
      {"integrate albedo --model ggx", "needs --mu"},
      {"integrate albedo-avg --model ggx --mu 0.5", "takes no --mu"},
      {"integrate fresnel-avg", "needs --eta"},
      {"integrate dfg --model lambert --mu 0.5", "specular"},
      {"integrate volume --model ggx --mu 0.5", "volume"},
      {"eval --model ggx --mu-o 0.5 --mu-l -0.1 --roughness 0.5", "--mu-l"},
      {"integrate albedo --model ggx --mu abc", "abc"},
  };
  for (auto& c : cases) {
    auto r = RunKiln(c[0]);
    INFO(c[0] << " -> " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(r.out.empty());
    CHECK(CountLines(r.err) == 1);
    CHECK(r.err.find(c[1]) != std::string::npos);
  }
}
