// kiln list: every model id with its parameters, or (--tables) every table kiln can bake; with
// --model-source / --model-library a user's lobe and its tables too.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "baker/cli/commands.h"
#include "baker/custom/custom_registry.h"
#include "baker/scene/plan_report.h"
#include "baker/scene/scene_json.h"
#include "baker/tables/catalogue.h"

namespace kiln::cli {
namespace {

void PrintModels() {
  std::vector<ModelInfo> all(AllModels().begin(), AllModels().end());
  all.insert(all.end(), AllBsdfModels().begin(), AllBsdfModels().end());
  for (const ModelInfo& m : all) {
    std::string line = m.id;
    for (const ParamInfo& p : m.params)
      line += " " + p.name + "=" + FullPrecision(p.def) + "[" + FullPrecision(p.lo) + "," +
              FullPrecision(p.hi) + "]";
    line += "  # " + std::string(m.bsdf ? "BSDF (reflection + transmission): " : "") + m.summary +
            "; roughness: " + m.roughness;
    std::printf("%s\n", line.c_str());
  }
}

}  // namespace

std::vector<ListedTable> AllListedTables() {
  std::vector<ListedTable> out;
  std::set<std::string> seen;
  for (const TableSpec& s : DefaultCatalogue())
    if (seen.insert(s.name).second) out.push_back({s, true});
  for (const TableSpec& s : OnRequestTables())
    if (seen.insert(s.name).second) out.push_back({s, false});
  for (const std::string& id : CustomModelIds()) {  // loaded by --model-source / --model-library
    std::vector<std::string> names = {id + "-albedo", id + "-albedo-avg"};
    if (FindModel(id)->specular()) names.push_back(id + "-dfg");
    for (const std::string& name : names)
      if (seen.insert(name).second) out.push_back({CatalogueTable(name), false, true});
  }
  return out;
}

std::string FormatTableList(const std::vector<ListedTable>& tables, bool json) {
  if (json) {
    nlohmann::json doc = nlohmann::json::array();
    for (const ListedTable& t : tables) {
      nlohmann::json axes = nlohmann::json::array();
      for (const AxisSpec& a : t.spec.axes)
        axes.push_back({{"name", a.name},
                        {"lo", a.lo},
                        {"hi", a.hi},
                        {"size", a.size},
                        {"warp", warpName(a.warp)}});
      const QuantityInfo& q = Describe(t.spec.quantity);
      doc.push_back({{"name", t.spec.name},
                     {"model", t.spec.model},
                     {"quantity", q.name},
                     {"channels", t.spec.channels},
                     {"axes", axes},
                     {"params", t.spec.params},
                     {"default_catalogue", t.inDefaultCatalogue},
                     {"custom_model", t.customModel},
                     {"method", t.spec.Method()},
                     {"description", q.description}});
    }
    return doc.dump(2) + "\n";
  }
  std::string out;
  for (const ListedTable& t : tables) {
    const QuantityInfo& q = Describe(t.spec.quantity);
    std::string fixed;  // the model parameters the table is baked at (a *-brdf's roughness)
    for (const auto& [name, value] : t.spec.params)
      fixed += (fixed.empty() ? " at " : ", ") + name + " = " + ExactNumber(value);
    // A user's lobe's table: baked by adaptive quadrature, the method says so (and the hash).
    const std::string method = t.customModel ? "; method: " + t.spec.Method() : "";
    out += t.spec.name + "  [" + (t.inDefaultCatalogue ? "default" : "on request") + "]  " +
           AxesText(t.spec) + fixed + "  # " + q.description + method + "\n";
  }
  return out;
}

void RegisterList(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "list", "print every model id with its parameters, or (--tables) every table kiln bakes");
  struct Args {
    bool models = false, tables = false, json = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_flag("--models", args->models,
                "list the models (the default): built-in ones, then any loaded by "
                "--model-source / --model-library");
  sub->add_flag("--tables", args->tables,
                "list the tables instead: name, default catalogue or on request, axes (range, "
                "nodes, warp), meaning");
  sub->add_flag("--json", args->json, "with --tables: one JSON array on stdout");
  sub->callback([args] {
    if (args->json && !args->tables)
      throw std::invalid_argument("list: --json applies to --tables");
    if (args->models && args->tables)
      throw std::invalid_argument("list: give --models or --tables, not both");
    if (!args->tables) return PrintModels();
    std::fputs(FormatTableList(AllListedTables(), args->json).c_str(), stdout);
  });
}

}  // namespace kiln::cli
