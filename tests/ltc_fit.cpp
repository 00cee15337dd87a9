// The LTC fit (baker/integrate/ltc_fit.h) and the ltc table kind (baker/quantities/ltc.cpp):
// Nelder-Mead, the LTC as a density, the fitted table reproducing its lobes within the error it
// declares, the hemisphere's polygon integral against the albedo, deterministic bytes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/integrate/ltc_fit.h"
#include "baker/integrate/quantities.h"
#include "baker/tables/catalogue.h"
#include "kiln/ltc.h"
#include "test_util.h"

using namespace kiln;

namespace {

/// A small ltc table of the catalogue (the published layout at `size` nodes per axis), baked.
Table SmallLtc(const char* name, int size, int threads) {
  CatalogueOptions copt;
  copt.size = size;
  BakeOptions opt;
  opt.threads = threads;
  opt.measureLookupError = false;
  return BakeTable(CatalogueTable(name, copt), opt);
}

}  // namespace

TEST_CASE("Nelder-Mead finds the minimum of a curved valley", "[ltc]") {
  auto rosenbrock = [](const double* x) {
    return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2) + std::pow(x[2] - 2, 2);
  };
  double x[3] = {-1, 1, 0};
  double f = NelderMead(rosenbrock, 3, x, 0.5, 5000, 1e-15);
  CHECK(f < 1e-8);
  CHECK(x[0] == Approx(1).margin(1e-3));
  CHECK(x[2] == Approx(2).margin(1e-3));
}

TEST_CASE("An LTC is a density on the sphere and samples itself", "[ltc]") {
  LtcMatrix m = LtcMatrix::From(LtcFrameParams{0.4, 0.25, -0.2, Normalize(Vec3{-0.5, 0, 0.8})});
  // integral of D over the sphere by a midpoint rule in (cos theta, phi).
  const int n = 400;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      double z = -1 + (i + 0.5) * 2 / n, phi = (j + 0.5) * Pi / n, s = SafeSqrt(1 - z * z);
      sum += m.Eval({s * std::cos(phi), s * std::sin(phi), z});
    }
  CHECK(sum * (2.0 / n) * (Pi / n) == Approx(1).margin(2e-3));
  // The stored inverse describes the same distribution (a scale of M^-1 does not change it).
  double minv[4] = {m.inv[0] / m.inv[4], m.inv[6] / m.inv[4], m.inv[2] / m.inv[4],
                    m.inv[8] / m.inv[4]};
  LtcMatrix back = LtcMatrix::FromInverse(minv);
  for (Vec3 l : {Vec3{0, 0, 1}, Normalize(Vec3{-0.5, 0.2, 0.8}), Normalize(Vec3{0.3, -0.4, 0.2})})
    CHECK(back.Eval(l) == Approx(m.Eval(l)).epsilon(1e-9));
  // The error of an LTC against itself as a lobe is 0 in any norm.
  CHECK(LtcFitError(LtcLobe("lambert", 0, 1), 1.0, LtcMatrix::From({}), 1, 32) < 1e-12);
}

TEST_CASE("M^-1 applied to the lobe's samples reproduces the lobe within the declared error",
          "[ltc]") {
  for (const char* name : {"ltc-ggx", "ltc-beckmann"}) {
    Table t = SmallLtc(name, 6, 2);
    TableSpec spec = SpecFromTable(t);
    REQUIRE(t.fitError.max >= 0);
    const size_t nc = t.channels.size();
    for (size_t i = 0; i < spec.TexelCount(); ++i) {
      double x[3];
      NodeCoordinates(spec, i, x);
      double r = x[0], mu = 1 - x[1] * x[1];
      LtcLobe lobe(spec.model, std::max(r, std::sqrt(1e-5)), LtcFitMu(mu));
      double norm;
      Vec3 dir;
      LtcLobeMoments(lobe, 128, &norm, &dir);
      const double c[4] = {t.data[i * nc], t.data[i * nc + 1], t.data[i * nc + 2],
                           t.data[i * nc + 3]};
      // An independent measurement (more samples than the bake's) of the same L1 error.
      double l1 = LtcFitError(lobe, norm, LtcMatrix::FromInverse(c), 1, 64);
      INFO(name << " r " << r << " mu " << mu << " L1 " << l1 << " declared " << t.fitError.max);
      CHECK(l1 <= t.fitError.max * 1.05 + 1e-3);
      if (mu > 0.3) CHECK(l1 < 0.5);  // away from grazing the fit is close (caught a broken fit)
    }
    CHECK(t.fitError.rms <= t.fitError.max);
    CHECK(t.fitError.polygonMax >= 0);
  }
}

