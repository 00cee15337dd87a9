// Why ltc-charlie declared a fit L1 above 2 with the self-normalised estimate, and that the
// overlap form (LtcOverlapError) it declares now is a stable measurement (README "LTC tables").
// [long]: bakes the full 64 x 64 sheen tables (~2 s each); run with
//   build/tests/kiln_tests "[ltc-sheen-norm]" -s
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "baker/bake/bake.h"
#include "baker/integrate/ltc_fit.h"
#include "baker/tables/catalogue.h"

using namespace kiln;

TEST_CASE("A sheen table's proposal norm falls short, the overlap L1 is stable and at most 2",
          "[long][ltc][ltc-sheen-norm]") {
  for (const char* name : {"ltc-charlie", "ltc-charlie-smith"}) {
    BakeOptions opt;
    opt.threads = 2;
    opt.measureLookupError = false;
    Table t = BakeTable(CatalogueTable(name), opt);
    TableSpec spec = SpecFromTable(t);
    const size_t nc = t.channels.size();
    double worstShort = 0, worstSpread = 0, worstL1 = 0, shortR = 0, shortMu = 0;
    for (size_t i = 0; i < spec.TexelCount(); ++i) {
      if (t.data[i * nc + 4] < 1e-3) continue;  // left out of the declared error
      double x[3];
      NodeCoordinates(spec, i, x);
      double r = x[0], mu = LtcFitMu(1 - x[1] * x[1]);
      LtcLobe lobe(spec.model, r, mu);
      // The norm the self-normalised estimate took: the proposal's 16 x 16 samples.
      double n16;
      Vec3 dir;
      LtcLobeMoments(lobe, 16, &n16, &dir);
      const double norm = t.data[i * nc + 4];  // the fixed rule's (charlie-smith: at mu)
      const double c[4] = {t.data[i * nc], t.data[i * nc + 1], t.data[i * nc + 2],
                           t.data[i * nc + 3]};
      LtcMatrix m = LtcMatrix::FromInverse(c);
      double l16 = LtcOverlapError(lobe, norm, m, 16), l64 = LtcOverlapError(lobe, norm, m, 64);
      if (1 - n16 / norm > worstShort) {
        worstShort = 1 - n16 / norm;
        shortR = r;
        shortMu = mu;
      }
      worstSpread = std::max(worstSpread, std::fabs(l16 - l64));
      worstL1 = std::max(worstL1, l16);
      CHECK(l16 <= 2);
      CHECK(l64 <= 2);
    }
    std::printf(
        "%s: proposal norm short by up to %.0f %% (r %.3f mu %.4f); overlap L1 max %.4f, "
        "|16x16 - 64x64| up to %.4f\n",
        name, 100 * worstShort, shortR, shortMu, worstL1, worstSpread);
    // Even with the horizon density the proposal's 16 x 16 norm falls short by up to ~25 % (it
    // fell short by 100 % without it: no sample on the lobe at r = 0.045, N.V = 0.24): a
    // self-normalised L1 exceeds 2 there, the cause of ltc-charlie's old 2.48.
    CHECK(worstShort > 0.1);
    // The declared 16 x 16 measure's sampling spread (verify re-measures the same 16 x 16).
    CHECK(worstSpread < 0.1);
  }
}
