// The glass bake's memo of columns (integrate/dielectric_albedo.cpp, dielectric_albedo_avg.cpp):
// {E_R, E_T} of a column of etas and the evaluations one texel took, by the bits of the
// arguments. Two tables of one family (albedo-r and albedo-t, or r-avg and t-avg) baked in one
// process compute each column once; a hit returns the bits the rule computes (it is
// deterministic) and charges the same evaluations, so files and manifests do not depend on what
// else was baked. DielectricChannelMemo: the same for columns whose two channels are computed
// apart (the glass averages: E_avg_R alone for r-avg, E_avg_T alone for t-avg), an entry holding
// the channels computed so far and each one's evaluations.
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

/// A memo of columns of two independent channels (channel c: bit c of `has`), by the bits of the
/// arguments as DielectricColumnMemo: a lookup finds an entry with the channels it holds, the
/// caller computes the channels it needs and the entry lacks, and Merge adds them. A hit charges
/// the evaluations of the channels it reads, so files and manifests do not depend on what else
/// was baked.
class DielectricChannelMemo {
 public:
  using Key = DielectricColumnMemo::Key;
  struct Value {
    std::vector<std::array<double, 2>> e;  ///< channel c meaningful where has & (1 << c)
    long long evals[2] = {0, 0};           ///< one texel's evaluations of each channel
    int has = 0;
  };
  /// At most maxEntries entries; then new keys are not kept.
  explicit DielectricChannelMemo(size_t maxEntries) : max_(maxEntries) {}
  /// The entry of k, or false (out untouched).
  bool Find(const Key& k, Value& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = map_.find(k);
    if (it == map_.end()) return false;
    out = it->second;
    return true;
  }
  /// Adds the channels of v that the entry of k lacks (v.e holds as many etas as k), creating the
  /// entry unless the memo is full.
  void Merge(const Key& k, const Value& v) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = map_.find(k);
    if (it == map_.end()) {
      if (map_.size() < max_) map_.emplace(k, v);
      return;
    }
    AddChannels(it->second, v);
  }
  /// Copies into `held` the channels of v it lacks (the same number of etas).
  static void AddChannels(Value& held, const Value& v) {
    for (int c = 0; c < 2; ++c) {
      if ((held.has >> c & 1) || !(v.has >> c & 1)) continue;
      for (size_t e = 0; e < held.e.size(); ++e) held.e[e][c] = v.e[e][c];
      held.evals[c] = v.evals[c];
      held.has |= 1 << c;
    }
  }

 private:
  size_t max_;
  std::mutex mutex_;
  std::map<Key, Value> map_;
};

}  // namespace kiln
