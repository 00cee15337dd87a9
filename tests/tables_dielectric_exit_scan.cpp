// The exit glass tables held to their declared lookup bound off the bake's own search (issue
// #15): a dense scan of the lookup (kiln::sampleQuantity, linear, as `kiln sample`) against the
// fixed rule the bake integrates with, where the exit E has its structures: mu graded within
// 0.05 of mu = eta' (E_T's one-sided point at high roughness) and of the critical cosine mu_c,
// eta' between the nodes and around 1 / sqrt 2 (where the two cross and the mu warp's breaks
// swap), roughness 0.8 .. 1 and a few lower. [long]: it bakes both tables (~1 minute of CPU).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "baker/integrate/dielectric_albedo.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"

using namespace kiln;

TEST_CASE("the exit glass tables stay within their declared lookup bound on a dense scan",
          "[long][dielectric-exit-scan]") {
  const std::string dir = test::TempDir("exit_scan");
  const test::CommandResult bake = test::RunKiln(
      "bake --only ggx-dielectric-albedo-r-exit,ggx-dielectric-albedo-t-exit -j 2 "
      "--out " +
      dir);
  INFO(bake.err);
  REQUIRE(bake.exitCode == 0);
  const Table tables[2] = {loadTable(dir + "/ggx-dielectric-albedo-r-exit.exr"),
                           loadTable(dir + "/ggx-dielectric-albedo-t-exit.exr")};
  const double lo = 1.0 / 3, hi = 1.0 / 1.1;
  std::vector<double> etas = {lo, hi};
  for (int i = 0; i < 47; ++i) etas.push_back(lo + (hi - lo) * (i + 0.37) / 47.0);
  for (double d : {-3e-3, -1e-3, -3e-4, -1e-4, 0.0, 1e-4, 3e-4, 1e-3, 3e-3})
    etas.push_back(std::sqrt(0.5) + d);
  const double rs[] = {0.8, 0.83, 0.87, 0.9, 0.93, 0.95, 0.97, 0.985, 0.995, 1.0, 0.3, 0.55, 0.7};
  double worst[2] = {0, 0};
  long points = 0;
  for (double eta : etas) {
    const double muc = std::sqrt(1 - eta * eta);
    std::vector<double> mus;
    for (int k = -20; k <= 20; ++k) {
      const double d = 0.05 * std::copysign(std::pow(std::fabs(k) / 20.0, 2), k);
      mus.push_back(eta + d);
      mus.push_back(muc + d);
    }
    for (int k = 0; k <= 24; ++k) mus.push_back(std::pow((k + 0.5) / 25.0, 2));
    for (double r : rs)
      for (double mu : mus) {
        if (!(mu >= 0 && mu <= 1)) continue;
        const std::array<double, 2> e = FixedRuleDielectricAlbedo(mu, std::max(r * r, 1e-12), eta);
        const double p[3] = {mu, r, eta};
        for (int c = 0; c < 2; ++c) {
          double got = 0;
          sampleQuantity(tables[c], p, &got);
          worst[c] = std::max(worst[c], std::fabs(got - e[c]));
        }
        ++points;
      }
  }
  for (int c = 0; c < 2; ++c) {
    INFO(tables[c].name << ": " << points << " points, max |lookup - fixed rule| " << worst[c]
                        << ", declared " << tables[c].lookupError.max);
    CHECK(worst[c] <= tables[c].lookupError.max);
    CHECK(tables[c].lookupError.max < 9.5e-4);
  }
  std::filesystem::remove_all(dir);
}
