// The thread count of a -j / --threads request, for every part of kiln that runs threads.
#pragma once
#include <algorithm>
#include <thread>

namespace kiln {

/// Threads for a request: `requested` when positive, else every hardware thread the system
/// reports (at least 1: std::thread::hardware_concurrency may report 0).
inline int ThreadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace kiln
