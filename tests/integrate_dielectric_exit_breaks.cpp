// The exit walk's faster panel breaks (baker/integrate/dielectric_exit_breaks.h): its acos of the
// inner breaks (an economised asin series, no libm) is within 5e-16 of std::acos over (-1, 1),
// at both sides of its switch |x| = 1/2, next to -+1 and at a seeded sample of the rest; and its
// false-position root finder lands on the root of a monotone function and of one with a kink,
// to 1e-15. The breaks themselves are held through the walk they give
// (tests/integrate_dielectric_rule_heldout.cpp: within the rule's bound of adaptive quadrature).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "baker/integrate/dielectric_exit_breaks.h"

using namespace kiln;

namespace {

/// The acos's bound against std::acos (4.4e-16 measured: two ulps of pi / 2).
constexpr double kAcosBound = 5e-16;

}  // namespace

TEST_CASE("the exit walk's acos is within 5e-16 of std::acos over (-1, 1)",
          "[dielectric][glass-rule]") {
  double worst = 0;
  auto check = [&](double x) {
    const double d = std::abs(dielectric_exit_breaks::Acos(x) - std::acos(x));
    INFO("x " << x);
    CHECK(d <= kAcosBound);
    worst = std::max(worst, d);
  };
  const double below1 = std::nextafter(1.0, 0.0);
  for (double x : {0.0, -0.0, 0.5, std::nextafter(0.5, 1.0), std::nextafter(0.5, 0.0), -0.5,
                   std::nextafter(-0.5, -1.0), below1, -below1, 1 - 1e-12, -1 + 1e-12, 1e-300})
    check(x);
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> uniform(-1, 1), exponent(-16, 0);
  for (int i = 0; i < 20000; ++i) {
    check(uniform(rng));
    const double near = 1 - std::pow(10.0, exponent(rng));  // within 1e-16 .. 1 of -+1
    if (near < 1) {
      check(near);
      check(-near);
    }
  }
  INFO("worst " << worst);
  CHECK(worst > 0);  // not libm itself
}

TEST_CASE("the exit walk's root finder lands within 1e-15 of the root",
          "[dielectric][glass-rule]") {
  using dielectric_exit_breaks::Root;
  SECTION("a smooth monotone function") {
    auto f = [](double t) { return std::cos(t) - 0.3; };
    const double lo = 0, hi = 1.5, root = std::acos(0.3);
    CHECK(std::abs(Root(f, lo, hi, f(lo), f(hi)) - root) <= 1e-15);
  }
  SECTION("a square-root kink next to the root, decreasing") {
    auto f = [](double t) { return 0.2 - std::sqrt(std::max(0.0, t - 0.1)); };
    const double lo = 0, hi = 1, root = 0.1 + 0.04;
    CHECK(std::abs(Root(f, lo, hi, f(lo), f(hi)) - root) <= 1e-15);
  }
  SECTION("a root at the bracket's end") {
    auto f = [](double t) { return t - 0.25; };
    CHECK(std::abs(Root(f, 0.25, 0.5, f(0.25), f(0.5)) - 0.25) <= 1e-15);
  }
}
