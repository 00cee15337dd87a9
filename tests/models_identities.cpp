// The exact identities of docs/models.md, each checked against the models and integrators.
#include <catch2/catch.hpp>
#include <cmath>

#include "baker/models/materials.h"
#include "baker/models/registry.h"
#include "test_util.h"

using namespace kiln;
using kiln::test::Albedo;

namespace {

/// integral D(h) cos(theta_h) dh by adaptive quadrature in theta_h, panels graded around alpha.
template <class Dist>
double ProjectedNdfArea(const Dist& dist) {
  double a = dist.alpha;
  double breaks[] = {0, a / 10, a, 10 * a, Pi / 2};
  int n = 10 * a < Pi / 2 ? 5 : 2;
  if (n == 2) breaks[1] = Pi / 2;
  auto g = [&](double theta) {
    Vec3 wm = SphericalDirection(std::sin(theta), std::cos(theta), 0);
    return Channels<1>{2 * Pi * dist.D(wm) * std::cos(theta) * std::sin(theta)};
  };
  return IntegrateAdaptive<1>(g, breaks, n, 1e-13, 2000)[0];
}

/// integral max(0, o.h) D(h) dh over the hemisphere of h, split where o.h = 0.
template <class Dist>
double VisibleNormalArea(const Dist& dist, double mu_o) {
  Vec3 wo = ViewDirection(mu_o);
  double a = dist.alpha, tb[] = {0, a / 10, a, 10 * a, Pi / 2};
  int nt = 5;
  if (10 * a >= Pi / 2) tb[1] = Pi / 2, nt = 2;
  auto outer = [&](double theta) {
    double st = std::sin(theta), ct = std::cos(theta);
    // o.h = 0 at cos(phi) = -mu_o cos / (sin_o sin): integrate phi over [0, pi] split there.
    double c = -mu_o * ct / (wo.x * st);
    double phis[3] = {0, std::acos(Clamp(c, -1.0, 1.0)), Pi};
    auto inner = [&](double phi) {
      Vec3 wm = SphericalDirection(st, ct, phi);
      return Channels<1>{std::max(0.0, Dot(wo, wm)) * dist.D(wm)};
    };
    return (2 * st) * IntegrateAdaptive<1>(inner, phis, 3, 1e-12, 2000);
  };
  return IntegrateAdaptive<1>(outer, tb, nt, 1e-10, 2000)[0];
}

}  // namespace

TEST_CASE("Every NDF is normalised: integral D(h) (n.h) dh = 1", "[identities]") {
  for (double r : {0.1, 0.3, 0.6, 1.0}) {
    double alpha = r * r;
    CHECK(ProjectedNdfArea(GGXDistribution{alpha}) == Approx(1).margin(1e-9));
    CHECK(ProjectedNdfArea(BeckmannDistribution{alpha}) == Approx(1).margin(1e-9));
    CHECK(ProjectedNdfArea(BlinnPhongDistribution{alpha}) == Approx(1).margin(1e-9));
  }
}

TEST_CASE("Smith masking is exact: integral G1(o) max(0, o.h) D(h) dh = mu_o", "[identities]") {
  for (double r : {0.3, 0.6, 1.0})
    for (double mu : {0.05, 0.3, 0.7, 0.95}) {
      double alpha = r * r;
      GGXDistribution ggx{alpha};
      BeckmannDistribution beckmann{alpha};
      CHECK(G1(ggx, mu) * VisibleNormalArea(ggx, mu) == Approx(mu).margin(1e-9));
      CHECK(G1(beckmann, mu) * VisibleNormalArea(beckmann, mu) == Approx(mu).margin(1e-9));
    }
}

TEST_CASE(
    "Blinn-Phong normalisation: integral (h.n)^s do = 4 pi (2 - 2^(-s/2)) / (s + 2) for l = n",
    "[identities]") {
  for (double s : {0.0, 1.0, 10.0, 100.0, 1000.0}) {
    // h = (o + n)/|o + n| has n.h = cos(theta_o / 2).
    auto g = [&](double theta) {
      return Channels<1>{2 * Pi * std::pow(std::cos(theta / 2), s) * std::sin(theta)};
    };
    double breaks[] = {0, 0.1, Pi / 2};
    double numeric = IntegrateAdaptive<1>(g, breaks, 3, 1e-13, 2000)[0];
    double exact = 4 * Pi * (2 - std::exp2(-s / 2)) / (s + 2);
    CHECK(numeric == Approx(exact).epsilon(1e-10));
    CHECK(1 / exact == Approx(NormalizedBlinnPhong::Normalization(s)).epsilon(1e-14));
  }
}

TEST_CASE("F0 from the measured indices matches seed 004 to its 3 digits", "[identities]") {
  int checked = 0;
  for (const MeasuredMaterial& m : MeasuredMaterials()) {
    if (m.seedF0 < 0) continue;
    CHECK(m.F0() == Approx(m.seedF0).margin(5e-4));
    ++checked;
  }
  CHECK(checked == 5);
  CHECK(FindMaterial("gold")->F0() == Approx(0.887).margin(5e-4));
  CHECK(FindMaterial("carbon")->F0() == Approx(0.2).margin(5e-4));
}

