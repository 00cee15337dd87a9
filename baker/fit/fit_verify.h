// `kiln verify DIR/TABLE-fit.h`: re-measures a fit's max error by the search of fit.h, from the
// form and coefficients the header states, and compares it with the bound the header states.
#pragma once
#include <string>

#include "baker/fit/fit_writer.h"

namespace kiln {

struct FitVerifyResult {
  ParsedFit fit;
  FitErrorReport measured;
  bool ok = false;
  std::string problem;  ///< one line when !ok
  std::string note;     ///< one line when the table's spec changed since the fit (still measured)
};

/// True when `path` names a fit header (ends in "-fit.h").
bool IsFitHeaderPath(const std::string& path);

/// Verifies the fit header at `path` (its table must be in kiln's catalogue): ok when the
/// re-measured max is at most the stated one. Throws std::invalid_argument for a file that does not
/// read as a fit.
FitVerifyResult VerifyFitHeader(const std::string& path, int threads);

}  // namespace kiln
