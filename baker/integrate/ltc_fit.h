// Linearly transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light
// Shading with Linearly Transformed Cosines"): the fit of an LTC to a BRDF lobe, its error, and
// the direct integration of a lobe over a polygon the runtime's LTC integral is checked against.
//
// Conventions: view o = (sqrt(1 - mu^2), 0, mu), normal +z, F = 1. The lobe is f(o, l) mu_l
// (cosine included) of a registry model at perceptual roughness r (alpha = r^2 for the microfacet
// models). The LTC is D(l) = max(0, l'.z)/pi |det M^-1| / |M^-1 l|^3 with l' = M^-1 l / |M^-1 l|,
// M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], Z the lobe's average direction (its
// "dominant direction") rotated about y by the fit's free-frame stage, X = (Z.z, 0, -Z.x),
// Y = (0, 1, 0), as the paper's fitting code.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "baker/math/vec3.h"
#include "baker/models/registry.h"

namespace kiln {

/// One lobe f(o, l) mu_l of a model at F = 1, with the proposal the fit's error integrals
/// sample it by (docs/models.md "LTC", "The fit's proposals"):
/// - microfacet lobes (MicrofacetBRDF, unity-brdf1/2: GGX at Unity's a, capped where Unity's
///   epsilons flatten the peak) by their D cos(theta_m) normals reflected about o; Ward's lobes
///   by Beckmann's (the same exp(-tan^2 theta_m / alpha^2));
/// - the Charlie sheens by a mixture of the clamped cosine (1/4), the horizon density
///   mu_l = u^3 (1/4: a small-roughness sheen lobe is a sliver along the horizon) and their
///   NDF's normals reflected about o (1/2: a sheen's grazing lobe that the cosine alone misses);
/// - ashikhmin-velvet by an even mixture of the clamped cosine and the normals of its NDF's
///   inverted-Gaussian term (cot(theta_m) Rayleigh-distributed: exact) reflected about o;
/// - the mirror-direction Phong lobes (lafortune, unity-brdf3) by a mixture of the clamped
///   cosine and (n + 1) / (2 pi) max(0, m.l)^n about the mirror direction m (and, for
///   unity-brdf3's even (R.L)^4, about -m: its twin at grazing views);
/// - any other model by the clamped cosine.
class LtcLobe {
 public:
  /// `model` a registry id, r its roughness (perceptual; alpha = r^2), mu = cos(theta_o) > 0.
  /// Throws std::invalid_argument for an unknown model.
  LtcLobe(const std::string& model, double r, double mu);
  /// f(o, l) mu_l at F = 1 (cosine included); 0 below the horizon. The registry model's
  /// Evaluate times mu_l, bit for bit (a height-correlated microfacet lobe takes EvalPdf's f,
  /// charlie-smith its view's Lambda kept).
  double Eval(Vec3 wi) const;
  /// The proposal's direction at (u1, u2) in [0, 1)^2 (may be below the horizon).
  Vec3 Sample(double u1, double u2) const;
  /// The proposal's n x n stratified directions Sample((i + 0.5) / n, (j + 0.5) / n) at index
  /// i + n j, the bits of those n^2 calls: the microfacet and Charlie proposals take each
  /// column's part (of u1) and each row's cos and sin of 2 pi u2 once.
  std::vector<Vec3> SampleGrid(int n) const;
  /// The proposal's density over solid angle at wi.
  double Pdf(Vec3 wi) const;
  /// Eval(wi) and Pdf(wi) together, the same bits as the two calls (a microfacet lobe shares
  /// its half vector and D, and keeps mu_o + mu_o Lambda(o) of the height-correlated Smith G2).
  void EvalPdf(Vec3 wi, double* f, double* pdf) const;
  Vec3 wo() const { return wo_; }
  /// The microfacet alpha of a microfacet lobe, 1 for the others (a sheen lobe's width does not
  /// follow its alpha).
  /// A mirror-direction Phong lobe: the alpha of the Blinn-Phong exponent 4 n, sqrt(2 / (4 n + 2)).
  double Alpha() const { return kind_ >= 1 && kind_ <= 3 ? alpha_ : kind_ == 5 ? phongAlpha_ : 1; }
  /// The proposal's kind (the comment on kind_).
  int Kind() const { return kind_; }