TEST_CASE("Lambert: E(mu) = rho for all mu, E_avg = rho", "[identities]") {
  for (double mu : {0.0, 0.05, 0.5, 1.0})
    CHECK(Albedo("lambert", mu, 0) == Approx(1).margin(1e-12));
  IntegrationStats stats;
  ModelParams p;
  p.rho = 0.3;
  RhoParts avg = AverageAlbedo(MakeModel("lambert", p), IntegrationOptions{}, stats);
  CHECK(avg.At(0.3) == Approx(0.3).margin(1e-12));
}

TEST_CASE("Schlick Fresnel average = F0 + (1 - F0)/21", "[identities]") {
  for (double f0 : {0.0, 0.04, 0.5, 1.0}) {
    Fresnel F{Fresnel::Kind::Schlick, f0};
    IntegrationStats stats;
    CHECK(FresnelAverage(F, IntegrationOptions{}, stats) ==
          Approx(f0 + (1 - f0) / 21).margin(1e-12));
  }
}

TEST_CASE("Exact dielectric Fresnel average and its reciprocity across the interface",
          "[identities]") {
  auto closedForm = [](double e) {
    double e2 = e * e, e4 = e2 * e2;
    return 0.5 + (e - 1) * (3 * e + 1) / (6 * Sqr(e + 1)) +
           e2 * Sqr(e2 - 1) / std::pow(e2 + 1, 3) * std::log((e - 1) / (e + 1)) -
           2 * e * e2 * (e2 + 2 * e - 1) / ((e2 + 1) * (e4 - 1)) +
           8 * e4 * (e4 + 1) / ((e2 + 1) * Sqr(e4 - 1)) * std::log(e);
  };
  for (double eta : {1.05, 1.33, 1.5, 2.0, 3.0}) {
    IntegrationStats stats;
    Fresnel F{Fresnel::Kind::Dielectric, 0, eta};
    Fresnel Finv{Fresnel::Kind::Dielectric, 0, 1 / eta};
    double avg = FresnelAverage(F, IntegrationOptions{}, stats);
    double avgInv = FresnelAverage(Finv, IntegrationOptions{}, stats);
    CHECK(avg == Approx(closedForm(eta)).margin(1e-9));
    CHECK(1 - avg == Approx(eta * eta * (1 - avgInv)).margin(1e-9));
  }
}

TEST_CASE("GGX at alpha = 1: the closed forms of E and E_avg", "[identities]") {
  double ln2 = std::log(2.0);
  for (double mu : {0.05, 0.2, 0.5, 0.8, 1.0}) {
    CHECK(Albedo("ggx", mu, 1) == Approx(1 - mu * std::log(1 + 1 / mu)).margin(1e-9));
    CHECK(Albedo("ggx-separable", mu, 1) == Approx(2 * (1 - ln2) / (1 + mu)).margin(1e-9));
  }
  IntegrationStats stats;
  ModelParams p;
  p.roughness = 1;
  CHECK(AverageAlbedo(MakeModel("ggx", p), {}, stats).lin ==
        Approx(4.0 / 3 * (1 - ln2)).margin(1e-9));
  CHECK(AverageAlbedo(MakeModel("ggx-separable", p), {}, stats).lin ==
        Approx(4 * Sqr(1 - ln2)).margin(1e-9));
}

TEST_CASE("Height-correlated GGX: E -> 1 as mu -> 0 for every alpha", "[identities]") {
  for (double r : {0.1, 0.5, 1.0}) {
    CHECK(Albedo("ggx", 0.0, r) == Approx(1).margin(1e-8));
    CHECK(Albedo("ggx", 1e-7, r) == Approx(1).margin(1e-5));
  }
}

TEST_CASE("Burley and Frostbite closed forms", "[identities]") {
  for (double mu : {0.0, 0.1, 0.5, 1.0}) {
    CHECK(Albedo("burley", mu, 0) == Approx(41.0 / 42 * (1 - Pow5(1 - mu) / 2)).margin(1e-12));
    CHECK(Albedo("frostbite", mu, 0) == Approx(20.0 / 21 * (1 - Pow5(1 - mu))).margin(1e-12));
  }
  CHECK(Albedo("burley", 1, 1) == Approx(29.0 / 28).margin(1e-12));
  IntegrationStats stats;
  ModelParams p;
  p.roughness = 0;
  CHECK(AverageAlbedo(MakeModel("burley", p), {}, stats).lin ==
        Approx(Sqr(41.0 / 42)).margin(1e-10));
  CHECK(AverageAlbedo(MakeModel("frostbite", p), {}, stats).lin ==
        Approx(Sqr(20.0 / 21)).margin(1e-10));
}

