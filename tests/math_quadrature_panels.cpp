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

namespace {
/// An integrand that takes a panel's nodes at once, counting its calls of either kind.
struct NodesAtOnce {
  int single = 0, batches = 0;
  Channels<2> operator()(double x) {
    ++single;
    return {std::exp(-3 * x) * std::sin(7 * x), 1 / (1 + 25 * x * x)};
  }
  void EvaluateNodes(const double* x, int n, Channels<2>* out) {
    ++batches;
    for (int i = 0; i < n; ++i)
      out[i] = {std::exp(-3 * x[i]) * std::sin(7 * x[i]), 1 / (1 + 25 * x[i] * x[i])};
  }
};
}  // namespace

TEST_CASE("an integrand with EvaluateNodes gets each panel's 15 nodes in one call, the same bits",
          "[math][quadrature]") {
  const double breaks[3] = {-1, 0.25, 2};
  NodesAtOnce batched;
  auto single = [](double x) -> Channels<2> {
    return {std::exp(-3 * x) * std::sin(7 * x), 1 / (1 + 25 * x * x)};
  };
  static_assert(EvaluatesNodes<NodesAtOnce, 2>::value);
  static_assert(!EvaluatesNodes<decltype(single), 2>::value);
  double errBatched = 0, errSingle = 0;
  const Channels<2> a = IntegrateAdaptive<2>(batched, breaks, 3, 1e-12, 200, &errBatched);
  const Channels<2> b = IntegrateAdaptive<2>(single, breaks, 3, 1e-12, 200, &errSingle);
  CHECK(batched.single == 0);
  CHECK(batched.batches > 2);  // bisected past its first two panels
  CHECK(a[0] == b[0]);
  CHECK(a[1] == b[1]);
  CHECK(errBatched == errSingle);
  double x[15];
  GaussKronrod15Nodes(0.5, 1.5, x);
  CHECK(x[7] == 1.0);
  for (int j = 0; j < 14; ++j) CHECK(x[j] < x[j + 1]);
  CHECK(x[0] == 1.0 - 0.5 * gk15::xgk[0]);
}
