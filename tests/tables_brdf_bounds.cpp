// The shipped oren-nayar-brdf, gotanda-ggx-brdf and blinn-phong-normalization tables (luts/)
// are within 1e-3 of direct evaluation over their whole domain with linear filtering, in the
// units the file declares (its stored channels, kiln/stored.h), and what `kiln sample` prints
// for them is the quantity itself (f, the normalization factor) on the physical coordinates.
// The scan is dense and not the bake's own points: 10^5 points uniform in texel space, 10^5
// uniform in the physical parameters, and the neighbourhoods of the kinks (cos(phi) = 0, the
// diagonal mu_l = mu_o) and of every corner and edge of the domain.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "baker/models/registry.h"
#include "baker/tables/catalogue.h"
#include "baker/tables/spec.h"
#include "cli_util.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"
#include "test_util.h"

using namespace kiln;
using kiln::test::CommandResult;
using kiln::test::RunKiln;

namespace {

struct Scan {
  double max = 0;  ///< max over channels and points of |lookup - exact|, stored units
  std::string where;
  long long points = 0;
};

std::string PointText(const double* p, int dims) {
  std::ostringstream s;
  s.precision(6);
  for (int d = 0; d < dims; ++d) s << (d ? " " : "") << p[d];
  return s.str();
}

/// Compares the linear lookup of `table` at table coordinates x with its spec's exact channels.
void CheckAt(const Table& table, const TableSpec& spec, const double* x, Scan& scan) {
  IntegrationStats st;
  std::vector<double> exact = EvaluateSpec(spec, x, st);
  std::vector<float> got(table.channels.size());
  table.view().sample(x, got.data());
  for (size_t c = 0; c < got.size(); ++c) {
    double e = std::abs(got[c] - exact[c]);
    if (e > scan.max) {
      scan.max = e;
      scan.where = "table coordinates " + PointText(x, table.dims());
    }
  }
  ++scan.points;
}

/// True when the physical brdf point p = (mu_l, mu_o, phi) lies in the table's domain (its
/// lookup is not clamped).
bool InBrdfDomain(const Table& table, const double* p) {
  const Axis& a0 = table.axes[0].axis;
  const Axis& a1 = table.axes[1].axis;
  if (storedForm(table) == StoredForm::BrdfSymmetric) {
    double hi = std::max(p[0], p[1]), lo = std::min(p[0], p[1]);
    return hi >= a0.lo && hi <= a0.hi && lo >= a1.lo * hi;
  }
  return p[0] >= a0.lo && p[0] <= a0.hi && p[1] >= a1.lo && p[1] <= a1.hi;
}

/// The dense scan of a table (any stored form, the plain form of files before issue #12 too).
Scan DenseScan(const Table& table) {
  const TableSpec spec = SpecFromTable(table);
  const int dims = table.dims();
  Scan scan;
  test::Rng rng(2024);
  // 1. Uniform in texel space: every cell alike.
  for (int i = 0; i < 100000; ++i) {
    double t[3] = {rng.Uniform(), rng.Uniform(), rng.Uniform()}, x[3];
    PointAtWarped(spec, t, x);
    CheckAt(table, spec, x, scan);
  }
  // 2. The first and last two cells of every axis, the others uniform.
  for (int i = 0; i < 30000; ++i) {
    double t[3] = {rng.Uniform(), rng.Uniform(), rng.Uniform()}, x[3];
    int d = i % dims;
    double edge = 2.0 / std::max(1, table.size(d) - 1) * rng.Uniform();
    t[d] = (i / dims) % 2 ? edge : 1 - edge;
    PointAtWarped(spec, t, x);
    CheckAt(table, spec, x, scan);
  }
  if (table.quantity != "brdf") return scan;
  // 3. Physical points (mu_l, mu_o, phi): uniform, near cos(phi) = 0, near the diagonal, near
  // the horizon and the normal, through the table's own coordinates (kiln/stored.h).
  const StoredForm form = storedForm(table);
  for (int i = 0; i < 100000; ++i) {
    double p[3] = {rng.Uniform(), rng.Uniform(), Pi * rng.Uniform()};
    switch (i % 5) {
      case 1:
        p[2] = Pi / 2 + 0.04 * (rng.Uniform() - 0.5);
        break;
      case 2:
        p[1] = std::clamp(p[0] + 2e-3 * (rng.Uniform() - 0.5), 0.0, 1.0);
        break;
      case 3:
        p[0] = 0.06 * rng.Uniform();
        p[1] = 0.06 * rng.Uniform();
        break;
      case 4:
        p[0] = 1 - 0.02 * rng.Uniform();
        p[1] = (i / 5) % 2 ? 1 - 0.02 * rng.Uniform() : rng.Uniform();
        break;
      default:
        break;
    }
    if (!InBrdfDomain(table, p)) continue;
    double x[3];
    storedCoordinates(form, p, x, 3);
    CheckAt(table, spec, x, scan);
  }
  return scan;
}

Table Shipped(const std::string& name) {
  return loadTable(std::string(KILN_SOURCE_DIR) + "/luts/" + name + ".exr");
}

/// f of `model` at rho (lin + quad parts) at roughness r, view mu_o, light (mu_l, phi).
double ModelF(const std::string& model, double r, double rho, double mu_l, double mu_o,
              double phi) {
  ModelParams mp;
  mp.roughness = r;
  RhoParts e =
      EvaluateParts(MakeModel(model, mp), ViewDirection(mu_o), DirectionFromMuPhi(mu_l, phi));
  return e.At(rho);
}

}  // namespace

