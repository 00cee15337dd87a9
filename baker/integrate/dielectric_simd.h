// Eight doubles per instruction for the glass rules' fixed walks (integrate/dielectric_albedo.cpp:
// the E tables' eta columns and the exit side's per-point walk), where the CPU has AVX-512F
// (checked at run time; the portable code of dielectric_albedo.cpp runs elsewhere). The column
// paths (dielectric_simd.cpp) do the portable code's IEEE operations lane by lane (add, mul, div,
// sqrt correctly rounded; min, max and the branches as selects with the same operand order; no
// fused multiply-add) in the same order, and the caller sums the lanes' terms in the walk's
// order: the same bits on either path. The exit walk's ring (FastRingSums,
// dielectric_simd_exit.cpp) fuses multiply-adds and sums in lanes, and its portable form
// (PortableRingSums) does the same with std::fma: the same bits too
// (tests/integrate_dielectric_simd.cpp).
#pragma once
#include <cmath>

namespace kiln {
namespace dielectric_simd {

/// True where the AVX-512F paths run: the CPU has AVX-512F, the environment variable
/// KILN_NO_AVX512 is unset, empty or "0" at the first call, and SetEnabled(false) was not called.
bool Enabled();
/// Turns the AVX-512F paths off (false) or back on where the CPU has them (tests compare the
/// two paths' bits).
void SetEnabled(bool on);

/// Most azimuth nodes of one ring (dielectric_walk.h: kMaxPhiBreaks - 1 panels of at most
/// kMaxCachedGaussNodes nodes, quadrature.h; dielectric_albedo.cpp checks it).
constexpr int kMaxRingNodes = 39 * 64;

/// One ring's nodes (phi, w) as the walk visits them, and the AVX-512F paths' per-node arrays.
struct RingBuffer {
  int J = 0;
  double phi[kMaxRingNodes], w[kMaxRingNodes];
  double wR[kMaxRingNodes], wb[kMaxRingNodes], cc[kMaxRingNodes], tR[kMaxRingNodes],
      tT[kMaxRingNodes];
  unsigned char valid[kMaxRingNodes];
};

/// One ring of the exit side's per-point walk (dielectric_albedo.cpp, FastView): the view's and
/// the ring's constants. c = A + B cos(phi) with A = mu cos_m, B = sin_o sin_m; cosM > 0.
struct FastRing {
  double A, B, cosM, mu, eta, eta2, eta2m1, a2, gDen;
  double invEta;  ///< 1 / eta, the view's (one division a view, not a ring)
  bool reflectOnly;
  /// The reflected channel as total internal reflection's complement (the exit pair's walk,
  /// dielectric_albedo.cpp, "The exit pair by total internal reflection's complement"): *sumR
  /// sums (1 - F) times the reflected term with F = 1, only where 0 <= F < 1, instead of F times
  /// it; *sumT as without.
  bool tirComplement = false;
};

/// The exit ring's cos phi = -sin(x), x = phi - pi/2 in [-pi/2, pi/2]: sin x = x P(x^2), P of
/// degree 8 with kRingSinSeries[i] y^i's coefficient: sin's Taylor series (to x^33, exact
/// rationals) economised by shifted Chebyshev polynomials on y in [0, pi^2 / 4] to degree 8, then
/// rounded; |x P(x^2) - sin x| below 2.4e-17 over [-pi/2, pi/2] (exact arithmetic, a scratch
/// check at 20,001 points; dielectric_walk::CosHalfTurn's Taylor series to x^21 has 2 more terms).
/// The exit ring's forms (FastRingSums, PortableRingSums) evaluate it by Estrin's scheme.
constexpr int kRingSinTerms = 9;
constexpr double kRingSinSeries[kRingSinTerms] = {1.0,
                                                  -0.16666666666666666,
                                                  0.008333333333333186,
                                                  -0.0001984126984120872,
                                                  2.755731921123654e-06,
                                                  -2.5052106891168703e-08,
                                                  1.6058940907182887e-10,
                                                  -7.643027273612204e-13,
                                                  2.7215821926997076e-15};

/// The ring's sums of FastView's terms at its J nodes (phi[j], w[j]): *sumR = sum_j
/// w[j] R(phi[j]), *sumT likewise (cos phi by kRingSinSeries). Fused multiply-add and
/// eight lanes of partial sums in one fixed order (dielectric_simd_exit.cpp); PortableRingSums
/// gives its bits. Needs Enabled().
void FastRingSums(const FastRing& r, const double* phi, const double* w, int J, double* sumR,
                  double* sumT);

/// FastRingSums on any CPU: the same operations in the same order, one node at a time (std::fma
/// where FastRingSums fuses; node j in lane j mod 8 of the same partial sums): its bits
/// (dielectric_exit_ring.cpp). The exit walk's path where Enabled() is false.
void PortableRingSums(const FastRing& r, const double* phi, const double* w, int J, double* sumR,
                      double* sumT);
/// PortableRingSums by the CPU's FMA instructions where it has them (true, the default) or by
/// libm's std::fma (false): the same bits either way (tests compare them).
void SetPortableFmaInstructions(bool on);

/// dielectric_walk::OuterRing for the n Gauss nodes (t[k], w[k]) of the outer panel [va, vb] of
/// a GGX problem with alpha^2 = a2, eight nodes per instruction (Smooth's and FromV's IEEE
/// operations in their order: their bits): the rings that exist (v and the Jacobian positive), in
/// order, into sinM, cosM (the ring's normal) and wo (its outer weight); returns their count.
/// Needs Enabled().
int FastOuterRings(double va, double vb, double a2, const double* t, const double* w, int n,
                   double* sinM, double* cosM, double* wo);

/// The inner breaks' view constants of the exit walk (dielectric_exit_breaks.h, PhiBreaks): the
/// thresholds c0 in its order (mu / (2 cos_m), cs, the reflected layer's (m + mu) / (2 cos_m),
/// then where exitSide c_crit and the refracted layer's c at q = refracted[i] / cos_m).
struct ExitPhiView {
  double mu, st, cCrit, eta2m1;
  bool exitSide;  ///< eta < 1
  int ncs, nReflected, nRefracted;
  const double *cs, *reflected, *refracted;
  /// The reflected ray's thresholds below this are no boundaries (ExitBreakConsts::cDrop).
  double cDrop = -INFINITY;
};

/// Most boundaries of one ring's PhiBreaks (dielectric_walk.h's kMaxPhiBreaks).
constexpr int kMaxRingPhis = 40;

/// dielectric_exit_breaks::PhiBreaks of m <= 8 rings (cos_m, sin_m) at once, one ring a lane:
/// ring l's sorted boundaries into phis[l], their count into np[l] (>= 2, or 0). The same
/// operations as the scalar PhiBreaks (no fused multiply-add; acos by the same polynomial and
/// order): its bits. Needs Enabled().
void PhiBreaks8(const ExitPhiView& v, const double* cosM, const double* sinM, int m,
                double (*phis)[kMaxRingPhis], int* np);

/// One ring of the entering side's column walks (dielectric_albedo.cpp, ReflectedMoments;
/// dielectric_btdf.cpp, BtdfColumnWalk): the view's
/// and the ring's constants (cosM > 0).
struct ColumnRing {
  double A, B, cosM, mu, gDen, a2;
  double oma2;  ///< 1 - a2
  double kh;    ///< mu a2 / (2 gDen): the refracted ray's masking over the view's (EtaTerms)
};

/// The ColumnRing at polar angle (cosM, sinM) of a view with cosine mu, sine st and gDen = mu +
/// mu Lambda(o), given the ring constants k (dielectric_lanes::RingConstsOf: a2, oma2, kh).
template <class RingConsts>
ColumnRing ColumnRingOf(double mu, double st, double gDen, double cosM, double sinM,
                        const RingConsts& k) {
  return {mu * cosM, st * sinM, cosM, mu, gDen, k.a2, k.oma2, k.kh};
}

/// The column walk's reflected part at the J nodes (phi, w) of ring r (dielectric_albedo.cpp,
/// ReflectedMoments): the nodes with c > 0 and a reflected ray above the horizon (a weight wR !=
/// 0), in order, their wR (w (c / cos_m) over the view's and the reflected ray's masking) into
/// wR[0 ..] and cc = min(c, 1) into cc[0 ..]; returns how many. Needs Enabled().
int ReflectedRing(const ColumnRing& r, const double* phi, const double* w, int J, double* wR,
                  double* cc);
/// The BTDF pair's per-node shared part at the J nodes (phi, w) of ring r: c > 0 marks the node
/// visited (valid[j] = 1, else 0 and the rest unset), wb = w (c / cos_m) / gDen, cc = min(c, 1).
/// Needs Enabled().
void BtdfRingShared(const ColumnRing& r, const double* phi, const double* w, int J,
                    unsigned char* valid, double* wb, double* cc);

/// dielectric_moments::RingMoments (dielectric_fresnel_moments.h: the column walk's E_R moments of
/// one ring's J kept nodes) with one eight-lane instruction where the portable form takes four
/// lane pairs: the same lanes, operations and order, its bits. Needs Enabled().
void RingMoments8(const double* wR, const double* cc, int J, double* ring);

/// The BTDF pair's column walk (dielectric_btdf.cpp, BtdfColumnWalk) likewise: per valid node
/// j in order and eta e < 8 * groups, t = wb p / den, ring0[e] += t, ring1[e] += t (1 - Tf).
/// Needs Enabled().
void BtdfRingEtas(const ColumnRing& r, const unsigned char* valid, const double* wb,
                  const double* cc, int J, const double* eta2m1, const double* eta2,
                  const double* inv, int groups, double* ring0, double* ring1);
/// The same terms for one eta, eight nodes per instruction, into t0[j] = t, t1[j] = t F (0 at
/// invalid nodes). Needs Enabled().
void BtdfRingOneEta(const ColumnRing& r, const double* wb, const double* cc, int J, double eta2m1,
                    double eta2, double inv, double* t0, double* t1);

/// Most etas of a column (kMaxDielectricColumn, dielectric_albedo.h; asserted there).
constexpr int kMaxColumnEtas = 64;

/// Adds one ring of a column walk to the column's totals: the ring's per-eta sums ring0[e],
/// ring1[e] by allEtas(ring0, ring1) for a column of eight or more etas, else per eta by
/// oneEta(e), which fills buf.tR, buf.tT at the ring's J nodes, summed here in the nodes' order;
/// then total[e] += wo ring[e]. Shared by the E tables' and the BTDF pair's column walks (the
/// same operations in the same order as each wrote them before).
template <class AllEtas, class OneEta>
void AddColumnRing(int n, RingBuffer& buf, double wo, AllEtas allEtas, OneEta oneEta,
                   double* total0, double* total1) {
  double ring0[kMaxColumnEtas] = {}, ring1[kMaxColumnEtas] = {};
  if (n >= 8) {
    allEtas(ring0, ring1);
  } else {
    for (int e = 0; e < n; ++e) {
      oneEta(e);
      double s0 = 0, s1 = 0;
      for (int j = 0; j < buf.J; ++j) {
        s0 = s0 + buf.tR[j];
        s1 = s1 + buf.tT[j];
      }
      ring0[e] = s0;
      ring1[e] = s1;
    }
  }
  for (int e = 0; e < n; ++e) {
    total0[e] = total0[e] + wo * ring0[e];
    total1[e] = total1[e] + wo * ring1[e];
  }
}

}  // namespace dielectric_simd
}  // namespace kiln
