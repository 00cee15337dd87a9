// A root4-layer-split axis with a constant split point (Axis::split, the file attribute
// kiln.axis<i>.split): the split is data of the table, not physics of the runtime. A constant
// split is t = 1/2 at every layer scale, survives a write and a load, and lets the warp sit on a
// 2-axis table; a file without the attribute keeps the critical cosine of axis 2's eta (the glass
// exit tables). unity-brdf2-albedo splits mu at sqrt(0.1), the kink of Unity's max(0.1, LdotH^2).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "baker/io/exr_writer.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "kiln/exr_loader.h"
#include "kiln/lut.h"
#include "kiln/table.h"
#include "average_reference.h"

using namespace kiln;

TEST_CASE("constant split: x = split is node (N - 1) / 2 at every layer scale",
          "[runtime][split]") {
  const Axis a{0.0, 1.0, 33, Warp::Root4LayerSplit, 0.3};
  REQUIRE(a.valid());
  REQUIRE(a.hasConstantSplit());
  for (double c : {0.0, 1e-12, 1e-4, 0.01, 0.25, 1.0}) {
    INFO("c " << c);
    CHECK(a.node(16, c, a.split) == 0.3);
    if (c > 0) CHECK(a.texel(0.3, c, a.split) == 16.0);
  }
}

TEST_CASE("constant split: valid only strictly inside (lo, hi) and only on root4-layer-split",
          "[runtime][split]") {
  CHECK(!Axis{0.0, 1.0, 33, Warp::Root4LayerSplit, 0.0}.valid());
  CHECK(!Axis{0.0, 1.0, 33, Warp::Root4LayerSplit, 1.0}.valid());
  CHECK(!Axis{0.0, 1.0, 33, Warp::Root4LayerSplit, INFINITY}.valid());
  CHECK(!Axis{0.0, 1.0, 33, Warp::Root4Layer, 0.3}.valid());
  CHECK(!axisProblem(Axis{0.0, 1.0, 33, Warp::Root4Layer, 0.3}).empty());
  CHECK(Axis{0.0, 1.0, 33, Warp::Root4LayerSplit}.valid());  // NaN: the critical cosine
}

// f = max(0, mu - 0.3) at every r, tabulated on 33 x 5 nodes and looked up between the rows:
// with the split at 0.3 the kink is a grid line of every row; root4-layer (no split) puts it
// inside a cell whose ends move with r.
TEST_CASE("constant split: a 2-axis table reads it and holds a fixed kink on a grid line",
          "[runtime][split]") {
  auto maxError = [](const Axis& a0, bool checkView) {
    const Axis a1{0.0, 1.0, 5, Warp::Sqrt};
    std::vector<float> data(static_cast<size_t>(a0.size) * 5);
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < a0.size; ++i) {
        const double mu = a0.node(i, layerScale(0, 1, a1.node(j)), 0.3);
        data[static_cast<size_t>(j * a0.size + i)] = static_cast<float>(std::max(0.0, mu - 0.3));
      }
    LutView v;
    v.data = data.data();
    v.channels = 1;
    v.dims = 2;
    v.axis[0] = a0;
    v.axis[1] = a1;
    REQUIRE(v.valid());
    const double x0[2] = {0.5, 0.5};
    if (checkView) CHECK(v.splitAt(x0) == 0.3);
    double worst = 0;
    for (int j = 0; j <= 100; ++j)
      for (int i = 0; i <= 400; ++i) {
        const double x[2] = {i / 400.0, 0.05 + 0.95 * j / 100.0};
        float got = 0;
        v.sample(x, &got);
        worst = std::max(worst, std::fabs(got - std::max(0.0, x[0] - 0.3)));
      }
    return worst;
  };
  const double split = maxError(Axis{0.0, 1.0, 33, Warp::Root4LayerSplit, 0.3}, true);
  const double plain = maxError(Axis{0.0, 1.0, 33, Warp::Root4Layer}, false);
  INFO("split " << split << " plain " << plain);
  CHECK(split < 0.03);
  CHECK(plain > 2 * split);
  // Without a constant split (NaN) the warp needs axis 2: a 2-axis view is invalid.
  LutView v;
  float one = 0;
  v.data = &one;
  v.channels = 1;
  v.dims = 2;
  v.axis[0] = Axis{0.0, 1.0, 33, Warp::Root4LayerSplit};
  v.axis[1] = Axis{0.0, 1.0, 1, Warp::Sqrt};
  CHECK(!v.valid());
  v.axis[0].split = 0.3;
  CHECK(v.valid());
}

