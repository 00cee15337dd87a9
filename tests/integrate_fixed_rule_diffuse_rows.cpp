// The diffuse fixed rule evaluates Oren-Nayar's (full and qualitative) and Gotanda's GGX diffuse
// polar factors once per row of theta_l (fixed_rule_diffuse.cpp, kHasPolarFactors): they depend
// on the two polar angles alone, so every azimuth of a row gets the bits Parts gives it, and the
// committed tables are unchanged.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "baker/models/gotanda.h"
#include "baker/models/oren_nayar.h"
#include "baker/tables/spec.h"
#include "committed_texels.h"
#include "float_bits.h"

using namespace kiln;

namespace {

/// Whether, on a grid of views, lights (the horizon and the normal included) and azimuths
/// (forward, backward, sideways), PartsAt with the polar factors of the row's first azimuth gives
/// Parts' bits at every azimuth; counts the pairs checked.
template <class M>
int CheckRows(const M& m) {
  int checked = 0;
  for (double muO : {0.0, 1e-6, 0.01, 0.2, 0.5, 0.7071, 0.95, 1.0})
    for (double muL : {0.0, 1e-5, 0.03, 0.3, 0.5, 0.7071, 0.99, 1.0}) {
      const Vec3 wo = ViewDirection(muO);
      const double sinL = std::sqrt(1 - muL * muL);
      const PairGeometry first(wo, Vec3{sinL, 0, muL});
      const auto polar = m.PolarFactors(first);
      for (double phi = 0; phi <= 6.3; phi += 0.05) {
        const Vec3 wi{sinL * std::cos(phi), sinL * std::sin(phi), muL};
        const RhoParts row = m.PartsAt(polar, PairGeometry(wo, wi)), own = m.Parts(wo, wi);
        INFO("mu_o " << muO << " mu_l " << muL << " phi " << phi);
        REQUIRE(test::Bits(row.lin) == test::Bits(own.lin));
        REQUIRE(test::Bits(row.quad) == test::Bits(own.quad));
        ++checked;
      }
    }
  return checked;
}

}  // namespace

TEST_CASE("Oren-Nayar's and Gotanda's polar factors serve every azimuth of a row bit for bit",
          "[integrate][fixed-rule][diffuse-rows]") {
  int checked = 0;
  for (double sigma : {0.0, 0.05, 0.3, 0.5, 1.0}) {
    checked += CheckRows(OrenNayar{sigma, 1});
    checked += CheckRows(OrenNayarQualitative{sigma, 1, false});
    checked += CheckRows(OrenNayarQualitative{sigma, 1, true});
    checked += CheckRows(GotandaGGXDiffuse{sigma, 1, 0});
    checked += CheckRows(GotandaGGXDiffuse{sigma, 1, 0.04});
  }
  CHECK(checked == 5 * 5 * 64 * 127);
}

TEST_CASE("The diffuse fixed rule's rows give the committed Oren-Nayar and Gotanda GGX texels",
          "[integrate][fixed-rule][diffuse-rows]") {
  // Every 7th node of the catalogue's tables (all rows and columns visited), as the bake
  // evaluates it, against the float32 texel in luts/.
  for (const char* name : {"oren-nayar-albedo", "oren-nayar-qualitative-albedo",
                           "oren-nayar-qualitative-ir-albedo", "gotanda-ggx-albedo"}) {
    INFO(name);
    CHECK(test::TexelsDifferingFromRule(name, 7) == 0);
  }
}
