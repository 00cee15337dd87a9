// kiln verify re-measures an ltc table's declared polygon error (QuantityInfo::verifyTable): the
// committed value passes, an understated one fails.
#include <catch2/catch.hpp>

#include <string>

#include "baker/tables/quantity.h"
#include "committed_luts.h"
#include "kiln/exr_loader.h"

using namespace kiln;

TEST_CASE("kiln verify re-measures an ltc table's polygon error", "[verify][ltc]") {
  Table t = loadTable(test::LutsDir() + "/ltc-ggx-1.exr");
  const auto check = Describe(Quantity::Ltc).verifyTable;
  REQUIRE(check != nullptr);
  std::string summary;
  CHECK(check(t, 2, summary).empty());
  INFO(summary);
  CHECK(summary.find("polygon error max") != std::string::npos);
  t.fitError.polygonMax *= 0.9;  // understated
  std::string problem = check(t, 2, summary);
  CHECK(problem.find("EXCEEDS the declared polygon error") != std::string::npos);
}
