// The committed tables in luts/: they load, they are exact at their nodes, they keep their
// declared lookup-error bounds, and the default 2D microfacet tables meet 1e-3 off the corner.
#include <catch2/catch.hpp>
#include <dirent.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "cli_util.h"
#include "committed_luts.h"
#include "kiln/exr_loader.h"
#include "test_util.h"

using namespace kiln;
using kiln::test::LutFiles;
using kiln::test::LutsDir;

namespace {

/// One file per table, as the manifest's "file" names it (part 1 of a table stored in parts,
/// whose loading reads the other parts too).
std::vector<std::string> TableFiles() {
  auto manifest = nlohmann::json::parse(test::ReadFile(LutsDir() + "/manifest.json"));
  std::vector<std::string> out;
  for (auto& t : manifest["tables"]) out.push_back(t["file"].get<std::string>());
  std::sort(out.begin(), out.end());
  return out;
}

constexpr double kLookupBound = 1e-3;   ///< the default 2D microfacet tables' lookup error
constexpr double kReferenceTol = 1e-5;  ///< their references' tolerance: 100 times below it
constexpr int kLookupPoints = 300;      ///< the seeded points of each table's check

}  // namespace

TEST_CASE("luts/ holds the catalogue, listed in its manifest", "[luts]") {
  auto files = LutFiles();
  REQUIRE(files.size() >= 50);
  auto manifest = nlohmann::json::parse(test::ReadFile(LutsDir() + "/manifest.json"));
  // Every file is listed once: an entry's "file", or one of its "files" (a table in parts).
  std::vector<std::string> listed;
  for (auto& t : manifest["tables"]) {
    if (t.contains("files")) {
      CHECK(t["files"][0] == t["file"]);
      for (auto& f : t["files"]) listed.push_back(f.get<std::string>());
    } else {
      listed.push_back(t["file"].get<std::string>());
    }
  }
  std::sort(listed.begin(), listed.end());
  CHECK(listed == files);
  for (auto& t : manifest["tables"]) {
    INFO(t["name"]);
    CHECK(t["layout"] == kLayoutVersion);
    CHECK(std::find(files.begin(), files.end(), t["file"].get<std::string>()) != files.end());
    CHECK(t["bake_error"].get<double>() < 1e-6);
    // Every shipped table declares (the bake's lookup-error search: 1.5 x (the max it found +
    // its reference's distance from the bake rule)) below 1e-3 over its whole domain, but the
    // LTC tables in the published layout (kind ltc; 64 linear nodes of roughness x
    // sqrt(1 - N.V), for the shaders written for the original textures): they cannot follow the
    // albedo's layer at N.V -> 0, their norm channels declare 0.163 (ltc-ggx), 0.129
    // (ltc-beckmann, ltc-blinn-phong) (README "LTC tables"); kiln's own layout, ltc-ggx-kiln (on
    // request), declares 7.5e-4. ltc-charlie-smith declares 0.209: its N.V = 0 row holds the
    // norm at mu = 1e-4, where its albedo starts, and at r = 0.12 E rises from 1.16 there to 1.28
    // at mu = 0.005 and falls to 1.05 at the next row (mu = 0.0315): a peak no linear axis in
    // sqrt(1 - N.V) follows (docs/ltc.md).
    const std::string name = t["name"].get<std::string>();
    const bool publishedLtc =
        name == "ltc-ggx" || name == "ltc-beckmann" || name == "ltc-blinn-phong";
    const double limit = name == "ltc-charlie-smith" ? 0.25 : publishedLtc ? 0.2 : 1e-3;
    CHECK(t["lookup_error"]["max"].get<double>() < limit);
  }
}

TEST_CASE("A lookup at a node of any committed table returns the stored texel exactly", "[luts]") {
  for (const std::string& name : TableFiles()) {
    Table t = loadTable(LutsDir() + "/" + name);
    LutView v = t.view();
    size_t nc = t.channels.size(), n = t.data.size() / nc;
    size_t stride = std::max<size_t>(1, n / 2000);
    for (size_t i = 0; i < n; i += stride) {
      double x[3];
      size_t k = i;
      for (int d = 0; d < t.dims(); ++d) {
        x[d] = t.axes[d].axis.node(static_cast<int>(k % t.axes[d].axis.size));
        k /= t.axes[d].axis.size;
      }
      const Axis& a0 = t.axes[0].axis;
      const int i0 = static_cast<int>(i % a0.size);
      // A collapsed layer (r = 0, eta = 1) places its nodes up to t = 1/2 (root4-layer) or
      // below 1 (layer-eta) at mu = 0, which maps to one t: no lookup lands on the others, the
      // layer's limit (lut.h), read by lookups next to the collapse point.
      // A split axis 0 (root4-layer-split, -split2) places its nodes by axis 2's value too.
      x[0] = a0.node(i0, v.layerScaleAt(x), v.splitAt(x));
      if (a0.texel(x[0], v.layerScaleAt(x), v.splitAt(x)) != i0) continue;
      float lin[8], cub[8];
      v.sample(x, lin, Filter::Linear);
      v.sample(x, cub, Filter::Cubic);
      for (size_t c = 0; c < nc; ++c) {
        INFO(name << " texel " << i);
        REQUIRE(lin[c] == t.data[i * nc + c]);
        REQUIRE(cub[c] == t.data[i * nc + c]);
      }
    }
  }
}

