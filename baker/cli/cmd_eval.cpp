// kiln eval: the BRDF value f(o, l) (no cosine) of one model at one pair of directions.
#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"

namespace kiln::cli {

void RegisterEval(CLI::App& app) {
  auto* sub = app.add_subcommand("eval", "print the BRDF value f(o, l), cosine excluded");
  struct Args {
    std::string model;
    double mu_o = 1, mu_l = 1, phi = 0;
    ModelParamOptions params;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("--model,-m", args->model, "model id (see kiln list)")->required();
  sub->add_option("--mu-o", args->mu_o, "cos(theta_o) of the view direction, [0, 1]")->required();
  sub->add_option("--mu-l", args->mu_l, "cos(theta_l) of the light direction, [0, 1]")->required();
  sub->add_option("--phi", args->phi, "azimuth of l minus azimuth of o, radians");
  args->params.Add(sub);
  sub->callback([args] {
    auto check = [](const char* name, double x) {
      if (!(x >= 0 && x <= 1))
        throw std::invalid_argument(std::string("eval: ") + name + " = " + FullPrecision(x) +
                                    " is outside [0, 1]");
    };
    check("--mu-o", args->mu_o);
    check("--mu-l", args->mu_l);
    if (!std::isfinite(args->phi)) throw std::invalid_argument("eval: --phi must be finite");
    AnyModel model = MakeModel(args->model, args->params.Params());
    double f =
        Evaluate(model, ViewDirection(args->mu_o), DirectionFromMuPhi(args->mu_l, args->phi));
    std::printf("%s\n", FullPrecision(f).c_str());
  });
}

}  // namespace kiln::cli
