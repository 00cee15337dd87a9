// The diffuse fixed rule (baker/integrate/fixed_rule_diffuse.h, the bake method of every diffuse
// albedo table) against the adaptive reference at 1e-10, for every catalogue diffuse model over a
// dense (mu, r) grid that includes mu = 0, mu = 1, r = 0 and the top of the roughness range.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "baker/integrate/fixed_rule_diffuse.h"
#include "baker/integrate/quantities.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

namespace {

/// The view cosines of the grid: both ends, the grazing decades and the bulk.
std::vector<double> MuGrid() {
  std::vector<double> mu = {0, 1e-8, 1e-6, 1e-4, 1e-3, 3e-3, 0.01, 0.03};
  for (int i = 1; i <= 12; ++i) mu.push_back(i / 12.0);
  mu.push_back(0.999);
  return mu;
}

/// Roughness values spanning the model's range, ends included (one value for a model without).
std::vector<double> RoughnessGrid(const std::string& model) {
  const ModelInfo& info = *FindModel(model);
  for (const ParamInfo& p : info.params)
    if (p.name == "roughness") {
      std::vector<double> r;
      for (int i = 0; i <= 4; ++i) r.push_back(p.hi * i / 4.0);
      r.push_back(p.hi * 0.01);
      return r;
    }
  return {0};
}

AnyModel ModelAtRoughness(const std::string& model, double r) {
  ModelParams p;
  for (const ParamInfo& q : FindModel(model)->params)
    if (q.name == "roughness") p.roughness = r;
  return MakeModel(model, p);
}

struct Worst {
  double error = 0;
  std::string where;
};

/// The rule's worst |fixed - adaptive at 1e-10| over the grid for `model`, both rho parts.
/// stopAbove >= 0: returns as soon as one point errs by more than stopAbove (a check that the
/// error exceeds it needs no further point).
Worst WorstError(const std::string& model, const DiffuseRuleOptions& opt, double stopAbove = -1) {
  Worst w;
  IntegrationOptions ref;
  ref.tol = 1e-10;
  for (double r : RoughnessGrid(model)) {
    AnyModel m = ModelAtRoughness(model, r);
    for (double mu : MuGrid()) {
      IntegrationStats st;
      RhoParts want = DirectionalAlbedo(m, mu, ref, st);
      RhoParts got = FixedRuleDiffuseAlbedo(m, mu, opt);
      double e = std::max(std::abs(got.lin - want.lin), std::abs(got.quad - want.quad));
      if (!(e <= w.error)) {
        w.error = e;
        w.where = "mu=" + std::to_string(mu) + " r=" + std::to_string(r);
      }
      if (stopAbove >= 0 && !(w.error <= stopAbove)) return w;
    }
  }
  return w;
}

}  // namespace

TEST_CASE(
    "Every diffuse model's fixed rule is within its bound of adaptive quadrature at 1e-10 over "
    "a dense (mu, r) grid",
    "[integrate][fixed-rule-diffuse]") {
  for (const std::string& model : CatalogueDiffuseModels()) {
    Worst w = WorstError(model, {});
    std::printf("diffuse fixed rule %-26s worst %.3g at %s\n", model.c_str(), w.error,
                w.where.c_str());
    INFO(model << ": worst " << w.error << " at " << w.where);
    CHECK(w.error <= kDiffuseRuleBound);
  }
}

TEST_CASE("The diffuse rule with too few nodes misses the bound (the check can fail)",
          "[integrate][fixed-rule-diffuse]") {
  DiffuseRuleOptions coarse;
  coarse.thetaNodes = 2;
  coarse.phiNodes = 2;
  // The same grid as the test above, walked until the first point beyond the bound.
  for (const char* model : {"oren-nayar", "hammon"}) {
    Worst w = WorstError(model, coarse, kDiffuseRuleBound);
    INFO(model << ": " << w.error << " at " << w.where);
    CHECK(w.error > kDiffuseRuleBound);
  }
}

TEST_CASE("The diffuse rule is deterministic and refuses a specular model",
          "[integrate][fixed-rule-diffuse]") {
  AnyModel m = ModelAtRoughness("hammon", 0.7);
  for (double mu : {0.0, 0.3, 1.0}) {
    long long e1 = 0, e2 = 0;
    RhoParts a = FixedRuleDiffuseAlbedo(m, mu, {}, &e1), b = FixedRuleDiffuseAlbedo(m, mu, {}, &e2);
    CHECK(a.lin == b.lin);
    CHECK(a.quad == b.quad);
    CHECK(e1 == e2);
    CHECK(e1 > 0);
  }
  CHECK_THROWS_AS(FixedRuleDiffuseAlbedo(ModelAtRoughness("ggx", 0.5), 0.5), std::invalid_argument);
}
