// The inner nodes of the microfacet fixed rule (fixed_rule_microfacet.cpp) for Beckmann and
// Blinn-Phong, a panel at a time: eight nodes per AVX-512F instruction where those paths run
// (dielectric_simd::Enabled(): the CPU has it and KILN_NO_AVX512 is not set), then four per AVX2
// instruction where the CPU has it, then two per SSE2 instruction, the exp, log and log1p inline
// (math/fast_exp_log.h), Lambda(l) in its one-exp form (models/beckmann_lambda.h). Each lane does
// the scalar form's operations in its order, without fused multiply-adds, so every path gives the
// same bits (tests/integrate_fixed_rule_beckmann_nodes.cpp).
//
// A node is t = tan(t'/2) on the azimuth with cos p = c, t' the polar angle of the GGX-stretched
// normal (fixed_rule_microfacet.cpp, "Derivation"); it adds weight times
//     t (2 o'_x c t + o'_z C) / q^3 r g  to sumV  and that times (1 - o.h)^5 to sumB,
// C = 1 - t^2, q = 1 + t^2, r the NDF's ratio to GGX's, g = G2 / G1_ggx(o).
#pragma once

namespace kiln {

/// What the nodes of one view need (fixed_rule_microfacet.cpp's Context).
struct BeckmannNodeView {
  double a = 1;             ///< alpha
  double mu = 1, st = 0;    ///< the view's cosine and sine
  double oxs = 0, ozs = 1;  ///< the stretched view o'
  double gNum = 1;          ///< mu + mu Lambda_ggx(o)
  double gDenO = 1;         ///< mu + mu Lambda(o), Beckmann's
  double gRatio = 1;        ///< gNum / gDenO
  double blinnK = 0;        ///< Blinn-Phong: 1 / alpha^2 - 1
  bool blinnPhong = false;  ///< Blinn-Phong's r (else Beckmann's)
  bool separable = false;   ///< separable Smith G2 (else height-correlated)
};

/// Adds the n nodes (t[i], weight[i]) of the azimuth with cos p = c to (sumV, sumB) in the order
/// given; nodes below the horizon (mu_l <= 0) or where r = 0 add nothing. SSE2 where available.
void AddBeckmannNodes(const BeckmannNodeView& v, double c, const double* t, const double* weight,
                      int n, double& sumV, double& sumB);

/// r, the NDF's ratio to GGX's at a node, as the scalar form computes it: Beckmann's
/// exp(-u) (1 + u)^2 (u = sOverC2 where C2 > 0), Blinn-Phong's (qm)^2 (1 + aSOverC2)^(-K)
/// (0: the node adds nothing). The lanes take it where their exp leaves ExpFast's table.
double BeckmannNodeRatio(const BeckmannNodeView& v, double C2, double sOverC2, double qm,
                         double aSOverC2);

/// The same one node at a time in scalar arithmetic (the lanes' reference).
void AddBeckmannNodesScalar(const BeckmannNodeView& v, double c, const double* t,
                            const double* weight, int n, double& sumV, double& sumB);

}  // namespace kiln
