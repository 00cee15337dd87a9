// kiln integrate: one hemispherical integral, printed at full precision on one line.
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/integrate/quantities.h"

namespace kiln::cli {

void RegisterIntegrate(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "integrate",
      "print a hemispherical integral: albedo (E at rho = 1, F = 1), albedo-avg, dfg (A B), "
      "fresnel-avg");
  struct Args {
    std::string quantity, model;
    double mu = 1, tol = 1e-9;
    bool stats = false;
    CLI::Option* oMu = nullptr;
    ModelParamOptions params;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("quantity", args->quantity, "albedo | albedo-avg | dfg | fresnel-avg")
      ->required()
      ->check(CLI::IsMember({"albedo", "albedo-avg", "dfg", "fresnel-avg"}));
  sub->add_option("--model,-m", args->model, "model id (see kiln list)");
  args->oMu = sub->add_option("--mu", args->mu, "cos(theta_o), [0, 1]");
  sub->add_option("--tol", args->tol, "absolute tolerance")->capture_default_str();
  sub->add_flag("--stats", args->stats, "also print evaluations and seconds on stderr");
  args->params.Add(sub);
  sub->callback([args] {
    const std::string& q = args->quantity;
    // Below 1e-13 the error estimates are rounding noise: the work grows without bound.
    if (!(args->tol >= 1e-13 && args->tol <= 0.1))
      throw std::invalid_argument("integrate: --tol " + FullPrecision(args->tol) + " must be in [1e-13, 0.1]");
    bool needsMu = q == "albedo" || q == "dfg";
    if (needsMu && !args->oMu->count()) throw std::invalid_argument("integrate " + q + ": needs --mu");
    if (!needsMu && args->oMu->count())
      throw std::invalid_argument("integrate " + q + ": takes no --mu");
    if (needsMu && !(args->mu >= 0 && args->mu <= 1))
      throw std::invalid_argument("integrate: --mu = " + FullPrecision(args->mu) +
                                  " is outside [0, 1]");
    IntegrationOptions opt;
    opt.tol = args->tol;
    IntegrationStats stats;
    auto t0 = std::chrono::steady_clock::now();
    std::string out;
    ModelParams p = args->params.Params();
    if (q == "fresnel-avg") {
      if (!args->model.empty()) throw std::invalid_argument("integrate fresnel-avg: takes no --model");
      if (!p.eta) throw std::invalid_argument("integrate fresnel-avg: needs --eta");
      if (!(*p.eta > 0 && *p.eta <= 100))
        throw std::invalid_argument("integrate fresnel-avg: --eta must be in (0, 100]");
      if (p.k && !(*p.k >= 0 && *p.k <= 100))
        throw std::invalid_argument("integrate fresnel-avg: --k must be in [0, 100]");
      if (p.roughness || p.rho || p.f0 || p.rs || p.nu || p.nv)
        throw std::invalid_argument("integrate fresnel-avg: takes only --eta and --k");
      out = FullPrecision(FresnelAverage(FresnelFromParams(p), opt, stats));
    } else {
      if (args->model.empty()) throw std::invalid_argument("integrate " + q + ": needs --model");
      // Albedo tables use F = 1 and rho = 1 unless a Fresnel parameter is given explicitly.
      AnyModel model = MakeModel(args->model, p);
      if (q == "albedo" || q == "albedo-avg") {
        RhoParts e = q == "albedo" ? DirectionalAlbedo(model, args->mu, opt, stats)
                                   : AverageAlbedo(model, opt, stats);
        double rho = p.rho.value_or(1);
        out = FullPrecision(e.At(rho));
      } else {
        auto ab = SplitSumDFG(model, args->mu, opt, stats);
        out = FullPrecision(ab[0]) + " " + FullPrecision(ab[1]);
      }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s\n", out.c_str());
    if (args->stats)
      std::fprintf(stderr, "evals %lld seconds %.6f error-estimate %.3g\n", stats.evals, seconds,
                   stats.errorEstimate);
  });
}

}  // namespace kiln::cli
