// The arcsine warp of kiln/lut.h: t = (2 / pi) asin(sqrt(y)), y = sin^2(t pi / 2), nodes dense
// at both ends (as sqrt at lo, as square at hi) and about linear between: a roughness axis
// that bends most near r = 1 and must keep a thin first cell at r = 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "kiln/lut.h"

using namespace kiln;

TEST_CASE("arcsine: the name round-trips, nodes are sin^2(pi t / 2), symmetric about 1/2",
          "[runtime][axis]") {
  Warp w = Warp::Linear;
  REQUIRE(warpFromName("arcsine", w));
  CHECK(w == Warp::Arcsine);
  CHECK(std::string(warpName(Warp::Arcsine)) == "arcsine");
  CHECK(!isLayerWarp(Warp::Arcsine));
  const Axis a{0.0, 1.0, 56, Warp::Arcsine};
  REQUIRE(a.valid());
  CHECK(a.node(0) == 0.0);
  CHECK(a.node(55) == 1.0);
  for (int i = 0; i < 56; ++i) {
    const double t = i / 55.0, s = std::sin(t * kPi / 2);
    CHECK(a.node(i) == Approx(s * s).margin(1e-15));
    CHECK(a.node(i) + a.node(55 - i) == Approx(1.0).margin(1e-15));
    CHECK(a.texel(a.node(i)) == i);
    CHECK(a.warped(a.node(i)) == Approx(t).margin(1e-13));
  }
}

TEST_CASE("arcsine: the end cells are as thin as sqrt's first, the middle ones as linear's",
          "[runtime][axis]") {
  const int n = 56;
  const Axis arc{0.0, 1.0, n, Warp::Arcsine}, sq{0.0, 1.0, n, Warp::Sqrt};
  const double h = 1.0 / (n - 1);
  // first cell: (pi / 2)^2 h^2 against sqrt's h^2; last cell the same (sqrt's: 2 h)
  CHECK(arc.node(1) == Approx(std::pow(kPi / 2 * h, 2)).epsilon(1e-3));
  CHECK(arc.node(1) < 2.5 * sq.node(1));
  CHECK(1 - arc.node(n - 2) == Approx(arc.node(1)).epsilon(1e-12));
  CHECK(1 - arc.node(n - 2) < 0.05 * (1 - sq.node(n - 2)));
  for (int i = 0; i + 1 < n; ++i) CHECK(arc.node(i + 1) - arc.node(i) <= kPi / 2 * h * 1.0001);
}
