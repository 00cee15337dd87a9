// The Chebyshev coefficients of Fresnel's reflectance on the entering side (derivation and
// measured error in dielectric_fresnel_moments.h).
#include "baker/integrate/dielectric_fresnel_moments.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <unordered_map>

#include "baker/models/fresnel.h"

namespace kiln {
namespace dielectric_moments {
namespace {

/// Chebyshev points of the interpolation (the first kind: x_j = cos(pi (j + 1/2) / kSamples)).
constexpr int kSamples = 64;
/// Most etas remembered (the bake's axes hold 40; the lookup-error search's points add more).
constexpr size_t kMaxRemembered = 1 << 16;

struct Basis {
  double x[kSamples];
  double cosTable[kTerms][kSamples];  ///< T_k(x_j) = cos(pi k (j + 1/2) / kSamples)
};

const Basis& BasisOf() {
  static const Basis b = [] {
    Basis r;
    const double pi = std::acos(-1.0);
    for (int j = 0; j < kSamples; ++j) {
      r.x[j] = std::cos(pi * (j + 0.5) / kSamples);
      for (int k = 0; k < kTerms; ++k) r.cosTable[k][j] = std::cos(pi * k * (j + 0.5) / kSamples);
    }
    return r;
  }();
  return b;
}

Coefficients Fit(double eta) {
  const Basis& b = BasisOf();
  double f[kSamples];
  for (int j = 0; j < kSamples; ++j) f[j] = FrDielectric((b.x[j] + 1) / 2, eta);
  Coefficients co;
  for (int k = 0; k < kTerms; ++k) {
    double s = 0;
    for (int j = 0; j < kSamples; ++j) s = s + f[j] * b.cosTable[k][j];
    co.a[k] = s * (k == 0 ? 1.0 : 2.0) / kSamples;
  }
  return co;
}

}  // namespace

const Coefficients& FresnelChebyshev(double eta) {
  static std::mutex mutex;
  static std::unordered_map<std::uint64_t, Coefficients> memo;
  static thread_local Coefficients spare;
  std::uint64_t key;
  std::memcpy(&key, &eta, sizeof key);
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = memo.find(key);
    if (it != memo.end()) return it->second;  // entries are never erased: the reference stays
  }
  const Coefficients co = Fit(eta);
  std::lock_guard<std::mutex> lock(mutex);
  if (memo.size() >= kMaxRemembered) {
    spare = co;
    return spare;
  }
  return memo.emplace(key, co).first->second;
}

double EvaluateSeries(const Coefficients& co, double c) {
  const double x = 2 * c - 1;
  double t0 = 1, t1 = x, s = co.a[0] + co.a[1] * x;
  for (int k = 2; k < kTerms; ++k) {
    const double t2 = (x + x) * t1 - t0;
    s = s + co.a[k] * t2;
    t0 = t1;
    t1 = t2;
  }
  return s;
}

}  // namespace dielectric_moments
}  // namespace kiln
