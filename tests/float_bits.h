// The bits of a float or a double, for the tests that hold lookups bit for bit.
#pragma once
#include <cstdint>
#include <cstring>

namespace kiln::test {

/// f's IEEE 754 bits (two floats with the same bits are the same float, -0 and NaN payloads
/// told apart).
inline uint32_t Bits(float f) {
  uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

/// x's IEEE 754 bits (the double counterpart of Bits(float)).
inline uint64_t Bits(double x) {
  uint64_t u = 0;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

}  // namespace kiln::test
