// The lookup-error search's reference (issue #13): SearchReference evaluates a verification-grade
// form of each fixed rule (QuantityInfo::searchRule: fewer nodes, about half the evaluations).
// These tests hold every such rule within kSearchRuleBound of the bake's own rule on dense grids
// of its domain, corners included (mu = 0, 1e-9, 1; roughness 0 and 1; eta next to 1), and its
// charge (the bake rule's evaluations per search-rule evaluation that the search's budget
// assumes) to the measured ratio, so the search buys at least the points it bought before. The
// bake rules themselves are held to adaptive quadrature by tests/integrate_fixed_rule*.cpp.
// Also: each kind's fixed-rule version is its own part of the spec hash.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "baker/integrate/fixed_rule_dfg.h"
#include "baker/integrate/fixed_rule_diffuse.h"
#include "baker/integrate/fixed_rule_microfacet.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"

using namespace kiln;

namespace {

/// Points of a (mu, roughness) table: mu on a root4 grid with 0, 1e-9 and 1, r from 0 to 1.
std::vector<std::array<double, 2>> MuRoughnessGrid(int nMu, int nR) {
  std::vector<std::array<double, 2>> xs;
  for (int j = 0; j <= nR; ++j)
    for (int i = 0; i <= nMu; ++i) {
      double mu = std::pow(static_cast<double>(i) / nMu, 4);
      if (i == 1) mu = 1e-9;
      xs.push_back({mu, static_cast<double>(j) / nR});
    }
  return xs;
}

/// Worst |search reference - bake rule| (max over channels) of `spec` at `xs`, and the ratio of
/// the bake rule's integrand evaluations to the search rule's own (its charged count / charge).
struct Comparison {
  double worst = 0, maxDeclared = 0;
  long long bakeEvals = 0, searchCharged = 0;
  std::string where;
};

template <class Points>
Comparison Compare(const TableSpec& spec, const Points& xs) {
  Comparison c;
  for (const auto& p : xs) {
    double x[3] = {0, 0, 0};
    std::copy(p.begin(), p.end(), x);
    IntegrationStats bake, search;
    std::vector<double> want = EvaluateSpec(spec, x, bake);
    std::vector<double> got = SearchReference(spec, x, search);
    REQUIRE(got.size() == want.size());
    c.bakeEvals += bake.evals;
    c.searchCharged += search.evals;
    c.maxDeclared = std::max(c.maxDeclared, search.errorEstimate);
    for (size_t k = 0; k < got.size(); ++k)
      if (std::abs(got[k] - want[k]) > c.worst) {
        c.worst = std::abs(got[k] - want[k]);
        char buf[96];
        std::snprintf(buf, sizeof buf, "x = (%g, %g, %g)", x[0], x[1], x[2]);
        c.where = buf;
      }
  }
  return c;
}

/// The catalogue's spec named `name`.
TableSpec CatalogueSpec(const std::string& name) {
  for (const TableSpec& s : DefaultCatalogue({}))
    if (s.name == name) return s;
  FAIL("no catalogue table " << name);
  return {};
}

}  // namespace

TEST_CASE(
    "The search's microfacet rule lies within kSearchRuleBound of the bake's rule over (mu, r), "
    "corners included, at no more than 1 / SearchMicrofacetCharge of its evaluations",
    "[lookup-search][search-reference]") {
  const auto xs = MuRoughnessGrid(48, 40);
  for (const char* name : {"beckmann-dfg", "beckmann-separable-dfg", "blinn-phong-albedo"}) {
    TableSpec spec = CatalogueSpec(name);
    REQUIRE(UsesFixedRule(spec));
    Comparison c = Compare(spec, xs);
    FixedRuleModel model;
    REQUIRE(FixedRuleModelFor(spec.model.c_str(), &model));
    const double charge = SearchMicrofacetCharge(model);
    double ratio =
        static_cast<double>(c.bakeEvals) / (static_cast<double>(c.searchCharged) / charge);
    std::printf("%-24s search rule - bake rule: worst %.2e at %s; bake / search evaluations %.2f\n",
                name, c.worst, c.where.c_str(), ratio);
    CHECK(c.worst <= kSearchRuleBound);
    CHECK(c.maxDeclared == kSearchRuleBound);
    CHECK(ratio >= charge);
  }
}

