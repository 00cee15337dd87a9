// The physical checks of an average albedo, shared by the stress test at the roughness edges and
// the rule tests that compute the same adaptive averages (tests/stress_integrals.cpp says which).
#pragma once
#include <catch2/catch.hpp>

#include <cmath>

#include "baker/models/registry.h"

namespace kiln::test {

/// How far above 1 an energy-conserving model's adaptive E_avg may lie (its quadrature error).
constexpr double kAverageEnergyTol = 1e-6;

/// E_avg = lin + quad of model m: finite, non-negative where m is nonNegative, at most
/// 1 + kAverageEnergyTol where m is energyConserving.
inline void CheckAverageAlbedoPhysical(const ModelInfo& m, double total) {
  CHECK(std::isfinite(total));
  if (m.nonNegative) CHECK(total >= 0);
  if (m.energyConserving) CHECK(total <= 1 + kAverageEnergyTol);
}

}  // namespace kiln::test
