// The ggx-dielectric albedo tables store E_R or E_T minus a closed form g (kiln/stored.h,
// StoredForm::DielectricAlbedoResidual) and sampleQuantity adds g back: g is the smooth
// interface's F or 1 - F at roughness 0 (both sides, total internal reflection included), so the
// r = 0 row holds 0; for r > 0 it is continuous in r, follows the rough E (within the table's
// job), and softens the kink of total internal reflection instead of keeping it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "baker/models/fresnel.h"
#include "kiln/stored.h"

using namespace kiln;

namespace {
/// A 2 x 2 x 2 table of kind `quantity` over mu [0, 1], roughness [0, 1], eta [lo, hi] holding
/// `value` at every node in channel `channel`.
Table Tiny(const std::string& quantity, const std::string& channel, double lo, double hi,
           float value) {
  Table t;
  t.name = "ggx-dielectric-" + quantity;
  t.model = "ggx-dielectric";
  t.quantity = quantity;
  t.channels = {channel};
  t.channelMeanings = {"test"};
  t.axes = {{"mu", Axis{0, 1, 2, Warp::Linear}},
            {"roughness", Axis{0, 1, 2, Warp::Linear}},
            {"eta", Axis{lo, hi, 2, Warp::Linear}}};
  t.data.assign(8, value);
  return t;
}
}  // namespace

TEST_CASE("dielectricFresnelSoft: exact at delta 0 on both sides, smooth across the kink",
          "[runtime][stored][dielectric]") {
  for (double eta : {1 / 3.0, 0.7, 1 / 1.1, 1.1, 1.5, 3.0})
    for (double mu : {0.0, 1e-6, 0.3, 0.5, 0.7142, 0.95, 1.0}) {
      INFO("mu " << mu << " eta " << eta);
      CHECK(dielectricFresnelSoft(mu, eta, 0.0) == Approx(FrDielectric(mu, eta)).margin(1e-15));
      CHECK(dielectricFresnelSoft(mu, eta, 1e-14) == Approx(FrDielectric(mu, eta)).margin(1e-6));
    }
  // Exit at eta = 0.7: F has a square-root kink at mu_c = sqrt(1 - 0.49); the softened F has a
  // finite slope there and stays in [0, 1], below 1 just past the kink.
  const double muC = std::sqrt(1 - 0.49), d = 0.01;
  const double slope =
      (dielectricFresnelSoft(muC + 1e-7, 0.7, d) - dielectricFresnelSoft(muC - 1e-7, 0.7, d)) /
      2e-7;
  CHECK(std::isfinite(slope));
  CHECK(std::abs(slope) < 50);
  CHECK(std::abs((FrDielectric(muC + 1e-7, 0.7) - 1) / 1e-7) > 100);  // the exact F's kink
  for (double mu = 0; mu <= 1; mu += 0.01) {
    const double f = dielectricFresnelSoft(mu, 0.7, d);
    CHECK(f >= 0);
    CHECK(f <= 1);
  }
}

TEST_CASE("dielectricAlbedoClosedForm: F and 1 - F at roughness 0, continuous as r -> 0+",
          "[runtime][stored][dielectric]") {
  for (double eta : {1 / 3.0, 0.7, 1 / 1.1, 1.1, 1.5, 3.0})
    for (double mu : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      INFO("mu " << mu << " eta " << eta);
      const double F = FrDielectric(mu, eta);
      CHECK(dielectricAlbedoClosedForm(mu, 0.0, eta, false) == Approx(F).margin(1e-15));
      CHECK(dielectricAlbedoClosedForm(mu, 0.0, eta, true) == Approx(1 - F).margin(1e-15));
      // r -> 0+ meets the smooth interface away from the GGX layer at mu = 0.
      if (mu > 0.05)
        for (bool t : {false, true})
          CHECK(dielectricAlbedoClosedForm(mu, 1e-4, eta, t) ==
                Approx(dielectricAlbedoClosedForm(mu, 0.0, eta, t)).margin(1e-3));
    }
}

