// The median of timed rounds, as the benchmarks quote them.
#pragma once
#include <algorithm>
#include <vector>

namespace kiln {

/// The median of xs: the middle value, the mean of the middle two for an even count, 0 for none.
inline double Median(std::vector<double> xs) {
  if (xs.empty()) return 0;
  std::sort(xs.begin(), xs.end());
  const size_t n = xs.size();
  return n % 2 ? xs[n / 2] : (xs[n / 2 - 1] + xs[n / 2]) / 2;
}

}  // namespace kiln
