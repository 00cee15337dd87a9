// The adaptive Gauss-Kronrod driver's parts (baker/math/quadrature.h): QUADPACK's error rescaling
// without pow, and the panel list that holds its first panels inline.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "baker/math/quadrature.h"

using namespace kiln;

TEST_CASE("ErrorScale is QUADPACK's min(1, r^1.5) within an ulp, NaN and infinity included",
          "[math][quadrature]") {
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double r = std::pow(10.0, -30 + 31 * (i / 200000.0));
    const double want = std::min(1.0, std::pow(r, 1.5)), got = ErrorScale(r);
    worst = std::max(worst, std::abs(got - want) / (std::nextafter(want, INFINITY) - want));
  }
  CHECK(worst <= 1);
  CHECK(ErrorScale(0) == 0);
  CHECK(ErrorScale(1) == 1);
  CHECK(ErrorScale(0.25) == 0.125);
  CHECK(ErrorScale(std::nextafter(1.0, 0.0)) < 1);
  CHECK(ErrorScale(INFINITY) == 1);
  CHECK(ErrorScale(NAN) == std::min(1.0, std::pow(NAN, 1.5)));
}

TEST_CASE("the panel list keeps order and values across its move to the heap",
          "[math][quadrature]") {
  constexpr int kInline = 8;
  InlineList<double, kInline> list(3);
  std::vector<double> same;
  for (int i = 0; i < 5 * kInline; ++i) {
    list.push_back(i);
    same.push_back(i);
    list[i / 2] = -list[i / 2];  // writes through either storage
    same[i / 2] = -same[i / 2];
    REQUIRE(list.size() == i + 1);
    for (int j = 0; j <= i; ++j) REQUIRE(list[j] == same[j]);
  }
}

TEST_CASE("IntegrateAdaptive past its inline panels integrates to its tolerance",
          "[math][quadrature]") {
  // cos(100 x) on [0, 20]: 318 periods, a few per panel at most.
  long long evals = 0;
  auto f = [&](double x) {
    ++evals;
    return Channels<1>{std::cos(100 * x)};
  };
  const double breaks[] = {0, 7, 20};
  double err = 0;
  bool capped = false;
  const double got = IntegrateAdaptive<1>(f, breaks, 3, 1e-10, 2000, &err, &capped)[0];
  // 15 evaluations per first panel and 30 per bisection: more panels than the list holds inline.
  REQUIRE((evals / 15 + 2) / 2 > kInlinePanels);
  CHECK(!capped);
  CHECK(err <= 1e-10);
  CHECK(std::abs(got - std::sin(2000.0) / 100) <= 1e-10);
}