// Every committed table passes `kiln verify`: tests/verify_committed_luts.cpp.

namespace {

/// The worst lookup error of the 2D table `t` against adaptive quadrature at kReferenceTol over
/// kLookupPoints seeded points, a third of them grazing (mu down to 1e-12) and a third in the
/// corner (mu, r) -> (0, 0). stopAbove >= 0: returns at the first point beyond it. `references`,
/// when not null, receives each point's reference (every channel), in the order of the points (the
/// same for every table); `given`, when not null, holds them instead of integrating.
double LookupWorst(const Table& t, std::string& where, double stopAbove = -1,
                   std::vector<std::vector<double>>* references = nullptr,
                   const std::vector<std::vector<double>>* given = nullptr) {
  TableSpec spec = SpecFromTable(t);
  test::Rng rng(99);
  double worst = 0;
  for (int i = 0; i < kLookupPoints; ++i) {
    double u = rng.Uniform(), v = rng.Uniform();
    double x[2] = {u, v};
    if (i % 3 == 1) x[0] = std::pow(10.0, -12 * u);  // grazing, down to 1e-12
    if (i % 3 == 2) {                                // the corner
      x[0] = std::pow(10.0, -12 * u);
      x[1] = i % 2 ? 0.0 : std::pow(10.0, -6 * v);
    }
    IntegrationStats st;
    const std::vector<double> exact =
        given ? (*given)[static_cast<size_t>(i)] : EvaluateSpec(spec, x, kReferenceTol, st);
    if (references) references->push_back(exact);
    float got[2];
    t.view().sample(x, got);
    for (size_t c = 0; c < exact.size(); ++c)
      if (std::abs(got[c] - exact[c]) > worst) {
        worst = std::abs(got[c] - exact[c]);
        where = "mu " + std::to_string(x[0]) + " r " + std::to_string(x[1]);
      }
    if (stopAbove >= 0 && worst > stopAbove) break;
  }
  return worst;
}

}  // namespace

TEST_CASE(
    "Default 2D microfacet tables: lookup error below 1e-3 over the whole domain, "
    "grazing angles and roughness 0 included",
    "[luts]") {
  // The root4-layer mu axis follows the layer mu ~ alpha at every roughness (lut.h), so the
  // corner (mu, r) -> (0, 0) is sampled like the rest: a third of the points lie in it. The
  // references are adaptive quadrature, independent of the fixed rule the ggx tables are baked
  // with, at a tolerance 100 times below the bound checked (kReferenceTol).
  // ggx-albedo's E is ggx-dfg's A + B (F = 1): its references are the DFG's, summed, at the same
  // points (each channel within kReferenceTol, their sum within twice it: 50 times below the
  // bound), instead of a second integration of the same integrand.
  std::vector<std::vector<double>> dfg, albedo;
  for (const char* name :
       {"ggx-dfg", "ggx-albedo", "ggx-separable-dfg", "beckmann-dfg", "blinn-phong-albedo"}) {
    const bool isDfg = std::string(name) == "ggx-dfg", isAlbedo = std::string(name) == "ggx-albedo";
    if (isAlbedo) {
      REQUIRE(dfg.size() == static_cast<size_t>(kLookupPoints));
      for (const std::vector<double>& ab : dfg) albedo.push_back({ab[0] + ab[1]});
      // The identity, checked where it is hardest: the bulk, a grazing view, the corner.
      const TableSpec e = CatalogueTable("ggx-albedo"), ab = CatalogueTable("ggx-dfg");
      for (const std::array<double, 2>& x :
           {std::array<double, 2>{0.5, 0.5}, {1e-6, 0.3}, {1e-9, 1e-4}}) {
        IntegrationStats st;
        const std::vector<double> own = EvaluateSpec(e, x.data(), kReferenceTol, st),
                                  sum = EvaluateSpec(ab, x.data(), kReferenceTol, st);
        INFO("mu " << x[0] << " r " << x[1]);
        CHECK(std::abs(own[0] - (sum[0] + sum[1])) <= 2 * kReferenceTol);
      }
    }
    std::string where;
    const double worst = LookupWorst(loadTable(LutsDir() + "/" + name + ".exr"), where, -1,
                                     isDfg ? &dfg : nullptr, isAlbedo ? &albedo : nullptr);
    INFO(name << " worst " << worst << " at " << where);
    CHECK(worst < kLookupBound);
  }
}

TEST_CASE(
    "A ggx-albedo whose texels are one mu node off misses the 1e-3 lookup bound (the check can "
    "fail)",
    "[luts]") {
  Table t = loadTable(LutsDir() + "/ggx-albedo.exr");
  const size_t n0 = static_cast<size_t>(t.axes[0].axis.size), nc = t.channels.size();
  for (size_t k = 0; k + 1 < t.data.size() / nc; ++k)
    if ((k + 1) % n0 != 0)
      for (size_t c = 0; c < nc; ++c) t.data[k * nc + c] = t.data[(k + 1) * nc + c];
  std::string where;
  const double worst = LookupWorst(t, where, kLookupBound);
  INFO("worst " << worst << " at " << where);
  CHECK(worst > kLookupBound);
}
