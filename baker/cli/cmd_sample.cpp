// kiln sample: the interpolated channels of a table at one point, in the file's own units.
#include <cstdio>
#include <stdexcept>

#include "baker/cli/commands.h"
#include "baker/io/texture_readers.h"
#include "kiln/exr_loader.h"

namespace kiln::cli {

void RegisterSample(CLI::App& app) {
  auto* sub = app.add_subcommand("sample", "print a table's interpolated channels at X [Y [Z]]");
  struct Args {
    std::string file;
    std::vector<double> x;
    bool cubic = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("file", args->file,
                  "a kiln table: .exr, or .ktx2, .dds, .png as kiln bake --format writes them")
      ->required();
  sub->add_option("coords", args->x, "one value per axis, in axis order (see kiln inspect)")
      ->required();
  sub->add_flag("--cubic", args->cubic, "Catmull-Rom instead of linear interpolation");
  sub->callback([args] {
    Table t = LoadAnyTable(args->file);
    if (static_cast<int>(args->x.size()) != t.dims())
      throw std::invalid_argument("sample: '" + args->file + "' has " + std::to_string(t.dims()) +
                                  " axes, got " + std::to_string(args->x.size()) + " coordinates");
    for (double v : args->x)
      if (!std::isfinite(v)) throw std::invalid_argument("sample: coordinates must be finite");
    std::vector<float> out(t.channels.size());
    t.view().sample(args->x.data(), out.data(), args->cubic ? Filter::Cubic : Filter::Linear);
    std::string line;
    for (float v : out) line += (line.empty() ? "" : " ") + FullPrecision(v);
    std::printf("%s\n", line.c_str());
  });
}

}  // namespace kiln::cli
