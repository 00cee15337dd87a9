// The peers' estimators of `kiln bench` (baker/quantities/monte_carlo.h,
// baker/bench/estimate_table.h) converge to kiln's exact integrals: same conventions (alpha = r^2,
// height-correlated Smith), same texels.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "builtin_models.h"
#include "baker/bench/estimate_table.h"
#include "baker/integrate/quantities.h"
#include "baker/tables/catalogue.h"

using namespace kiln;

namespace {

IntegrationOptions Tight() {
  IntegrationOptions o;
  o.tol = 1e-10;
  return o;
}

ModelParams Rough(double r) {
  ModelParams p;
  p.roughness = r;
  return p;
}

/// Smooth texels: away from grazing views and from the mirror limit.
const double kTexels[][2] = {{0.5, 0.5}, {0.9, 0.7}, {0.3, 0.8}, {0.7, 0.3}};

/// Max over the smooth texels and both channels of |MC DFG - exact|.
double DfgError(const PointSet& points) {
  double worst = 0;
  for (const auto& t : kTexels) {
    IntegrationStats st;
    auto exact = SplitSumDFG(MakeModel("ggx", Rough(t[1])), t[0], Tight(), st);
    auto mc = EstimateDFG(points, t[0], t[1] * t[1]);
    worst = std::max({worst, std::abs(mc[0] - exact[0]), std::abs(mc[1] - exact[1])});
  }
  return worst;
}

double FresnelError(const PointSet& points, double eta) {
  double worst = 0;
  for (const auto& t : kTexels) {
    ModelParams p = Rough(t[1]);
    p.eta = eta;
    IntegrationStats st;
    double exact = DirectionalAlbedo(MakeModel("ggx", p), t[0], Tight(), st).lin;
    worst =
        std::max(worst, std::abs(EstimateFresnelAlbedo(points, t[0], t[1] * t[1], eta) - exact));
  }
  return worst;
}

double DiffuseError(const std::string& id, const PointSet& points) {
  double worst = 0;
  for (const auto& t : kTexels) {
    AnyModel m = MakeModel(id, Rough(t[1]));
    IntegrationStats st;
    RhoParts exact = DirectionalAlbedo(m, t[0], Tight(), st);
    RhoParts mc = EstimateDiffuseAlbedo(points, m, t[0]);
    worst = std::max({worst, std::abs(mc.lin - exact.lin), std::abs(mc.quad - exact.quad)});
  }
  return worst;
}

}  // namespace

TEST_CASE("Hammersley points are (i/N, radical inverse of i) with equal weights", "[bench]") {
  CHECK(RadicalInverse2(0) == 0.0);
  CHECK(RadicalInverse2(1) == 0.5);
  CHECK(RadicalInverse2(2) == 0.25);
  CHECK(RadicalInverse2(3) == 0.75);
  CHECK(RadicalInverse2(6) == 0.375);
  CHECK(RadicalInverse2(0x80000000u) == 0x1p-32);
  PointSet p = HammersleyPoints(16);
  REQUIRE(p.size() == 16);
  double sum = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    sum += p.weight[i];
    CHECK(std::atan2(p.sinPhi[i], p.cosPhi[i]) ==
          Approx(std::remainder(2 * Pi * i / 16, 2 * Pi)).margin(1e-12));
  }
  CHECK(sum == Approx(1).margin(1e-15));
  // Every 1/16-wide stratum of u2 holds exactly one point (a (0, 1)-sequence in base 2).
  std::vector<int> strata(16, 0);
  for (double u : p.u2) ++strata[static_cast<int>(u * 16)];
  CHECK(std::all_of(strata.begin(), strata.end(), [](int c) { return c == 1; }));
}

TEST_CASE("the Gauss-Legendre rule integrates polynomials of degree 2n - 1 exactly", "[bench]") {
  for (int n : {1, 2, 5, 12, 64}) {
    std::vector<double> x, w;
    GaussLegendre01(n, x, w);
    REQUIRE(static_cast<int>(x.size()) == n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += w[i] * std::pow(x[i], k);
      INFO("n = " << n << ", degree " << k);
      CHECK(sum == Approx(1.0 / (k + 1)).margin(1e-13));
    }
    CHECK(std::is_sorted(x.begin(), x.end()));
  }
  PointSet p = GaussLegendrePoints(4);
  CHECK(p.size() == 16);
}

TEST_CASE("Monte Carlo DFG converges to kiln's exact split-sum DFG", "[bench]") {
  double e64 = DfgError(HammersleyPoints(64)), e1024 = DfgError(HammersleyPoints(1024)),
         e16k = DfgError(HammersleyPoints(16384));
  INFO("errors " << e64 << " " << e1024 << " " << e16k);
  CHECK(e1024 < e64);
  CHECK(e16k < e1024);
  CHECK(e1024 < 5e-3);  // "within a few 1e-3 at 1024 samples for a smooth texel"
  CHECK(e16k < 1e-3);
  // The same estimator on the Gauss-Legendre product rule.
  double g8 = DfgError(GaussLegendrePoints(8)), g128 = DfgError(GaussLegendrePoints(128));
  CHECK(g128 < g8);
  CHECK(g128 < 1e-4);
}

