// The glass bake's memo of columns (integrate/dielectric_albedo.cpp, dielectric_albedo_avg.cpp):
// {E_R, E_T} of a column of etas and the evaluations one texel took, by the bits of the
// arguments. Two tables of one family (albedo-r and albedo-t, or r-avg and t-avg) baked in one
// process compute each column once; a hit returns the bits the rule computes (it is
// deterministic) and charges the same evaluations, so files and manifests do not depend on what
// else was baked. DielectricChannelMemo: the same for columns whose two channels are computed
// apart (the glass averages: E_avg_R alone for r-avg, E_avg_T alone for t-avg), an entry holding
// the channels computed so far and each one's evaluations.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

namespace kiln {

/// A map by the bits of a column's arguments, under one lock: the part both memos share.
template <class Value>
class DielectricBitsMap {
 public:
  using Key = std::vector<std::uint64_t>;
  /// The key of a column: the bits of (a, b) and of every eta.
  static Key KeyOf(double a, double b, const double* etas, int n) {
    Key k = {Bits(a), Bits(b)};
    for (int e = 0; e < n; ++e) k.push_back(Bits(etas[e]));
    return k;
  }
  /// The entry of k, or false (out untouched).
  bool Find(const Key& k, Value& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = map_.find(k);
    if (it == map_.end()) return false;
    out = it->second;
    return true;
  }

 protected:
  static std::uint64_t Bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  std::mutex mutex_;
  std::map<Key, Value> map_;
};

struct DielectricColumnValue {
  std::vector<std::array<double, 2>> e;
  long long evals = 0;
};

class DielectricColumnMemo : public DielectricBitsMap<DielectricColumnValue> {
 public:
  using Value = DielectricColumnValue;
  /// Keeps v under k unless the memo holds kMaxColumns already.
  void Keep(const Key& k, const Value& v) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.size() < kMaxColumns) map_.emplace(k, v);
  }
  /// out[0 .. n-1] of the column (a, b, etas[0 .. n-1]): the kept one, else what
  /// integrate(e, &evals) writes (n entries; one texel's evaluations), which is then kept. Adds
  /// the column's evaluations to *evals if given.
  template <class Integrate>
  void Column(double a, double b, const double* etas, int n, std::array<double, 2>* out,
              long long* evals, Integrate integrate) {
    const Key key = KeyOf(a, b, etas, n);
    Value v;
    if (!Find(key, v)) {
      v.e.resize(n);
      integrate(v.e.data(), &v.evals);
      Keep(key, v);
    }
    std::copy(v.e.begin(), v.e.end(), out);
    if (evals) *evals += v.evals;
  }

 private:
  static constexpr size_t kMaxColumns = 1 << 15;  // 32,768 columns
};

/// A memo of columns of two independent channels (channel c: bit c of `has`), by the bits of the
/// arguments as DielectricColumnMemo: a lookup finds an entry with the channels it holds, the
/// caller computes the channels it needs and the entry lacks, and Merge adds them. A hit charges
/// the evaluations of the channels it reads, so files and manifests do not depend on what else
/// was baked.
struct DielectricChannelValue {
  std::vector<std::array<double, 2>> e;  ///< channel c meaningful where has & (1 << c)
  long long evals[2] = {0, 0};           ///< one texel's evaluations of each channel
  int has = 0;
};

class DielectricChannelMemo : public DielectricBitsMap<DielectricChannelValue> {
 public:
  using Value = DielectricChannelValue;
  /// At most maxEntries entries; then new keys are not kept.
  explicit DielectricChannelMemo(size_t maxEntries) : max_(maxEntries) {}
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
};

}  // namespace kiln
