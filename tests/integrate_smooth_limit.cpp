// Roughness 0 is the smooth limit: a microfacet lobe at alpha = 0 is a mirror (or a smooth
// dielectric interface), whose integrals are exact: E = F(mu) (1 without Fresnel), the DFG split
// A = 1 - (1 - mu)^5, B = (1 - mu)^5, E_avg = 2 int F mu dmu. EvaluateSpec, `kiln integrate` and
// the r = 0 rows of the baked tables give these values; 0 < r keeps the floor alpha >= 1e-12.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "baker/bake/bake.h"
#include "baker/integrate/quantities.h"
#include "baker/models/fresnel.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"

using namespace kiln;

namespace {

const char* const kModels[] = {"ggx", "ggx-separable", "beckmann", "beckmann-separable",
                               "blinn-phong"};
const double kMus[] = {0.0, 1e-13, 1e-10, 1e-6, 0.01, 0.5, 1.0};

TableSpec Spec(Quantity q, const std::string& model) {
  const QuantityInfo& info = Describe(q);
  return info.makeSpec(model, info.defaultAxes(model));
}

}  // namespace

TEST_CASE("EvaluateSpec at roughness 0 is the mirror: E = 1, A = 1 - (1 - mu)^5, B = (1 - mu)^5",
          "[integrate][smooth]") {
  for (const char* model : kModels) {
    TableSpec albedo = Spec(Quantity::Albedo, model), dfg = Spec(Quantity::Dfg, model),
              avg = Spec(Quantity::AlbedoAvg, model);
    for (double mu : kMus) {
      INFO(model << " mu " << mu);
      const double x[2] = {mu, 0.0};
      IntegrationStats st;
      CHECK(EvaluateSpec(albedo, x, st)[0] == 1.0);
      CHECK(EvaluateSpec(albedo, x, 1e-9, st)[0] == 1.0);
      std::vector<double> ab = EvaluateSpec(dfg, x, st);
      CHECK(ab[0] == 1 - Pow5(1 - mu));
      CHECK(ab[1] == Pow5(1 - mu));
      CHECK(EvaluateSpec(dfg, x, 1e-9, st) == ab);
    }
    const double r0 = 0.0;
    IntegrationStats st;
    CHECK(EvaluateSpec(avg, &r0, st)[0] == 1.0);
    // 0 < r is the floored lobe (alpha = 1e-12): grazing shadowing is still there.
    const double tiny[2] = {1e-13, 1e-9};
    INFO(model);
    CHECK(EvaluateSpec(albedo, tiny, 1e-9, st)[0] < 0.99);
  }
}

TEST_CASE("GGX with dielectric Fresnel at roughness 0 is the smooth interface: E = F(mu, eta)",
          "[integrate][smooth]") {
  TableSpec e = Spec(Quantity::FresnelAlbedo, "ggx"), avg = Spec(Quantity::FresnelAlbedoAvg, "ggx");
  for (double eta : {1.0, 1.0001, 1.5, 3.0}) {
    for (double mu : kMus) {
      const double x[3] = {mu, 0.0, eta};
      IntegrationStats st;
      CHECK(EvaluateSpec(e, x, st)[0] == FrDielectric(mu, eta));
    }
    const double x[2] = {0.0, eta};
    IntegrationStats st;
    IntegrationOptions opt;
    opt.tol = 1e-10;
    CHECK(EvaluateSpec(avg, x, st)[0] ==
          Approx(FresnelAverage(Fresnel{Fresnel::Kind::Dielectric, 0, eta, 0}, opt, st))
              .margin(1e-7));
  }
}

TEST_CASE("Diffuse models at roughness 0 are unchanged (their r = 0 is already exact)",
          "[integrate][smooth]") {
  for (const char* model : {"burley", "oren-nayar", "hammon"}) {
    TableSpec albedo = Spec(Quantity::Albedo, model);
    const double x[2] = {0.3, 0.0};
    IntegrationStats st;
    CHECK(EvaluateSpec(albedo, x, 1e-9, st) ==
          Describe(Quantity::Albedo).evaluate(albedo, x, 1e-9, st));
  }
}

