// kiln inspect --axes (baker/bake/axis_budget.h): the per-axis budget of a table's linear
// interpolation error, h^2 f'' / 8 from the node values along each axis, and where it is.
#include <catch2/catch.hpp>

#include <cmath>

#include "baker/bake/axis_budget.h"
#include "kiln/table.h"

using namespace kiln;

namespace {

/// A (mu, roughness, eta) table with the given mu warp, filled by f at each node's coordinates.
template <class F>
Table Filled(Warp muWarp, int n0, int n1, int n2, F f) {
  Table t;
  t.name = "budget-test";
  t.quantity = "albedo-t";
  t.channels = {"E"};
  t.axes = {{"mu", Axis{0, 1, n0, muWarp}},
            {"roughness", Axis{0, 1, n1, Warp::Sqrt}},
            {"eta", Axis{1.1, 3, n2, Warp::Linear}}};
  t.data.assign(static_cast<size_t>(n0) * n1 * n2, 0.0f);
  LutView v = t.view();
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        std::array<double, 3> x = NodeCoordinates(v, {i, j, k});
        t.data[(static_cast<size_t>(k) * n1 + j) * n0 + i] = static_cast<float>(f(x));
      }
  return t;
}

}  // namespace

TEST_CASE("the budget of a function quadratic in one warped coordinate sits on that axis alone",
          "[axis-budget]") {
  // f = t_eta^2 with t_eta = (eta - 1.1) / 1.9 (the eta axis is linear): second difference
  // 2 h^2 along eta, h = 1 / (n2 - 1); exactly linear along mu and roughness (f ignores them).
  const int n2 = 9;
  Table t = Filled(Warp::Linear, 5, 4, n2, [](const std::array<double, 3>& x) {
    const double u = (x[2] - 1.1) / 1.9;
    return u * u;
  });
  std::vector<AxisBudget> b = AxisErrorBudget(t.view());
  REQUIRE(b.size() == 3);
  CHECK(b[0].max < 1e-7);
  CHECK(b[1].max < 1e-7);
  const double h = 1.0 / (n2 - 1);
  CHECK(b[2].max == Approx(2 * h * h / 8).epsilon(1e-5));
  REQUIRE(b[2].profile.size() == static_cast<size_t>(n2));
  CHECK(b[2].profile.front() == 0);  // the end nodes have no stencil
  CHECK(b[2].profile.back() == 0);
  for (int i = 1; i + 1 < n2; ++i) CHECK(b[2].profile[i] == Approx(2 * h * h / 8).epsilon(1e-4));
}

TEST_CASE("the budget's node coordinates are the nodes the sampler reads, layer warps included",
          "[axis-budget]") {
  // A kink in mu at 0.3 (|mu - 0.3|): on a root4-layer mu axis the nodes move with the
  // roughness, so the budget's coordinates must be the layer's; the sampler returns the stored
  // value at a node exactly.
  for (Warp w : {Warp::Linear, Warp::Root4Layer, Warp::Root4LayerSplit}) {
    INFO(warpName(w));
    Table t = Filled(w, 17, 6, 5, [](const std::array<double, 3>& x) {
      return std::abs(x[0] - 0.3) + 0.1 * x[1] + 0.01 * x[2];
    });
    LutView v = t.view();
    REQUIRE(v.valid());
    for (const AxisBudget& b : AxisErrorBudget(v)) {
      float got = 0;
      v.sample(b.where.data(), &got);
      CHECK(got == v.at(b.node[0], b.node[1], b.node[2], 0));
    }
    // The largest budget is along mu (the kink), at a node next to mu = 0.3.
    std::vector<AxisBudget> b = AxisErrorBudget(v);
    CHECK(b[0].max > b[1].max);
    CHECK(b[0].max > b[2].max);
  }
}