TEST_CASE(
    "dielectricAlbedoClosedForm: under total internal reflection it stays at F = 1 as r -> 0+",
    "[runtime][stored][dielectric]") {
  // A table's corner cell (0 < r < its first node) interpolates between the r = 0 row (g = F) and
  // that node: g must not carry a layer of its own there. mu / alpha >= 100, where GGX's albedo
  // dip (h) has faded: g_R within 1e-3 of F = 1 and g_T of 0, for every exit eta.
  for (double eta : {1 / 3.0, 0.5, 0.7, 1 / 1.1})
    for (double mu : {1e-6, 1e-4, 1e-2, 0.2})
      for (double r : {1e-4, 1e-3}) {
        if (mu < 100 * r * r || !(mu < 0.9 * std::sqrt(1 - eta * eta))) continue;
        INFO("mu " << mu << " r " << r << " eta " << eta);
        CHECK(dielectricAlbedoClosedForm(mu, r, eta, false) == Approx(1.0).margin(1e-3));
        CHECK(dielectricAlbedoClosedForm(mu, r, eta, true) == Approx(0.0).margin(1e-3));
      }
}

TEST_CASE("dielectricAlbedoClosedForm: continuous in eta at mu = 0 and high roughness",
          "[runtime][stored][dielectric]") {
  // sqrt(mu^2 + alpha^2) crosses the critical cosine as eta varies: the softening must not vanish
  // there (a jump of 0.59 in g_T between eta 0.38 and 0.39 at r = 0.96 with delta = 4 alpha mu).
  for (double r : {0.5, 0.8, 0.96})
    for (bool t : {false, true}) {
      double prev = dielectricAlbedoClosedForm(0.0, r, 1 / 3.0, t), worst = 0;
      for (int i = 1; i <= 2000; ++i) {
        const double eta = 1 / 3.0 + (1 / 1.1 - 1 / 3.0) * i / 2000;
        const double g = dielectricAlbedoClosedForm(0.0, r, eta, t);
        worst = std::max(worst, std::abs(g - prev));
        prev = g;
      }
      INFO("r " << r << " transmit " << t);
      CHECK(worst < 0.01);
    }
}

TEST_CASE("ggx-dielectric residual tables: a lookup is the residual plus the closed form",
          "[runtime][stored][dielectric]") {
  struct Case {
    const char* quantity;
    const char* channel;
    double lo, hi;
    bool transmit;
  };
  for (const Case& c : {Case{"albedo-r", "E_R_residual", 1.1, 3, false},
                        Case{"albedo-t", "E_T_residual", 1.1, 3, true},
                        Case{"albedo-r-exit", "E_R_residual", 1 / 3.0, 1 / 1.1, false},
                        Case{"albedo-t-exit", "E_T_residual", 1 / 3.0, 1 / 1.1, true}}) {
    Table t = Tiny(c.quantity, c.channel, c.lo, c.hi, 0.125f);
    REQUIRE(storedForm(t) == StoredForm::DielectricAlbedoResidual);
    for (double mu : {0.0, 0.4, 0.8, 1.0})
      for (double r : {0.0, 0.3, 1.0}) {
        const double eta = (c.lo + c.hi) / 2;
        const double p[3] = {mu, r, eta};
        double e = 0;
        sampleQuantity(t, p, &e);
        INFO(c.quantity << " mu " << mu << " r " << r);
        CHECK(e ==
              Approx(0.125 + dielectricAlbedoClosedForm(mu, r, eta, c.transmit)).margin(1e-12));
      }
    // A channel named E_R (a file of E itself) samples as stored.
    Table plain = Tiny(c.quantity, c.transmit ? "E_T" : "E_R", c.lo, c.hi, 0.25f);
    CHECK(storedForm(plain) == StoredForm::Plain);
  }
}
