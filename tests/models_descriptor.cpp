// The model descriptor is the one place per model: no model id is compared as a string under
// baker/, a model's fixed rule is the one its descriptor names (never chosen by what the model
// is not), and a model registered at run time is found, built and baked like a built-in one.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "baker/bake/bake.h"
#include "baker/integrate/quantities.h"
#include "baker/models/registry.h"
#include "baker/tables/quantity.h"
#include "baker/tables/spec.h"

using namespace kiln;

namespace {

/// The registered ids: every BRDF and BSDF model.
std::vector<std::string> RegisteredIds() {
  std::vector<std::string> ids;
  for (const ModelInfo& m : AllModels()) ids.push_back(m.id);
  for (const ModelInfo& m : AllBsdfModels()) ids.push_back(m.id);
  return ids;
}

/// `id` inside a regular expression.
std::string Escaped(const std::string& id) {
  return std::regex_replace(id, std::regex(R"([-.])"), R"(\$&)");
}

/// "path:line: text" of every comparison of a string with model id `id` in `text`: == / != on
/// either side, .compare("id"), strcmp(..., "id").
std::vector<std::string> ComparisonsWith(const std::string& path, const std::string& text,
                                         const std::string& id) {
  // Every form below holds the quoted id: a text without it has none, and skips the regex
  // (std::regex is slow to build and to run: once per file and id, the scan took seconds).
  if (text.find("\"" + id + "\"") == std::string::npos) return {};
  const std::string q = "\"" + Escaped(id) + "\"";
  const std::regex re("(==|!=)\\s*" + q + "|" + q + "\\s*(==|!=)|compare\\(\\s*" + q +
                      "|strn?cmp\\([^;]*" + q);
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it) {
    const auto at = text.begin() + it->position();
    out.push_back(path + ":" + std::to_string(1 + std::count(text.begin(), at, '\n')) + ": " +
                  it->str());
  }
  return out;
}

/// A plain Phong lobe about the mirror direction (Lafortune's value type) under an id of its
/// own, with no fixed rule: what a user adds to try a lobe.
ModelInfo PhongWithoutRule(const std::string& id) {
  ModelInfo m;
  m.id = id;
  m.summary = "test: normalised Phong lobe, no fixed rule";
  m.roughness = "n = (2 / alpha^2 - 2) / 4, alpha = max(r^2, 0.01)";
  m.params = {{"roughness", 0, 1, 0.5, "perceptual roughness r"},
              {"rs", 0, 1, 1, "specular reflectance R_s"}};
  m.reciprocal = m.energyConserving = m.nonNegative = true;
  m.domain = IntegrationDomain::Light;  // light space, like the diffuse models
  m.make = [](const ModelArgs& a) -> AnyModel { return LafortuneBRDF::Phong(a.roughness, a.rs); };
  m.rule = RuleFamily::None;
  return m;
}

/// Registers a model for one test and removes it again.
struct Registered {
  explicit Registered(ModelInfo m) : id(m.id) { RegisterModel(std::move(m)); }
  ~Registered() { UnregisterModel(id); }
  std::string id;
};

}  // namespace

TEST_CASE("no string under baker/ is compared with a model id", "[models][descriptor]") {
  const std::filesystem::path root = std::filesystem::path(KILN_SOURCE_DIR) / "baker";
  std::vector<std::string> found;
  size_t files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h" && ext != ".inc")) continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    ++files;
    for (const std::string& id : RegisteredIds())
      for (const std::string& hit :
           ComparisonsWith(e.path().lexically_relative(root).string(), text.str(), id))
        found.push_back(hit);
  }
  CHECK(files > 50);
  CHECK(RegisteredIds().size() >= 34);
  INFO("resolve the id once (FindModel) and ask the descriptor instead");
  for (const std::string& hit : found) UNSCOPED_INFO(hit);
  CHECK(found.empty());
}

