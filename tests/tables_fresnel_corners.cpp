// The committed Fresnel tables against direct evaluation, densely in their hard corners: the
// layer of width sqrt(eta^2 - 1) at mu = 0 as eta -> 1 (fresnel-dielectric), the cell corners,
// and eta = 1 and mu = 0 exactly. Nothing may exceed 1e-3 nor the file's declared bound.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "baker/models/fresnel.h"
#include "kiln/exr_loader.h"
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
