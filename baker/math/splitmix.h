// SplitMix64 (Steele, Lea & Flood 2014): a small fixed-seed stream of uniform doubles for
// reproducible random points.
#pragma once
#include <cstdint>

namespace kiln {

/// The golden-ratio increment of SplitMix64's state, 2^64 / phi rounded to odd.
constexpr uint64_t kSplitMixIncrement = 0x9E3779B97F4A7C15ull;

/// Advances `state` by one SplitMix64 step and returns its output's top 53 bits as a double
/// in [0, 1), multiples of 2^-53.
inline double SplitMixUniform(uint64_t& state) {
  uint64_t z = (state += kSplitMixIncrement);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (z >> 11) * 0x1p-53;
}

}  // namespace kiln
