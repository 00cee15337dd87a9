// kiln fit TABLE [--max-error E | --terms N] [--out DIR]: a closed form of a table's exact
// integrals with a verified bound (baker/fit/, docs/fits.md).
#include <sys/stat.h>

#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/fit/fit_writer.h"
#include "baker/io/atomic_write.h"
#include "baker/tables/catalogue.h"

namespace kiln::cli {

namespace {
/// The bound `kiln fit` aims at without --max-error or --terms.
constexpr double kDefaultFitMaxError = 2e-3;
}  // namespace

void RegisterFit(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "fit",
      "fit a closed form (Chebyshev polynomial in warped axes, or Horner's rule for one axis) "
      "to a 1D or 2D table's exact "
      "integrals; writes DIR/TABLE-fit.h, .glsl, .hlsl stating the max error found by a search");
  struct Args {
    std::string table, out = ".";
    double maxError = 0;
    int terms = 0, threads = 0;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("table", args->table, "catalogue table name (kiln list --tables)")->required();
  auto* oMax = sub->add_option("--max-error", args->maxError,
                               "the cheapest form whose searched max error is at most E "
                               "(default 2e-3)");
  auto* oTerms = sub->add_option("--terms", args->terms,
                                 "the best form with at most N coefficients per channel");
  oMax->excludes(oTerms);
  sub->add_option("--out", args->out, "output folder")->capture_default_str();
  sub->add_option("-j,--threads", args->threads, "threads (default: all cores)");
  sub->callback([args, oMax, oTerms] {
    CheckThreads("fit", args->threads);
    if (oMax->count() && !(args->maxError >= 1e-6 && args->maxError <= 1))
      throw std::invalid_argument("fit: --max-error " + FullPrecision(args->maxError) +
                                  " must be in [1e-6, 1]");
    if (oTerms->count() && !(args->terms >= 2 && args->terms <= 289))
      throw std::invalid_argument("fit: --terms " + std::to_string(args->terms) +
                                  " must be in [2, 289]");
    struct stat st {};
    if (stat(args->out.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
      throw std::invalid_argument("fit: --out '" + args->out + "' is not a folder");
    TableSpec spec = CatalogueTable(args->table);
    FitOptions opt;
    opt.threads = args->threads;
    opt.terms = oTerms->count() ? args->terms : 0;
    opt.maxError = oMax->count() ? args->maxError : kDefaultFitMaxError;
    FitResult fit = FitTable(spec, opt);
    const std::string base = args->out + "/" + spec.name + "-fit";
    PendingFile h(base + ".h"), g(base + ".glsl"), l(base + ".hlsl");
    h.WriteBytes(FitCppHeader(fit, KILN_VERSION));
    g.WriteBytes(FitGlsl(fit, KILN_VERSION));
    l.WriteBytes(FitHlsl(fit, KILN_VERSION));
    PendingFile::CommitAll({&h, &g, &l});
    std::printf(
        "%s: max error %.3e (off the jump %.3e, median %.3e) over %lld points; "
        "%s form, %d terms per channel, %d operations; wrote %s.{h,glsl,hlsl}\n",
        spec.name.c_str(), fit.error.max, fit.error.maxOffJump, fit.error.median, fit.error.points,
        FitBasisName(fit.form.basis), fit.form.TermsPerChannel(), fit.form.OperationCount(),
        base.c_str());
  });
}

}  // namespace kiln::cli
