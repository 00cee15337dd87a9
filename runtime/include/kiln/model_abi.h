// The C ABI of a user's BRDF ("custom model"), version 1: a C++ file that includes this header
// and defines the functions below with C linkage is a model kiln evaluates, integrates, bakes and
// verifies like a built-in one (`kiln ... --model-source my_lobe.cpp`, or a shared library built
// from it with `--model-library my_lobe.so`). docs/custom-models.md describes it with examples.
//
// Conventions: directions are unit vectors in the local frame, z the normal; wo (view) and wi
// (light) point away from the surface. kiln_model_eval returns f(wo, wi), the cosine excluded, at
// the given roughness in [0, 1]; it must be finite and >= 0 for every pair with wo.z, wi.z >= 0
// (kiln stops with the directions named where it is not) and may return 0 below the horizon.
// kiln calls the functions from several threads at once: they must not modify shared state.
#ifndef KILN_MODEL_ABI_H
#define KILN_MODEL_ABI_H

/// The ABI version this header describes.
#define KILN_MODEL_ABI_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

// --- Required ---------------------------------------------------------------------------------

/// KILN_MODEL_ABI_VERSION (1).
int kiln_model_abi_version(void);
/// The model's id, as tables and the command line name it: lower-case letters, digits and '-',
/// not a built-in model's id (e.g. "my-lobe": tables my-lobe-albedo, my-lobe-albedo-avg, ...).
const char* kiln_model_id(void);
/// 1 when the lobe peaks around the mirror direction (a microfacet-like lobe, integrated over
/// half vectors and given dfg tables), 0 for a smooth lobe (integrated over light directions).
int kiln_model_is_specular(void);
/// f(wo, wi), cosine excluded; z is the normal; roughness in [0, 1].
double kiln_model_eval(const double wo[3], const double wi[3], double roughness);

// --- Optional (looked up when present) ----------------------------------------------------------

/// The microfacet alpha whose GGX lobe kiln walks to integrate a specular lobe at `roughness`
/// (an importance hint: any alpha integrates correctly, a close one quickly). Default
/// max(roughness^2, 1e-3).
double kiln_model_importance_alpha(double roughness);
/// 1 when the directional albedo is at most 1 for every view and roughness (a property kiln
/// lists and `kiln verify` reports against the baked albedo); default 0 (not claimed).
int kiln_model_energy_conserving(void);
/// More parameters than the roughness: how many (at most 4), and each one's name, range and
/// default. A name must be one of kiln's parameter options: rho, f0, rs, eta, k, nu, nv (given on
/// the command line as --rho 0.5, ...). Tables are baked at the defaults.
int kiln_model_param_count(void);
const char* kiln_model_param_name(int index);
void kiln_model_param_range(int index, double* lo, double* hi, double* def);
/// f(wo, wi) with the parameters' values in declaration order; used instead of kiln_model_eval
/// when the model declares parameters.
double kiln_model_eval_params(const double wo[3], const double wi[3], double roughness,
                              const double* params);
/// f(wo, wi) of a specular lobe given also wh = (wo + wi) / |wo + wi|, the half vector kiln's
/// half-vector walk generated: its components carry full relative precision, where wo + wi
/// rounded from the two directions holds the half vector's slope only to ~1e-16 absolute (too
/// coarse for a lobe sharper than alpha ~1e-7). `params` holds the declared parameters' values in
/// declaration order (not to be read when none is declared). When present, kiln integrates a
/// specular lobe with it instead of kiln_model_eval / kiln_model_eval_params (which it still uses
/// for single evaluations); it must agree with them up to rounding. A lobe written in terms of
/// the half vector's components (tan^2 theta_h = (wh.x^2 + wh.y^2) / wh.z^2) keeps its precision
/// down to alpha = 1e-12.
double kiln_model_eval_half(const double wo[3], const double wh[3], const double wi[3],
                            double roughness, const double* params);

#ifdef __cplusplus
}
#endif

#endif  // KILN_MODEL_ABI_H