TEST_CASE("The shipped brdf and Blinn-Phong tables are the catalogue's, below 1e-3 everywhere",
          "[tables][brdf]") {
  for (const char* name : {"oren-nayar-brdf", "gotanda-ggx-brdf", "blinn-phong-normalization"}) {
    Table table = Shipped(name);
    INFO(name);
    // The file is the current catalogue entry (not a stale bake), so the scan tests the spec.
    CHECK(SpecFromTable(table).Hash() == CatalogueTable(name).Hash());
    CHECK(table.specHash == CatalogueTable(name).Hash());
    Scan scan = DenseScan(table);
    INFO("dense scan: max " << scan.max << " at " << scan.where << " over " << scan.points
                            << " points; declared " << table.lookupError.max);
    CHECK(scan.points >= 130000);
    CHECK(scan.max < 1e-3);
    CHECK(table.lookupError.filter == "linear");
    CHECK(table.lookupError.max < 1e-3);
    CHECK(table.size(0) * table.size(1) * table.size(2) <= 32768);
  }
}

TEST_CASE("The brdf tables say what they store: f on cos(phi), or f max(mu_l, mu_o)",
          "[tables][brdf]") {
  Table on = Shipped("oren-nayar-brdf");
  CHECK(storedForm(on) == StoredForm::BrdfSymmetric);
  CHECK(on.channels == std::vector<std::string>{"g_rho", "g_rho2"});
  CHECK(on.channelMeanings[0].find("max(mu_l, mu_o)") != std::string::npos);
  Table gg = Shipped("gotanda-ggx-brdf");
  CHECK(storedForm(gg) == StoredForm::BrdfCosPhi);
  CHECK(gg.channels == std::vector<std::string>{"f"});
  Table bp = Shipped("blinn-phong-normalization");
  CHECK(storedForm(bp) == StoredForm::BlinnPhongRatio);
  CHECK(bp.channelMeanings[0].find("(s + 2) / (8 pi)") != std::string::npos);
  // A file in the form before issue #12 (f on mu_l, mu_o, phi) is read as plain.
  CHECK(storedFormOf("brdf", "mu_l", "phi", "f_rho") == StoredForm::Plain);
}

