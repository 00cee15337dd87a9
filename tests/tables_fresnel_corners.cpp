// The committed Fresnel tables against direct evaluation, densely in their hard corners: the
// layer of width sqrt(eta^2 - 1) at mu = 0 as eta -> 1 (fresnel-dielectric), the cell corners,
// and eta = 1 and mu = 0 exactly. Nothing may exceed 1e-3 nor the file's declared bound
// (ggx-fresnel-albedo: its declared bound; its first eta cell is not below 1e-3 yet).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/models/fresnel.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"
#include "test_util.h"

using namespace kiln;

namespace {

struct Worst {
  double err = 0, mu = 0, eta = 0;
  long points = 0;
  void Probe(const LutView& v, double mu, double eta) {
    const double x[2] = {mu, eta};
    float got = 0;
    v.sample(x, &got);
    const double e = std::abs(got - FrDielectric(mu, eta));
    ++points;
    if (e > err) {
      err = e;
      this->mu = mu;
      this->eta = eta;
    }
  }
};

}  // namespace

TEST_CASE("fresnel-dielectric: below 1e-3 and its declared bound over the whole domain",
          "[tables][fresnel]") {
  Table t = loadTable(std::string(KILN_SOURCE_DIR) + "/luts/fresnel-dielectric.exr");
  const LutView v = t.view();
  REQUIRE(v.axis[0].warp == Warp::LayerEta);
  Worst w;
  test::Rng rng(12);
  for (int i = 0; i < 120000; ++i) {
    const double a = rng.Uniform(), b = rng.Uniform();
    double mu = 0, eta = 1;
    switch (i % 4) {
      case 0:  // anywhere
        mu = a;
        eta = 1 + 2 * b;
        break;
      case 1:  // eta -> 1, mu down to 1e-12
        eta = 1 + std::pow(10.0, -16 * b);
        mu = std::pow(10.0, -12 * a);
        break;
      case 2: {  // inside the layer: mu within 1e-3 .. 1e3 of c = sqrt(eta^2 - 1)
        eta = 1 + std::pow(10.0, -8 * b);
        const double c = std::sqrt((eta - 1) * (eta + 1));
        mu = std::min(1.0, c * std::pow(10.0, 6 * a - 3));
        break;
      }
      default: {  // next to a node of either axis (the cell corners)
        const int i0 = static_cast<int>(a * 127), i1 = static_cast<int>(b * 127);
        eta = v.axis[1].node(i1) + (rng.Uniform() - 0.5) * 1e-9;
        eta = std::min(3.0, std::max(1.0, eta));
        const double c = etaLayerScale(1.0, 3.0, eta);
        mu = v.axis[0].node(i0, c) * (1 + (rng.Uniform() - 0.5) * 1e-6);
        mu = std::min(1.0, std::max(0.0, mu));
      }
    }
    w.Probe(v, mu, eta);
  }
  // (mu down to 1e-150: below, mu^2 underflows and FrDielectric(mu, 1) takes mu for 0)
  for (double eta : {1.0, std::nextafter(1.0, 2.0), 1 + 1e-12, 1 + 1e-6, 1.5, 3.0})
    for (double mu : {0.0, 1e-150, 1e-12, 1e-6, 0.5, 1.0}) w.Probe(v, mu, eta);
  INFO("worst " << w.err << " at mu " << w.mu << " eta - 1 " << w.eta - 1 << " over " << w.points
                << " points; declared " << t.lookupError.max);
  CHECK(w.points > 100000);
  CHECK(w.err < 1e-3);
  CHECK(w.err <= t.lookupError.max);
}

TEST_CASE("ggx-fresnel-albedo: a dense scan of its domain stays within its declared bound",
          "[tables][fresnel]") {
  Table t = loadTable(std::string(KILN_SOURCE_DIR) + "/luts/ggx-fresnel-albedo.exr");
  const LutView v = t.view();
  // mu follows the GGX layer mu ~ alpha = r^2 (root4-layer coupled to roughness); the domain
  // starts at eta = 1.3, where real dielectrics do (ice 1.31, water 1.33); the file stores E
  // minus a closed form, which sampleQuantity adds back (what `kiln sample` prints).
  REQUIRE(v.axis[0].warp == Warp::Root4Layer);
  REQUIRE(storedForm(t) == StoredForm::FresnelAlbedoResidual);
  REQUIRE(v.axis[2].lo == 1.3);
  REQUIRE(v.axis[2].hi == 3.0);
  CHECK(static_cast<long>(v.axis[0].size) * v.axis[1].size * v.axis[2].size <= 48L * 48 * 24);
  const double etaLo = v.axis[2].lo, etaHi = v.axis[2].hi;
  double worst = 0, wmu = 0, wr = 0, weta = 0;
  long points = 0;
  auto probe = [&](double mu, double r, double eta) {
    const double x[3] = {mu, r, eta};
    double got = 0;
    sampleQuantity(t, x, &got);
    // Roughness 0 is the smooth interface, E = F(mu, eta); else the bake's fixed rule.
    const double ref = r == 0 ? FrDielectric(mu, eta) : FixedRuleGGXFresnelAlbedo(mu, r * r, eta);
    const double e = std::abs(got - ref);
    ++points;
    if (e > worst) {
      worst = e;
      wmu = mu;
      wr = r;
      weta = eta;
    }
  };
  test::Rng rng(13);
  const double eta1 = v.axis[2].node(1);  // the end of the first eta cell
  for (int i = 0; i < 32000; ++i) {
    const double a = rng.Uniform(), b = rng.Uniform(), c = rng.Uniform();
    switch (i % 4) {
      case 0:  // anywhere
        probe(a, b, etaLo + (etaHi - etaLo) * c);
        break;
      case 1:  // the corner mu, r -> 0 in the first eta cell
        probe(std::pow(10.0, -10 * a), std::pow(10.0, -6 * b), etaLo + (eta1 - etaLo) * c);
        break;
      case 2:  // the r = 0 row (the smooth interface) and the first r cell, any eta
        probe(std::pow(10.0, -8 * a), i % 8 == 2 ? 0.0 : v.axis[1].node(1) * b,
              etaLo + (etaHi - etaLo) * c);
        break;
      default: {  // next to a node of every axis (the cell corners)
        const int i1 = static_cast<int>(b * (v.axis[1].size - 1));
        const int i2 = static_cast<int>(c * (v.axis[2].size - 1));
        const double r = std::min(1.0, v.axis[1].node(i1) + rng.Uniform() * 1e-7);
        const double eta = std::min(etaHi, v.axis[2].node(i2) + rng.Uniform() * 1e-9);
        const int i0 = static_cast<int>(a * (v.axis[0].size - 1));
        const double mu = v.axis[0].node(i0, layerScale(0.0, 1.0, r)) * (1 + 1e-6 * rng.Uniform());
        probe(std::min(1.0, mu), r, eta);
      }
    }
  }
  for (double eta : {etaLo, std::nextafter(etaLo, 2.0), 1.5, etaHi})
    for (double r : {0.0, 1e-6, 1e-3, 0.5, 1.0})
      for (double mu : {0.0, 1e-12, 1e-6, 0.5, 1.0}) probe(mu, r, eta);
  INFO("worst " << worst << " at mu " << wmu << " r " << wr << " eta " << weta << " over " << points
                << " points; declared " << t.lookupError.max);
  CHECK(points > 32000);
  CHECK(worst < 1e-3);
  CHECK(worst <= t.lookupError.max);
  CHECK(t.lookupError.max < 1e-3);
}
