// The lookup-error search (baker/bake/lookup_error.h) that the bake declares its bound from and
// `kiln verify` repeats: it finds a corrupted texel, the worst point of a thin layer that cell
// centres and random points miss, gives the same report for any thread count, and finds nothing
// above the bound of the committed tables.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "baker/bake/bake.h"
#include "baker/bake/lookup_error.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"
#include <nlohmann/json.hpp>

#include "cli_util.h"
#include "kiln/exr_loader.h"
#include "test_util.h"

using namespace kiln;
using kiln::test::TempDir;

namespace {

/// The most channels of the tables these tests scan.
constexpr size_t kMaxChannels = 8;

BakeOptions TwoThreads() {
  BakeOptions o;
  o.threads = 2;
  return o;
}

/// |lookup - reference| at the point of warped coordinates t (max over channels). The lookup is
/// LutView::sample's (LutSampler::sampleDouble, the double path the baker's search measures),
/// with the sampler prepared once by the caller instead of at every point of a dense scan.
double ErrorAt(const TableSpec& spec, const LutSampler& sampler, const double* t) {
  double x[3] = {0, 0, 0};
  PointAtWarped(spec, t, x);
  IntegrationStats st;
  std::vector<double> exact = EvaluateSpec(spec, x, st);
  float got[kMaxChannels];  // the callers check both channel counts against it
  sampler.sampleDouble(x, got);
  double m = 0;
  for (size_t c = 0; c < exact.size(); ++c) m = std::max(m, std::abs(got[c] - exact[c]));
  return m;
}

}  // namespace