TEST_CASE("Ashikhmin-Shirley diffuse: E(mu) = rho (1 - R_s)(1 - (1 - mu/2)^5)", "[identities]") {
  for (double rs : {0.0, 0.3})
    for (double mu : {0.0, 0.3, 1.0}) {
      ModelParams p;
      p.rs = rs;
      IntegrationStats stats;
      double e = DirectionalAlbedo(MakeModel("ashikhmin-shirley-diffuse", p), mu, {}, stats).lin;
      CHECK(e == Approx((1 - rs) * (1 - Pow5(1 - mu / 2))).margin(1e-12));
    }
}

TEST_CASE("tri-Ace Lambert: E = 1 - R_s (F0 + (1 - F0)/21)", "[identities]") {
  ModelParams p;
  p.rs = 0.5;
  p.f0 = 0.04;
  IntegrationStats stats;
  double e = DirectionalAlbedo(MakeModel("triace-lambert", p), 0.4, {}, stats).lin;
  CHECK(e == Approx(1 - 0.5 * (0.04 + 0.96 / 21)).margin(1e-12));
}

TEST_CASE("Fujii normalised ION: E(1) and E_avg closed forms", "[identities]") {
  double c1 = 0.5 - 2 / (3 * Pi), c2 = 2.0 / 3 - 28 / (15 * Pi);
  for (double s : {0.0, 0.4, 1.0}) {
    CHECK(Albedo("fujii-normalized", 1, s) == Approx(1 / (1 + c1 * s)).margin(1e-12));
    ModelParams p;
    p.roughness = s;
    IntegrationStats stats;
    CHECK(AverageAlbedo(MakeModel("fujii-normalized", p), {}, stats).lin ==
          Approx((1 + c2 * s) / (1 + c1 * s)).margin(1e-9));
  }
}

TEST_CASE(
    "Oren-Nayar at normal view: qualitative E(1) = rho A, full E(1) = rho C1 + 0.17 rho^2 ...",
    "[identities]") {
  for (double s : {0.0, 0.3, 1.0, 1.5}) {
    double s2 = s * s;
    CHECK(Albedo("oren-nayar-qualitative", 1, s) ==
          Approx(1 - 0.5 * s2 / (s2 + 0.33)).margin(1e-12));
    CHECK(Albedo("oren-nayar-qualitative-ir", 1, s) ==
          Approx(1 - 0.5 * s2 / (s2 + 0.57)).margin(1e-12));
    ModelParams p;
    p.roughness = s;
    IntegrationStats stats;
    RhoParts e = DirectionalAlbedo(MakeModel("oren-nayar", p), 1, {}, stats);
    CHECK(e.lin == Approx(1 - 0.5 * s2 / (s2 + 0.33)).margin(1e-12));
    CHECK(e.quad == Approx(0.17 * s2 / (s2 + 0.13)).margin(1e-12));
  }
}

TEST_CASE("Limits: Oren-Nayar and Fujii at sigma = 0, Hammon at alpha = 0 at normal incidence",
          "[identities]") {
  Vec3 n{0, 0, 1}, wo = ViewDirection(0.6), wi = DirectionFromMuPhi(0.3, 2.0);
  for (const char* id : {"oren-nayar", "oren-nayar-qualitative", "oren-nayar-qualitative-ir",
                         "fujii", "gotanda-fresnel"}) {
    ModelParams p;
    p.roughness = 0;
    INFO(id);
    CHECK(Evaluate(MakeModel(id, p), wo, wi) * Pi ==
          Approx(std::string(id) == "gotanda-fresnel"
                     ? 21.0 / 20 * (1 - Pow5(0.7)) * (1 - Pow5(0.4))
                     : 1.0)
              .margin(1e-12));
  }
  ModelParams p0;
  p0.roughness = 0;
  CHECK(Evaluate(MakeModel("fujii-normalized", p0), wo, wi) * Pi == Approx(1).margin(1e-12));
  CHECK(Evaluate(MakeModel("hammon", p0), n, n) * Pi == Approx(1.05).margin(1e-12));
}

TEST_CASE("DFG consistency: A + B = E (F = 1) and F0 A + B = albedo with Schlick F0",
          "[identities]") {
  for (const char* id : {"ggx", "ggx-separable", "beckmann", "blinn-phong"})
    for (double r : {0.1, 0.5, 1.0})
      for (double mu : {0.05, 0.5, 1.0}) {
        ModelParams p;
        p.roughness = r;
        IntegrationStats stats;
        auto ab = SplitSumDFG(MakeModel(id, p), mu, {}, stats);
        INFO(id << " r=" << r << " mu=" << mu);
        CHECK(ab[0] + ab[1] == Approx(Albedo(id, mu, r)).margin(2e-9));
        p.f0 = 0.04;
        double withF = DirectionalAlbedo(MakeModel(id, p), mu, {}, stats).lin;
        CHECK(0.04 * ab[0] + ab[1] == Approx(withF).margin(2e-9));
      }
}