TEST_CASE("the scan finds each form of a comparison with a model id", "[models][descriptor]") {
  CHECK(ComparisonsWith("a", "if (model == \"ggx\") x;", "ggx").size() == 1);
  CHECK(ComparisonsWith("a", "if (m != \"ward-duer\")", "ward-duer").size() == 1);
  CHECK(ComparisonsWith("a", "\"charlie\" ==\n    model", "charlie").size() == 1);
  CHECK(ComparisonsWith("a", "id.compare(\"lambert\")", "lambert").size() == 1);
  CHECK(ComparisonsWith("a", "std::strcmp(e.name, \"ggx\")", "ggx").size() == 1);
  CHECK(ComparisonsWith("a", "m.id = \"ggx\"; MakeModel(\"ggx\", p);", "ggx").empty());
  CHECK(ComparisonsWith("a", "x == \"ggx-separable\"", "ggx").empty());
}

TEST_CASE("every built-in model states its rule family and has a factory", "[models][descriptor]") {
  for (const ModelInfo& m : AllModels()) {
    INFO(m.id);
    CHECK(m.make);
    CHECK(FindModel(m.id) == &m);
    // A fixed rule of a family is named only by models of its integration domain.
    if (m.rule == RuleFamily::Microfacet || m.rule == RuleFamily::Ward) CHECK(m.specular());
    if (m.rule == RuleFamily::Diffuse || m.rule == RuleFamily::Sheen ||
        m.rule == RuleFamily::MirrorLobe)
      CHECK_FALSE(m.specular());
    if (m.catalogue == CatalogueGroup::Diffuse) CHECK(m.rule == RuleFamily::Diffuse);
    if (m.catalogue == CatalogueGroup::Microfacet) CHECK(m.rule == RuleFamily::Microfacet);
    if (m.catalogue == CatalogueGroup::Sheen) CHECK(m.rule == RuleFamily::Sheen);
  }
}

TEST_CASE("a model with no rule family is baked by adaptive quadrature, not the diffuse rule",
          "[models][descriptor]") {
  Registered phong(PhongWithoutRule("test-phong-no-rule"));
  REQUIRE(FindModel("test-phong-no-rule"));
  const QuantityInfo& albedo = Describe(Quantity::Albedo);
  // A 2 x 2 table whose first texel is at mu = 0.510, r = 0.317.
  TableSpec spec = albedo.makeSpec(
      "test-phong-no-rule",
      {{"mu", 0.510, 1, 2, Warp::Linear}, {"roughness", 0.317, 1, 2, Warp::Linear}});
  spec.tol = 1e-9;
  CHECK_FALSE(UsesFixedRule(spec));
  CHECK(spec.Method().rfind("light space: adaptive Gauss-Kronrod", 0) == 0);
  CHECK(spec.Method().find("fixed") == std::string::npos);

  BakeOptions opt;
  opt.threads = 1;
  opt.measureLookupError = false;
  Table t = BakeTable(spec, opt);
  REQUIRE(t.data.size() == 4);
  CHECK(t.method == spec.Method());

  IntegrationOptions io;
  io.tol = 1e-11;
  IntegrationStats st;
  ModelParams p;
  p.roughness = 0.317;
  const double e = DirectionalAlbedo(MakeModel("test-phong-no-rule", p), 0.510, io, st).lin;
  CHECK(std::abs(t.data[0] - e) <= 1e-9 + 1e-7 * e);  // the adaptive integral, to float
}

TEST_CASE("RegisterModel refuses a taken id and a descriptor without a factory",
          "[models][descriptor]") {
  ModelInfo taken = PhongWithoutRule("ggx");
  CHECK_THROWS_WITH(RegisterModel(taken), Catch::Contains("'ggx' exists already"));
  ModelInfo bsdf = PhongWithoutRule("ggx-dielectric");
  CHECK_THROWS_WITH(RegisterModel(bsdf), Catch::Contains("exists already"));
  ModelInfo noFactory = PhongWithoutRule("test-no-factory");
  noFactory.make = nullptr;
  CHECK_THROWS_WITH(RegisterModel(noFactory), Catch::Contains("has no factory"));
  CHECK_FALSE(FindModel("test-no-factory"));
  {
    Registered r(PhongWithoutRule("test-listed"));
    CHECK(AllModels().back().id == "test-listed");
    CHECK(std::holds_alternative<LafortuneBRDF>(MakeModel("test-listed", {})));
  }
  CHECK_FALSE(FindModel("test-listed"));
  CHECK_FALSE(UnregisterModel("ggx"));  // built-in models stay
}