TEST_CASE("kiln verify reports one texel corrupted by 1e-2, in the interior or near a corner",
          "[verify][search]") {
  // burley-albedo at 16 x 16 nodes: adaptive quadrature, a bound of about 1e-3.
  CatalogueOptions copt;
  copt.size = 16;
  TableSpec spec = CatalogueTable("burley-albedo", copt);
  Table baked = BakeTable(spec, TwoThreads());
  REQUIRE(baked.lookupError.max > 0);
  REQUIRE(baked.lookupError.max < 5e-3);
  std::string dir = TempDir("verify_corrupt");
  WriteBakedTable(dir, baked, false, false);
  const std::string file = dir + "/burley-albedo.exr";
  auto clean = test::RunKiln("verify " + file + " -j 2 --quiet");
  INFO(clean.out << clean.err);
  CHECK(clean.exitCode == 0);

  const size_t nc = baked.channels.size();
  for (int node : {8 + 16 * 7, 1 + 16 * 1}) {  // (mu 8, r 7) interior; (mu 1, r 1) by the corner
    Table bad = baked;
    bad.data[static_cast<size_t>(node) * nc] += 1e-2f;
    WriteBakedTable(dir, bad, false, false);
    auto r = test::RunKiln("verify " + file + " -j 2 --quiet");
    INFO("node " << node << "\n" << r.out << r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.out.find("EXCEEDS BOUND") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("The search finds a thin layer's worst error within 10%", "[verify][search]") {
  // fresnel-dielectric at 16 x 16 nodes: F(mu, eta) rises from 0 to 1 in a layer
  // mu < ~sqrt(eta - 1), far thinner than the first eta cell (eta < 1.0035). The worst case by a
  // dense scan of every cell (256 x 256 points each, in warped coordinates).
  CatalogueOptions copt;
  copt.size = 16;
  TableSpec spec = CatalogueTable("fresnel-dielectric", copt);
  BakeOptions o = TwoThreads();
  o.measureLookupError = false;
  Table t = BakeTable(spec, o);
  LutView view = t.view();
  const LutSampler sampler(view);
  REQUIRE(static_cast<size_t>(view.channels) <= kMaxChannels);
  REQUIRE(spec.channels.size() <= kMaxChannels);
  const int cells = 15, scan = 256;
  double truth = 0;
  for (int c1 = 0; c1 < cells; ++c1)
    for (int c0 = 0; c0 < cells; ++c0)
      for (int j = 0; j < scan; ++j)
        for (int i = 0; i < scan; ++i) {
          double tt[3] = {(c0 + (i + 0.5) / scan) / cells, (c1 + (j + 0.5) / scan) / cells, 0};
          truth = std::max(truth, ErrorAt(spec, sampler, tt));
        }
  LookupSearchOptions opt;
  opt.threads = 2;
  LookupErrorReport rep = MeasureLookupError(spec, view, opt);
  INFO("dense scan " << truth << ", search " << rep.max << " at " << rep.WhereText(spec));
  CHECK(rep.max >= 0.9 * truth);
  CHECK(rep.max <= 1.1 * truth);
}

TEST_CASE(
    "The search finds the conductor's layer at n = 1 within 10%, where cell centres and random "
    "points miss it by more than 2x",
    "[verify][search]") {
  // fresnel-conductor at 32^3 nodes on its former axes (n in [0.1, 4], k in [0, 8], beyond
  // the metals the catalogue's table now covers): for k -> 0 the reflectance jumps across
  // n = 1 (total reflection below it at grazing mu), inside the cell n in [0.98, 1.11]; the
  // stored residual keeps that kink. The worst case by a scan concentrated on that layer:
  // 512 mu values x n = 1 +- 10^-7..10^-1 (129 values) x k = 0 and 10^-7..10^-0.5 (33 values),
  // in axis units.
  TableSpec spec = Describe(Quantity::FresnelConductor)
                       .makeSpec("none", {{"mu", 0, 1, 32, Warp::Root4},
                                          {"n", 0.1, 4, 32, Warp::Linear},
                                          {"k", 0, 8, 32, Warp::Linear}});
  BakeOptions o = TwoThreads();
  o.measureLookupError = false;
  Table t = BakeTable(spec, o);
  LutView view = t.view();
  const LutSampler sampler(view);
  REQUIRE(static_cast<size_t>(view.channels) <= kMaxChannels);
  REQUIRE(spec.channels.size() <= kMaxChannels);
  double truth = 0;
  for (int i = 0; i < 512; ++i)
    for (int j = -64; j <= 64; ++j)
      for (int k = 0; k <= 32; ++k) {
        double dn = j == 0 ? 0.0 : std::pow(10.0, -7 + 6.0 * std::abs(j) / 64);
        double x[3] = {(i + 0.5) / 512, j < 0 ? 1 - dn : 1 + dn,
                       k == 0 ? 0.0 : std::pow(10.0, -7 + 6.5 * k / 32)};
        double tt[3];
        for (int d = 0; d < 3; ++d) tt[d] = spec.axes[d].ToAxis().warped(x[d]);
        truth = std::max(truth, ErrorAt(spec, sampler, tt));
      }
  // The old measurement: every cell centre and 1000 random points.
  const int cells = 31;
  double centresAndRandom = 0;
  for (int c2 = 0; c2 < cells; ++c2)
    for (int c1 = 0; c1 < cells; ++c1)
      for (int c0 = 0; c0 < cells; ++c0) {
        double tt[3] = {(c0 + 0.5) / cells, (c1 + 0.5) / cells, (c2 + 0.5) / cells};
        centresAndRandom = std::max(centresAndRandom, ErrorAt(spec, sampler, tt));
      }
  test::Rng rng(7);
  for (int i = 0; i < 1000; ++i) {
    double tt[3] = {rng.Uniform(), rng.Uniform(), rng.Uniform()};
    centresAndRandom = std::max(centresAndRandom, ErrorAt(spec, sampler, tt));
  }
  LookupSearchOptions opt;
  opt.threads = 2;
  LookupErrorReport rep = MeasureLookupError(spec, view, opt);
  INFO("layer scan " << truth << ", centres + random " << centresAndRandom << ", search " << rep.max
                     << " at " << rep.WhereText(spec) << " (" << rep.points << " points)");
  CHECK(rep.max >= 0.9 * truth);
  CHECK(centresAndRandom * 2 < truth);
}

TEST_CASE("The search reports the same for -j 1 and -j 2", "[verify][search]") {
  CatalogueOptions copt;
  copt.size = 12;
  for (const char* name : {"burley-albedo", "fresnel-conductor"}) {
    TableSpec spec = CatalogueTable(name, copt);
    BakeOptions o = TwoThreads();
    o.measureLookupError = false;
    Table t = BakeTable(spec, o);
    LookupSearchOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.randomPoints = two.randomPoints = 100;
    LookupErrorReport a = MeasureLookupError(spec, t.view(), one);
    LookupErrorReport b = MeasureLookupError(spec, t.view(), two);
    INFO(name);
    CHECK(a.max == b.max);
    CHECK(a.rms == b.rms);
    CHECK(a.where == b.where);
    CHECK(a.points == b.points);
    CHECK(a.cells == b.cells);
    CHECK(a.climbed == b.climbed);
  }
  // And the command: the same stdout (its per-table seconds go to stderr).
  std::string dir = TempDir("verify_threads");
  REQUIRE(test::RunKiln("bake --quiet --only burley-albedo,fresnel-dielectric --size 12 -j 2 "
                        "--out " +
                        dir)
              .exitCode == 0);
  auto j1 = test::RunKiln("verify " + dir + " -j 1");
  auto j2 = test::RunKiln("verify " + dir + " -j 2");
  CHECK(j1.exitCode == j2.exitCode);
  CHECK(j1.out == j2.out);
  CHECK(test::CountLines(j2.err) == 3);  // a line per table and the total
  CHECK(j2.err.find("burley-albedo") != std::string::npos);
  CHECK(j2.err.find("declared") != std::string::npos);
  auto quiet = test::RunKiln("verify " + dir + " -j 2 --quiet");
  CHECK(quiet.out == j2.out);
  CHECK(quiet.err == j2.err.substr(j2.err.find("kiln: error:") == std::string::npos
                                       ? j2.err.size()
                                       : j2.err.find("kiln: error:")));
  std::filesystem::remove_all(dir);
}

TEST_CASE("kiln verify refuses a budget out of [0, 1e7] in one line", "[verify][search][cli]") {
  const std::string table = std::string(KILN_SOURCE_DIR) + "/luts/lambert-albedo.exr";
  for (const char* arg : {"--budget -1", "--budget 10000001", "--budget nan", "--tol 0"}) {
    auto r = test::RunKiln("verify " + table + " " + arg);
    INFO(arg << ": " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(test::CountLines(r.err) == 1);
    CHECK(r.err.find(std::string(arg).substr(0, std::string(arg).find(' '))) != std::string::npos);
  }
}

TEST_CASE("Every committed table: the search finds nothing above its declared bound",
          "[verify][search][long]") {
  // The search kiln verify runs, on each table of luts/ (one per table kind and model),
  // against the bake's own method; tolerance as kiln verify's.
  for (const char* name :
       {"fresnel-dielectric", "fresnel-conductor", "fresnel-dielectric-avg", "ggx-fresnel-albedo",
        "ggx-fresnel-albedo-avg", "ggx-dfg", "ggx-albedo", "ggx-albedo-avg", "burley-albedo",
        "blinn-phong-normalization", "oren-nayar-brdf", "gotanda-ggx-brdf", "ggx-separable-albedo",
        "beckmann-dfg"}) {
    Table t = loadTable(std::string(KILN_SOURCE_DIR) + "/luts/" + name + ".exr");
    TableSpec spec = SpecFromTable(t);
    LookupSearchOptions opt;
    opt.threads = 2;
    LookupErrorReport rep = MeasureLookupError(spec, t.view(), opt);
    INFO(name << ": max " << rep.max << " at " << rep.WhereText(spec) << ", declared "
              << t.lookupError.max);
    CHECK(rep.max <= t.lookupError.max + spec.tol + t.bakeError);
  }
}

TEST_CASE(
    "kiln verify with a budget below one cell's probes probes that cell in full and reports it",
    "[verify][cli][hostile]") {
  // A budget smaller than one cell's probes: the search probes the first cell (a corner) in full.
  // It used to probe nothing and read the report of an empty search (a segfault).
  for (const char* budget : {"1", "2", "3"}) {
    auto r = kiln::test::RunKiln(std::string("verify ") + KILN_SOURCE_DIR +
                                 "/luts/lambert-albedo.exr --budget " + budget + " -j 1 --json");
    INFO("--budget " << budget << ": " << r.out << r.err);
    REQUIRE(r.exitCode == 0);
    auto j = nlohmann::json::parse(r.out);
    const auto& t = j["tables"][0];
    CHECK(t["cells"].get<long long>() == 1);
    CHECK(t["budget"].get<long long>() > 3);  // raised to the cell's probes
    CHECK(t["points"].get<long long>() > 0);
    CHECK(t["ok"].get<bool>());
  }
}
