// The committed fresnel-conductor table against direct evaluation of the exact conductor Fresnel
// term, densely over its whole declared domain (the metals in the visible), and `kiln sample`
// on it: F itself at a point of the domain, a one-line refusal naming the domain outside it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <tuple>

#include "baker/models/fresnel.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"
#include "scene_util.h"
#include "test_util.h"

using namespace kiln;

namespace {

const std::string kTable = std::string(KILN_SOURCE_DIR) + "/luts/fresnel-conductor.exr";

struct Worst {
  double err = 0, mu = 0, n = 0, k = 0;
  long points = 0;
  void Probe(const Table& t, double mu, double n, double k) {
    const double p[3] = {mu, n, k};
    double got = 0;
    sampleQuantity(t, p, &got);
    const double e = std::abs(got - FrComplex(mu, n, k));
    ++points;
    if (e > err) {
      err = e;
      this->mu = mu;
      this->n = n;
      this->k = k;
    }
  }
};

}  // namespace

TEST_CASE("fresnel-conductor: below 1e-3 and its declared bound over the whole domain",
          "[tables][fresnel][conductor]") {
  Table t = loadTable(kTable);
  REQUIRE(storedForm(t) == StoredForm::ConductorResidual);
  REQUIRE(t.dims() == 3);
  const Axis& am = t.axes[0].axis;
  const Axis& an = t.axes[1].axis;
  const Axis& ak = t.axes[2].axis;
  // The domain the README and docs/models.md state: mu in [0, 1], n in [0.03, 4], k in [1.5, 10].
  CHECK(am.lo == 0.0);
  CHECK(am.hi == 1.0);
  CHECK(an.lo == Approx(0.03));
  CHECK(an.hi == 4.0);
  CHECK(ak.lo == 1.5);
  CHECK(ak.hi == 10.0);
  Worst w;
  test::Rng rng(31);
  for (int i = 0; i < 150000; ++i) {
    const double a = rng.Uniform(), b = rng.Uniform(), c = rng.Uniform();
    double mu = a, n = an.lo * std::pow(an.hi / an.lo, b), k = ak.lo * std::pow(ak.hi / ak.lo, c);
    switch (i % 4) {
      case 0:  // anywhere, uniform in (mu, log n, log k)
        break;
      case 1:  // grazing: mu down to 1e-9
        mu = std::pow(10.0, -9 * a);
        break;
      case 2:  // the low-k, low-n edge and the high-n edge
        k = ak.lo + (ak.hi - ak.lo) * c * c * c;
        n = b < 0.5 ? an.lo * std::pow(2.0, 8 * b) : an.hi - 2 * (1 - b);
        break;
      default: {  // next to a node of every axis (the cell corners)
        const auto near = [&](const Axis& ax, double u) {
          const int j = static_cast<int>(u * (ax.size - 1));
          const double x = ax.node(j) + (rng.Uniform() - 0.5) * 1e-3 * (ax.hi - ax.lo) / ax.size;
          return std::min(ax.hi, std::max(ax.lo, x));
        };
        mu = near(am, a);
        n = near(an, b);
        k = near(ak, c);
      }
    }
    w.Probe(t, mu, n, k);
  }
  for (double mu : {0.0, 1e-12, 1e-3, 0.5, 1.0})
    for (double n : {an.lo, 1.0, an.hi})
      for (double k : {ak.lo, ak.hi}) w.Probe(t, mu, n, k);
  INFO("worst " << w.err << " at mu " << w.mu << " n " << w.n << " k " << w.k << " over "
                << w.points << " points; declared " << t.lookupError.max);
  CHECK(w.points > 150000);
  CHECK(t.lookupError.max < 1e-3);
  CHECK(w.err < 1e-3);
  CHECK(w.err <= t.lookupError.max);
  // No more texels than the former 32^3.
  CHECK(am.size * an.size * ak.size <= 32 * 32 * 32);
}

TEST_CASE("kiln sample prints F on fresnel-conductor and refuses points outside its domain",
          "[tables][fresnel][conductor][cli]") {
  // Gold at 550 nm: n 0.18, k 3.4.
  auto r = test::RunKiln("sample " + kTable + " 0.5 0.18 3.4");
  REQUIRE(r.exitCode == 0);
  CHECK(std::stod(r.out) == Approx(FrComplex(0.5, 0.18, 3.4)).margin(1e-3));
  for (const char* outside : {"0.5 0.9998 0", "0.5 0.01 3", "0.5 5 3", "0.5 1 11", "1.5 1 3"}) {
    auto bad = test::RunKiln("sample " + kTable + " " + outside);
    INFO(outside << ": " << bad.err);
    CHECK(bad.exitCode != 0);
    CHECK(test::CountLines(bad.err) == 1);
    CHECK(bad.err.find("outside the domain") != std::string::npos);
    CHECK(bad.err.find("n in [0.03, 4], k in [1.5, 10]") != std::string::npos);
  }
}

TEST_CASE("kiln plan refuses a metal outside fresnel-conductor's domain in one line",
          "[tables][fresnel][conductor][scene]") {
  const auto scene = [](const std::string& eta, const std::string& k) {
    return "{\"kiln_scene\": 1, \"materials\": [{\"name\": \"m\", \"model\": \"ggx\", "
           "\"roughness\": 0.3, \"eta\": " +
           eta + ", \"k\": " + k + ", \"tables\": [\"fresnel-conductor\"]}]}";
  };
  // Gold (n 0.18, k 3.4) is inside; its table is the domain's, narrowed.
  Plan gold = test::PlanText(scene("0.18", "3.4"), "gold.kiln.json");
  REQUIRE(gold.tables.size() == 1);
  // k 0.5 (no metal) and n 5 are outside: one line naming the axis and the domain.
  for (const auto& [eta, k, what] :
       {std::tuple<const char*, const char*, const char*>{"0.9", "0.5", "k 0.5 is outside"},
        {"5", "3", "n 5 is outside"}}) {
    std::string dir = test::SceneTempDir("conductor");
    test::WriteText(dir + "/m.kiln.json", scene(eta, k));
    auto r = test::RunKiln("plan " + dir + "/m.kiln.json");
    INFO(r.err);
    CHECK(r.exitCode != 0);
    CHECK(test::CountLines(r.err) == 1);
    CHECK(r.err.find(what) != std::string::npos);
    CHECK(r.err.find("fresnel-conductor's domain") != std::string::npos);
    test::RemoveTree(dir);
  }
}
