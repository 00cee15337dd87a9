// The runtime's polygon-light integral against an LTC (runtime/include/kiln/ltc.h): the clamped
// cosine's form factor with the identity, the horizon clip, the winding, the world frame, and
// fitted LTCs against direct integration of the BRDF over polygons (baker/integrate/ltc_fit.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "baker/integrate/ltc_fit.h"
#include "kiln/ltc.h"

using namespace kiln;

namespace {

/// norm * E of the LTC with stored coefficients c over polygon p (two-sided), in the view frame.
double LtcIntegral(const double c[4], const std::vector<Vec3>& p) {
  double minv[9], pts[kLtcMaxVertices][3];
  ltcLocalInverse(LtcInverse{c[0], c[1], c[2], c[3]}, minv);
  for (size_t i = 0; i < p.size(); ++i) {
    pts[i][0] = p[i].x;
    pts[i][1] = p[i].y;
    pts[i][2] = p[i].z;
  }
  return ltcPolygonIntegral(minv, pts, int(p.size()), true);
}

const double kIdentity[4] = {1, 0, 0, 1};

}  // namespace

TEST_CASE("With M^-1 = I the polygon integral is the clamped cosine's form factor",
          "[ltc][runtime]") {
  LtcLobe lambert("lambert", 0, 1);  // f mu_l = mu_l / pi
  for (const std::vector<Vec3>& p : LtcTestPolygons()) {
    double direct = IntegrateLobeOverPolygon(lambert, p.data(), int(p.size()), 1e-9);
    CHECK(LtcIntegral(kIdentity, p) == Approx(direct).margin(1e-7));
  }
  // The quad covering the hemisphere to 1e-3 rad of the horizon holds all but ~1e-6 of it.
  CHECK(LtcIntegral(kIdentity, LtcTestPolygons()[0]) == Approx(1).margin(1e-5));
}

TEST_CASE("A polygon below the horizon gives 0, one across it is clipped", "[ltc][runtime]") {
  std::vector<Vec3> below = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
  CHECK(LtcIntegral(kIdentity, below) == 0);
  // A quad from the horizon plane's edge up to z = 1 equals its upper half.
  std::vector<Vec3> across = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
  std::vector<Vec3> upper = {{-1, 1, 0}, {1, 1, 0}, {1, 1, 1}, {-1, 1, 1}};
  CHECK(LtcIntegral(kIdentity, across) == Approx(LtcIntegral(kIdentity, upper)).margin(1e-12));
  CHECK(LtcIntegral(kIdentity, across) > 0.05);
}

TEST_CASE("One-sided lights count counter-clockwise polygons only", "[ltc][runtime]") {
  double minv[9];
  ltcLocalInverse(LtcInverse{}, minv);
  const double ccw[4][3] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const double cw[4][3] = {{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1}};
  double e = ltcPolygonIntegral(minv, ccw, 4, false);
  CHECK(e > 0.1);
  CHECK(ltcPolygonIntegral(minv, cw, 4, false) == 0);
  CHECK(ltcPolygonIntegral(minv, cw, 4, true) == Approx(e).epsilon(1e-12));
  CHECK(ltcPolygonIntegral(minv, ccw, 2, true) == 0);  // a bad count
}

TEST_CASE("The world-frame inverse equals the shading-frame one for a rotated scene",
          "[ltc][runtime]") {
  const LtcInverse t{0.6, -0.2, 0.5, 0.3};
  // Shading frame: n = z, v in the xz plane. World: the same rotated by 90 degrees about x.
  const double n[3] = {0, -1, 0}, v[3] = {0.6, -0.8, 0};  // rotated (0,0,1) and (0.6,0,0.8)
  double world[9], local[9];
  ltcWorldInverse(t, n, v, world);
  ltcLocalInverse(t, local);
  const double p[4][3] = {{-1, -0.3, 1}, {0.5, -0.3, 1}, {0.5, 0.4, 1.2}, {-1, 0.4, 1.2}};
  double q[4][3];
  for (int i = 0; i < 4; ++i) {  // rotate (x, y, z) -> (x, -z, y)
    q[i][0] = p[i][0];
    q[i][1] = -p[i][2];
    q[i][2] = p[i][1];
  }
  CHECK(ltcPolygonIntegral(world, q, 4, true) ==
        Approx(ltcPolygonIntegral(local, p, 4, true)).epsilon(1e-12));
}

TEST_CASE("A fitted LTC integrates polygons as the BRDF does, within its fit error",
          "[ltc][runtime]") {
  // |norm E_ltc(P) - integral_P f mu_l| <= norm * integral |f mu_l / norm - D| (L1) for any P.
  struct Case {
    const char* model;
    double r, mu;
  } cases[] = {{"ggx", 0.3, 1.0}, {"ggx", 0.5, 0.7}, {"ggx", 0.8, 0.4}, {"beckmann", 0.4, 0.8}};
  for (const Case& c : cases) {
    LtcLobe lobe(c.model, c.r, c.mu);
    double norm;
    Vec3 dir;
    LtcLobeMoments(lobe, 256, &norm, &dir);
    LtcTexel t = FitLtc(lobe, norm, LtcFrameParams{c.r * c.r, c.r * c.r, 0, dir}, c.mu >= 1);
    double l1 = LtcFitError(lobe, norm, LtcMatrix::FromInverse(t.minv), 1, 64);
    INFO(c.model << " r " << c.r << " mu " << c.mu << " L1 " << l1);
    CHECK(l1 < 0.5);
    for (const std::vector<Vec3>& p : LtcTestPolygons()) {
      double direct = IntegrateLobeOverPolygon(lobe, p.data(), int(p.size()), 1e-7);
      double ltc = norm * LtcIntegral(t.minv, p);
      CHECK(std::fabs(ltc - direct) <= norm * l1 + 1e-3);
    }
  }
}
