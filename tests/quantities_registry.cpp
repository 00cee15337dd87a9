// The quantity registry (baker/quantities/): one descriptor per table kind, looked up by name
// once; and the catalogue it builds is the committed one, spec for spec (hash, method, channels,
// meanings, axes, params against luts/manifest.json), so the re-bake is byte for byte.
#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <set>

#include "baker/scene/kiln_scene_reader.h"
#include "baker/tables/catalogue.h"
#include "cli_util.h"
#include "test_util.h"

using namespace kiln;

TEST_CASE("Every quantity has one descriptor, found by its name", "[quantities]") {
  std::set<std::string> names;
  size_t i = 0;
  for (const QuantityInfo* q : AllQuantities()) {
    INFO(q->name);
    CHECK(static_cast<size_t>(q->id) == i++);
    CHECK(&Describe(q->id) == q);
    CHECK(names.insert(q->name).second);
    CHECK(FindQuantity(q->name) == q);
    CHECK(std::string(q->description).size() > 0);
    CHECK(q->makeSpec);
    CHECK(q->defaultAxes);
    CHECK(q->evaluate);
    CHECK(q->method);
    CHECK(static_cast<bool>(q->fixedRule) == static_cast<bool>(q->usesFixedRule));
    CHECK(static_cast<bool>(q->fixedRuleMethod) == static_cast<bool>(q->usesFixedRule));
    CHECK(static_cast<bool>(q->integrate) == (q->integrateName != nullptr));
  }
  CHECK(FindQuantity("volume") == nullptr);
  CHECK(FindQuantity("") == nullptr);
  CHECK(FindQuantity("DFG") == nullptr);
}

TEST_CASE("The names scenes, files and kiln integrate use are unchanged", "[quantities]") {
  CHECK(SceneTableKinds() ==
        std::vector<std::string>{
            "dfg", "albedo", "albedo-avg", "fresnel-albedo", "fresnel-albedo-avg",
            "fresnel-dielectric", "fresnel-dielectric-avg", "fresnel-conductor", "albedo-r",
            "albedo-t", "albedo-r-exit", "albedo-t-exit", "albedo-r-avg", "albedo-t-avg",
            "albedo-r-exit-avg", "albedo-t-exit-avg", "btdf-split-sum"});
  std::set<std::string> integrable;
  for (const QuantityInfo* q : AllQuantities())
    if (q->integrateName) integrable.insert(q->integrateName);
  CHECK(integrable == std::set<std::string>{"albedo", "albedo-avg", "albedo-r", "albedo-t", "dfg",
                                            "fresnel-avg"});
  CHECK(TableName(FindQuantity("albedo-r-exit")->id, "ggx-dielectric") ==
        "ggx-dielectric-albedo-r-exit");
  CHECK(TableName(FindQuantity("dfg")->id, "ggx") == "ggx-dfg");
  CHECK(TableName(FindQuantity("fresnel-albedo")->id, "ggx") == "ggx-fresnel-albedo");
  CHECK(TableName(FindQuantity("fresnel-conductor")->id, "none") == "fresnel-conductor");
}

TEST_CASE("A table with an unknown quantity is refused by name", "[quantities]") {
  Table t;
  t.name = "x";
  t.quantity = "volume";
  try {
    SpecFromTable(t);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "table 'x': unknown quantity 'volume'");
  }
}

TEST_CASE("The catalogue's specs are the committed tables' (hash, method, channels, axes)",
          "[quantities][luts]") {
  auto manifest =
      nlohmann::json::parse(test::ReadFile(std::string(KILN_SOURCE_DIR) + "/luts/manifest.json"));
  std::map<std::string, nlohmann::json> byName;
  for (auto& e : manifest["tables"]) byName[e["name"].get<std::string>()] = e;
  std::vector<TableSpec> catalogue = DefaultCatalogue();
  CHECK(catalogue.size() == byName.size());
  for (const TableSpec& s : catalogue) {
    INFO(s.name);
    REQUIRE(byName.count(s.name));
    const auto& e = byName[s.name];
    CHECK(e["spec_hash"] == s.Hash());
    CHECK(e["method"] == s.Method());
    CHECK(e["quantity"] == QuantityName(s.quantity));
    CHECK(e["model"] == s.model);
    CHECK(e["channels"] == s.channels);
    CHECK(e["channel_meanings"] == s.meanings);
    CHECK(e["params"] == s.ParamsText());
    CHECK(e["tolerance"].get<double>() == s.tol);
    REQUIRE(e["axes"].size() == s.axes.size());
    for (size_t i = 0; i < s.axes.size(); ++i) {
      const auto& a = e["axes"][i];
      CHECK(a["name"] == s.axes[i].name);
      CHECK(a["lo"].get<double>() == s.axes[i].lo);
      CHECK(a["hi"].get<double>() == s.axes[i].hi);
      CHECK(a["size"].get<int>() == s.axes[i].size);
      CHECK(a["warp"] == warpName(s.axes[i].warp));
    }
  }
}

TEST_CASE("A model without hemispherical tables (a fibre) is refused in one line by every kind",
          "[quantities][cli]") {
  // kajiya-kay's lobes are around the fibre's tangent: no albedo, dfg or average over the normal.
  for (const char* kind : {"albedo --mu 0.5", "dfg --mu 0.5", "albedo-avg"}) {
    INFO(kind);
    auto r = test::RunKiln(std::string("integrate ") + kind + " --model kajiya-kay");
    CHECK(r.exitCode != 0);
    CHECK(r.out.empty());
    CHECK(r.err.find("kajiya-kay") != std::string::npos);
    CHECK(r.err.find("fibre") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  auto plan = test::RunKiln("bake --only kajiya-kay-albedo --out /tmp/kiln-no-fibre-table");
  CHECK(plan.exitCode != 0);
  CHECK(plan.err.find("kajiya-kay-albedo") != std::string::npos);
}
