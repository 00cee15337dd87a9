// A process-wide memo of two-channel references by the bits of their arguments: the texel
// check's glass references (E_R and E_T, or the two averages, from one integration) integrate a
// point once and serve both table kinds from it.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>

namespace kiln::test {

/// {channel 0, channel 1} by the exact bits of K doubles. Thread-safe; two threads asking for the
/// same new point may both compute it (the first result kept is the one every later call reads).
template <std::size_t K>
class PointMemo {
 public:
  using Value = std::array<double, 2>;

  /// The value kept for `point`, or compute() kept and returned.
  template <class Compute>
  Value Get(const std::array<double, K>& point, Compute&& compute) {
    const Key key = Bits(point);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = memo_.find(key);
      if (it != memo_.end()) return it->second;
    }
    const Value v = compute();
    std::lock_guard<std::mutex> lock(mutex_);
    return memo_.emplace(key, v).first->second;
  }

 private:
  using Key = std::array<std::uint64_t, K>;
  static Key Bits(const std::array<double, K>& point) {
    Key key;
    for (std::size_t i = 0; i < K; ++i) std::memcpy(&key[i], &point[i], sizeof key[i]);
    return key;
  }
  std::mutex mutex_;
  std::map<Key, Value> memo_;
};

}  // namespace kiln::test
