// The error atlas of kiln's cheap approximations (issue #16): for each pair (a cheap model, the
// reference it approximates, their shared parameters and how roughness maps between them), over a
// (mu, roughness) grid, the directional-albedo difference E_cheap - E_ref and the largest
// cosine-weighted BRDF difference over the light hemisphere, max_wi |f_cheap - f_ref| mu_i.
//
// Conventions: view o = (sqrt(1 - mu^2), 0, mu), normal +z, rho = 1; f excludes the cosine; the
// BRDF difference is weighted by mu_i = cos(theta_i) so that the 1/mu blow-ups of some models at
// a grazing light stay comparable (it is the difference of the reflected radiance under a unit
// directional light). Every model compared is isotropic: wi is searched over theta_i in
// [0, pi/2], phi_i in [0, pi] (phi_i = 0 on the view's side, pi the mirror side).
// docs/atlas/README.md is written by `kiln atlas`; docs/models.md ("Error atlas") the method.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "baker/models/registry.h"

namespace kiln {

/// How the atlas's roughness coordinate becomes a side's own `roughness` parameter.
enum class AtlasRoughnessMap {
  Same,            ///< the side's roughness is the atlas coordinate itself
  FujiiSigmaPrime  ///< sigma' = B(sigma) / A(sigma) of Fujii's fit to the full Oren-Nayar at
                   ///< rho = 1 (FujiiSigmaPrime), the atlas coordinate being sigma
};

/// A constant factor applied to a side's BRDF (and so to its albedo).
enum class AtlasRescale {
  None,
  BlinnPhong204  ///< blinn-phong-normalized with tri-Ace's (s + 2.04)/(8 pi) in place of its exact
                 ///< N(s): f times NormalizationApprox(s) / Normalization(s)
};

/// One side of a comparison: a registry model, its fixed parameters ("f0=0.04", "eta=1.5,k=0",
/// empty for the defaults), its roughness mapping and an optional rescale.
struct AtlasSide {
  AtlasSide() = default;
  AtlasSide(std::string model_, std::string params_ = "",
            AtlasRoughnessMap map_ = AtlasRoughnessMap::Same,
            AtlasRescale rescale_ = AtlasRescale::None)
      : model(std::move(model_)), params(std::move(params_)), map(map_), rescale(rescale_) {}
  std::string model;
  std::string params;
  AtlasRoughnessMap map = AtlasRoughnessMap::Same;
  AtlasRescale rescale = AtlasRescale::None;
};

/// One comparison of the atlas: the CSV and PNG are named after `name`; the roughness coordinate
/// `axis` runs over [lo, hi]; `note` says what is compared and how roughness maps (README).
struct AtlasPair {
  std::string name;
  AtlasSide cheap, ref;
  std::string axis = "roughness";
  double lo = 0, hi = 1;
  std::string note;
};

/// x printed by std::snprintf with `fmt` (a single double conversion), for the atlas's tables,
/// CSVs and plot labels.
std::string AtlasNumber(double x, const char* fmt = "%.4g");

/// Every pair of the atlas, one line each (baker/atlas/atlas_pairs.cpp).
const std::vector<AtlasPair>& AtlasPairs();

/// sigma' of fujii-normalized matching sigma of the full Oren-Nayar: Fujii defines sigma' as the
/// ratio of the non-diffuse to the diffuse term, B / A; kiln takes his fit to the full model,
/// A = 1 - 0.5 s2/(s2 + 0.33) + 0.17 s2/(s2 + 0.13) (rho = 1), B = 0.45 s2/(s2 + 0.09).
double FujiiSigmaPrime(double sigma);

/// Grid and tolerance of the max search over the light hemisphere.
struct MaxSearchOptions {
  int thetaNodes = 24;    ///< grid nodes in theta_i (cell centres over [0, pi/2])
  int phiNodes = 25;      ///< grid nodes in phi_i (ends included over [0, pi])
  int starts = 6;         ///< best grid nodes and seeds refined by a pattern search
  double minStep = 1e-7;  ///< the pattern search stops below this step (radians)
};

/// The largest value of g(theta, phi) over theta in [0, pi/2], phi in [0, pi] and where it is.
struct HemisphereMax {
  double value = 0, theta = 0, phi = 0;
};

/// Maximises g over the hemisphere: the grid of `opt` plus the `seeds` (theta, phi), then a
/// pattern search over the 8 compass and diagonal directions (steps halved down to opt.minStep)
/// from the opt.starts best of them.
/// Deterministic. A NaN of g counts as -inf.
HemisphereMax MaxOverHemisphere(const std::function<double(double theta, double phi)>& g,
                                const MaxSearchOptions& opt,
                                const std::vector<std::pair<double, double>>& seeds = {});

/// Grid and methods of an atlas.
struct AtlasOptions {
  int muNodes = 32;         ///< mu = j / muNodes, j = 1..muNodes
  int roughnessNodes = 32;  ///< lo + (hi - lo) i / (n - 1)
  double tol = 1e-9;        ///< adaptive quadrature's absolute tolerance where no fixed rule
  MaxSearchOptions search;
  int threads = 2;
};

/// One grid point: E of both sides at rho = 1, dE = E_cheap - E_ref, max_df and its wi.
struct AtlasCell {
  double mu = 0, roughness = 0;
  double eRef = 0, eCheap = 0, dE = 0;
  double maxDf = 0, argMu = 0, argPhi = 0;  ///< argmax wi as (mu_i, phi_i)
};

/// The grid of one pair, mu fastest, and the albedo method of each side.
struct AtlasResult {
  AtlasPair pair;
  int nMu = 0, nR = 0;
  std::vector<AtlasCell> cells;
  std::string cheapMethod, refMethod;
};

/// Throws std::invalid_argument with one line naming the problem: an unknown model, a parameter
/// a model does not take or out of its range, a roughness range outside [lo, hi] valid for the
/// sides, an empty name.
void CheckAtlasPair(const AtlasPair& pair);

/// A side's model at atlas roughness r (its mapping applied; rescale not included).
AnyModel AtlasModel(const AtlasSide& side, double r);

/// f of a side at atlas roughness r: the model's BRDF (no cosine) times its rescale.
double AtlasF(const AtlasSide& side, const AnyModel& model, Vec3 wo, Vec3 wi);

/// E(mu) of a side at atlas roughness r, rho = 1, with the side's own Fresnel term: by the bake's
/// fixed rule where one exists (diffuse and microfacet albedo; GGX with Schlick f0 as
/// f0 A + B of the DFG rule; GGX with exact eta by the fresnel-albedo rule), else adaptive
/// quadrature to `tol`. `method` (optional) receives the method in words.
double AtlasAlbedo(const AtlasSide& side, double mu, double r, double tol,
                   std::string* method = nullptr);

/// max over wi of |f_cheap - f_ref| mu_i at view mu and atlas roughness r (seeds: the grid, the
/// mirror direction and rings around it, the rows theta_i = theta_o and phi_i = pi/2).
HemisphereMax AtlasMaxDf(const AtlasPair& pair, double mu, double r, const MaxSearchOptions& opt);

/// The whole grid of one pair (CheckAtlasPair first), in parallel on opt.threads: the same
/// values for any thread count.
AtlasResult ComputeAtlas(const AtlasPair& pair, const AtlasOptions& opt);

/// The CSV of a result: header mu,roughness,E_ref,E_cheap,dE,max_df,argmax_mu_i,argmax_phi_i,
/// one row per cell, %.9g.
std::string AtlasCsv(const AtlasResult& result);

/// The PNG of a result: two heatmaps over (mu, roughness), dE and max_df, with labelled axes and
/// a colour bar each (max_df on a log10 scale when it spans more than three decades).
std::string AtlasPng(const AtlasResult& result);

/// One heatmap panel of a PNG: values over a (mu, roughness) grid, mu fastest; `allowLog`: log10
/// when they span more than three decades; `unit` labels the colour bar.
struct HeatmapPanel {
  std::string title;
  std::vector<double> values;
  bool allowLog = false;
  std::string unit;
};

/// A PNG of heatmap panels side by side over an nMu x nR grid (viridis, a colour bar each, the
/// first and last mu and roughness on the axes, `axis` naming the roughness axis) under a
/// one-line `heading`.
std::string HeatmapPng(const std::string& heading, const std::vector<HeatmapPanel>& panels, int nMu,
                       int nR, double muFirst, double muLast, double rFirst, double rLast,
                       const std::string& axis);

/// docs/atlas/README.md: per pair the worst |dE| and worst max_df and where, the methods, the
/// mappings, and `command`, the command that regenerated it.
std::string AtlasReadme(const std::vector<AtlasResult>& results, const AtlasOptions& opt,
                        const std::string& command);

}  // namespace kiln
