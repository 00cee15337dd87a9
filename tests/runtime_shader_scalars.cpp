// Specification: the GLSL and HLSL snippets compute what the C++ runtime computes. Their scalar
// functions (the warps and layer scales that place a lookup, the Fresnel terms and the closed
// forms a stored table adds back) are compiled here as C++ in float, straight from
// runtime/shaders/kiln_lut.glsl and .hlsl (tests/tools/shader_scalars.cpp writes them at build
// time), and evaluated against kiln/lut.h and kiln/stored.h in double at the same inputs rounded
// to float. A transcription slip in a snippet (a sign, a constant, a branch) fails here; the
// tolerances are float rounding (32-bit: GLSL highp, HLSL float), far below the tables' 1e-3:
// 2e-6 on the entering side, 5e-5 where exit indices are among the inputs (at the critical
// cosine, 0.943 for eta' = 1/3, F's square-root kink turns the float rounding of mu^2 + eta^2 - 1,
// ~1e-7, into 1.3e-5 of F and 1.7e-5 of the exit form).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kiln/lut.h"
#include "kiln/stored.h"
#include "shader_scalars_glsl.h"
#include "shader_scalars_hlsl.h"

namespace {

/// One snippet's functions, as the tests call them.
#define KILN_SNIPPET(NAME, NS)                                                                     \
  struct NAME {                                                                                    \
    using Axis = NS::KilnAxis;                                                                     \
    static float Fresnel(float mu, float eta) { return NS::kilnFresnelDielectric(mu, eta); }       \
    static float FresnelAlbedo(float mu, float r, float eta) {                                     \
      return NS::kilnFresnelAlbedoClosedForm(mu, r, eta);                                          \
    }                                                                                              \
    static float DielectricAlbedo(float mu, float r, float eta, bool t) {                          \
      return NS::kilnDielectricAlbedoClosedForm(mu, r, eta, t);                                    \
    }                                                                                              \
    static float DielectricExit(float mu, float r, float eta, bool t) {                            \
      return NS::kilnDielectricExitClosedForm(mu, r, eta, t);                                      \
    }                                                                                              \
    static float BtdfFresnel(float mu, float r, float eta) {                                       \
      return NS::kilnBtdfFresnelClosedForm(mu, r, eta);                                            \
    }                                                                                              \
    static float LayerScale(float x1, Axis a0, Axis a1) { return NS::kilnLayerScale(x1, a0, a1); } \
    static float Warped(float x, Axis a, float c, float split) {                                   \
      return NS::kilnWarped(x, a, c, split);                                                       \
    }                                                                                              \
    static float Coord(float x, Axis a, float c, float split) {                                    \
      return NS::kilnCoord(x, a, c, split);                                                        \
    }                                                                                              \
    static float SplitAt(float x2, Axis a0, Axis a2) { return NS::kilnSplitAt(x2, a0, a2); }       \
  };
KILN_SNIPPET(Glsl, kiln_glsl)
KILN_SNIPPET(Hlsl, kiln_hlsl)
#undef KILN_SNIPPET

/// Inputs of the closed forms: the tables' view cosines, roughnesses and both sides' indices
/// (eta' = 0.707: the critical cosine and mu = eta' cross; 0.943: the critical cosine at 1/3).
const std::vector<float> kMu = {0.0f,  1e-6f, 1e-3f, 0.01f, 0.05f, 0.1f, 0.2f,   0.3f,  0.4f,
                                0.45f, 0.5f,  0.6f,  0.7f,  0.8f,  0.9f, 0.943f, 0.97f, 1.0f};
const std::vector<float> kRoughness = {0.0f, 1e-3f, 0.01f, 0.05f, 0.1f, 0.2f,
                                       0.3f, 0.5f,  0.7f,  0.8f,  0.9f, 1.0f};
const std::vector<float> kEtaEnter = {1.1f, 1.2f, 1.33f, 1.5f, 2.0f, 3.0f};
const std::vector<float> kEtaExit = {1.0f / 3.0f, 0.4f,  0.5f,  0.62f,
                                     0.707f,      0.75f, 0.85f, 1.0f / 1.1f};

std::vector<float> BothSides() {
  std::vector<float> etas = kEtaEnter;
  etas.insert(etas.end(), kEtaExit.begin(), kEtaExit.end());
  return etas;
}

/// The largest |shader(mu, r, eta) - runtime(mu, r, eta)| over the inputs (a NaN: infinity).
template <class Shader, class Runtime>
double WorstOver(const std::vector<float>& etas, Shader shader, Runtime runtime) {
  double worst = 0.0;
  for (float eta : etas)
    for (float r : kRoughness)
      for (float mu : kMu) {
        const double d = std::fabs(double(shader(mu, r, eta)) - runtime(mu, r, eta));
        worst = d <= worst ? worst : (std::isnan(d) ? INFINITY : d);
      }
  return worst;
}

}  // namespace