TEST_CASE("sampleQuantity turns the stored channels back into f and N(s)", "[tables][brdf]") {
  // Oren-Nayar: f = g / mu_max, so the lookup error in f is the stored one over mu_max; the
  // shipped table keeps it below 1e-3 down to mu_max = 0.02.
  Table on = Shipped("oren-nayar-brdf");
  Table gg = Shipped("gotanda-ggx-brdf");
  test::Rng rng(7);
  double worstOn = 0, worstGg = 0;
  for (int i = 0; i < 20000; ++i) {
    double p[3] = {0.02 + 0.98 * rng.Uniform(), 0.02 + 0.98 * rng.Uniform(), Pi * rng.Uniform()};
    if (i % 2) p[0] = 0.02 + 0.05 * rng.Uniform();
    double out[2];
    sampleQuantity(on, p, out);
    double rho = 0.7;
    worstOn = std::max(worstOn, std::abs(rho * out[0] + rho * rho * out[1] -
                                         ModelF("oren-nayar", 0.5, rho, p[0], p[1], p[2])));
    sampleQuantity(gg, p, out);
    worstGg = std::max(worstGg, std::abs(out[0] - ModelF("gotanda-ggx", 0.5, 1, p[0], p[1], p[2])));
  }
  INFO("worst |f - model| oren-nayar " << worstOn << ", gotanda-ggx " << worstGg);
  CHECK(worstOn < 1e-3);
  CHECK(worstGg < 1e-3);
  Table bp = Shipped("blinn-phong-normalization");
  double worstRel = 0;
  for (int i = 0; i <= 4000; ++i) {
    double s = std::pow(10.0, 4.0 * i / 4000), out[2];
    sampleQuantity(bp, &s, out);
    double exact = (s + 2) / (4 * Pi * (2 - std::exp2(-s / 2))), approx = (s + 2.04) / (8 * Pi);
    worstRel = std::max({worstRel, std::abs(out[0] / exact - 1), std::abs(out[1] / approx - 1)});
  }
  INFO("worst relative error of N(s) " << worstRel);
  CHECK(worstRel < 1e-5);
}

TEST_CASE("kiln sample takes mu_l mu_o phi of a brdf table and prints f itself",
          "[tables][brdf][cli]") {
  const std::string luts = std::string(KILN_SOURCE_DIR) + "/luts/";
  const double points[][3] = {{0.3, 0.7, 1.0}, {0.9, 0.05, 2.5}, {0.05, 0.04, 0.1}};
  for (const auto& p : points) {
    std::ostringstream args;
    args.precision(17);
    args << p[0] << " " << p[1] << " " << p[2];
    CommandResult on = RunKiln("sample " + luts + "oren-nayar-brdf.exr " + args.str());
    REQUIRE(on.exitCode == 0);
    double f_rho = 0, f_rho2 = 0;
    std::istringstream(on.out) >> f_rho >> f_rho2;
    INFO("oren-nayar at " << args.str() << ": kiln sample " << on.out);
    CHECK(std::abs(f_rho + f_rho2 - ModelF("oren-nayar", 0.5, 1, p[0], p[1], p[2])) < 1e-3);
    CommandResult gg = RunKiln("sample " + luts + "gotanda-ggx-brdf.exr " + args.str());
    REQUIRE(gg.exitCode == 0);
    INFO("gotanda-ggx: kiln sample " << gg.out);
    CHECK(std::abs(std::stod(gg.out) - ModelF("gotanda-ggx", 0.5, 1, p[0], p[1], p[2])) < 1e-3);
  }
  CommandResult bp = RunKiln("sample " + luts + "blinn-phong-normalization.exr 5000");
  REQUIRE(bp.exitCode == 0);
  double exact = 0, approx = 0;
  std::istringstream(bp.out) >> exact >> approx;
  CHECK(exact == Approx(5002 / (8 * Pi)).epsilon(1e-6));
  CHECK(approx == Approx(5002.04 / (8 * Pi)).epsilon(1e-6));
}

// Not a CTest case ([long]): the same dense scan of every table in $KILN_SCAN_DIR (e.g. the files
// of an older commit, `git show REV:luts/NAME.exr`), printed; how the README's before/after was
// measured.
TEST_CASE("Dense scan of the tables in KILN_SCAN_DIR", "[.][scan][long]") {
  const char* dir = std::getenv("KILN_SCAN_DIR");
  REQUIRE(dir != nullptr);
  for (const char* name : {"oren-nayar-brdf", "gotanda-ggx-brdf", "blinn-phong-normalization"}) {
    Table table = loadTable(std::string(dir) + "/" + name + ".exr");
    Scan scan = DenseScan(table);
    std::printf("%-26s dense scan max %.3g at %s (%lld points), declared %.3g\n", name, scan.max,
                scan.where.c_str(), scan.points, table.lookupError.max);
  }
}