TEST_CASE("constant split: written as kiln.axis0.split and read back, absent reads as NaN",
          "[runtime][split][io]") {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("kiln-constant-split-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Table t;
  t.generator = "kiln test";
  t.name = "split";
  t.model = "none";
  t.quantity = "albedo";
  t.channels = {"E"};
  t.channelMeanings = {"directional albedo"};
  t.axes = {{"mu", {0.0, 1.0, 9, Warp::Root4LayerSplit, 0.31622776601683794}},
            {"roughness", {0.0, 1.0, 2, Warp::Sqrt}}};
  t.data.assign(18, 0.5f);
  writeTable((dir / "split.exr").string(), t, false);
  const Table back = loadTable((dir / "split.exr").string());
  CHECK(back.axes[0].axis.split == 0.31622776601683794);  // bit for bit (a double attribute)
  CHECK(std::isnan(back.axes[1].axis.split));
  // A 3-axis split table without the attribute: NaN, the critical cosine of axis 2's eta.
  t.axes = {{"mu", {0.0, 1.0, 9, Warp::Root4LayerSplit}},
            {"roughness", {0.0, 1.0, 2, Warp::Sqrt}},
            {"eta", {1.0 / 3, 1 / 1.1, 2, Warp::Linear}}};
  t.data.assign(36, 0.5f);
  writeTable((dir / "critical.exr").string(), t, false);
  const Table old = loadTable((dir / "critical.exr").string());
  CHECK(std::isnan(old.axes[0].axis.split));
  const double x[3] = {0.5, 0.5, 0.5};
  CHECK(old.view().splitAt(x) == criticalSplit(0, 1, 1.0 / 3, 1 / 1.1, 0.5));
  fs::remove_all(dir);
}

TEST_CASE("the exit tables keep the critical cosine: no split attribute, no new hash text",
          "[dielectric][split]") {
  for (const char* name : {"ggx-dielectric-albedo-r-exit", "ggx-dielectric-albedo-t-exit"}) {
    const TableSpec spec = CatalogueTable(name, CatalogueOptions{});
    CHECK(std::isnan(spec.axes[0].split));
    CHECK(spec.HashText().find("split=") == std::string::npos);
  }
}

TEST_CASE("unity-brdf2-albedo: the kink mu = sqrt(0.1) is the middle mu node of every row",
          "[unity][split]") {
  const TableSpec spec = CatalogueTable("unity-brdf2-albedo", CatalogueOptions{});
  REQUIRE(spec.axes.size() == 2);
  REQUIRE(spec.axes[0].warp == Warp::Root4LayerSplit);
  REQUIRE(spec.axes[0].split == std::sqrt(0.1));
  const size_t n0 = static_cast<size_t>(spec.axes[0].size), n1 = spec.axes[1].size;
  REQUIRE((n0 - 1) % 8 == 0);
  for (size_t j = 0; j < n1; ++j) {
    double x[2];
    NodeCoordinates(spec, j * n0 + (n0 - 1) / 2, x);
    INFO("roughness " << x[1]);
    CHECK(x[0] == std::sqrt(0.1));
  }
  CHECK(spec.HashText().find("split=") != std::string::npos);
}

// The average integrates E(mu) across the same kink: its mu panels are graded about sqrt(0.1)
// from alpha (fixed_rule_average.h, kinkLayer). Without them the rule was 1.7e-3 off at
// r = 0.0537 (a = 2.9e-3, the kink smoothed over ~a).
namespace {

/// unity-brdf2-albedo-avg's fixed rule at roughness r within 1e-6 of the adaptive integrator
/// (1e-8, test::AdaptiveAverageSpec).
void CheckUnity2Average(double r) {
  const TableSpec spec = CatalogueTable("unity-brdf2-albedo-avg", CatalogueOptions{});
  REQUIRE(UsesFixedRule(spec));
  IntegrationStats fixedStats;
  const double x[1] = {r};
  const double fixed = EvaluateSpec(spec, x, fixedStats)[0];
  const double adaptive = test::AdaptiveAverageSpec(spec, x, 1e-8)[0];
  INFO("r " << r << " fixed " << fixed << " adaptive " << adaptive);
  CHECK(std::fabs(fixed - adaptive) < 1e-6);
}

}  // namespace

// One test per roughness (each adaptive average takes seconds).
TEST_CASE(
    "unity-brdf2-albedo-avg: the fixed rule is the adaptive integrator's within 1e-6 at "
    "r = 0.0537",
    "[unity][split]") {
  CheckUnity2Average(0.0536717);
}

TEST_CASE(
    "unity-brdf2-albedo-avg: the fixed rule is the adaptive integrator's within 1e-6 at r = 0.1",
    "[unity][split]") {
  CheckUnity2Average(0.1);
}

TEST_CASE(
    "unity-brdf2-albedo-avg: the fixed rule is the adaptive integrator's within 1e-6 at r = 0.3",
    "[unity][split]") {
  CheckUnity2Average(0.3);
}
