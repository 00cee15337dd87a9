// The table bake the peers ship, for comparison: Monte Carlo over Hammersley points with
// importance sampling (Karis 2013 "Real Shading in Unreal Engine 4"; Filament libs/ibl DFG;
// LearnOpenGL "Specular IBL"; the Khronos glTF IBL sampler), and the same estimator with the
// Hammersley points replaced by a fixed Gauss-Legendre product rule.
//
// Conventions (the same as kiln's, so that errors compare like for like): alpha = r^2 (clamped
// to MinAlpha like MakeModel), height-correlated Smith, BRDF values without the cosine, view
// v = (sqrt(1 - mu^2), 0, mu), normal +z. A point set holds N points u = (u1, u2) in [0, 1)^2
// with weights summing to 1; Hammersley's are (i / N, radicalInverse(i)) with weight 1 / N.
//   Microfacet (dfg, fresnel-albedo): h from GGX's D cos pdf, phi_h = 2 pi u1,
//     cos^2 theta_h = (1 - u2) / (1 + (alpha^2 - 1) u2); l = reflect(v, h); the sample weight is
//     f mu_l / pdf(l) = 4 Vis mu_l (v.h) / (n.h), Vis = G / (4 mu_o mu_l); samples with
//     mu_l <= 0 weigh 0. dfg splits it by Fc = (1 - v.h)^5 into A (1 - Fc) and B (Fc);
//     fresnel-albedo multiplies it by FrDielectric(v.h, eta).
//   Diffuse (albedo of a light-space model): cosine-weighted l (pdf mu_l / pi, seed 002),
//     phi_l = 2 pi u1, cos theta_l = sqrt(1 - u2) (u2 = 0 is the normal: no sample lies on the
//     horizon, where some models' f is not finite); the sample weight is pi f(v, l).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "baker/math/quadrature.h"  // GaussLegendre01
#include "baker/models/registry.h"
#include "baker/tables/spec.h"

namespace kiln {

/// Van der Corput radical inverse in base 2 of i (its bits mirrored about the binary point),
/// in [0, 1).
inline double RadicalInverse2(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
  i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
  i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
  i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
  return i * 0x1p-32;
}

/// A weighted point set on the unit square, stored as the sampling code needs it: the azimuth
/// 2 pi u1 as its cosine and sine, u2, and the weight.
struct PointSet {
  std::vector<double> cosPhi, sinPhi, u2, weight;
  size_t size() const { return u2.size(); }
};

/// The N Hammersley points (i / N, radicalInverse(i)), weight 1 / N.
PointSet HammersleyPoints(int n);

/// The n x n Gauss-Legendre product rule on the unit square (N = n^2 points).
PointSet GaussLegendrePoints(int n);

/// The GGX alpha the estimators sample at roughness r: r^2 of r clamped to [0, 1], at least
/// MinAlpha (as MakeModel clamps it).
inline double MonteCarloAlpha(double r) {
  return std::max(AlphaFromPerceptual(Clamp(r, 0.0, 1.0)), MinAlpha);
}

/// One texel's estimates (bench/estimate_table.h's table bake runs the same code). alpha is the
/// GGX alpha.
std::array<double, 2> EstimateDFG(const PointSet& points, double mu, double alpha);
double EstimateFresnelAlbedo(const PointSet& points, double mu, double alpha, double eta);
RhoParts EstimateDiffuseAlbedo(const PointSet& points, const AnyModel& model, double mu);

/// Fills row `row` of a table (axis 0, all channels interleaved: width x channels floats at
/// `out`); called from several threads at once.
using MonteCarloRows = std::function<void(size_t row, float* out)>;

/// A table kind's Monte Carlo estimator (QuantityInfo::monteCarlo): which specs it can bake, and
/// the row filler over a point set (state every row shares, e.g. the cosine-weighted
/// directions, built once by prepare; `points` must outlive the filler).
struct MonteCarloEstimator {
  bool (*supports)(const TableSpec& spec);
  MonteCarloRows (*prepare)(const TableSpec& spec, const PointSet& points);
};

/// The estimators the descriptors point to: GGX dfg over (mu, roughness); ggx-fresnel-albedo
/// over (mu, roughness, eta); the albedo of a diffuse (light-space) model over (mu, roughness).
extern const MonteCarloEstimator kGgxDfgMonteCarlo;
extern const MonteCarloEstimator kGgxFresnelAlbedoMonteCarlo;
extern const MonteCarloEstimator kDiffuseAlbedoMonteCarlo;

/// True when EstimateTable can bake `spec`: its quantity has an estimator that supports it
/// (today dfg of model ggx, fresnel-albedo, and albedo of a diffuse model).
bool EstimatorSupports(const TableSpec& spec);

}  // namespace kiln
