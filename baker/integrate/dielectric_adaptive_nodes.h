// The glass adaptive references' inner integrand, a Gauss-Kronrod panel's nodes at once: the E
// pair's (dielectric_albedo.cpp, Integrand) and the BTDF pair's (dielectric_btdf.cpp,
// BtdfIntegrand) in eight AVX-512F lanes (dielectric_adaptive_nodes.cpp), with the scalar code's
// IEEE operations lane by lane in its order (no fused multiply-add, SinCosHalfTurn's polynomial,
// the branches as selects): the scalar walk's bits (tests/integrate_dielectric_adaptive_nodes.cpp).
#pragma once
#include "baker/math/quadrature.h"
#include "baker/models/microfacet.h"

namespace kiln {
namespace dielectric_adaptive {

/// One ring (microfacet polar angle fixed) of the E pair's adaptive walk: c = A + B cos(phi) with
/// A = mu cos_m, B = sin_o sin_m; cosM > 0; the view's constants as the scalar code computes
/// them (eta2m1 = (eta - 1)(eta + 1), eta2 = eta eta, eta2p1 = eta2 + 1, a2 = alpha alpha,
/// negMuOverEta = (-mu) / eta).
struct AlbedoRing {
  double A, B, cosM, mu, gDen, a2, eta, eta2m1, eta2, eta2p1, negMuOverEta;
};

/// For i < n: out[i] = dj times the E pair's integrand {R, T} of ring r at azimuth phi (cos phi
/// by SinCosHalfTurn), phi = dielectric_walk::RingAzimuth(phis, np, y[i], &dj) (y[i] in [0, np -
/// 1], np >= 2): the bits of dielectric_albedo.cpp's scalar Integrand. Needs
/// dielectric_simd::Enabled().
void AlbedoNodes(const AlbedoRing& r, const double* y, const double* phis, int np, int n,
                 Channels<2>* out);

/// One ring of the BTDF pair's adaptive walk (eta >= 1): as AlbedoRing, with muOverEta = mu /
/// eta.
struct BtdfRing {
  double A, B, cosM, mu, gDen, a2, eta, eta2m1, eta2, eta2p1, muOverEta;
};

/// AlbedoNodes for the BTDF pair's integrand {T_lobe, T_F} of ring r: the bits of
/// dielectric_btdf.cpp's scalar BtdfIntegrand. Needs dielectric_simd::Enabled().
void BtdfNodes(const BtdfRing& r, const double* y, const double* phis, int np, int n,
               Channels<2>* out);

/// The E pair's adaptive walk at (mu, alpha, eta) (DielectricAlbedo's view), ring h with azimuth
/// boundaries phis[0 .. np - 1]: its n nodes y (AlbedoNodes' out) as the walk evaluates a
/// panel's: by AlbedoNodes where dielectric_simd::Enabled(), else one at a time by the scalar
/// Integrand (dielectric_albedo.cpp). Tests compare the two.
void AlbedoRingNodes(double mu, double alpha, double eta, PolarParam h, const double* y,
                     const double* phis, int np, int n, Channels<2>* out);
/// The same for the BTDF pair's adaptive walk (DielectricBtdfPair's view, eta >= 1; BtdfNodes,
/// else dielectric_btdf.cpp's BtdfIntegrand).
void BtdfRingNodes(double mu, double alpha, double eta, PolarParam h, const double* y,
                   const double* phis, int np, int n, Channels<2>* out);

}  // namespace dielectric_adaptive
}  // namespace kiln