TEST_CASE("kiln integrate --roughness 0 prints the smooth values", "[integrate][smooth][cli]") {
  auto one = [](const std::string& args) {
    test::CommandResult r = test::RunKiln("integrate " + args);
    INFO(args << ": " << r.out << r.err);
    REQUIRE(r.exitCode == 0);
    return r.out;
  };
  for (const char* model : kModels) {
    const std::string m = std::string(" --model ") + model;
    CHECK(std::stod(one("albedo" + m + " --mu 1e-13 --roughness 0")) == 1.0);
    CHECK(std::stod(one("albedo" + m + " --mu 0 --roughness 0")) == 1.0);
    CHECK(std::stod(one("albedo-avg" + m + " --roughness 0")) == 1.0);
    std::string ab = one("dfg" + m + " --mu 0.25 --roughness 0");
    size_t split = 0;
    double a = std::stod(ab, &split), b = std::stod(ab.substr(split));
    CHECK(a == 1 - Pow5(0.75));
    CHECK(b == Pow5(0.75));
  }
  CHECK(std::stod(one("albedo --model ggx --mu 0.3 --roughness 0 --eta 1.5")) ==
        Approx(FrDielectric(0.3, 1.5)).epsilon(1e-15));
  IntegrationStats st;
  IntegrationOptions opt;
  opt.tol = 1e-10;
  CHECK(
      std::stod(one("albedo-avg --model ggx --roughness 0 --eta 1.5")) ==
      Approx(FresnelAverage(Fresnel{Fresnel::Kind::Dielectric, 0, 1.5, 0}, opt, st)).margin(1e-8));
  // r > 0 is the floored lobe, not the mirror
  CHECK(std::stod(one("albedo --model ggx-separable --mu 1e-13 --roughness 1e-7")) < 0.99);
}

TEST_CASE("A baked table's r = 0 row: smooth values from t_s on, the layer's limit below",
          "[integrate][smooth][bake]") {
  for (const char* model : {"ggx", "beckmann"}) {
    TableSpec spec = Spec(Quantity::Dfg, model);
    spec.axes[0].size = 17;  // odd: t = 1/2 is a node
    spec.axes[1].size = 6;
    spec.tol = 1e-7;
    BakeOptions opt;
    opt.measureLookupError = false;
    opt.progress = false;
    opt.threads = 2;
    Table t = BakeTable(spec, opt);
    const Axis mu = spec.axes[0].ToAxis();
    const int th = 8;  // floor(16 / 2): the node t = 1/2
    REQUIRE(mu.collapsedStart() == 0.5);
    for (int i = 0; i < 17; ++i) {
      double x[2];
      NodeCoordinates(spec, static_cast<size_t>(i), x);
      INFO(model << " node " << i << " mu " << x[0]);
      REQUIRE(x[1] == 0.0);
      if (i < th) {
        CHECK(x[0] == 0.0);  // the collapsed layer sits at mu = 0 ...
        double e[2];
        NodeEvaluationPoint(spec, static_cast<size_t>(i), e);
        CHECK(e[1] == 1e-6);  // ... and holds the layer's limit (alpha = 1e-12)
        CHECK(e[0] == mu.unwarped(i / 16.0, 1e-12));
      } else {
        std::array<double, 2> ab = {1 - Pow5(1 - x[0]), Pow5(1 - x[0])};
        CHECK(t.data[2 * i] == static_cast<float>(ab[0]));
        CHECK(t.data[2 * i + 1] == static_cast<float>(ab[1]));
      }
    }
    // A lookup at r = 0 reads only the smooth nodes: exact at mu = 0 (the node t = 1/2 of an
    // odd axis; an even one blends it with the next smooth node).
    float got[2];
    const double x0[2] = {0.0, 0.0};
    t.view().sample(x0, got);
    CHECK(got[0] == 0.0f);
    CHECK(got[1] == 1.0f);
  }
}

TEST_CASE("The committed microfacet tables' r = 0 rows are the smooth values",
          "[integrate][smooth][luts]") {
  const std::string dir = std::string(KILN_SOURCE_DIR) + "/luts/";
  for (const char* model : kModels) {
    for (const char* kind : {"-albedo", "-dfg"}) {
      Table t = loadTable(dir + model + kind + ".exr");
      TableSpec spec = SpecFromTable(t);
      LutView v = t.view();
      const int n = v.axis[0].size, th = (n - 1) / 2;
      double worstNode = 0, worstLookup = 0;
      for (int i = th; i < n; ++i) {  // the stored smooth nodes
        double x[2];
        NodeCoordinates(spec, static_cast<size_t>(i), x);
        IntegrationStats st;
        std::vector<double> exact = EvaluateSpec(spec, x, st);
        for (int c = 0; c < v.channels; ++c)
          worstNode = std::max(worstNode, std::abs(v.at(i, 0, 0, c) - exact[c]));
      }
      for (double mu : kMus) {  // lookups at r = 0, mu = 0 included
        const double x[2] = {mu, 0.0};
        IntegrationStats st;
        std::vector<double> exact = EvaluateSpec(spec, x, st);
        float got[2];
        v.sample(x, got);
        for (int c = 0; c < v.channels; ++c)
          worstLookup = std::max(worstLookup, std::abs(got[c] - exact[c]));
      }
      INFO(model << kind << " worst node " << worstNode << ", lookup " << worstLookup);
      CHECK(worstNode <= 0x1p-24);  // float rounding of the exact values
      // E = 1 is a constant; A, B blend (1 - mu)^5 linearly between the row's nodes
      CHECK(worstLookup <= (std::string(kind) == "-albedo" ? 0x1p-24 : 1e-3));
    }
  }
}
