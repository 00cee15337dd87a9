// The fit error an ltc table in the overlap form declares (ltc-charlie-smith: the grid fit measures
// it with its own lobe samples and the norm the channel pass's fixed rule gave): the largest of the
// overlap errors at the stored coefficients, as measured from scratch.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "baker/bake/bake.h"
#include "baker/integrate/ltc_fit.h"
#include "baker/tables/catalogue.h"

using namespace kiln;

TEST_CASE("A small ltc-charlie-smith bake declares the largest overlap error of its texels",
          "[ltc]") {
  CatalogueOptions copt;
  copt.size = 7;
  BakeOptions opt;
  opt.threads = 2;
  opt.measureLookupError = false;
  const TableSpec spec = CatalogueTable("ltc-charlie-smith", copt);
  const Table t = BakeTable(spec, opt);
  const int n = spec.axes[0].size, nc = int(spec.channels.size());
  REQUIRE(spec.axes[0].name == "roughness");
  REQUIRE(spec.axes[1].name == "sqrt_one_minus_mu");
  double worst = 0;
  for (int is = 0; is < spec.axes[1].size; ++is)
    for (int ir = 0; ir < n; ++ir) {
      const float* c = &t.data[size_t(ir + n * is) * nc];
      if (c[4] < 1e-3) continue;  // left out (a norm below kLtcMinNorm)
      const double r = spec.axes[0].lo + (spec.axes[0].hi - spec.axes[0].lo) * ir / (n - 1);
      const double s = double(is) / (spec.axes[1].size - 1), mu = 1 - s * s;
      const LtcLobe lobe("charlie-smith", std::max(r, std::sqrt(1e-5)), LtcFitMu(mu));
      const double minv[4] = {c[0], c[1], c[2], c[3]};
      // The norm channel (float) for the fixed rule's double: the error moves by ~1e-7.
      worst = std::max(worst, LtcOverlapError(lobe, c[4], LtcMatrix::FromInverse(minv), 16));
    }
  INFO("declared " << t.fitError.max << ", re-measured " << worst);
  CHECK(t.fitError.max > 0);
  CHECK(t.fitError.max == Approx(worst).margin(1e-5));
}