TEST_CASE(
    "The GGX kernel's dfg rules (ggx, ggx-separable) are their own search reference: the same "
    "values, no added bound, evaluations charged once",
    "[lookup-search][search-reference]") {
  const auto xs = MuRoughnessGrid(24, 20);
  for (const char* name : {"ggx-dfg", "ggx-separable-dfg", "ggx-separable-albedo"}) {
    TableSpec spec = CatalogueSpec(name);
    REQUIRE(UsesFixedRule(spec));
    Comparison c = Compare(spec, xs);
    INFO(name);
    CHECK(c.worst == 0);
    CHECK(c.maxDeclared == 0);
    CHECK(c.searchCharged == c.bakeEvals);
  }
}

TEST_CASE(
    "The search's exact-Fresnel rule lies within kSearchRuleBound of the bake's rule over (mu, r, "
    "eta), eta next to 1 included",
    "[lookup-search][search-reference]") {
  TableSpec spec = CatalogueSpec("ggx-fresnel-albedo");
  REQUIRE(UsesFixedRule(spec));
  // Below kFresnelKernelEtaMin the generic rule (fixed_rule_microfacet.h), from it the GGX
  // kernel's (fixed_rule_dfg.h, the table's whole domain [1.3, 3]): each with its own charge.
  struct Range {
    std::vector<double> etas;
    double charge;
    const char* name;
  };
  const Range ranges[] = {
      {{1.0, 1 + 1e-9, 1 + 1e-6, 1.0001, 1.001, 1.0038, 1.01, 1.03, 1.1, 1.25, 1.2999},
       kSearchFresnelCharge,
       "generic rule, eta < 1.3"},
      {{1.3, 1.33, 1.4, 1.5, 1.65, 1.8, 2.0, 2.3, 2.6, 3.0},
       kSearchFresnelKernelCharge,
       "GGX kernel, eta >= 1.3"}};
  for (const Range& range : ranges) {
    std::vector<std::array<double, 3>> xs;
    for (double eta : range.etas)
      for (const auto& p : MuRoughnessGrid(24, 20)) xs.push_back({p[0], p[1], eta});
    Comparison c = Compare(spec, xs);
    double ratio =
        static_cast<double>(c.bakeEvals) / (static_cast<double>(c.searchCharged) / range.charge);
    std::printf("ggx-fresnel-albedo (%s) search rule - bake rule: worst %.2e at %s; ratio %.2f\n",
                range.name, c.worst, c.where.c_str(), ratio);
    INFO(range.name);
    CHECK(c.worst <= kSearchRuleBound);
    CHECK(c.maxDeclared == kSearchRuleBound);
    CHECK(ratio >= range.charge);
  }
}

TEST_CASE(
    "The search's diffuse rule lies within kSearchRuleBound of the bake's rule for every "
    "catalogue diffuse model over (mu, r)",
    "[lookup-search][search-reference]") {
  const auto xs = MuRoughnessGrid(40, 20);
  for (const std::string& model : CatalogueDiffuseModels()) {
    TableSpec spec = CatalogueSpec(model + "-albedo");
    REQUIRE(UsesFixedRule(spec));
    Comparison c = Compare(spec, xs);
    double ratio = static_cast<double>(c.bakeEvals) /
                   (static_cast<double>(c.searchCharged) / kSearchDiffuseCharge);
    INFO(model << ": worst " << c.worst << " at " << c.where << ", ratio " << ratio);
    CHECK(c.worst <= kSearchRuleBound);
    CHECK(ratio >= kSearchDiffuseCharge);
  }
}

