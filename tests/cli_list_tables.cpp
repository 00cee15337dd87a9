// kiln list --tables: every table kiln bakes by name (the default catalogue, then the tables
// baked on request) with its axes, its meaning and whether the default catalogue has it;
// --json gives the same as one JSON array.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <set>

#include "baker/tables/catalogue.h"
#include "stress_util.h"

using namespace kiln;
using namespace kiln::stress;

TEST_CASE("kiln list --tables lists every catalogue and on-request table once", "[cli][list]") {
  auto r = RunKilnFor(60, "list --tables");
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.empty());
  std::set<std::string> defaults, onRequest;
  for (const TableSpec& s : DefaultCatalogue()) defaults.insert(s.name);
  for (const TableSpec& s : OnRequestTables())
    if (!defaults.count(s.name)) onRequest.insert(s.name);
  REQUIRE(!onRequest.empty());
  CHECK(kiln::test::CountLines(r.out) == static_cast<int>(defaults.size() + onRequest.size()));
  CHECK(r.out.rfind("ggx-dfg  [default]  mu 0..1 (128, root4-layer) x roughness 0..1 (128, sqrt)"
                    "  # split-sum specular",
                    0) == 0);
  // A table baked at fixed model parameters says so.
  CHECK(r.out.find(" x cos_phi -1..1 (3, linear) at roughness = 0.5  # ") != std::string::npos);
  for (const std::string& name : onRequest)
    CHECK(r.out.find("\n" + name + "  [on request]  ") != std::string::npos);
}

TEST_CASE("kiln list --tables --json: name, axes, meaning and catalogue membership",
          "[cli][list]") {
  auto r = RunKilnFor(60, "list --tables --json");
  REQUIRE(r.exitCode == 0);
  nlohmann::json doc = nlohmann::json::parse(r.out);
  REQUIRE(doc.is_array());
  std::set<std::string> defaults;
  for (const TableSpec& s : DefaultCatalogue()) defaults.insert(s.name);
  std::set<std::string> names;
  for (const auto& t : doc) {
    std::string name = t.at("name");
    CHECK(names.insert(name).second);
    CHECK(t.at("default_catalogue").get<bool>() == (defaults.count(name) == 1));
    CHECK(!t.at("description").get<std::string>().empty());
    TableSpec spec = CatalogueTable(name);
    CHECK(t.at("params") == nlohmann::json(spec.params));
    REQUIRE(t.at("axes").size() == spec.axes.size());
    for (size_t i = 0; i < spec.axes.size(); ++i) {
      CHECK(t.at("axes")[i].at("name") == spec.axes[i].name);
      CHECK(t.at("axes")[i].at("lo").get<double>() == spec.axes[i].lo);
      CHECK(t.at("axes")[i].at("hi").get<double>() == spec.axes[i].hi);
      CHECK(t.at("axes")[i].at("size").get<int>() == spec.axes[i].size);
    }
  }
  for (const std::string& name : defaults) CHECK(names.count(name) == 1);
  auto refused = RunKilnFor(60, "list --json");
  CHECK(IsCleanRefusal(refused));
}