 private:
  AnyModel model_;
  Vec3 wo_;
  int kind_ = 0;  ///< 0 cosine proposal, 1 GGX, 2 Beckmann, 3 Blinn-Phong D cos proposal,
                  ///< 4 Charlie sheen: cosine + horizon + Charlie D cos mixture, 5 cosine + mirror
                  ///< Phong lobe(s), 6 velvet: cosine + inverted-Gaussian D cos mixture
  double alpha_ = 1;
  double phongN_ = 0, phongAlpha_ = 1;  ///< kind 5: the Phong exponent n and its alpha
  bool phongTwin_ = false;              ///< kind 5: a twin lobe about -m (unity-brdf3)
  /// Kind 5: the weights of the cosine, the lobe about m and its twin about -m (sum 1).
  double wCos_ = 1, wMirror_ = 0, wTwin_ = 0;
  double muLambdaO_ = -1;  ///< mu_o + mu_o Lambda(o), height-correlated microfacet lobes; else -1
  /// charlie-smith: its Lambda(mu_o), kept for Eval (CharlieSmithSheen::FGivenLambdaO); else -1.
  double sheenLambdaO_ = -1;
  double DCos(Vec3 wm) const;
};

/// The parameters of an LTC in its frame (ltc_fit.h header): M = [X Y Z] diag-ish(m11, m22, m13).
struct LtcFrameParams {
  double m11 = 1, m22 = 1, m13 = 0;
  Vec3 z{0, 0, 1};  ///< the frame's Z (unit, in the xz plane)
};

/// An LTC as matrices (row-major 3x3).
struct LtcMatrix {
  double m[9], inv[9], detInv;
  static LtcMatrix From(const LtcFrameParams& p);
  /// The LTC of stored coefficients (a, b, c, d): M^-1 = [[a, 0, c], [0, 1, 0], [b, 0, d]].
  static LtcMatrix FromInverse(const double minv[4]);
  /// D(l), the LTC density over solid angle (normalised to 1 over the sphere).
  double Eval(Vec3 l) const;
  /// Direction of the LTC at (u1, u2): cosine-sampled, mapped by M, normalised.
  Vec3 Sample(double u1, double u2) const;
};

/// What the fit of one texel gives.
struct LtcTexel {
  LtcFrameParams params;
  LtcFrameParams chain;  ///< the three-parameter (average-direction frame) result: the next start
  double minv[4] = {1, 0, 0, 1};  ///< M^-1 / (M^-1)_11 as (a, b, c, d): [[a,0,c],[0,1,0],[b,0,d]]
  double l3 = 0;                  ///< the minimised objective, integral |f mu_l / norm - D|^p
  double l1 = 0;                  ///< the fit error: integral over the sphere |f mu_l / norm - D|
  double lobeL2 = 0;  ///< integral f^2 of the normalised lobe (the objective at D = 0; p = 2)
};

/// How the fit samples the error integrals (MIS, balance heuristic, of the lobe's proposal and
/// the LTC, on a stratified n x n grid each: deterministic).
struct LtcFitOptions {
  int fitSamples = 16;    ///< n: the lobe's n x n points of the objective (and the frame)
  int ltcSamples = 8;     ///< m: the LTC's own m x m points of the objective
  int power = 2;          ///< the objective's norm: 2 or 3 (the paper's)
  int errorSamples = 16;  ///< n of the declared L1 error; 0: not measured
  /// The L1 error at the coefficients rounded to float (what a table stores), the norm from the
  /// measure's own samples (LtcFitError(lobe, -1, ...)); false: at the fit's double coefficients
  /// with the fit's norm.
  bool storedError = false;
  int maxIterations = 15;   ///< Nelder-Mead iterations (each of the two runs)
  int frameSteps = 60;      ///< then the free-frame stage's iterations (0: none)
  double step = 0.1;        ///< Nelder-Mead's initial step (in ln m11, ln m22, m13 / m11)
  double tolerance = 1e-7;  ///< stop when the simplex's objective spread is below this (relative)
  /// FitLtcGrid: a texel whose fit from its neighbour keeps more than half of integral f^2 (the
  /// objective of an LTC that misses the lobe) is fitted again from its column's first texel and
  /// from the clamped cosine, the lowest objective kept (deterministic; p = 2). Off for the
  /// catalogue's ltc-ggx, ltc-beckmann, ltc-blinn-phong (their bytes unchanged).
  bool retryMisses = false;
  /// FitLtcGrid: when set, each texel's l1 is the overlap form of the L1 error
  /// (LtcOverlapError, errorSamples^2 points of each proposal) at the coefficients rounded to
  /// float, with the lobe's norm this gives for texel (ir, im); the lobe's samples are the fit's
  /// own when the counts agree (the same bits as a separate LtcOverlapError). A norm <= 0 leaves
  /// that texel unmeasured (l1 = -1). The fit's own error (storedError) is then not measured.
  std::function<double(size_t ir, size_t im)> overlapNorm;
};

/// The lobe's norm integral f mu_l dl (F = 1) and average direction (unit) by the proposal's
/// n x n stratified samples.
void LtcLobeMoments(const LtcLobe& lobe, int n, double* norm, Vec3* averageDir);

/// Fits an LTC to `lobe` / norm (norm <= 0: estimated from the fit's own lobe samples)
/// minimising the L^p error over the sphere (opt.power; ltc_fit.cpp's header derives the
/// objective) by Nelder-Mead (written for kiln) from `start` over (ln m11, ln m22, m13 / m11);
/// with `isotropic` m22 = m11 and m13 = 0 (a view along the normal). The frame's Z is the
/// lobe's average direction. Deterministic.
LtcTexel FitLtc(const LtcLobe& lobe, double norm, const LtcFrameParams& start, bool isotropic,
                const LtcFitOptions& opt = {});

/// integral over the sphere |lobe / norm - D_ltc|^p (p = 1 or 3) by MIS (balance heuristic) of
/// the lobe's and the LTC's n x n stratified samples; norm <= 0: the norm estimated from the
/// same lobe samples (the lobe normalised to 1 by the measurement's own quadrature).
double LtcFitError(const LtcLobe& lobe, double norm, const LtcMatrix& ltc, int p, int n);

/// The L1 distance integral |lobe / norm - D_ltc| over the sphere in its overlap form,
/// 2 - 2 integral min(lobe / norm, D_ltc) (both densities of mass 1: exact when norm is the
/// lobe's exact integral, norm > 0), the overlap by MIS (balance heuristic) of the lobe's and the
/// LTC's n x n stratified samples. Each sample's term min(f, D) / (p_lobe + D) lies in [0, 1], so
/// the estimate is at most 2 (the quantity's bound) whatever the lobe's proposal misses, and a
/// narrow lobe's spikes cannot inflate it (unlike integral |f - D| / (p_lobe + D)).
double LtcOverlapError(const LtcLobe& lobe, double norm, const LtcMatrix& ltc, int n);

/// Nelder-Mead minimisation (Nelder & Mead 1965, standard coefficients 1, 2, 1/2, 1/2) of f
/// over `dim` <= 4 parameters from x (in/out) with initial step `step`; stops after maxIter
/// iterations or when the simplex's values agree to `tol` (relative). Returns min f.
double NelderMead(const std::function<double(const double*)>& f, int dim, double* x, double step,
                  int maxIter, double tol);

/// One whole LTC table of `model` on the published grid: nodes i / (n - 1) of the roughness r
/// and of s = sqrt(1 - mu) (theta_o clamped to 1.57 rad where s = 1, as the paper's code), r = 0
/// fitted at alpha = alphaFloor (an LTC cannot be a mirror). Rows of fixed r are fitted in order
/// of s from the node s = 0, each from the previous texel's solution; the s = 0 row from r = 1
/// down, sequentially; the r columns in parallel on `threads` threads (oneTBB): the same bits for
/// any count. Texel (ir, is) at index ir + n * is.
std::vector<LtcTexel> FitLtcTable(const std::string& model, int n, double alphaFloor, int threads,
                                  const LtcFitOptions& opt = {});

/// The same on any grid: roughness values rs (any order) and view cosines mus, mus[0] the
/// first row (isotropic when it is 1); texel (ir, im) at index ir + rs.size() * im. The first row
/// is fitted from the last roughness to the first, sequentially; then each roughness column
/// along mus from its first-row texel, the columns in parallel.
std::vector<LtcTexel> FitLtcGrid(const std::string& model, const std::vector<double>& rs,
                                 const std::vector<double>& mus, double alphaFloor, int threads,
                                 const LtcFitOptions& opt = {});

/// The view cosine the fit uses for mu: theta_o at most 1.57 rad (the paper's code).
double LtcFitMu(double mu);

/// integral of f(o, l) mu_l (F = 1) over the spherical polygon with vertices p (directions from
/// the shaded point, any length; convex as seen from it), clipped to the upper hemisphere, by
/// adaptive subdivision of its planar triangles with a degree-5 rule, to absolute tolerance tol
/// (refined to the lobe's width around the mirror direction). evals (optional) counts lobe
/// evaluations.
double IntegrateLobeOverPolygon(const LtcLobe& lobe, const Vec3* p, int count, double tol,
                                long long* evals = nullptr);

/// The fixed test polygons of the declared polygon error (docs/ltc.md "What each file
/// declares"), in the view's frame (normal +z, view in the xz-plane at x >= 0, so the mirror
/// side is x < 0): 0 a large quad covering the upper hemisphere (down to 1e-3 rad of the
/// horizon), 1 a quad around the normal, 2 a quad towards the mirror direction of mu = 0.5,
/// 3 a quad straddling the horizon on the mirror side, 4 a thin quad across the normal; then
/// the hard cases: 5 a quad straddling the horizon on the view's side, 6 one straddling it
/// across the view's plane (at y = 1), 7 one on the mirror side mostly below the horizon,
/// 8 a grazing quad on the mirror side, above the horizon (elevation 0.01 to 0.1 at x = -1).
/// Parts below z = 0 count for nothing (both the LTC integral and the reference clip there).
std::vector<std::vector<Vec3>> LtcTestPolygons();

/// Half the side of the near-mirror test quad, on the tangent plane at the mirror direction
/// (about 0.1 rad across).
constexpr double kLtcNearMirrorHalfSize = 0.05;

/// The near-mirror test polygon of the view wo (unit, in the normal's frame, z = N.V): a square
/// of side 2 kLtcNearMirrorHalfSize on the tangent plane of the unit sphere at wo's mirror
/// direction about the normal, centred on it (at grazing views it straddles the horizon).
std::vector<Vec3> LtcNearMirrorPolygon(Vec3 wo);

}  // namespace kiln
