// kiln sample: the interpolated quantity of a table at one physical point. A table in a stored
// form (kiln/stored.h: a brdf table on cos(phi) or on symmetric axes storing f max(mu_l, mu_o),
// blinn-phong-normalization storing ratios) is looked up on the coordinates derived from the
// physical ones and its channels are turned back into the quantity.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/io/texture_readers.h"
#include "baker/tables/quantity.h"
#include "kiln/exr_loader.h"
#include "kiln/stored.h"

namespace kiln::cli {

void RegisterSample(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "sample", "print a table's interpolated quantity at X [Y [Z]] (a brdf table: mu_l mu_o phi)");
  struct Args {
    std::string file;
    std::vector<double> x;
    bool cubic = false, clamp = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("file", args->file,
                  "a kiln table: .exr, or .ktx2, .dds, .png as kiln bake --format writes them")
      ->required();
  sub->add_option("coords", args->x,
                  "the physical point, one value per axis: the axes' own parameters (see kiln "
                  "inspect), for a brdf table mu_l mu_o phi (phi in radians)")
      ->required();
  sub->add_flag("--cubic", args->cubic, "Catmull-Rom instead of linear interpolation");
  sub->add_flag("--clamp", args->clamp,
                "clamp a point outside the table's axes to them, with a warning on stderr "
                "(without it such a point is an error)");
  sub->callback([args] {
    Table t = LoadAnyTable(args->file);
    if (static_cast<int>(args->x.size()) != t.dims())
      throw std::invalid_argument("sample: '" + args->file + "' has " + std::to_string(t.dims()) +
                                  " axes, got " + std::to_string(args->x.size()) + " coordinates");
    for (double v : args->x)
      if (!std::isfinite(v)) throw std::invalid_argument("sample: coordinates must be finite");
    auto Short = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.6g", v);
      return std::string(buf);
    };
    // The domain of each coordinate the user gives: its axis, except for the brdf forms (mu_l
    // and mu_o on the mu axes, phi any angle) and unity-nhxroughness's (x, r) in [0, 1].
    struct Coordinate {
      std::string name;
      double lo, hi;
    };
    std::vector<Coordinate> domain;
    const StoredForm form = storedForm(t);
    for (std::size_t d = 0; d < t.axes.size(); ++d) {
      const TableAxis& a = t.axes[d];
      if (form == StoredForm::UnityLobe)
        domain.push_back({d ? "r" : "x", 0, 1});
      else if ((form == StoredForm::BrdfCosPhi || form == StoredForm::BrdfSymmetric) && d == 2)
        domain.push_back({"phi", -HUGE_VAL, HUGE_VAL});
      else if (form == StoredForm::BrdfSymmetric)
        domain.push_back({d ? "mu_o" : "mu_l", t.axes[0].axis.lo, t.axes[0].axis.hi});
      else
        domain.push_back({a.name, a.axis.lo, a.axis.hi});
    }
    // A kind whose axes are its whole domain (QuantityInfo::sceneDomain: the metals in the
    // visible of fresnel-conductor, the real dielectrics of fresnel-albedo; a Ward albedo, whose
    // roughness may start above 0; unity-nhxroughness's x and r) is defined there only: no
    // --clamp. Any other table clamps a point outside its axes only when --clamp is given.
    const QuantityInfo* kind = FindQuantity(t.quantity);
    const bool definedOnAxesOnly = form == StoredForm::ConductorResidual ||
                                   form == StoredForm::WardAlbedo ||
                                   form == StoredForm::UnityLobe || (kind && kind->sceneDomain);
    std::string whole;  // every bounded coordinate's domain, for the message
    for (const Coordinate& c : domain)
      if (std::isfinite(c.lo))
        whole += std::string(whole.empty() ? "" : ", ") + c.name + " in [" + Short(c.lo) + ", " +
                 Short(c.hi) + "]";
    std::string clamped;
    for (std::size_t d = 0; d < domain.size(); ++d) {
      const Coordinate& c = domain[d];
      const double v = args->x[d];
      if (v >= c.lo && v <= c.hi) continue;
      if (!args->clamp || definedOnAxesOnly)
        throw std::invalid_argument(
            "sample: " + c.name + " " + Short(v) + " is outside the domain of '" + args->file +
            "': " + whole +
            (definedOnAxesOnly ? " (the table is defined there only)" : " (--clamp clamps)"));
      clamped += std::string(clamped.empty() ? "" : ", ") + c.name + " " + Short(v) + " to " +
                 Short(std::min(std::max(v, c.lo), c.hi)) + " ([" + Short(c.lo) + ", " +
                 Short(c.hi) + "])";
    }
    if (!clamped.empty())
      std::fprintf(stderr, "kiln: warning: sample: clamped %s\n", clamped.c_str());
    std::vector<double> out(t.channels.size());
    sampleQuantity(t, args->x.data(), out.data(), args->cubic ? Filter::Cubic : Filter::Linear);
    std::string line;
    for (double v : out) line += (line.empty() ? "" : " ") + FullPrecision(v);
    std::printf("%s\n", line.c_str());
  });
}

}  // namespace kiln::cli
