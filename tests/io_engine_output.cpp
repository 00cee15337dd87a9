// Specification of the engine layouts and the engine grid (issue #14): --layout ue4|filament
// for the dfg tables, --grid engine (texel-centred, sampled with the plain (NoV, roughness) as
// the texture coordinate), --flip-y, and `kiln bake --format` end to end.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "baker/io/texture_writers.h"
#include "baker/tables/engine_layout.h"
#include "cli_util.h"
#include "io_texture_util.h"
#include "test_util.h"

namespace fs = std::filesystem;
using kiln::test::RunKiln;

namespace {

kiln::TableSpec GgxDfgSpec(int size) {
  kiln::CatalogueOptions copt;
  copt.size = size;
  return kiln::CatalogueTable("ggx-dfg", copt);
}

kiln::Table Bake(const kiln::TableSpec& spec, bool lookup = false) {
  kiln::BakeOptions opt;
  opt.threads = 2;
  opt.measureLookupError = lookup;
  return kiln::BakeTable(spec, opt);
}

/// What a GPU's bilinear filter returns for channel c at texture coordinate (u, v) of a 2D
/// table (texel centres at (i + 0.5) / N, clamp to edge).
double Bilinear(const kiln::Table& t, double u, double v, int c) {
  const int w = t.size(0), h = t.size(1), nc = int(t.channels.size());
  const double x = std::min(std::max(u * w - 0.5, 0.0), w - 1.0);
  const double y = std::min(std::max(v * h - 0.5, 0.0), h - 1.0);
  const int x0 = std::min(int(x), w - 2), y0 = std::min(int(y), h - 2);
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int i, int j) { return double(t.data[(std::size_t(j) * w + i) * nc + c]); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

}  // namespace

TEST_CASE("layout filament stores (B, A + B), ue4 is kiln's (A, B), others are refused",
          "[io][layout]") {
  const kiln::TableSpec kilnSpec = GgxDfgSpec(8);
  kiln::TableSpec filament = kilnSpec, ue4 = kilnSpec;
  kiln::ApplyDfgLayout(filament, kiln::DfgLayout::Filament);
  kiln::ApplyDfgLayout(ue4, kiln::DfgLayout::Ue4);
  CHECK(ue4.Hash() == kilnSpec.Hash());  // the same bytes
  CHECK(filament.name == "ggx-dfg-filament");
  CHECK(filament.channels == std::vector<std::string>{"B", "A_plus_B"});
  CHECK(filament.Hash() != kilnSpec.Hash());
  const kiln::Table a = Bake(kilnSpec), f = Bake(filament);
  REQUIRE(a.data.size() == f.data.size());
  for (std::size_t i = 0; i < a.data.size(); i += 2) {
    CHECK(f.data[i] == a.data[i + 1]);
    CHECK(std::fabs(double(f.data[i + 1]) - (double(a.data[i]) + a.data[i + 1])) <= 2e-7);
  }
  CHECK(kiln::ParseDfgLayout("ue4") == kiln::DfgLayout::Ue4);
  CHECK_THROWS_WITH(kiln::ParseDfgLayout("ue5"), Catch::Contains("unknown --layout 'ue5'"));
  kiln::TableSpec albedo = kiln::CatalogueTable("ggx-albedo", {});
  CHECK_THROWS_WITH(kiln::ApplyDfgLayout(albedo, kiln::DfgLayout::Filament),
                    Catch::Contains("applies to dfg tables"));
}

TEST_CASE("the engine grid is texel-centred: the plain (NoV, roughness) is the texture coordinate",
          "[io][layout]") {
  kiln::TableSpec spec = GgxDfgSpec(16);
  const std::string kilnHash = spec.Hash();
  kiln::ApplyEngineGrid(spec);
  CHECK(spec.name == "ggx-dfg-engine");
  CHECK(spec.Hash() != kilnHash);
  for (const kiln::AxisSpec& a : spec.axes) {
    CHECK(a.warp == kiln::Warp::Linear);
    CHECK(a.lo == 0.5 / 16);
    CHECK(a.hi == 1 - 0.5 / 16);
    for (int i = 0; i < a.size; ++i)
      CHECK(a.ToAxis().node(i) == Approx((i + 0.5) / 16).epsilon(1e-14));
  }
  const kiln::Table t = Bake(spec, /*lookup=*/true);
  // Its lookup error is measured like any other table's.
  CHECK(t.lookupError.max > 0);
  CHECK(t.lookupError.max < 0.05);
  kiln::test::Rng rng(14);
  const kiln::LutView lut = t.view();
  for (int k = 0; k < 200; ++k) {
    const double x[2] = {rng.Uniform(), rng.Uniform()};
    CHECK(lut.axis[0].gpuCoord(x[0]) == Approx(std::min(std::max(x[0], 0.5 / 16), 1 - 0.5 / 16)));
    float out[2];
    lut.sample(x, out);
    // An engine's texture(lut, vec2(NoV, roughness)) with bilinear filtering.
    for (int c = 0; c < 2; ++c) CHECK(out[c] == Approx(Bilinear(t, x[0], x[1], c)).margin(1e-6));
  }
  kiln::TableSpec fresnel = kiln::CatalogueTable("fresnel-dielectric", {});
  CHECK_THROWS_WITH(kiln::ApplyEngineGrid(fresnel), Catch::Contains("needs (mu, roughness)"));
}

TEST_CASE("flip-y changes the hash and the name, the texels stay in kiln order in memory",
          "[io][layout]") {
  kiln::TableSpec spec = GgxDfgSpec(4);
  const std::string hash = spec.Hash();
  kiln::ApplyFlipY(spec);
  CHECK(spec.name == "ggx-dfg-flipy");
  CHECK(spec.Hash() != hash);
  const kiln::Table t = Bake(spec);
  CHECK(kiln::FlipsY(t));
  CHECK_FALSE(kiln::FlipsY(Bake(GgxDfgSpec(4))));
  CHECK(kiln::FileRowOrder(t, true) == std::vector<int>{3, 2, 1, 0});
}

TEST_CASE("kiln bake --format ktx2 --layout filament --grid engine --flip-y writes one file",
          "[io][layout][cli]") {
  const std::string dir = "/tmp/kiln_test_engine_" + std::to_string(getpid());
  fs::remove_all(dir);
  auto r = RunKiln("bake --out " + dir +
                   " --only ggx-dfg --size 8 --format ktx2 --layout filament --grid engine "
                   "--flip-y --no-lookup-error -j 2");
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const std::string name = "ggx-dfg-filament-engine-flipy";
  CHECK(fs::exists(dir + "/" + name + ".ktx2"));
  CHECK_FALSE(fs::exists(dir + "/" + name + ".exr"));
  auto manifest = nlohmann::json::parse(kiln::test::ReadFile(dir + "/manifest.json"));
  REQUIRE(manifest["tables"].size() == 1);
  CHECK(manifest["tables"][0]["file"] == name + ".ktx2");
  CHECK(manifest["tables"][0]["format"] == "ktx2");
  CHECK(manifest["tables"][0]["pixel_type"] == "float32");
  CHECK(manifest["tables"][0]["params"] == "flip_y=1");

  REQUIRE(RunKiln("bake --out " + dir +
                  " --only ggx-dfg --size 8 --format png16 "
                  "--no-lookup-error")
              .exitCode == 0);
  manifest = nlohmann::json::parse(kiln::test::ReadFile(dir + "/manifest.json"));
  CHECK(manifest["tables"][0]["file"] == "ggx-dfg.png");
  CHECK(manifest["tables"][0]["png16"]["scale"].size() == 2);
  REQUIRE(RunKiln("bake --out " + dir +
                  " --only ggx-dfg --size 8 --format dds --half "
                  "--no-lookup-error")
              .exitCode == 0);
  CHECK(fs::file_size(dir + "/ggx-dfg.dds") == 4 + 124 + 20 + 8 * 8 * 2 * 2);
  fs::remove_all(dir);
}

TEST_CASE("kiln bake refuses a bad --format/--layout/--grid/--flip-y with one line, no files",
          "[io][layout][cli]") {
  const std::string dir = "/tmp/kiln_test_engine_bad_" + std::to_string(getpid());
  for (const char* args : {"--only ggx-dfg --format tiff", "--only ggx-dfg --layout ue5",
                           "--only ggx-dfg --grid texel", "--only ggx-albedo --layout filament",
                           "--layout ue4", "--only fresnel-dielectric --grid engine",
                           "--only ggx-dfg --flip-y", "--only ggx-dfg --format png16 --half"}) {
    fs::remove_all(dir);
    auto r = RunKiln("bake --out " + dir + " --size 4 " + args);
    INFO(args << " -> " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(kiln::test::CountLines(r.err) == 1);
    CHECK(r.err.rfind("kiln: error: ", 0) == 0);
    CHECK_FALSE(fs::exists(dir));
  }
  fs::remove_all(dir);
}
