// ggx-fresnel-albedo stores E minus a closed form g(mu, r, eta) (kiln/stored.h,
// StoredForm::FresnelAlbedoResidual) and sampleQuantity adds g back: the runtime's dielectric
// Fresnel is the baker's, g is F(mu, eta) at roughness 0 (so the r = 0 row gives the smooth
// interface exactly), a lookup is the interpolated residual plus g at the point, a plan slice
// (roughness or eta in kiln.params) adds g at its params, and a file that stores E itself (the
// files before this form) still samples as E.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/models/fresnel.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"

using namespace kiln;

namespace {
const std::string kTable = std::string(KILN_SOURCE_DIR) + "/luts/ggx-fresnel-albedo.exr";

/// A 2 x 2 x 2 table of kind fresnel-albedo over mu [0, 1], roughness [0, 1], eta [1.3, 3]
/// holding `value` at every node in channel `channel`.
Table Tiny(const std::string& channel, float value) {
  Table t;
  t.name = "ggx-fresnel-albedo";
  t.model = "ggx";
  t.quantity = "fresnel-albedo";
  t.channels = {channel};
  t.channelMeanings = {"test"};
  t.axes = {{"mu", Axis{0, 1, 2, Warp::Linear}},
            {"roughness", Axis{0, 1, 2, Warp::Linear}},
            {"eta", Axis{1.3, 3, 2, Warp::Linear}}};
  t.data.assign(8, value);
  return t;
}
}  // namespace

TEST_CASE("the runtime's dielectric Fresnel is the baker's", "[runtime][stored][fresnel]") {
  for (double eta : {1.0, 1.0 + 1e-9, 1.3, 1.5, 2.4, 3.0})
    for (double mu : {0.0, 1e-12, 1e-6, 0.01, 0.3, 0.7, 1.0}) {
      INFO("mu " << mu << " eta " << eta);
      CHECK(dielectricFresnel(mu, eta) == Approx(FrDielectric(mu, eta)).margin(1e-15));
    }
}

TEST_CASE("fresnelAlbedoClosedForm: F at roughness 0, continuous as r -> 0+, bounded",
          "[runtime][stored][fresnel]") {
  for (double eta : {1.3, 1.5, 3.0})
    for (double mu : {0.0, 1e-9, 0.05, 0.5, 1.0}) {
      CHECK(fresnelAlbedoClosedForm(mu, 0.0, eta) == Approx(FrDielectric(mu, eta)).margin(1e-15));
      // Below r = 1e-6 alpha takes layerScale's floor 1e-12, as the table's mu axis does.
      CHECK(fresnelAlbedoClosedForm(mu, 1e-7, eta) == fresnelAlbedoClosedForm(mu, 1e-6, eta));
      for (double r : {1e-6, 1e-3, 0.1, 0.5, 1.0}) {
        const double g = fresnelAlbedoClosedForm(mu, r, eta);
        CHECK(g >= 0.0);
        CHECK(g <= 1.0);
      }
    }
  // In the GGX layer (mu ~ alpha) h carries the dip of E: g at mu = alpha is below g at 0.
  CHECK(fresnelAlbedoClosedForm(1e-6, 1e-3, 1.5) < fresnelAlbedoClosedForm(0.0, 1e-3, 1.5) - 0.05);
}

TEST_CASE("ggx-fresnel-albedo: a lookup is the interpolated residual plus the closed form",
          "[runtime][stored][fresnel]") {
  Table t = loadTable(kTable);
  REQUIRE(storedForm(t) == StoredForm::FresnelAlbedoResidual);
  REQUIRE(t.channels == std::vector<std::string>{"E_residual"});
  const LutView v = t.view();
  for (double x0 : {0.0, 1e-7, 0.02, 0.4, 1.0})
    for (double r : {0.0, 1e-4, 0.2, 0.75, 1.0})
      for (double eta : {1.3, 1.45, 2.2, 3.0}) {
        const double x[3] = {x0, r, eta};
        float stored = 0;
        v.sample(x, &stored);
        double e = 0;
        sampleQuantity(t, x, &e);
        INFO("mu " << x0 << " r " << r << " eta " << eta);
        CHECK(e == Approx(stored + fresnelAlbedoClosedForm(x0, r, eta)).margin(1e-12));
        // Roughness 0: the smooth interface, E = F(mu, eta), from the row's smooth nodes.
        if (r == 0)
          CHECK(e == Approx(FrDielectric(x0, eta)).margin(1e-6));
        else
          CHECK(e == Approx(FixedRuleGGXFresnelAlbedo(x0, r * r, eta)).margin(1e-3));
      }
}

TEST_CASE("a residual slice reads roughness and eta from kiln.params, E files sample as E",
          "[runtime][stored][fresnel]") {
  // A plan slice at roughness 0.3 and eta 1.5: axes (mu) only... kept 3D here with eta, and
  // roughness in the params: the closed form is taken at the params' roughness.
  Table slice = Tiny("E_residual", 0.0f);
  slice.axes.erase(slice.axes.begin() + 1);  // drop roughness: (mu, eta)
  slice.data.assign(4, 0.0f);
  slice.params = "roughness=0.3";
  REQUIRE(storedForm(slice) == StoredForm::FresnelAlbedoResidual);
  const double p[2] = {0.25, 1.5};
  double e = -1;
  sampleQuantity(slice, p, &e);
  CHECK(e == Approx(fresnelAlbedoClosedForm(0.25, 0.3, 1.5)).margin(1e-12));
  // A file that stores E itself (channel E, as every file before this form): sampled as is.
  Table plain = Tiny("E", 0.5f);
  REQUIRE(storedForm(plain) == StoredForm::Plain);
  const double q[3] = {0.25, 0.3, 1.5};
  sampleQuantity(plain, q, &e);
  CHECK(e == 0.5);
}
