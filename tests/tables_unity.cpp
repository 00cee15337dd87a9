// unity-nhxroughness (issue #16): Unity's BRDF3 lobe texture T(x, r) = UnityNHxRoughnessTexel,
// on kiln's lobe-exponent axes (s, n) storing P = T before Unity's clamp (kiln/stored.h
// UnityLobe), and at Unity's own 64 x 64 texel centres (unity-nhxroughness-native, on request).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/models/unity.h"
#include "baker/tables/catalogue.h"
#include "kiln/stored.h"

namespace kiln {
namespace {

Table Bake(const std::string& name, int threads) {
  BakeOptions opt;
  opt.threads = threads;
  return BakeTable(CatalogueTable(name, CatalogueOptions{}), opt);
}

/// The x = (R.L)^4 of the scan: uniform, then towards 1 (where the lobes of small r live, down
/// to 1 - x = 1e-9) and towards 0 (where the lobes of r -> 1 fall, down to the smallest double).
std::vector<double> ScanX() {
  std::vector<double> xs;
  for (int i = 0; i <= 200; ++i) xs.push_back(i / 200.0);
  for (int k = 4; k <= 36; ++k) xs.push_back(1 - std::pow(10.0, -k / 4.0));
  for (int k = 3; k <= 300; k += 3) xs.push_back(std::pow(10.0, -k));
  xs.push_back(4.9e-324);
  return xs;
}

std::vector<double> ScanR() {
  std::vector<double> rs = {0,     1e-3,  0.05,   0.0999,  0.1,       0.1001,  0.2,
                            0.316, 0.999, 0.9999, 0.99999, 0.9999875, 0.99999, 1};
  for (int i = 1; i < 100; ++i) rs.push_back(i / 100.0);
  return rs;
}

}  // namespace

TEST_CASE("unity-nhxroughness: every node holds Unity's texel formula", "[unity-tables]") {
  Table t = Bake("unity-nhxroughness", 2);
  REQUIRE(t.dims() == 2);
  REQUIRE(storedForm(t) == StoredForm::UnityLobe);
  const Axis& sAxis = t.axes[0].axis;
  const Axis& nAxis = t.axes[1].axis;
  // The n axis is Unity's own range: r = 1 at its start, r = 0 at its end.
  CHECK(nAxis.lo == UnitySpecPower(1) / 4);
  CHECK(nAxis.hi == UnitySpecPower(0) / 4);
  const double rAt[2] = {1, 0};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < sAxis.size; ++i) {
      double s = sAxis.node(i), n = nAxis.node(j * (nAxis.size - 1));
      float texel = t.data[static_cast<size_t>(j * (nAxis.size - 1) * sAxis.size + i)];
      double p = (n + 2) / (2 * Pi * Pi) * std::exp(-std::exp(s)) / kUnityNHxRoughnessRange;
      INFO("s " << s << " n " << n);
      CHECK(texel == static_cast<float>(p));  // the closed form, rounded once
      // ... which is Unity's texel at the (x, r) of the node: x^(n/4) = exp(-e^s). (At r = 1
      // the nodes past s ~ -5.4 lie at x below the smallest double: no x to compare at.)
      double x = std::exp(-4 * std::exp(s) / n);
      if (x > 1e-300)
        CHECK(std::min(1.0, p) == Approx(UnityNHxRoughnessTexel(x, rAt[j])).epsilon(1e-9));
    }
}

TEST_CASE(
    "unity-nhxroughness: the runtime's T is Unity's within the declared bound, x -> 1 "
    "and small r included",
    "[unity-tables]") {
  Table t = Bake("unity-nhxroughness", 2);
  const double bound = t.lookupError.max;
  CHECK(bound > 0);
  CHECK(bound < 1e-3);
  double worst = 0, worstX = 0, worstR = 0;
  for (double r : ScanR())
    for (double x : ScanX()) {
      double p[2] = {x, r}, got = 0;
      sampleQuantity(t, p, &got);
      double err = std::abs(got - UnityNHxRoughnessTexel(x, r));
      if (err > worst) worst = err, worstX = x, worstR = r;
    }
  INFO("worst " << worst << " at x " << worstX << " r " << worstR);
  CHECK(worst <= bound);
  // The ends: x = 1 reads Unity's peak min(1, (n + 2) / (32 pi^2)), x = 0 reads 0.
  for (double r : {0.0, 0.5, 1.0}) {
    double p1[2] = {1, r}, p0[2] = {0, r}, at1 = 0, at0 = 0;
    sampleQuantity(t, p1, &at1);
    sampleQuantity(t, p0, &at0);
    CHECK(at1 == Approx(UnityNHxRoughnessTexel(1, r)).margin(bound));
    CHECK(std::abs(at0) < 1e-12);
  }
}

TEST_CASE("unity-nhxroughness bakes the same bytes on 1 and 2 threads", "[unity-tables]") {
  for (const char* name : {"unity-nhxroughness", "unity-nhxroughness-native"}) {
    Table a = Bake(name, 1), b = Bake(name, 2);
    INFO(name);
    CHECK(a.data == b.data);
    CHECK(a.lookupError.max == b.lookupError.max);
    CHECK(a.specHash == b.specHash);
  }
}

TEST_CASE(
    "unity-nhxroughness-native: Unity's 64 x 64 texels, exact, on request, its large error "
    "declared",
    "[unity-tables]") {
  Table t = Bake("unity-nhxroughness-native", 2);
  REQUIRE(t.dims() == 2);
  REQUIRE(storedForm(t) == StoredForm::Plain);
  const Axis& xa = t.axes[0].axis;
  const Axis& ra = t.axes[1].axis;
  CHECK(xa.size == 64);
  CHECK(ra.size == 64);
  CHECK(xa.lo == 0.5 / 64);
  CHECK(xa.hi == 63.5 / 64);
  for (int j = 0; j < ra.size; ++j)
    for (int i = 0; i < xa.size; ++i)
      CHECK(t.data[static_cast<size_t>(j * xa.size + i)] ==
            static_cast<float>(UnityNHxRoughnessTexel(xa.node(i), ra.node(j))));
  // The finding: 64 texels cannot hold the lobes of small r (within x in [0.998, 1]).
  CHECK(t.lookupError.max > 1e-3);
  // Beyond the last texel centre the GPU clamps: at x = 1, r = 0 it reads x = 63.5 / 64, where
  // the lobe x^1250 is e^-9.8, instead of Unity's peak 1.
  double peak[2] = {1, 0}, got = 0;
  sampleQuantity(t, peak, &got);
  CHECK(UnityNHxRoughnessTexel(1, 0) == 1);
  CHECK(got < 1e-3);
  bool inDefault = false, onRequest = false;
  for (const TableSpec& s : DefaultCatalogue()) inDefault |= s.name == "unity-nhxroughness-native";
  for (const TableSpec& s : OnRequestTables()) onRequest |= s.name == "unity-nhxroughness-native";
  CHECK_FALSE(inDefault);
  CHECK(onRequest);
}

}  // namespace kiln
