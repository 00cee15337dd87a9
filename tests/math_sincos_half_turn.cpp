// SinCosHalfTurn (baker/math/sincos_half_turn.h), the adaptive references' sine and cosine of an
// azimuth: within 2 ulp of std::sin and std::cos on a dense grid of [0, pi], its ends, the
// quarter turns where its reduction switches, tiny angles (relative precision), the slack past
// the ends a rounded node can reach, and std::sin and std::cos themselves outside.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "baker/math/sincos_half_turn.h"

using namespace kiln;

namespace {

/// |a - b| in units of the spacing of doubles at b (the smallest normal spacing near 0).
double UlpsFrom(double a, double b) {
  const double mag = std::max(std::abs(b), std::numeric_limits<double>::min());
  return std::abs(a - b) / (std::nextafter(mag, INFINITY) - mag);
}

/// The worst distance in ulp of SinCosHalfTurn from std::sin and std::cos over phis.
double WorstUlps(const std::vector<double>& phis) {
  double worst = 0;
  for (double phi : phis) {
    const SinCos sc = SinCosHalfTurn(phi);
    worst = std::max(worst, UlpsFrom(sc.sin, std::sin(phi)));
    worst = std::max(worst, UlpsFrom(sc.cos, std::cos(phi)));
  }
  return worst;
}

/// x and its 3 neighbours on each side.
void AddNeighbours(double x, std::vector<double>& phis) {
  double lo = x, hi = x;
  phis.push_back(x);
  for (int i = 0; i < 3; ++i) {
    lo = std::nextafter(lo, -INFINITY);
    hi = std::nextafter(hi, INFINITY);
    phis.push_back(lo);
    phis.push_back(hi);
  }
}

}  // namespace

TEST_CASE("SinCosHalfTurn is std::sin and std::cos within 2 ulp over [0, pi], ends included",
          "[math][sincos]") {
  std::vector<double> phis;
  constexpr int kGrid = 1 << 20;
  for (int i = 0; i <= kGrid; ++i) phis.push_back(Pi * i / kGrid);
  for (double x : {0.0, Pi / 4, HalfPi, 3 * Pi / 4, Pi}) AddNeighbours(x, phis);
  for (double tiny : {1e-300, 1e-100, 1e-20, 1e-10, 1e-5}) {
    phis.push_back(tiny);
    phis.push_back(Pi - tiny);
    phis.push_back(HalfPi - tiny);
    phis.push_back(HalfPi + tiny);
  }
  phis.push_back(std::numeric_limits<double>::denorm_min());
  CHECK(WorstUlps(phis) <= 2);
  CHECK(SinCosHalfTurn(0).sin == 0);
  CHECK(SinCosHalfTurn(0).cos == 1);
  CHECK(SinCosHalfTurn(Pi).cos == -1);
}

TEST_CASE("SinCosHalfTurn is within 2 ulp past the ends of [0, pi], and libm's beyond",
          "[math][sincos]") {
  // A Gauss-Kronrod node rounded past an end lands just outside; the reduction covers a
  // quarter turn of slack on each side.
  std::vector<double> slack;
  constexpr int kGrid = 1 << 16;
  for (int i = 1; i < kGrid; ++i) {
    slack.push_back(-Pi / 4 * i / kGrid);
    slack.push_back(Pi + Pi / 4 * i / kGrid);
  }
  CHECK(WorstUlps(slack) <= 2);
  for (double phi : {-Pi / 4, Pi + Pi / 4, -1.0, 4.0, 100.0, -1e6, 1e300}) {
    const SinCos sc = SinCosHalfTurn(phi);
    CHECK(sc.sin == std::sin(phi));
    CHECK(sc.cos == std::cos(phi));
  }
  for (double bad : {NAN, INFINITY, -INFINITY}) {
    CHECK(std::isnan(SinCosHalfTurn(bad).sin));
    CHECK(std::isnan(SinCosHalfTurn(bad).cos));
  }
}

TEST_CASE("SphericalDirectionHalfTurn is SphericalDirection within rounding", "[math][sincos]") {
  for (double theta : {0.0, 1e-8, 0.3, 1.0, HalfPi})
    for (int i = 0; i <= 64; ++i) {
      const double phi = Pi * i / 64, s = std::sin(theta), c = std::cos(theta);
      const Vec3 a = SphericalDirectionHalfTurn(s, c, phi), b = SphericalDirection(s, c, phi);
      CHECK(std::abs(a.x - b.x) <= 3e-16);
      CHECK(std::abs(a.y - b.y) <= 3e-16);
      CHECK(a.z == b.z);
    }
}
