// The error atlas (baker/atlas/atlas.h, `kiln atlas`): a model against itself differs nowhere,
// known analytic differences come out, the max search finds a planted maximum, the albedo of
// each side is what the adaptive integrator gives, the grid is the same for any thread count,
// and bad input fails in one line without touching the output folder.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "baker/atlas/atlas.h"
#include "baker/integrate/quantities.h"
#include "cli_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {

AtlasOptions SmallGrid(int threads = 1) {
  AtlasOptions opt;
  opt.muNodes = 4;
  opt.roughnessNodes = 3;
  opt.threads = threads;
  return opt;
}

const AtlasPair& PairNamed(const std::string& name) {
  for (const AtlasPair& p : AtlasPairs())
    if (p.name == name) return p;
  FAIL("no atlas pair " << name);
  return AtlasPairs().front();
}

}  // namespace

TEST_CASE("atlas: a model against itself differs nowhere", "[atlas]") {
  for (const AtlasPair& pair :
       {AtlasPair{"self-ggx", {"ggx", "f0=0.04"}, {"ggx", "f0=0.04"}, "r", 0.1, 1, ""},
        AtlasPair{"self-on", {"oren-nayar"}, {"oren-nayar"}, "sigma", 0, 1.5, ""},
        AtlasPair{
            "self-bp", {"blinn-phong-normalized"}, {"blinn-phong-normalized"}, "r", 0.2, 1, ""}}) {
    AtlasResult r = ComputeAtlas(pair, SmallGrid());
    REQUIRE(r.cells.size() == 12);
    for (const AtlasCell& c : r.cells) {
      CHECK(c.dE == 0);
      CHECK(c.maxDf == 0);
      CHECK(c.eRef > 0);
    }
  }
}

TEST_CASE("atlas: Lambert against Oren-Nayar at sigma = 0 is zero", "[atlas]") {
  AtlasPair pair = PairNamed("lambert");
  pair.hi = 0;  // the sigma = 0 row only
  AtlasResult r = ComputeAtlas(pair, SmallGrid());
  for (const AtlasCell& c : r.cells) {
    CHECK(std::abs(c.dE) < 3e-7);  // two quadratures: each within its declared 1e-7
    CHECK(c.maxDf < 1e-15);        // the same BRDF, 1/pi, up to rounding
  }
  // And at sigma > 0 they differ: the test can fail.
  AtlasPair rough = PairNamed("lambert");
  rough.lo = rough.hi = 1.0;
  AtlasResult rr = ComputeAtlas(rough, SmallGrid());
  CHECK(rr.cells.back().maxDf > 1e-2);
}

TEST_CASE("atlas: Schlick and exact Fresnel agree at normal incidence", "[atlas]") {
  for (const char* name : {"ggx-schlick-vs-exact-eta1.33", "ggx-schlick-vs-exact-eta1.5",
                           "ggx-schlick-vs-exact-eta2"}) {
    const AtlasPair& pair = PairNamed(name);
    // F(o.h = 1) is f0 for both: the BRDFs agree where wo = wi = n, at every roughness ...
    for (double r : {0.1, 0.5, 1.0}) {
      AnyModel cheap = AtlasModel(pair.cheap, r), ref = AtlasModel(pair.ref, r);
      Vec3 n{0, 0, 1};
      double fc = AtlasF(pair.cheap, cheap, n, n), fr = AtlasF(pair.ref, ref, n, n);
      CHECK(fc > 0);
      CHECK(std::abs(fc - fr) <= 1e-14 * fr);
    }
    // ... and the mirror's albedo (r = 0, the smooth limit E = F(mu)) agrees at mu = 1.
    double ec = AtlasAlbedo(pair.cheap, 1.0, 0.0, 1e-9);
    double er = AtlasAlbedo(pair.ref, 1.0, 0.0, 1e-9);
    CHECK(std::abs(ec - er) < 1e-15);
    // Away from normal incidence Schlick differs from the exact term.
    CHECK(std::abs(AtlasAlbedo(pair.cheap, 0.2, 0.0, 1e-9) -
                   AtlasAlbedo(pair.ref, 0.2, 0.0, 1e-9)) > 1e-3);
  }
}

TEST_CASE("atlas: the 2.04 Blinn-Phong differs from the exact one by the ratio of the factors",
          "[atlas]") {
  const AtlasPair& pair = PairNamed("blinn-phong-2.04");
  for (double r : {0.3, 0.7, 1.0}) {
    double s = std::get<NormalizedBlinnPhong>(AtlasModel(pair.ref, r)).s;
    double ratio =
        NormalizedBlinnPhong::NormalizationApprox(s) / NormalizedBlinnPhong::Normalization(s);
    double ec = AtlasAlbedo(pair.cheap, 0.6, r, 1e-10), er = AtlasAlbedo(pair.ref, 0.6, r, 1e-10);
    CHECK(ec == Approx(ratio * er).epsilon(1e-12));
  }
  // s = 0 (r = 1): (0 + 2.04)/(8 pi) against 2/(4 pi): the approximation is 0.51 of the exact.
  double s0 = std::get<NormalizedBlinnPhong>(AtlasModel(pair.ref, 1.0)).s;
  CHECK(s0 == Approx(0).margin(1e-12));
}

