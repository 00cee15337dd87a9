#include "baker/fit/fit_verify.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "baker/tables/catalogue.h"

namespace kiln {

bool IsFitHeaderPath(const std::string& path) {
  const std::string tail = "-fit.h";
  return path.size() > tail.size() &&
         path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
}

FitVerifyResult VerifyFitHeader(const std::string& path, int threads) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("verify: cannot read '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  FitVerifyResult r;
  r.fit = ParseFitHeader(text.str(), path);
  const TableSpec spec = CatalogueTable(r.fit.form.table);
  if (spec.channels != r.fit.form.channels || spec.axes.size() != r.fit.form.axes.size())
    throw std::invalid_argument(path + ": its channels or axes are not those of table '" +
                                spec.name + "'");
  for (size_t d = 0; d < spec.axes.size(); ++d)
    if (spec.axes[d].name != r.fit.form.axes[d].name || spec.axes[d].lo != r.fit.form.axes[d].lo ||
        spec.axes[d].hi != r.fit.form.axes[d].hi)
      throw std::invalid_argument(path + ": axis " + r.fit.form.axes[d].name +
                                  " does not span table '" + spec.name + "''s domain");
  r.measured = MeasureFitError(spec, r.fit.form, threads);
  r.ok = r.measured.max <= r.fit.statedMax && r.measured.maxOffJump <= r.fit.statedOffJump;
  if (!r.ok) {
    char b[200];
    std::snprintf(b, sizeof b, "max error %.4g (off the jump %.4g) exceeds the stated %.3g (%.3g)",
                  r.measured.max, r.measured.maxOffJump, r.fit.statedMax, r.fit.statedOffJump);
    r.problem = b;
  }
  if (r.fit.specHash != spec.Hash())
    r.note = "fitted to spec " + r.fit.specHash + ", the table's spec is now " + spec.Hash();
  return r;
}

}  // namespace kiln
