// The built-in models' descriptor functions (declared from models/model_list.inc) and the
// parameter helpers the descriptor files share.
#pragma once
#include "baker/models/registry.h"

namespace kiln::model_list {

#define KILN_MODEL(F) ModelInfo F();
#include "baker/models/model_list.inc"
#undef KILN_MODEL

/// rho in [0, 1], default 1.
inline ParamInfo Rho() { return {"rho", 0, 1, 1, "albedo (diffuse reflectance)"}; }
/// roughness in [0, hi], default 0.5.
inline ParamInfo Rough(double hi, const char* doc) { return {"roughness", 0, hi, 0.5, doc}; }
/// f0 in [0, 1].
inline ParamInfo F0(double def) {
  return {"f0", 0, 1, def, "normal-incidence specular reflectance"};
}
/// rs in [0, 1].
inline ParamInfo Rs(double def) { return {"rs", 0, 1, def, "specular reflectance R_s"}; }
/// eta in [0.01, 100], default 1.5.
inline ParamInfo Eta() { return {"eta", 0.01, 100, 1.5, "index of refraction n (exact Fresnel)"}; }
/// k in [0, 100], default 0.
inline ParamInfo K() { return {"k", 0, 100, 0, "extinction coefficient k (conductor Fresnel)"}; }

/// sigma in radians, the Oren-Nayar family's roughness text.
constexpr const char* kSigmaText = "sigma = r (slope std. deviation, radians)";
/// pi / 2, the largest Oren-Nayar sigma.
constexpr double kHalfPi = Pi / 2;

}  // namespace kiln::model_list
