// Unity's three Standard-shader specular lobes against their formulas in UnityStandardBRDF.cginc,
// written out here from the shader's lines (not by calling the model), at a few directions.
#include <catch2/catch.hpp>
#include <cmath>

#include "baker/models/registry.h"

using namespace kiln;

namespace {

AnyModel Unity(const char* id, double r) {
  ModelParams p;
  p.roughness = r;
  return MakeModel(id, p);
}

struct Dirs {
  Vec3 v, l;
};

// View and light pairs: normal, off-specular, grazing, back-scatter.
const Dirs kDirs[] = {{ViewDirection(1.0), DirectionFromMuPhi(1.0, 0)},
                      {ViewDirection(0.8), DirectionFromMuPhi(0.7, Pi * 0.9)},
                      {ViewDirection(0.3), DirectionFromMuPhi(0.5, 2.0)},
                      {ViewDirection(0.15), DirectionFromMuPhi(0.2, 0.3)}};

double Dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 SafeNormalizeSum(Vec3 a, Vec3 b) {
  Vec3 s{a.x + b.x, a.y + b.y, a.z + b.z};
  double k = 1 / std::sqrt(std::max(0.001, Dot3(s, s)));
  return {k * s.x, k * s.y, k * s.z};
}

}  // namespace

TEST_CASE("unity-brdf1 is GGXTerm * SmithJointGGXVisibilityTerm (approximate) of the shader",
          "[models][unity]") {
  for (double r : {0.0, 0.1, 0.4, 0.8, 1.0})
    for (const Dirs& d : kDirs) {
      Vec3 h = SafeNormalizeSum(d.l, d.v);
      double nv = d.v.z, nl = d.l.z, nh = std::min(1.0, h.z);
      double a = std::max(r * r, 0.002);  // roughness = max(PerceptualRoughnessToRoughness, 0.002)
      double lambdaV = nl * (nv * (1 - a) + a), lambdaL = nv * (nl * (1 - a) + a);
      double V = 0.5 / (lambdaV + lambdaL + 1e-5);
      double a2 = a * a, dd = (nh * a2 - nh) * nh + 1;
      double D = (1 / Pi) * a2 / (dd * dd + 1e-7);
      double shader = V * D * Pi;  // specularTerm, F applied later; physical f = specularTerm / pi
      INFO("r=" << r << " mu_o=" << nv << " mu_l=" << nl);
      CHECK(Evaluate(Unity("unity-brdf1", r), d.v, d.l) == Approx(shader / Pi).epsilon(1e-13));
    }
}

TEST_CASE("unity-brdf1 multiplies Schlick's FresnelTerm(specColor, LdotH) when f0 is given",
          "[models][unity]") {
  ModelParams p;
  p.roughness = 0.5;
  p.f0 = 0.04;
  const Dirs& d = kDirs[2];
  Vec3 h = SafeNormalizeSum(d.l, d.v);
  double lh = Dot3(d.l, h), F = 0.04 + 0.96 * std::pow(1 - lh, 5);
  CHECK(Evaluate(MakeModel("unity-brdf1", p), d.v, d.l) ==
        Approx(F * Evaluate(Unity("unity-brdf1", 0.5), d.v, d.l)).epsilon(1e-13));
}

TEST_CASE("unity-brdf2 is the shader's GGX * 1/(LdotH^2 (roughness + 0.5)) term over pi",
          "[models][unity]") {
  for (double r : {0.0, 0.1, 0.4, 0.8, 1.0})
    for (const Dirs& d : kDirs) {
      Vec3 h = SafeNormalizeSum(d.l, d.v);
      double nh = std::min(1.0, h.z), lh = Dot3(d.l, h);
      double a = r * r, a2 = a * a;
      double dd = nh * nh * (a2 - 1.f) + 1.00001;
      double specularTerm = a2 / (std::max(0.1, lh * lh) * (a + 0.5) * (dd * dd) * 4);
      INFO("r=" << r << " mu_o=" << d.v.z << " mu_l=" << d.l.z);
      CHECK(Evaluate(Unity("unity-brdf2", r), d.v, d.l) ==
            Approx(specularTerm / Pi).epsilon(1e-13).margin(1e-300));
    }
}

TEST_CASE("unity-brdf3 reads 16 x the NHxRoughness texel at (R.L)^4 with R = reflect(v, n)",
          "[models][unity]") {
  for (double r : {0.0, 0.2, 0.5, 1.0})
    for (const Dirs& d : kDirs) {
      // reflect(viewDir, normal) = v - 2 (n.v) n
      Vec3 R{d.v.x, d.v.y, d.v.z - 2 * d.v.z};
      double rl = Dot3(R, d.l), rlPow4 = rl * rl * rl * rl;
      // PerceptualRoughnessToSpecPower, then the Phong exponent n / 4 and (n + 2)/(2 pi^2) (R.L)^n
      double m = r * r, sq = std::max(1e-4, m * m), nBlinn = std::max(2.0 / sq - 2.0, 1e-4);
      double n = nBlinn * 0.25;
      double specular = (n + 2.0) / (2.0 * Pi * Pi) * std::pow(std::abs(rl), n);
      double texel = std::min(1.0, specular / 16);
      INFO("r=" << r << " mu_o=" << d.v.z << " mu_l=" << d.l.z << " rlPow4=" << rlPow4);
      CHECK(UnityNHxRoughnessTexel(rlPow4, r) == Approx(texel).epsilon(1e-12).margin(1e-300));
      CHECK(Evaluate(Unity("unity-brdf3", r), d.v, d.l) ==
            Approx(16 * texel / Pi).epsilon(1e-12).margin(1e-300));
    }
}

TEST_CASE("unity-brdf3's texel saturates at 1 where (n + 2)/(2 pi^2) exceeds 16",
          "[models][unity]") {
  CHECK(UnityNHxRoughnessTexel(1.0, 0.0) == 1.0);  // n = 4999.5: 2.5e2 > 16
  CHECK(UnityNHxRoughnessTexel(1.0, 1.0) == Approx(2.0 / (2 * Pi * Pi) / 16).epsilon(1e-4));
  CHECK(UnityNHxRoughnessTexel(0.0, 0.5) == 0.0);
}

TEST_CASE("Unity's models are zero below the horizon and finite at r = 0", "[models][unity]") {
  for (const char* id : {"unity-brdf1", "unity-brdf2", "unity-brdf3"}) {
    CHECK(Evaluate(Unity(id, 0.5), ViewDirection(0.5), DirectionFromMuPhi(-0.1, 1)) == 0);
    double f = Evaluate(Unity(id, 0.0), ViewDirection(1), DirectionFromMuPhi(1, 0));
    INFO(id << " f at r = 0, normal incidence: " << f);
    CHECK(std::isfinite(f));
  }
  // BRDF2's a^2 numerator: no specular at all at r = 0.
  CHECK(Evaluate(Unity("unity-brdf2", 0.0), ViewDirection(1), DirectionFromMuPhi(1, 0)) == 0);
}