TEMPLATE_TEST_CASE("The snippets' closed forms equal the C++ runtime's to float rounding",
                   "[runtime][shaders]", Glsl, Hlsl) {
  SECTION("kilnFresnelDielectric is kiln::dielectricFresnel, entering and exit") {
    CHECK(WorstOver(
              BothSides(), [](float mu, float, float eta) { return TestType::Fresnel(mu, eta); },
              [](double mu, double, double eta) { return kiln::dielectricFresnel(mu, eta); }) <
          5e-5);
  }
  SECTION("kilnFresnelAlbedoClosedForm is kiln::fresnelAlbedoClosedForm") {
    CHECK(WorstOver(kEtaEnter, TestType::FresnelAlbedo, kiln::fresnelAlbedoClosedForm) < 2e-6);
  }
  SECTION("kilnBtdfFresnelClosedForm is kiln::btdfFresnelClosedForm") {
    CHECK(WorstOver(kEtaEnter, TestType::BtdfFresnel, kiln::btdfFresnelClosedForm) < 2e-6);
  }
  for (bool transmit : {false, true}) {
    INFO((transmit ? "E_T" : "E_R"));
    SECTION("kilnDielectricAlbedoClosedForm is kiln::dielectricAlbedoClosedForm") {
      CHECK(WorstOver(
                BothSides(),
                [&](float mu, float r, float eta) {
                  return TestType::DielectricAlbedo(mu, r, eta, transmit);
                },
                [&](double mu, double r, double eta) {
                  return kiln::dielectricAlbedoClosedForm(mu, r, eta, transmit);
                }) < 5e-5);
    }
    SECTION("kilnDielectricExitClosedForm is kiln::dielectricExitClosedForm") {
      CHECK(WorstOver(
                kEtaExit,
                [&](float mu, float r, float eta) {
                  return TestType::DielectricExit(mu, r, eta, transmit);
                },
                [&](double mu, double r, double eta) {
                  return kiln::dielectricExitClosedForm(mu, r, eta, transmit);
                }) < 5e-5);
    }
  }
}

/// How far a's warped coordinate moves when x and the split move by a few float roundings
/// (4e-7): the warps with a layer (root4 pieces: slope ~ d^(-3/4) at a distance d from a layer
/// end) are that ill-conditioned in any float code, the snippets' included.
double FloatSpread(const kiln::Axis& a, double x, double c, double split) {
  const double t = a.warped(x, c, split), d = 4e-7;
  double spread = 0.0;
  for (double dx : {-d, d})
    for (double ds : {-d, 0.0, d})
      spread = std::max(spread, std::fabs(a.warped(x + dx, c, split + ds) - t));
  return spread;
}

TEMPLATE_TEST_CASE("The snippets place a lookup where kiln/lut.h does, for every warp",
                   "[runtime][shaders]", Glsl, Hlsl) {
  using kiln::Warp;
  using Axis = typename TestType::Axis;
  for (Warp warp : {Warp::Linear, Warp::Sqrt, Warp::Square, Warp::Log, Warp::Root4,
                    Warp::Root4Layer, Warp::Angle, Warp::LayerEta, Warp::Root4LayerSplit,
                    Warp::Root4LayerAngle, Warp::Root4LayerSplit2, Warp::Arcsine}) {
    // Axis 0 over mu (33 nodes: (N - 1) % 32 == 0 for root4-layer-split2), axis 1 the roughness
    // (or eta for layer-eta), axis 2 the exit side's eta' (the split warps read it).
    const kiln::Axis a0{warp == Warp::Log ? 0.01 : 0.0, 1.0, 33, warp};
    const kiln::Axis a1 = warp == Warp::LayerEta ? kiln::Axis{1.0, 3.0, 24, Warp::Sqrt}
                                                 : kiln::Axis{0.0, 1.0, 24, Warp::Sqrt};
    const kiln::Axis a2{1.0 / 3.0, 1.0 / 1.1, 41, Warp::Angle};
    const Axis s0{float(a0.lo), float(a0.hi), float(a0.size), int(a0.warp)};
    const Axis s1{float(a1.lo), float(a1.hi), float(a1.size), int(a1.warp)};
    const Axis s2{float(a2.lo), float(a2.hi), float(a2.size), int(a2.warp)};
    for (float x2 : {0.2f, 1.0f / 3.0f, 0.5f, 0.7f, 0.70710678f, 0.72f, 0.8f, 1.0f / 1.1f, 1.2f}) {
      // The split argument as kiln::LutView::splitAt computes it (x2 already float).
      double split = 0.5;
      if (warp == Warp::Root4LayerSplit)
        split = kiln::criticalSplit(a0.lo, a0.hi, a2.lo, a2.hi, x2);
      if (warp == Warp::Root4LayerSplit2) split = kiln::clampedEta(a2.lo, a2.hi, x2);
      const float splitShader = TestType::SplitAt(x2, s0, s2);
      CHECK(std::fabs(splitShader - split) < 1e-6);
      for (float x1 : {0.0f, 1e-4f, 0.01f, 0.3f, 1.0f, 1.0001f, 1.1f, 2.0f, 3.0f}) {
        const double c = kiln::layerScaleFor(warp, a1.lo, a1.hi, x1);
        const float cs = TestType::LayerScale(x1, s0, s1);
        INFO("warp " << kiln::warpName(warp) << ", axis 1 at " << x1 << ", axis 2 at " << x2);
        if (kiln::isRoughnessLayerWarp(warp) || warp == Warp::LayerEta)
          CHECK(std::fabs(cs - c) <= 1e-6 * c);
        for (float x : {-0.5f, 0.0f,    1e-9f, 1e-6f, 1e-3f, 0.01f,  0.1f,  0.3f,    0.45f, 0.5f,
                        0.7f,  0.7071f, 0.72f, 0.77f, 0.9f,  0.943f, 0.99f, 0.9999f, 1.0f,  1.5f}) {
          INFO("x " << x);
          const double tol = 2e-6 + FloatSpread(a0, x, c, split);
          CHECK(std::fabs(TestType::Warped(x, s0, cs, splitShader) - a0.warped(x, c, split)) < tol);
          CHECK(std::fabs(TestType::Coord(x, s0, cs, splitShader) - a0.gpuCoord(x, c, split)) <
                tol);
        }
      }
    }
  }
}