TEST_CASE("atlas: each side's albedo is the adaptive integral of its BRDF", "[atlas]") {
  IntegrationOptions opt;
  opt.tol = 1e-10;
  for (const AtlasPair& pair : AtlasPairs())
    for (const AtlasSide* side : {&pair.cheap, &pair.ref})
      for (double mu : {0.1, 0.7})
        for (double t : {0.0, 1.0}) {
          double r = pair.lo + (pair.hi - pair.lo) * t;
          AnyModel m = AtlasModel(*side, r);
          IntegrationStats stats;
          RhoParts e = DirectionalAlbedo(m, mu, opt, stats);
          double scale = 1;  // the 2.04 side: its constant factor on the exact N(s)
          if (side->rescale == AtlasRescale::BlinnPhong204) {
            double s = std::get<NormalizedBlinnPhong>(m).s;
            scale = NormalizedBlinnPhong::NormalizationApprox(s) /
                    NormalizedBlinnPhong::Normalization(s);
          }
          INFO(pair.name << " " << side->model << " mu " << mu << " r " << r);
          CHECK(AtlasAlbedo(*side, mu, r, 1e-9) == Approx(scale * e.At(1)).margin(1e-6));
        }
}

TEST_CASE("atlas: the max search finds a planted maximum", "[atlas]") {
  MaxSearchOptions opt;
  // A peak of height 3 off every grid node and a broader, lower one elsewhere.
  const double t0 = 0.7371, p0 = 2.1234;
  auto g = [&](double t, double p) {
    return 3 * std::exp(-(Sqr(t - t0) + Sqr(p - p0)) / Sqr(0.08)) +
           2.5 * std::exp(-(Sqr(t - 0.3) + Sqr(p - 0.5)) / Sqr(0.3));
  };
  HemisphereMax m = MaxOverHemisphere(g, opt);
  CHECK(m.value == Approx(3).epsilon(1e-9));
  CHECK(std::abs(m.theta - t0) < 1e-5);
  CHECK(std::abs(m.phi - p0) < 1e-5);
  // A needle narrower than the grid is found from a seed near it, and missed without one.
  auto needle = [&](double t, double p) {
    return 1 + 9 * std::exp(-(Sqr(t - 1.2345) + Sqr(p - 3.0)) / Sqr(1e-3));
  };
  CHECK(MaxOverHemisphere(needle, opt).value < 2);
  HemisphereMax n = MaxOverHemisphere(needle, opt, {{1.2340, 3.0008}});
  CHECK(n.value == Approx(10).epsilon(1e-8));
  // A maximum on the boundary (the horizon, phi = pi) is reached.
  auto edge = [](double t, double p) { return t + p; };
  HemisphereMax e = MaxOverHemisphere(edge, opt);
  CHECK(e.value == Approx(Pi / 2 + Pi).epsilon(1e-12));
}

TEST_CASE("atlas: the search matches a dense scan on real pairs", "[atlas]") {
  for (const char* name : {"ggx-schlick-vs-exact-eta1.5", "fujii", "gotanda-ggx"}) {
    const AtlasPair& pair = PairNamed(name);
    for (double mu : {0.15, 0.8}) {
      for (double r : {pair.lo + 0.05, 0.5 * (pair.lo + pair.hi)}) {
        HemisphereMax m = AtlasMaxDf(pair, mu, r, MaxSearchOptions{});
        AnyModel cheap = AtlasModel(pair.cheap, r), ref = AtlasModel(pair.ref, r);
        double dense = 0;
        for (int i = 0; i <= 200; ++i)
          for (int j = 0; j <= 200; ++j) {
            double t = i * (Pi / 2) / 200, p = j * Pi / 200;
            Vec3 wi = SphericalDirection(std::sin(t), std::cos(t), p);
            double d = AtlasF(pair.cheap, cheap, ViewDirection(mu), wi) -
                       AtlasF(pair.ref, ref, ViewDirection(mu), wi);
            dense = std::max(dense, std::abs(d) * wi.z);
          }
        INFO(name << " mu " << mu << " r " << r);
        CHECK(m.value >= dense * (1 - 1e-9));
      }
    }
  }
}

TEST_CASE("atlas: the same values for any thread count", "[atlas]") {
  const AtlasPair& pair = PairNamed("oren-nayar-qualitative");
  CHECK(AtlasCsv(ComputeAtlas(pair, SmallGrid(1))) == AtlasCsv(ComputeAtlas(pair, SmallGrid(2))));
}

