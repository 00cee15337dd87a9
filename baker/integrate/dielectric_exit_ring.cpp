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

/// CosRing of dielectric_simd_exit.cpp: cos phi = -x P(x^2), x = phi - pi/2, P by
/// kRingSinSeries in Estrin's scheme, its steps fused.
KILN_RING_INLINE double CosRing(double phi) {
  const double x = phi - 1.5707963267948966, y = x * x;
  const double y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
  const double* k = kRingSinSeries;
  const double e01 = std::fma(k[1], y, k[0]), e23 = std::fma(k[3], y, k[2]);
  const double e45 = std::fma(k[5], y, k[4]), e67 = std::fma(k[7], y, k[6]);
  const double f03 = std::fma(e23, y2, e01), f47 = std::fma(e67, y2, e45);
  return -x * std::fma(k[8], y8, std::fma(f47, y4, f03));
}

/// A FastRing's constants as dielectric_simd_exit.cpp's ConstsOf makes them.
struct Consts {
  double A, B, cosM, mu, muHalf, invEta, eta2, eta2p1, eta2m1, e2m1sq, a2, oneMinusA2, gDen;
};

KILN_RING_INLINE Consts ConstsOf(const FastRing& r) {
  return {r.A,      r.B,      r.cosM,     r.mu,     0.5 * r.mu,
          r.invEta, r.eta2,   r.eta2 + 1, r.eta2m1, r.eta2m1 * r.eta2m1,
          r.a2,     1 - r.a2, r.gDen};
}

/// std::min(c, 1) as MINPD(1, c): (1 < c) ? 1 : c.
KILN_RING_INLINE double MinOneOf(double c) { return 1 < c ? 1.0 : c; }

/// Weigh of dielectric_simd_exit.cpp: wb fn p / (fd (gDen p + mu a2 s_i^2)), p = 2 mu_i
/// (sqrt(X) + mu_i), X = a2 + (1 - a2) mu_i^2, a2 s_i^2 = X - mu_i^2.
KILN_RING_INLINE double Weigh(double wb, double mi, double fn, double fd, const Consts& q) {
  const double mi2 = mi * mi;
  const double X = std::fma(q.oneMinusA2, mi2, q.a2), a2s2 = X - mi2;
  const double h = mi * (std::sqrt(X) + mi);  // p / 2
  return (wb * fn) * h / (fd * std::fma(q.gDen, h, q.muHalf * a2s2));
}

/// The weighted terms {R, T} of node (phi, w), added to *accR, *accT where they count (AddTerms
/// of dielectric_simd_exit.cpp, one lane; complement: R's (1 - F) share, FastRing).
KILN_RING_INLINE void AddTerms(const Consts& q, bool reflectOnly, bool complement, double phi,
                               double w, double* accR, double* accT) {
  const double c = std::fma(q.B, CosRing(phi), q.A);
  if (!(c > 0)) return;
  const double wb = w * c, cc = MinOneOf(c);
  const double g2 = std::fma(cc, cc, q.eta2m1);
  const bool gok = g2 > 0;
  const double g = gok ? std::sqrt(g2) : 0.0;
  double Fn = 1, Fd = 1;  // F = Fn / Fd
  bool part = false;      // 0 <= F < 1
  if (gok) {
    const double a = cc + g, b = std::fma(q.eta2, cc, g);
    const double aa = a * a, bb = b * b;
    const double x = std::fma(q.eta2p1 * cc, cc, -1.0);
    const double a4 = aa * aa, b4 = bb * bb;
    const double n = q.e2m1sq * std::fma(x * x, a4, b4), d = (a4 + a4) * b4;
    part = n < d;
    if (part) {
      Fn = n;
      Fd = d;
    }
  }
  const double muR = std::fma(c + c, q.cosM, -q.mu);
  if (complement) {
    if (part && muR > 0) *accR = *accR + Weigh(wb, muR, Fd - Fn, Fd, q);
  } else if (muR > 0 && Fn > 0) {
    *accR = *accR + Weigh(wb, muR, Fn, Fd, q);
  }
  if (reflectOnly) return;
  const double muT = std::fma(-(cc - g), q.cosM, q.mu) * q.invEta;
  if (part && muT > 0) *accT = *accT + Weigh(wb, muT, Fd - Fn, Fd, q);
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
      AddTerms(q, r.reflectOnly, r.tirComplement, phi[k], w[k], &accR[u][l], &accT[u][l]);
    }
  for (int k = j; k < J; ++k)
    AddTerms(q, r.reflectOnly, r.tirComplement, phi[k], w[k], &accR[0][k - j], &accT[0][k - j]);
  // LaneSum of dielectric_simd_exit.cpp after the two vectors' lane-wise sum.
  auto laneSum = [](const double(*acc)[kLanes]) {
    double l[kLanes];
    for (int i = 0; i < kLanes; ++i) l[i] = acc[0][i] + acc[1][i];
    return ((l[0] + l[4]) + (l[2] + l[6])) + ((l[1] + l[5]) + (l[3] + l[7]));
  };
  const double invCosM = 1 / r.cosM;
  *sumR = laneSum(accR) * invCosM;
  *sumT = laneSum(accT) * invCosM;
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