TEST_CASE("The polygon integral of a quad covering the hemisphere is the albedo", "[ltc]") {
  // norm * E(quad) differs from the albedo by norm * (the LTC's mass outside the quad), which the
  // L1 fit error bounds (plus the lobe's own mass within 1e-3 rad of the horizon).
  Table t = SmallLtc("ltc-ggx", 6, 2);
  TableSpec spec = SpecFromTable(t);
  const size_t nc = t.channels.size();
  const std::vector<Vec3> quad = LtcTestPolygons()[0];
  for (size_t i = 0; i < spec.TexelCount(); ++i) {
    double x[3];
    NodeCoordinates(spec, i, x);
    double r = x[0], mu = 1 - x[1] * x[1];
    double albedo = r > 0 ? test::Albedo("ggx", mu, r) : 1.0;
    const float* c = &t.data[i * nc];
    CHECK(c[4] == Approx(albedo).margin(1e-6));  // the norm channel is the albedo table's value
    double minv[9], pts[4][3];
    ltcLocalInverse(LtcInverse{c[0], c[1], c[2], c[3]}, minv);
    for (int v = 0; v < 4; ++v) {
      pts[v][0] = quad[v].x;
      pts[v][1] = quad[v].y;
      pts[v][2] = quad[v].z;
    }
    double e = c[4] * ltcPolygonIntegral(minv, pts, 4, true);
    INFO("r " << r << " mu " << mu << " E " << e << " albedo " << albedo);
    CHECK(std::fabs(e - albedo) <= albedo * t.fitError.max + 2e-3);
  }
}

TEST_CASE("An ltc bake is bit-identical for 1 and 2 threads", "[ltc]") {
  Table a = SmallLtc("ltc-ggx", 6, 1), b = SmallLtc("ltc-ggx", 6, 2);
  CHECK(a.data == b.data);
  CHECK(a.fitError.max == b.fitError.max);
  CHECK(a.fitError.polygonMax == b.fitError.polygonMax);
}

TEST_CASE("The ltc table declares the published layout", "[ltc]") {
  TableSpec s = CatalogueTable("ltc-ggx");
  REQUIRE(s.axes.size() == 2);
  CHECK(s.axes[0].name == "roughness");
  CHECK(s.axes[1].name == "sqrt_one_minus_mu");
  CHECK(s.axes[0].size == 64);
  CHECK(s.axes[1].size == 64);
  CHECK(s.channels ==
        std::vector<std::string>{"minv_a", "minv_b", "minv_c", "minv_d", "norm", "fresnel"});
}

TEST_CASE("The fit recovers an LTC lobe exactly: the clamped cosine is M = I", "[ltc]") {
  // Lambert's lobe f mu_l = mu_l / pi is the LTC of M = I at any view: from a wrong start the
  // fit must return to m11 = m22 = 1, m13 = 0 (the objective's two terms cancel there).
  for (double mu : {1.0, 0.5}) {
    LtcLobe lobe("lambert", 0, mu);
    LtcTexel t = FitLtc(lobe, -1, LtcFrameParams{0.6, 1.4, 0.2, Vec3{0, 0, 1}}, mu >= 1);
    INFO("mu " << mu << " m11 " << t.params.m11 << " m22 " << t.params.m22 << " m13 "
               << t.params.m13 << " L1 " << t.l1);
    CHECK(t.params.m11 == Approx(1).margin(0.03));
    CHECK(t.params.m22 == Approx(1).margin(0.03));
    CHECK(std::fabs(t.params.m13) < 0.03);
    CHECK(t.l1 < 0.03);
  }
}

TEST_CASE("The GGX fit never misses its lobe, grazing views included", "[ltc]") {
  // Two densities on the sphere that do not overlap are at L1 distance 2. The fit with a fixed
  // quadrature of D at the lobe's points alone let narrow LTCs drift off the grazing lobes
  // (declared max 2.01); the objective that charges the LTC its own integral D^2 keeps them on.
  Table t = SmallLtc("ltc-ggx", 8, 2);
  INFO("declared L1 max " << t.fitError.max << " rms " << t.fitError.rms);
  CHECK(t.fitError.max < 1.6);
  CHECK(t.fitError.rms < 0.6);
}