TEST_CASE("atlas: a bad pair fails in one line", "[atlas]") {
  AtlasPair bad{"bad", {"no-such-model"}, {"oren-nayar"}, "sigma", 0, 1, ""};
  CHECK_THROWS_WITH(CheckAtlasPair(bad), Catch::Contains("atlas pair 'bad'") &&
                                             Catch::Contains("unknown model 'no-such-model'"));
  CHECK_THROWS_AS(ComputeAtlas(bad, SmallGrid()), std::invalid_argument);
  AtlasPair range{"range", {"gotanda-ggx"}, {"oren-nayar"}, "sigma", 0, 1.5, ""};
  CHECK_THROWS_WITH(CheckAtlasPair(range), Catch::Contains("outside"));
  AtlasPair param{"param", {"lambert", "eta=1.5"}, {"oren-nayar"}, "sigma", 0, 1, ""};
  CHECK_THROWS_WITH(CheckAtlasPair(param), Catch::Contains("takes no parameter 'eta'"));
}

TEST_CASE("atlas: the CLI writes every file, atomically, and refuses bad input", "[atlas]") {
  std::string dir = TempDir("atlas");
  CommandResult ok = RunKiln("atlas --out " + dir + " --only lambert,fujii --grid 4 -j 2");
  REQUIRE(ok.exitCode == 0);
  for (const char* f : {"lambert.csv", "lambert.png", "fujii.csv", "fujii.png", "README.md"})
    CHECK(std::filesystem::is_regular_file(dir + "/" + f));
  std::string csv = ReadFile(dir + "/lambert.csv");
  CHECK(csv.rfind("mu,roughness,E_ref,E_cheap,dE,max_df,argmax_mu_i,argmax_phi_i\n", 0) == 0);
  CHECK(CountLines(csv) == 1 + 16);
  CHECK(ReadFile(dir + "/README.md").find("kiln atlas --out " + dir) != std::string::npos);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    CHECK(e.path().extension() != ".tmp");
  const std::string readme = ReadFile(dir + "/README.md");

  CommandResult pair = RunKiln("atlas --out " + dir + " --only lambert,no-such-pair");
  CHECK(pair.exitCode != 0);
  CHECK(CountLines(pair.err) == 1);
  CHECK(pair.err.find("unknown pair 'no-such-pair'") != std::string::npos);
  CHECK(ReadFile(dir + "/README.md") == readme);  // untouched

  CommandResult file = RunKiln("atlas --out " + dir + "/lambert.csv --only lambert --grid 4");
  CHECK(file.exitCode != 0);
  CHECK(CountLines(file.err) == 1);
  CHECK(file.err.find("--out") != std::string::npos);

  CommandResult grid = RunKiln("atlas --out " + dir + " --grid 1");
  CHECK(grid.exitCode != 0);
  CHECK(CountLines(grid.err) == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("atlas: docs/atlas is what `kiln atlas --out docs/atlas` writes", "[atlas]") {
  // One pair recomputed at the committed grid, and a row in the README for every pair: adding a
  // pair or changing the method without regenerating docs/atlas fails here.
  AtlasOptions opt;
  opt.threads = 2;
  const std::string dir = std::string(KILN_SOURCE_DIR) + "/docs/atlas/";
  CHECK(AtlasCsv(ComputeAtlas(PairNamed("fujii"), opt)) == ReadFile(dir + "fujii.csv"));
  const std::string readme = ReadFile(dir + "README.md");
  CHECK(readme.find("`kiln atlas --out docs/atlas`") != std::string::npos);
  for (const AtlasPair& p : AtlasPairs()) {
    INFO(p.name);
    CHECK(readme.find("| [" + p.name + "](" + p.name + ".png) |") != std::string::npos);
    CHECK(std::filesystem::is_regular_file(dir + p.name + ".csv"));
    CHECK(std::filesystem::is_regular_file(dir + p.name + ".png"));
  }
}

TEST_CASE("atlas: the search is never beaten by a 301 x 301 scan, every pair", "[atlas][long]") {
  // ~15 s: a 6 x 6 grid of (mu, r) per pair; the search must reach what the dense scan finds.
  for (const AtlasPair& pair : AtlasPairs())
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        double mu = (a + 0.5) / 6, r = pair.lo + (pair.hi - pair.lo) * b / 5;
        HemisphereMax m = AtlasMaxDf(pair, mu, r, MaxSearchOptions{});
        AnyModel cheap = AtlasModel(pair.cheap, r), ref = AtlasModel(pair.ref, r);
        double dense = 0;
        for (int i = 0; i <= 300; ++i)
          for (int j = 0; j <= 300; ++j) {
            double t = i * (Pi / 2) / 300, p = j * Pi / 300;
            Vec3 wi = SphericalDirection(std::sin(t), std::cos(t), p);
            double d = AtlasF(pair.cheap, cheap, ViewDirection(mu), wi) -
                       AtlasF(pair.ref, ref, ViewDirection(mu), wi);
            dense = std::max(dense, std::abs(d) * wi.z);
          }
        INFO(pair.name << " mu " << mu << " r " << r);
        CHECK(m.value >= dense * (1 - 1e-6));
      }
}
