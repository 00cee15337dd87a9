// The split-sum BTDF pair's table (baker/quantities/dielectric_btdf.cpp): glTF transmission asks
// for it at eta = ior, it is in the default catalogue, the bake is the same for any thread count,
// and baked by eta columns it holds the rule's point values, and its stored form (T_F minus
// btdfFresnelClosedForm) reads back as the pair, {1, F(mu)} on the smooth row.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "baker/bake/bake.h"
#include "baker/integrate/dielectric_btdf.h"
#include "baker/models/fresnel.h"
#include "baker/tables/catalogue.h"
#include "kiln/stored.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

TEST_CASE("glTF transmission asks for the split-sum BTDF pair at eta = ior",
          "[dielectric-btdf][scene]") {
  Plan plan = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0,
      "roughnessFactor": 0.3}, "extensions": {"KHR_materials_transmission":
      {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.7}}})"));
  const PlannedTable* t = nullptr;
  for (const PlannedTable& p : plan.tables)
    if (p.spec.quantity == Quantity::DielectricBtdfSplitSum) t = &p;
  REQUIRE(t != nullptr);
  CHECK(t->spec.model == "ggx-dielectric");
  CHECK(t->spec.params.at("eta") == 1.7);
  CHECK(t->spec.channels == std::vector<std::string>{"T_lobe", "T_F_residual"});
  // Without transmission no pair; an ior below the glass tables' 1.1 has none either (a note
  // says why).
  Plan opaque = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_ior": {"ior": 1.7}}})"));
  for (const PlannedTable& p : opaque.tables)
    CHECK(p.spec.quantity != Quantity::DielectricBtdfSplitSum);
  Plan below = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_ior": {"ior": 1.05}}})"));
  for (const PlannedTable& p : below.tables)
    CHECK(p.spec.quantity != Quantity::DielectricBtdfSplitSum);
  CHECK(FindNote(below, SceneNote::Kind::NotYet, "ggx-dielectric-btdf-split-sum"));
}

TEST_CASE("the split-sum BTDF pair is in the default catalogue, the same with 1 and 2 threads",
          "[dielectric-btdf]") {
  int inCatalogue = 0;
  for (const TableSpec& s : DefaultCatalogue())
    inCatalogue += s.quantity == Quantity::DielectricBtdfSplitSum;
  CHECK(inCatalogue == 1);
  CatalogueOptions copt;
  copt.size = 4;
  TableSpec spec = CatalogueTable("ggx-dielectric-btdf-split-sum", copt);
  BakeOptions one, two;
  one.threads = 1;
  two.threads = 2;
  one.measureLookupError = two.measureLookupError = false;
  Table a = BakeTable(spec, one), b = BakeTable(spec, two);
  REQUIRE(a.data.size() == b.data.size());
  CHECK(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(a.data[0])) == 0);
  // Baked by eta columns: every texel as EvaluateSpec gives it at its node (what the lookup-error
  // search and kiln verify evaluate).
  const size_t nc = spec.channels.size();
  for (size_t i = 0; i < spec.TexelCount(); ++i) {
    double x[3];
    NodeEvaluationPoint(spec, i, x);
    IntegrationStats st;
    const std::vector<double> v = EvaluateSpec(spec, x, st);
    for (size_t c = 0; c < nc; ++c) {
      INFO("texel " << i << " channel " << c);
      CHECK(a.data[i * nc + c] == static_cast<float>(v[c]));
    }
  }
  // Read back: the stored form adds the closed form to T_F.
  REQUIRE(storedForm(a) == StoredForm::BtdfSplitSumResidual);
  for (double mu : {0.0, 1.0})
    for (double eta : {1.1, 3.0}) {
      double p[3] = {mu, 0.0, eta}, out[2];
      sampleQuantity(a, p, out);
      INFO("mu " << mu << " eta " << eta);
      CHECK(std::abs(out[0] - 1) < 1e-6);
      CHECK(std::abs(out[1] - FrDielectric(mu, eta)) < 1e-6);
    }
  double p[3] = {1.0, 1.0, 3.0}, out[2];
  sampleQuantity(a, p, out);
  std::array<double, 2> want = FixedRuleDielectricBtdfPair(1.0, 1.0, 3.0);
  CHECK(std::abs(out[0] - want[0]) < 1e-6);
  CHECK(std::abs(out[1] - want[1]) < 1e-6);
}