TEST_CASE("kiln's own LTC layout is the dfg's axes, on request", "[ltc]") {
  TableSpec s = CatalogueTable("ltc-ggx-kiln");
  REQUIRE(s.axes.size() == 2);
  CHECK(s.axes[0].name == "mu");
  CHECK(s.axes[0].warp == Warp::Root4Layer);
  CHECK(s.axes[1].name == "roughness");
  bool inDefault = false;
  for (const TableSpec& d : DefaultCatalogue()) inDefault |= d.name == "ltc-ggx-kiln";
  CHECK_FALSE(inDefault);
}

TEST_CASE("A lobe's fused EvalPdf gives the same bits as Eval and Pdf", "[ltc]") {
  // The fit and its error measure read f and the proposal's density through EvalPdf (one half
  // vector, one D); the separate calls are the definition, and Eval the registry's model.
  for (const char* model : {"ggx", "beckmann", "blinn-phong"})
    for (double r : {0.05, 0.4, 1.0})
      for (double mu : {1.0, 0.5, 0.05}) {
        LtcLobe lobe(model, r, mu);
        ModelParams mp;
        mp.roughness = r;
        const AnyModel m = MakeModel(model, mp);
        for (int j = 0; j < 9; ++j)
          for (int i = 0; i < 9; ++i) {
            Vec3 wi = lobe.Sample((i + 0.5) / 9, (j + 0.5) / 9);
            double f = -1, p = -1;
            lobe.EvalPdf(wi, &f, &p);
            INFO(model << " r " << r << " mu " << mu << " wi " << wi.x << " " << wi.y << " "
                       << wi.z);
            CHECK(f == lobe.Eval(wi));
            const double def = wi.z > 0 ? Evaluate(m, lobe.wo(), wi) * wi.z : 0;
            CHECK(f == (std::isfinite(def) ? def : 0));
            CHECK(p == lobe.Pdf(wi));
          }
      }
}

TEST_CASE("A Charlie sheen lobe's proposal samples its albedo: Sample and Pdf agree", "[ltc]") {
  // The mixture of the clamped cosine and the Charlie NDF's reflected normals: the estimate
  // integral f mu_l = mean f / pdf over its stratified samples is the sheen's directional albedo
  // (the lobe the ltc-charlie fit normalises by).
  for (double r : {0.2, 0.5, 1.0})
    for (double mu : {0.9, 0.5, 0.1}) {
      LtcLobe lobe("charlie", r, mu);
      double norm = 0;
      Vec3 dir;
      LtcLobeMoments(lobe, 128, &norm, &dir);
      IntegrationOptions opt;
      opt.tol = 1e-9;
      IntegrationStats st;
      ModelParams p;
      p.roughness = r;
      double e = DirectionalAlbedo(MakeModel("charlie", p), mu, opt, st).lin;
      INFO("r " << r << " mu " << mu << " samples " << norm << " albedo " << e);
      CHECK(std::fabs(norm - e) < 2e-3 * std::max(1.0, e));
    }
}

TEST_CASE("A lobe's sample grid is its n x n stratified samples, bit for bit", "[ltc]") {
  // Every proposal kind: the microfacet ones (GGX, Beckmann, Blinn-Phong), the Charlie sheens
  // (each of their three branches of u1), and kinds the grid takes sample by sample.
  int compared = 0;
  for (const char* model : {"ggx", "beckmann", "blinn-phong", "charlie", "charlie-smith",
                            "ashikhmin-velvet", "lafortune", "lambert"})
    for (double r : {0.05, 0.4, 1.0})
      for (double mu : {LtcFitMu(0), 0.3, 1.0})
        for (int n : {1, 7, 16}) {
          const LtcLobe lobe(model, r, mu);
          const std::vector<Vec3> grid = lobe.SampleGrid(n);
          REQUIRE(grid.size() == size_t(n) * n);
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
              const Vec3 want = lobe.Sample((i + 0.5) / n, (j + 0.5) / n);
              const Vec3 got = grid[size_t(i) + size_t(n) * j];
              INFO(model << " r " << r << " mu " << mu << " n " << n << " i " << i << " j " << j);
              CHECK(std::memcmp(&got, &want, sizeof got) == 0);
              ++compared;
            }
        }
  CHECK(compared == 8 * 3 * 3 * (1 + 49 + 256));
}
