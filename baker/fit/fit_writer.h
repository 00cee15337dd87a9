// The files `kiln fit` writes (DIR/TABLE-fit.h, .glsl, .hlsl) and the reading of a header back
// (`kiln verify DIR/TABLE-fit.h`). Each file states in a comment the fit's max error over the
// table's whole declared domain, its operation count and its coefficients' source, and carries
// the form on one machine-readable line ("// kiln-fit-form: ...").
#pragma once
#include <string>

#include "baker/fit/fit.h"

namespace kiln {

/// "kiln_fit_" + the table's name with '-' as '_'.
std::string FitFunctionName(const std::string& table);

/// The bound a file states: the measured max rounded up to three significant digits.
double StatedBound(double measured);

/// The C++ header: `inline void kiln_fit_NAME(const float* x, float* out)` (x: axis values in
/// the table's order, out: its channels), the same float operations as EvaluateFit.
std::string FitCppHeader(const FitResult& fit, const std::string& kilnVersion);
/// The GLSL function `floatN kiln_fit_NAME(floatD x)` (float, vec2 .. vec4; GLSL ES 3.00 and
/// 3.30 and later).
std::string FitGlsl(const FitResult& fit, const std::string& kilnVersion);
/// The HLSL function (Shader Model 5 and later), as the GLSL.
std::string FitHlsl(const FitResult& fit, const std::string& kilnVersion);

/// What a fit header states.
struct ParsedFit {
  FitForm form;
  double statedMax = 0;      ///< its "max error E"
  double statedOffJump = 0;  ///< its max error off the mirror's jump (fit.h kLayerJumpMu)
  std::string specHash;      ///< the spec hash of the table it was fitted to
};

/// Reads a header FitCppHeader wrote: the form line, the coefficients, the stated bound.
/// Throws std::invalid_argument naming the file and what is missing.
ParsedFit ParseFitHeader(const std::string& text, const std::string& path);

}  // namespace kiln
