// kiln integrate: one hemispherical integral, printed at full precision on one line.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/integrate/hemisphere.h"
#include "baker/tables/quantity.h"

namespace kiln::cli {

namespace {

/// The quantities `kiln integrate` offers, by their command name (alphabetical).
std::vector<const QuantityInfo*> Integrable() {
  std::vector<const QuantityInfo*> out;
  for (const QuantityInfo* q : AllQuantities())
    if (q->integrateName) out.push_back(q);
  std::sort(out.begin(), out.end(), [](const QuantityInfo* a, const QuantityInfo* b) {
    return std::string(a->integrateName) < b->integrateName;
  });
  return out;
}

}  // namespace

void RegisterIntegrate(CLI::App& app) {
  std::vector<std::string> names, help;
  for (const QuantityInfo* q : Integrable()) {
    names.push_back(q->integrateName);
    help.push_back(q->integrateHelp);
  }
  auto join = [](const std::vector<std::string>& items, const std::string& sep) {
    std::string s;
    for (const std::string& i : items) s += (s.empty() ? "" : sep) + i;
    return s;
  };
  auto* sub =
      app.add_subcommand("integrate", "print a hemispherical integral: " + join(help, ", "));
  struct Args {
    std::string quantity, model;
    double mu = 1, tol = 1e-9;
    bool stats = false;
    CLI::Option* oMu = nullptr;
    ModelParamOptions params;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("quantity", args->quantity, join(names, " | "))
      ->required()
      ->check(CLI::IsMember(names));
  sub->add_option("--model,-m", args->model, "model id (see kiln list)");
  args->oMu = sub->add_option("--mu", args->mu, "cos(theta_o), [0, 1]");
  sub->add_option("--tol", args->tol, "absolute tolerance")->capture_default_str();
  sub->add_flag("--stats", args->stats, "also print evaluations and seconds on stderr");
  args->params.Add(sub);
  sub->callback([args] {
    const std::string& q = args->quantity;
    const QuantityInfo* info = nullptr;
    for (const QuantityInfo* i : Integrable())
      if (q == i->integrateName) info = i;
    if (!info) throw std::invalid_argument("integrate: unknown quantity '" + q + "'");
    // Below 1e-13 the error estimates are rounding noise: the work grows without bound.
    if (!(args->tol >= 1e-13 && args->tol <= 0.1))
      throw std::invalid_argument("integrate: --tol " + FullPrecision(args->tol) +
                                  " must be in [1e-13, 0.1]");
    bool needsMu = info->integrateNeedsMu;
    if (needsMu && !args->oMu->count())
      throw std::invalid_argument("integrate " + q + ": needs --mu");
    if (!needsMu && args->oMu->count())
      throw std::invalid_argument("integrate " + q + ": takes no --mu");
    if (needsMu && !(args->mu >= 0 && args->mu <= 1))
      throw std::invalid_argument("integrate: --mu = " + FullPrecision(args->mu) +
                                  " is outside [0, 1]");
    IntegrateRequest request;
    request.name = q;
    request.model = args->model;
    request.mu = args->mu;
    request.tol = args->tol;
    IntegrationStats stats;
    auto t0 = std::chrono::steady_clock::now();
    std::string out = info->integrate(request, args->params.Params(), stats);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s\n", out.c_str());
    if (args->stats)
      std::fprintf(stderr, "evals %lld seconds %.6f error-estimate %.3g\n", stats.evals, seconds,
                   stats.errorEstimate);
  });
}

}  // namespace kiln::cli
