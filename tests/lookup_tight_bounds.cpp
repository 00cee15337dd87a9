// A declared lookup bound is within a small factor of what it bounds: where the search's
// verification-grade reference lies further from the bake's rule than the error it found, the
// bake searches again with its own rule (bake.cpp, MeasureLookupError).
#include <catch2/catch.hpp>

#include <string>

#include "baker/bake/lookup_error.h"
#include "committed_luts.h"
#include "kiln/exr_loader.h"

using namespace kiln;

TEST_CASE("The smooth averages declare at most 4x the lookup error the bake's rule finds",
          "[lookup][tight-bounds]") {
  for (const char* name :
       {"shirley-albedo-avg", "ashikhmin-shirley-diffuse-albedo-avg", "burley-albedo-avg"}) {
    Table t = loadTable(test::LutsDir() + "/" + name + ".exr");
    TableSpec spec = SpecFromTable(t);
    LookupSearchOptions opt;
    opt.threads = 2;
    opt.bakeRule = true;
    LookupErrorReport rep = MeasureLookupError(spec, t.view(), opt);
    INFO(name << ": declared " << t.lookupError.max << ", found " << rep.max);
    CHECK(rep.referenceError == 0);
    CHECK(rep.max <= t.lookupError.max);
    CHECK(t.lookupError.max <= 4 * rep.max);
  }
}
