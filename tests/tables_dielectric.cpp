// The rough dielectric's tables (baker/quantities/dielectric_albedo.cpp): glTF glass maps to them
// (KHR_materials_transmission: the entering pair; KHR_materials_volume: the exit pair too, at
// eta = 1/ior), an ior outside a table's domain leaves that table out with a note, and the bake
// is the same for any thread count.
#include <catch2/catch.hpp>

#include <cstring>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "baker/models/fresnel.h"
#include "cli_util.h"
#include "scene_util.h"

using namespace kiln;
using namespace kiln::test;

namespace {
const PlannedTable* FindKind(const Plan& plan, Quantity q) {
  for (const PlannedTable& t : plan.tables)
    if (t.spec.quantity == q) return &t;
  return nullptr;
}
}  // namespace

TEST_CASE(
    "glTF transmission asks for the dielectric tables and their averages, volume for the exit "
    "side too",
    "[dielectric][scene]") {
  Plan plan = PlanSceneFile(ScenePath("glass.gltf"));
  for (Quantity q : {Quantity::DielectricAlbedoR, Quantity::DielectricAlbedoT,
                     Quantity::DielectricAlbedoRExit, Quantity::DielectricAlbedoTExit,
                     Quantity::DielectricAlbedoRAvg, Quantity::DielectricAlbedoTAvg,
                     Quantity::DielectricAlbedoRExitAvg, Quantity::DielectricAlbedoTExitAvg}) {
    const PlannedTable* t = FindKind(plan, q);
    REQUIRE(t != nullptr);
    CHECK(t->spec.model == "ggx-dielectric");
    const bool exit =
        q == Quantity::DielectricAlbedoRExit || q == Quantity::DielectricAlbedoTExit ||
        q == Quantity::DielectricAlbedoRExitAvg || q == Quantity::DielectricAlbedoTExitAvg;
    // One ior: the eta axis is dropped into the params, at ior or 1/ior.
    // (An average whose roughness is one value too keeps eta as a 2-node axis from there.)
    const double eta = exit ? 1 / 1.5 : 1.5;
    if (t->spec.params.count("eta"))
      CHECK(t->spec.params.at("eta") == eta);
    else
      CHECK(
          (t->spec.axes.size() == 1 && t->spec.axes[0].name == "eta" && t->spec.axes[0].lo == eta));
    // Entering: both materials (roughness 0.05 and 0.4); exit: only the one with a volume.
    CHECK(t->reasons.size() == (exit ? 1u : 2u));
  }
}

TEST_CASE("an ior outside a dielectric table's domain leaves that table out, with a note",
          "[dielectric][scene]") {
  // ior 1.05: below every dielectric table's domain: none is planned, each is noted; the GGX
  // lobe's tables still are.
  Plan below = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_ior": {"ior": 1.05}}})"));
  CHECK(TableNames(below) ==
        std::vector<std::string>{"ggx-dfg-r1", "ggx-albedo-r1", "ggx-albedo-avg-r1"});
  const PlanNote* glass = FindNote(below, SceneNote::Kind::NotYet, "ggx-dielectric-albedo-r");
  REQUIRE(glass);
  CHECK(glass->why.find("eta 1.05 is outside its domain [1.1, 3]") != std::string::npos);
  // ior 1.2: inside the glass tables' [1.1, 3] but below fresnel-albedo's 1.3, which the
  // material's dielectric layer also asks for: the glass tables are planned, fresnel-albedo is
  // noted with its domain.
  Plan between = PlanText(OneMaterialGltf(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_ior": {"ior": 1.2}}})"));
  CHECK(FindTable(between, "ggx-dielectric-albedo-r-r1-ior1.2"));
  const PlanNote* fresnel = FindNote(between, SceneNote::Kind::NotYet, "ggx-fresnel-albedo");
  REQUIRE(fresnel);
  CHECK(fresnel->why.find("eta 1.2 is outside its domain [1.3, 3]") != std::string::npos);
}

TEST_CASE("the dielectric tables bake the same values with 1 and 2 threads", "[dielectric]") {
  for (const char* name : {"ggx-dielectric-albedo-t", "ggx-dielectric-albedo-r-exit"}) {
    CatalogueOptions copt;
    copt.size = 4;
    TableSpec spec = CatalogueTable(name, copt);
    BakeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.measureLookupError = two.measureLookupError = false;
    Table a = BakeTable(spec, one), b = BakeTable(spec, two);
    REQUIRE(a.data.size() == b.data.size());
    CHECK(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(a.data[0])) == 0);
  }
}

TEST_CASE("kiln integrate albedo-r|albedo-t --model ggx-dielectric prints E_R, E_T",
          "[dielectric]") {
  auto t = RunKiln("integrate albedo-t --model ggx-dielectric --mu 0.5 --roughness 0 --eta 1.5");
  REQUIRE(t.exitCode == 0);
  CHECK(std::stod(t.out) == 1 - FrDielectric(0.5, 1.5));  // the smooth interface, exact
  auto r = RunKiln("integrate albedo-r --model ggx-dielectric --mu 0.5 --roughness 0.5 --eta 0.7");
  REQUIRE(r.exitCode == 0);
  CHECK(std::stod(r.out) > FrDielectric(0.5, 0.7) - 0.5);  // a number, in (0, 1)
  CHECK(std::stod(r.out) < 1);
  auto bad = RunKiln("integrate albedo-r --model ggx --mu 0.5");
  CHECK(bad.exitCode != 0);
  CHECK(bad.err.find("ggx-dielectric") != std::string::npos);
}
