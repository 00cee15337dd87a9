// The glass bake's memo of columns (integrate/dielectric_albedo.cpp, dielectric_albedo_avg.cpp):
// {E_R, E_T} of a column of etas and the evaluations one texel took, by the bits of the
// arguments. Two tables of one family (albedo-r and albedo-t, or r-avg and t-avg) baked in one
// process compute each column once; a hit returns the bits the rule computes (it is
// deterministic) and charges the same evaluations, so files and manifests do not depend on what
// else was baked.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

namespace kiln {

class DielectricColumnMemo {
 public:
  using Key = std::vector<std::uint64_t>;
  struct Value {
    std::vector<std::array<double, 2>> e;
    long long evals = 0;
  };
  /// The key of a column: the bits of (a, b) and of every eta.
  static Key KeyOf(double a, double b, const double* etas, int n) {
    Key k = {Bits(a), Bits(b)};
    for (int e = 0; e < n; ++e) k.push_back(Bits(etas[e]));
    return k;
  }
  bool Find(const Key& k, Value& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = map_.find(k);
    if (it == map_.end()) return false;
    out = it->second;
    return true;
  }
  /// Keeps v under k unless the memo holds kMaxColumns already.
  void Keep(const Key& k, const Value& v) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.size() < kMaxColumns) map_.emplace(k, v);
  }

 private:
  static constexpr size_t kMaxColumns = 1 << 15;  // 32,768 columns
  static std::uint64_t Bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  std::mutex mutex_;
  std::map<Key, Value> map_;
};

}  // namespace kiln
