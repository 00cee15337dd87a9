// Closed forms and small tables engines ship in place of kiln's tables, measured against kiln's
// exact integrals by the fit search (fit.h MeasureFitError) like kiln's own fits (docs/fits.md
// "Engine approximations", docs/atlas/tables.md). Each is written here from its published
// formula or data (facts, not code); the source and licence are named at each function.
// Every one has the FitEvaluator signature: x = (mu, roughness) in the table's axis order, `out`
// the table's channels; `form` is ignored.
#pragma once
#include "baker/fit/fit.h"

namespace kiln {

/// Karis 2014, "Physically Based Shading on Mobile" (Unreal Engine 4's EnvBRDFApprox, three.js's
/// former DFGApprox): (A, B) of GGX at x = (mu, roughness), roughness the perceptual one
/// (alpha = roughness^2), in float:
///   r = roughness (-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04),
///   a = min(r.x^2, 2^(-9.28 mu)) r.x + r.y,  (A, B) = (-1.04 a + r.z, 1.04 a + r.w).
void KarisEnvBrdfApprox(const FitForm& form, const float* x, float* out);

/// Lazarov's gloss g in [0, 1] for kiln's roughness r (alpha = r^2): the Blinn-Phong exponent of
/// Call of Duty: Black Ops, n = 8192^g (Lazarov 2011 and 2013), matched to the microfacet alpha
/// by Walter et al. 2007's n = 2 / alpha^2 - 2, so g = log(2 / r^4 - 2) / log(8192), clamped to
/// [0, 1] (r below 0.125 gives g = 1, r above (2/3)^(1/4) = 0.904 gives g = 0). In float.
float LazarovGloss(float roughness);

/// Lazarov 2013, "Getting More Physical in Call of Duty: Black Ops II" (SIGGRAPH 2013 course),
/// its EnvironmentBRDF as Karis 2014 quotes it: with gloss g (LazarovGloss),
///   t = g (1/0.96, 0.475, (0.0275 - 0.25 0.04)/0.96, 0.25) + (0, 0, (0.015 - 0.75 0.04)/0.96,
///   0.75), a0 = t.x min(t.y, 2^(-9.28 mu)) + t.z,  a1 = t.w,  result = saturate(a0 + f0 (a1 -
///   a0)).
/// Written as the table's (A, B): the result at f0 = 0 is B and at f0 = 1 is A + B, so
/// B = saturate(a0), A = saturate(a1) - saturate(a0) (exact for every f0 where a0 >= 0).
void LazarovEnvironmentBrdf(const FitForm& form, const float* x, float* out);

/// three.js's IBLSheenBRDF of the releases that sample the 16 x 16 DFGLUTData
/// (src/renderers/shaders/ShaderChunk/lights_physical_pars_fragment.glsl.js, MIT), at
/// x = (mu, sheen roughness r): with q = 1 / (r + 0.1),
///   a = -1.9362 + 1.0678 r + 0.4573 r^2 - 0.8469 q,  b = -0.6014 + 0.5538 r - 0.4670 r^2 - 0.1255
///   q, E = saturate(exp(a mu + b)).
/// The shader multiplies it by irradiance / pi (pi L under a uniform radiance L), so E stands
/// for the sheen lobe's directional albedo, integral f mu_l dl.
void ThreeSheenAlbedo(const FitForm& form, const float* x, float* out);

/// three.js's former IBLSheenBRDF (the releases with DFGApprox; same file, MIT), a fit cited to
/// Estevez and Kulla 2017: for r < 0.25, a = -339.2 r^2 + 161.4 r - 25.9,
/// b = 44.0 r^2 - 23.7 r + 3.26, else a = -8.48 r^2 + 14.3 r - 9.95, b = 1.97 r^2 - 3.27 r + 0.72;
/// DG = exp(a mu + b) + (r < 0.25 ? 0 : 0.1 (r - 0.25)); the shader returns saturate(DG / pi)
/// and multiplies it by the irradiance (pi L), so the albedo it stands for is
/// E = pi saturate(DG / pi).
void ThreeSheenAlbedoFormer(const FitForm& form, const float* x, float* out);

/// three.js's 16 x 16 DFGLUTData (RG16F; R = A, G = B of GGX) as the GPU samples it: bilinear,
/// texel centres at (i + 0.5) / 16, clamp to edge, u = roughness, v = mu.
void ThreeDfgLutLookup(const FitForm& form, const float* x, float* out);

/// three.js's DFGLUTData texels (baker/fit/three_dfg_lut_data.cpp): [row = v = mu][col = u =
/// roughness][A, B].
extern const float kThreeDfgLut[16][16][2];

/// The measuring form of a (mu, roughness) table `spec` for an approximation: degree 1 per axis
/// with the given warps (the search grid is uniform in the warped axes, so a root4 or layer mu
/// warp probes grazing densely).
FitForm ProbeForm(const TableSpec& spec, FitWarp muWarp, FitWarp roughnessWarp);

/// ProbeForm of a (mu, roughness) DFG table with the warps of kiln's GGX fit (layer mu, sqrt
/// roughness): the grazing, low-roughness corner is probed as densely as kiln's own fits.
FitForm DfgProbeForm(const TableSpec& spec);

}  // namespace kiln
