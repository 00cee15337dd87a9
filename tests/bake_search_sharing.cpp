// A microfacet albedo derived from its dfg in the same run reads the references its dfg's
// lookup-error search evaluated where the two searches' points coincide (SearchMemo,
// QuantityInfo::searchDerivesFromSource): fewer evaluations, the same declared report as a
// search of its own.
#include <catch2/catch.hpp>

#include "baker/bake/bake.h"
#include "baker/tables/catalogue.h"
#include "test_bake_cache.h"

using namespace kiln;

TEST_CASE("A microfacet albedo's search reuses its dfg's references and declares the same bound",
          "[bake][derived][search-sharing]") {
  for (const std::string& model : CatalogueMicrofacetModels()) {
    INFO(model);
    const TableSpec dfg = test::SmallSpec(Quantity::Dfg, model),
                    albedo = test::SmallSpec(Quantity::Albedo, model);
    BakeOptions opt;
    opt.threads = 2;
    // The albedo alone: a search of its own.
    BakeStats ownStats;
    Table own = BakeTable(albedo, opt, &ownStats);
    CHECK(ownStats.lookupReused == 0);
    // After its dfg, in one run: the dfg's search references are kept and read.
    NodeValueCache cache({dfg, albedo});
    NodeValues* keep = cache.KeepFor(dfg);
    REQUIRE(keep != nullptr);
    REQUIRE(keep->keepSearchMemo);
    BakeTable(dfg, opt, nullptr, nullptr, keep);
    REQUIRE(keep->searchMemo != nullptr);
    CHECK(keep->searchMemo->size() > 0);
    BakeStats sharedStats;
    Table shared = BakeTable(albedo, opt, &sharedStats, cache.SourceFor(albedo));
    CHECK(sharedStats.lookupReused > 0);
    CHECK(sharedStats.lookupReused <= sharedStats.lookupPoints);
    CHECK(sharedStats.lookupPoints == ownStats.lookupPoints);
    // The same search, so the same declaration, to the bit.
    CHECK(shared.lookupError.max == own.lookupError.max);
    CHECK(shared.lookupError.rms == own.lookupError.rms);
    CHECK(shared.lookupError.cubicMax == own.lookupError.cubicMax);
    CHECK(shared.lookupError.cubicRms == own.lookupError.cubicRms);
    CHECK(shared.lookupError.where == own.lookupError.where);
  }
}

TEST_CASE("A table no search reads keeps no search references", "[bake][search-sharing]") {
  const TableSpec dfg = test::SmallSpec(Quantity::Dfg, "ggx");
  NodeValueCache alone({dfg});
  CHECK(alone.KeepFor(dfg) == nullptr);
  // A sheen albedo copies its cloth dfg's report (sharesSourceLookupError): nothing to read.
  const TableSpec cloth = test::SmallSpec(Quantity::Dfg, CatalogueSheenModels().front()),
                  sheen = test::SmallSpec(Quantity::Albedo, CatalogueSheenModels().front());
  NodeValueCache withSheen({cloth, sheen});
  REQUIRE(withSheen.KeepFor(cloth) != nullptr);
  CHECK_FALSE(withSheen.KeepFor(cloth)->keepSearchMemo);
}
