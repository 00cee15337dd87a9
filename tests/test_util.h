// Helpers the specification tests share: deterministic sampling and numerical references.
#pragma once
#include <cstdint>
#include <string>

#include "baker/integrate/quantities.h"
#include "baker/math/quadrature.h"

namespace kiln::test {

/// A fixed-seed generator (SplitMix64) so every test sees the same points on every run.
struct Rng {
  uint64_t state;
  explicit Rng(uint64_t seed) : state(seed) {}
  double Uniform() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (z >> 11) * (1.0 / 9007199254740992.0);
  }
};

/// E(mu) at rho = 1 (lin + quad) of model `id` at roughness r, F = 1.
inline double Albedo(const std::string& id, double mu, double r, double tol = 1e-10) {
  ModelParams p;
  if (FindModel(id)->params.front().name == "roughness") p.roughness = r;
  IntegrationOptions opt;
  opt.tol = tol;
  IntegrationStats stats;
  RhoParts e = DirectionalAlbedo(MakeModel(id, p), mu, opt, stats);
  return e.lin + e.quad;
}

inline bool TakesRoughness(const ModelInfo& m) {
  for (const ParamInfo& p : m.params)
    if (p.name == "roughness") return true;
  return false;
}

}  // namespace kiln::test