TEST_CASE("Monte Carlo GGX albedo with dielectric Fresnel converges to kiln's", "[bench]") {
  for (double eta : {1.2, 1.5, 2.5}) {
    double e64 = FresnelError(HammersleyPoints(64), eta),
           e1024 = FresnelError(HammersleyPoints(1024), eta),
           e16k = FresnelError(HammersleyPoints(16384), eta);
    INFO("eta " << eta << ": errors " << e64 << " " << e1024 << " " << e16k);
    CHECK(e1024 < e64);
    CHECK(e16k < e1024);
    CHECK(e1024 < 3e-3);
  }
}

TEST_CASE("cosine-weighted Monte Carlo diffuse albedo converges to kiln's", "[bench]") {
  for (const char* id : {"burley", "oren-nayar"}) {
    double e64 = DiffuseError(id, HammersleyPoints(64)),
           e1024 = DiffuseError(id, HammersleyPoints(1024)),
           e16k = DiffuseError(id, HammersleyPoints(16384));
    INFO(id << ": errors " << e64 << " " << e1024 << " " << e16k);
    CHECK(e1024 < e64);
    CHECK(e16k < e1024);
    CHECK(e1024 < 3e-3);
  }
}

TEST_CASE("no diffuse sample lies on the horizon: estimates stay finite at grazing views",
          "[bench]") {
  PointSet points = HammersleyPoints(256);
  for (const ModelInfo& info : test::BuiltInModels()) {
    if (info.specular()) continue;
    for (double r : {0.0, 0.5, 1.0}) {
      ModelParams p;
      for (const ParamInfo& q : info.params)
        if (q.name == "roughness") p.roughness = q.lo + r * (q.hi - q.lo);
      RhoParts e = EstimateDiffuseAlbedo(points, MakeModel(info.id, p), 0.0);
      INFO(info.id << " r " << r << ": " << e.lin << " " << e.quad);
      CHECK(std::isfinite(e.lin));
      CHECK(std::isfinite(e.quad));
      CHECK(std::abs(e.lin) + std::abs(e.quad) < 10);
    }
  }
}

TEST_CASE("EstimateTable bakes the spec's nodes, the same on any thread count", "[bench]") {
  for (const char* name : {"ggx-dfg", "burley-albedo", "oren-nayar-albedo", "ggx-fresnel-albedo"}) {
    TableSpec spec = CatalogueTable(name);
    for (AxisSpec& a : spec.axes) a.size = a.name == "eta" ? 3 : 5;
    REQUIRE(EstimatorSupports(spec));
    PointSet points = HammersleyPoints(256);
    BakeStats st1, st2;
    Table one = EstimateTable(spec, points, "mc", 1, &st1);
    Table two = EstimateTable(spec, points, "mc", 2, &st2);
    INFO(name);
    CHECK(one.data == two.data);
    CHECK(st1.evals == static_cast<long long>(spec.TexelCount() * 256));
    REQUIRE(one.data.size() == spec.TexelCount() * spec.channels.size());
    // Texel (i, j[, k]) holds the estimate at the axes' nodes.
    Axis mu = spec.axes[0].ToAxis(), r = spec.axes[1].ToAxis();
    size_t nc = spec.channels.size();
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        size_t k = static_cast<size_t>(j * 5 + i) + (spec.axes.size() == 3 ? 2 * 25 : 0);
        double alpha = std::max(r.node(j) * r.node(j), MinAlpha);
        double c = mu.warp == Warp::Root4Layer ? layerScale(r.lo, r.hi, r.node(j)) : 1e-12;
        if (spec.quantity == FindQuantity("dfg")->id) {
          auto ab = EstimateDFG(points, mu.node(i, c), alpha);
          CHECK(one.data[k * nc] == static_cast<float>(ab[0]));
          CHECK(one.data[k * nc + 1] == static_cast<float>(ab[1]));
        } else if (spec.quantity == FindQuantity("fresnel-albedo")->id) {
          double eta = spec.axes[2].ToAxis().node(2);
          CHECK(one.data[k] ==
                static_cast<float>(EstimateFresnelAlbedo(points, mu.node(i, c), alpha, eta)));
        } else {
          RhoParts e =
              EstimateDiffuseAlbedo(points, MakeModel(spec.model, Rough(r.node(j))), mu.node(i, c));
          if (nc == 2) {
            CHECK(one.data[k * 2] == static_cast<float>(e.lin));
            CHECK(one.data[k * 2 + 1] == static_cast<float>(e.quad));
          } else {
            CHECK(one.data[k] == static_cast<float>(e.lin + e.quad));
          }
        }
      }
  }
  TableSpec brdf = CatalogueTable("oren-nayar-brdf");
  CHECK_FALSE(EstimatorSupports(brdf));
  CHECK_THROWS_AS(EstimateTable(brdf, HammersleyPoints(4), "mc", 1), std::invalid_argument);
}
