// The glass walks' two paths in a test: the same call by the AVX-512F lanes and by the portable
// code (dielectric_simd::SetEnabled), for tests that hold the two to the same bits.
#pragma once
#include <utility>

#include "baker/integrate/dielectric_simd.h"

namespace kiln::test {

/// Runs f with the AVX-512F paths on, then off, and restores them; returns {on, off}.
template <class F>
auto BothPaths(F&& f) {
  dielectric_simd::SetEnabled(true);
  auto on = f();
  dielectric_simd::SetEnabled(false);
  auto off = f();
  dielectric_simd::SetEnabled(true);
  return std::make_pair(on, off);
}

}  // namespace kiln::test
