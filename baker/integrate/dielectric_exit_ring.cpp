// The exit walk's ring on any CPU (dielectric_simd.h, PortableRingSums): FastRingSums of
// dielectric_simd_exit.cpp one node at a time, with its operations and its order, so both paths
// give the same bits. Each fused multiply-add is std::fma (correctly rounded, in hardware or in
// glibc's software, on every x86-64), every other operation an IEEE add, mul, div or sqrt
// (compiled with -ffp-contract=off: no product is fused unless written so); min and max as the
// vector path's selects; node j goes to lane j mod 8 of partial sum (j mod 16) / 8 (a ring's last
// eight nodes or fewer to the first), and the sums are reduced as FastRingSums reduces them.
// The body is compiled twice on x86-64: for the baseline (std::fma a call into libm) and with
// the FMA instructions (std::fma one instruction, where the CPU has them): the same bits, the
// second about 3x faster.
#include <atomic>
#include <cmath>

#include "baker/integrate/dielectric_simd.h"

namespace kiln {
namespace dielectric_simd {
namespace {

#if defined(__x86_64__) && defined(__GNUC__)
#define KILN_RING_FMA_CLONE 1
#endif
#define KILN_RING_INLINE inline __attribute__((always_inline))

/// The lanes of one vector of partial sums.
constexpr int kLanes = 8;

/// CosHalfTurnFused of dielectric_simd_exit.cpp: dielectric_walk::CosHalfTurn's series (cos phi
/// = -sin(phi - pi/2) to x^21), its Horner steps fused.
KILN_RING_INLINE double CosHalfTurnFused(double phi) {
  const double x = phi - 1.5707963267948966, x2 = x * x;
  const double* k = kCosHalfTurnSeries;
  double p = k[0];
  p = std::fma(p, x2, k[1]);
  p = std::fma(p, x2, k[2]);
  p = std::fma(p, x2, k[3]);
  p = std::fma(p, x2, k[4]);
  p = std::fma(p, x2, k[5]);
  p = std::fma(p, x2, k[6]);
  p = std::fma(p, x2, k[7]);
  p = std::fma(p, x2, k[8]);
  p = std::fma(p, x2, k[9]);
  p = std::fma(p, x2, k[10]);
  return -x * p;
}

/// A FastRing's constants as dielectric_simd_exit.cpp's ConstsOf makes them.
struct Consts {
  double A, B, cosM, invCosM, mu, invEta, eta2, eta2p1, eta2m1, e2m1sq, a2, gDen;
};

KILN_RING_INLINE Consts ConstsOf(const FastRing& r) {
  return {r.A,    r.B,        r.cosM,   1 / r.cosM,          r.mu, r.invEta,
          r.eta2, r.eta2 + 1, r.eta2m1, r.eta2m1 * r.eta2m1, r.a2, r.gDen};
}

/// std::max(0, x) as MAXPD(x, 0): (x > 0) ? x : 0.
KILN_RING_INLINE double MaxZero(double x) { return x > 0 ? x : 0.0; }
/// std::min(c, 1) as MINPD(1, c): (1 < c) ? 1 : c.
KILN_RING_INLINE double MinOneOf(double c) { return 1 < c ? 1.0 : c; }
/// std::min(1, x) as MINPD(x, 1): (x < 1) ? x : 1 (1 for a NaN x, as the vector path's).
KILN_RING_INLINE double MinWithOne(double x) { return x < 1 ? x : 1.0; }

/// Weigh of dielectric_simd_exit.cpp: wb f p / (gDen p + mu a2 s_i^2), p = 2 mu_i (sqrt(mu_i^2
/// + a2 s_i^2) + mu_i), s_i^2 = max(0, 1 - mu_i^2).
KILN_RING_INLINE double Weigh(double wb, double mi, double f, const Consts& q) {
  const double a2s2 = q.a2 * MaxZero(std::fma(-mi, mi, 1.0));
  const double p = (mi + mi) * (std::sqrt(std::fma(mi, mi, a2s2)) + mi);
  return (wb * f) * p / std::fma(q.gDen, p, q.mu * a2s2);
}

/// The weighted terms {R, T} of node (phi, w), added to *accR, *accT where they count (AddTerms
/// of dielectric_simd_exit.cpp, one lane).
KILN_RING_INLINE void AddTerms(const Consts& q, bool reflectOnly, double phi, double w,
                               double* accR, double* accT) {
  const double c = std::fma(q.B, CosHalfTurnFused(phi), q.A);
  if (!(c > 0)) return;
  const double wb = w * (c * q.invCosM), cc = MinOneOf(c);
  const double g2 = std::fma(cc, cc, q.eta2m1);
  const bool gok = g2 > 0;
  const double g = gok ? std::sqrt(g2) : 0.0;
  double F = 1;
  if (gok) {
    const double a = cc + g, b = std::fma(q.eta2, cc, g);
    const double aa = a * a, bb = b * b;
    const double x = std::fma(q.eta2p1 * cc, cc, -1.0);
    const double a4 = aa * aa, b4 = bb * bb;
    F = MinWithOne(q.e2m1sq * std::fma(x * x, a4, b4) / ((a4 + a4) * b4));
  }
  const double muR = std::fma(c + c, q.cosM, -q.mu);
  if (muR > 0 && F > 0) *accR = *accR + Weigh(wb, muR, F, q);
  if (reflectOnly) return;
  const double muT = std::fma(-(cc - g), q.cosM, q.mu) * q.invEta;
  if (F < 1 && muT > 0) *accT = *accT + Weigh(wb, muT, 1 - F, q);
}

/// PortableRingSums' body (inlined into each of its compiled forms).
KILN_RING_INLINE void RingSums(const FastRing& r, const double* phi, const double* w, int J,
                               double* sumR, double* sumT) {
  const Consts q = ConstsOf(r);
  // Two vectors of partial sums, as FastRingSums keeps them.
  double accR[2][kLanes] = {}, accT[2][kLanes] = {};
  int j = 0;
  for (; J - j > kLanes; j += 2 * kLanes)
    for (int k = j; k < j + 2 * kLanes && k < J; ++k) {
      const int u = (k - j) / kLanes, l = (k - j) % kLanes;
      AddTerms(q, r.reflectOnly, phi[k], w[k], &accR[u][l], &accT[u][l]);
    }
  for (int k = j; k < J; ++k)
    AddTerms(q, r.reflectOnly, phi[k], w[k], &accR[0][k - j], &accT[0][k - j]);
  // LaneSum of dielectric_simd_exit.cpp after the two vectors' lane-wise sum.
  auto laneSum = [](const double(*acc)[kLanes]) {
    double l[kLanes];
    for (int i = 0; i < kLanes; ++i) l[i] = acc[0][i] + acc[1][i];
    return ((l[0] + l[4]) + (l[2] + l[6])) + ((l[1] + l[5]) + (l[3] + l[7]));
  };
  *sumR = laneSum(accR);
  *sumT = laneSum(accT);
}

void RingSumsBaseline(const FastRing& r, const double* phi, const double* w, int J, double* sumR,
                      double* sumT) {
  RingSums(r, phi, w, J, sumR, sumT);
}

#if defined(KILN_RING_FMA_CLONE)
__attribute__((target("fma"))) void RingSumsFma(const FastRing& r, const double* phi,
                                                const double* w, int J, double* sumR,
                                                double* sumT) {
  RingSums(r, phi, w, J, sumR, sumT);
}
#endif

bool CpuHasFma() {
#if defined(KILN_RING_FMA_CLONE)
  return __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

std::atomic<bool>& FmaSwitch() {
  static std::atomic<bool> on{CpuHasFma()};
  return on;
}

}  // namespace

void SetPortableFmaInstructions(bool on) { FmaSwitch().store(on && CpuHasFma()); }

void PortableRingSums(const FastRing& r, const double* phi, const double* w, int J, double* sumR,
                      double* sumT) {
#if defined(KILN_RING_FMA_CLONE)
  if (FmaSwitch().load(std::memory_order_relaxed)) return RingSumsFma(r, phi, w, J, sumR, sumT);
#endif
  RingSumsBaseline(r, phi, w, J, sumR, sumT);
}

}  // namespace dielectric_simd
}  // namespace kiln