TEST_CASE(
    "The search's form of every catalogue average lies within kSearchRuleBound of the bake's "
    "rule at sampled roughness values, ends included",
    "[lookup-search][search-reference]") {
  std::vector<std::array<double, 1>> rs;
  for (double r : {0.0, 1e-3, 0.02, 0.1, 0.3, 0.6, 0.9, 1.0}) rs.push_back({r});
  for (const TableSpec& spec : DefaultCatalogue({})) {
    if (spec.quantity != Quantity::AlbedoAvg || !UsesFixedRule(spec)) continue;
    // The roughness values within the table's axis (the Charlie pair's from 0.045).
    std::vector<std::array<double, 1>> in;
    for (const auto& r : rs) in.push_back({std::max(r[0], spec.axes[0].lo)});
    Comparison c = Compare(spec, in);
    INFO(spec.name << ": worst " << c.worst << " at " << c.where);
    CHECK(c.worst <= kSearchRuleBound);
    CHECK(c.maxDeclared <= kSearchRuleBound);
  }
  TableSpec f = CatalogueSpec("ggx-fresnel-albedo-avg");
  std::vector<std::array<double, 2>> xs;
  for (double r : {0.0, 0.05, 0.5, 1.0})
    for (double eta : {1.0, 1.001, 1.5, 3.0}) xs.push_back({r, eta});
  Comparison c = Compare(f, xs);
  INFO("ggx-fresnel-albedo-avg: worst " << c.worst << " at " << c.where);
  CHECK(c.worst <= kSearchRuleBound);
}

TEST_CASE(
    "Each table kind's fixed-rule version is its own part of the spec hash (a rule change of one "
    "kind re-bakes its tables only)",
    "[lookup-search][spec-hash]") {
  for (const TableSpec& spec : DefaultCatalogue({})) {
    const std::string text = spec.HashText();
    const QuantityInfo& q = Describe(spec.quantity);
    const std::string tag =
        std::string("|fixed-rule:") +
        (q.fixedRuleVersionOf ? q.fixedRuleVersionOf(spec) : q.fixedRuleVersion);
    INFO(spec.name);
    if (UsesFixedRule(spec))
      CHECK(text.find(tag + "|") != std::string::npos);
    else
      CHECK(text.find("|fixed-rule:") == std::string::npos);
    // Version 3: the GGX kernel's variants (ggx-separable's microfacet kinds, the exact-Fresnel
    // albedo and its average), the sheen rows with the inline exp and log (charlie's dfg and
    // albedo, ashikhmin-velvet's three), the glass exit pair's third revision. Version 4: the
    // Beckmann family's one-exp Lambda and SIMD nodes after fewer nodes (the microfacet kinds of
    // beckmann, beckmann-separable and blinn-phong), charlie-smith's inline sheen rows after its
    // own node counts (ltc-charlie-smith's version is the ltc kind's "fit4o-rule3"), the Charlie
    // average after its own panels; the glass entering tables' (E_R, E_T, the BTDF split sum)
    // own fourth revision. The rest keep the hashes of before.
    const bool microfacetKind = spec.name.find("-dfg") != std::string::npos ||
                                spec.name.find("-albedo") != std::string::npos;
    const bool beckmannFamily = spec.model == "beckmann" || spec.model == "beckmann-separable" ||
                                spec.model == "blinn-phong";
    const bool version4 =
        (beckmannFamily && microfacetKind) ||
        (spec.model == "charlie-smith" && spec.quantity != Quantity::Ltc) ||
        spec.name == "charlie-albedo-avg" || spec.name == "ggx-dielectric-albedo-r" ||
        spec.name == "ggx-dielectric-albedo-t" || spec.name == "ggx-dielectric-btdf-split-sum";
    const bool version3 =
        (spec.model == "ggx-separable" && microfacetKind) || spec.name == "ggx-fresnel-albedo" ||
        spec.name == "ggx-fresnel-albedo-avg" ||
        ((spec.model == "charlie" || spec.model == "ashikhmin-velvet") && microfacetKind &&
         spec.name != "charlie-albedo-avg") ||
        spec.name == "ggx-dielectric-albedo-r-exit" || spec.name == "ggx-dielectric-albedo-t-exit";
    CHECK((text.find("|fixed-rule:3|") != std::string::npos) == version3);
    CHECK((text.find("|fixed-rule:4|") != std::string::npos) == version4);
  }
}
