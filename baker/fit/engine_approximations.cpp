#include "baker/fit/engine_approximations.h"

#include <algorithm>
#include <cmath>

namespace kiln {
namespace {

float Saturate(float v) { return std::min(std::max(v, 0.0f), 1.0f); }

/// ln(8192): Lazarov's exponent n = 8192^g.
constexpr float kLnLazarovMaxExponent = 9.01091334f;
constexpr float kPiF = 3.14159265f;

}  // namespace

void KarisEnvBrdfApprox(const FitForm&, const float* x, float* out) {
  const float mu = x[0], r = x[1];
  const float rx = r * -1.0f + 1.0f, ry = r * -0.0275f + 0.0425f;
  const float rz = r * -0.572f + 1.04f, rw = r * 0.022f - 0.04f;
  const float a = std::min(rx * rx, std::exp2(-9.28f * mu)) * rx + ry;
  out[0] = -1.04f * a + rz;
  out[1] = 1.04f * a + rw;
}

float LazarovGloss(float roughness) {
  const float r2 = roughness * roughness;
  const float n = 2.0f / (r2 * r2) - 2.0f;  // +inf at r = 0, 0 at r = 1
  if (!(n > 1.0f)) return 0.0f;             // log(n) <= 0 (also catches NaN)
  return std::min(std::log(n) / kLnLazarovMaxExponent, 1.0f);
}

void LazarovEnvironmentBrdf(const FitForm&, const float* x, float* out) {
  const float mu = x[0], g = LazarovGloss(x[1]);
  const float tx = g * (1.0f / 0.96f), ty = g * 0.475f;
  const float tz = g * ((0.0275f - 0.25f * 0.04f) / 0.96f) + (0.015f - 0.75f * 0.04f) / 0.96f;
  const float tw = g * 0.25f + 0.75f;
  const float a0 = tx * std::min(ty, std::exp2(-9.28f * mu)) + tz;
  const float b = Saturate(a0);
  out[0] = Saturate(tw) - b;
  out[1] = b;
}

void ThreeSheenAlbedo(const FitForm&, const float* x, float* out) {
  const float mu = x[0], r = x[1], r2 = r * r, q = 1.0f / (r + 0.1f);
  const float a = -1.9362f + 1.0678f * r + 0.4573f * r2 - 0.8469f * q;
  const float b = -0.6014f + 0.5538f * r - 0.4670f * r2 - 0.1255f * q;
  out[0] = Saturate(std::exp(a * mu + b));
}

void ThreeSheenAlbedoFormer(const FitForm&, const float* x, float* out) {
  const float mu = x[0], r = x[1], r2 = r * r;
  const bool low = r < 0.25f;
  const float a = low ? -339.2f * r2 + 161.4f * r - 25.9f : -8.48f * r2 + 14.3f * r - 9.95f;
  const float b = low ? 44.0f * r2 - 23.7f * r + 3.26f : 1.97f * r2 - 3.27f * r + 0.72f;
  const float dg = std::exp(a * mu + b) + (low ? 0.0f : 0.1f * (r - 0.25f));
  out[0] = kPiF * Saturate(dg * (1.0f / kPiF));
}

void ThreeDfgLutLookup(const FitForm&, const float* x, float* out) {
  constexpr int kSize = 16;
  auto coord = [](float t, int& i, float& f) {
    const float p = std::min(std::max(t * kSize - 0.5f, 0.0f), kSize - 1.0f);
    i = std::min(static_cast<int>(p), kSize - 2);
    f = p - static_cast<float>(i);
  };
  int r0, c0;
  float fr, fc;
  coord(x[0], r0, fr);  // v = mu: the row
  coord(x[1], c0, fc);  // u = roughness: the column
  const auto& t = kThreeDfgLut;
  for (int k = 0; k < 2; ++k) {
    const float a = t[r0][c0][k] + fc * (t[r0][c0 + 1][k] - t[r0][c0][k]);
    const float b = t[r0 + 1][c0][k] + fc * (t[r0 + 1][c0 + 1][k] - t[r0 + 1][c0][k]);
    out[k] = a + fr * (b - a);
  }
}

FitForm ProbeForm(const TableSpec& spec, FitWarp muWarp, FitWarp roughnessWarp) {
  FitForm form = Skeleton(spec);
  for (FitAxis& f : form.axes) {
    f.degree = 1;
    f.warp = f.name == "mu" ? muWarp : roughnessWarp;
  }
  return form;
}

FitForm DfgProbeForm(const TableSpec& spec) {
  return ProbeForm(spec, FitWarp::Layer, FitWarp::Sqrt);
}

}  // namespace kiln
