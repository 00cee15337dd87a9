// kiln inspect: a table's attributes and channel ranges, optionally a false-colour picture.
#include <algorithm>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <fstream>
#include <set>

#include "baker/bake/axis_budget.h"
#include "baker/cli/commands.h"
#include "baker/io/table_json.h"
#include "baker/io/texture_readers.h"
#include "baker/io/atomic_write.h"
#include "baker/io/png_writer.h"
#include "kiln/exr_loader.h"

namespace kiln::cli {
namespace {

/// `kiln inspect --json`: the file's attributes and per-channel ranges as one JSON object.
std::string InspectJson(const std::string& file, const Table& t, const std::string& png) {
  using nlohmann::ordered_json;
  ordered_json doc;
  doc["file"] = file;
  doc["name"] = t.name;
  doc["generator"] = t.generator;
  doc["format"] = kFormatVersion;
  doc["model"] = t.model;
  doc["quantity"] = t.quantity;
  doc["params"] = t.params;
  doc["axes"] = AxesJson(t.axes);
  doc["method"] = t.method;
  doc["tolerance"] = t.tolerance;
  doc["bake_error"] = t.bakeError;
  doc["lookup_error"] = {{"max", t.lookupError.max},
                         {"rms", t.lookupError.rms},
                         {"filter", t.lookupError.filter},
                         {"where", t.lookupError.where},
                         {"cubic_max", t.lookupError.cubicMax},
                         {"cubic_rms", t.lookupError.cubicRms}};
  doc["spec_hash"] = t.specHash;
  doc["channels"] = ordered_json::array();
  size_t nc = t.channels.size();
  for (size_t c = 0; c < nc; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = c; i < t.data.size(); i += nc) {
      lo = std::min(lo, static_cast<double>(t.data[i]));
      hi = std::max(hi, static_cast<double>(t.data[i]));
    }
    doc["channels"].push_back(
        {{"name", t.channels[c]},
         {"meaning", c < t.channelMeanings.size() ? t.channelMeanings[c] : ""},
         {"min", lo},
         {"max", hi}});
  }
  if (!png.empty()) doc["png"] = png;
  return doc.dump(2) + "\n";
}

/// The file channel that holds each storage channel of the (already loaded) table at `path`: in
/// an EXR of today's layout Y (1 channel) or R, G, B, A, in one of layout 1 R, G, B, A, in
/// older ones the kiln names (the loader's rule); in KTX2, DDS and PNG16 R, G, B, A. A table
/// stored in parts (more than 4 channels) names part 2's channels "2:R", "2:G", ...
std::vector<std::string> ExrChannelsOf(const std::string& path, const Table& t) {
  const int parts = tablePartCount(t.channels.size());
  char head[12] = {};
  std::ifstream(path, std::ios::binary).read(head, sizeof head);
  const bool exr = SniffTableFile(std::string(head, sizeof head)) == TableFileKind::Exr;
  if (parts > 1 || !exr) {
    std::vector<std::string> out;
    for (int p = 1; p <= parts; ++p) {
      const std::size_t first = std::size_t(p - 1) * kMaxChannelsPerFile;
      const std::size_t count =
          std::min<std::size_t>(kMaxChannelsPerFile, t.channels.size() - first);
      for (const std::string& n : exr ? exrChannelNames(count) : exrLayout1ChannelNames(count))
        out.push_back(p > 1 ? std::to_string(p) + ":" + n : n);
    }
    return out;
  }
  std::set<std::string> inFile;
  Imf::InputFile file(path.c_str());
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
    inFile.insert(it.name());
  const std::size_t nc = t.channels.size();
  const std::vector<std::string> today = exrFileChannels(nc), layout1 = exrLayout1ChannelNames(nc);
  if (!today.empty() && inFile == std::set<std::string>(today.begin(), today.end()))
    return exrChannelNames(nc);
  if (!layout1.empty() && inFile == std::set<std::string>(layout1.begin(), layout1.end()))
    return layout1;
  return t.channels;
}

}  // namespace

void RegisterInspect(CLI::App& app) {
  auto* sub = app.add_subcommand("inspect", "print a table's attributes and per-channel ranges");
  struct Args {
    std::string file, png;
    bool json = false;
    bool axes = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("file", args->file,
                  "a kiln table: .exr, or .ktx2, .dds, .png as kiln bake --format writes them")
      ->required();
  sub->add_option("--png", args->png, "also write a false-colour PNG of every channel");
  sub->add_flag("--json", args->json,
                "print the attributes as one JSON object on stdout (keys: docs/cli.md)");
  sub->add_flag("--axes", args->axes,
                "also print each channel's linear-interpolation error budget per axis: the max "
                "of h^2 f''/8 from the node values (warped coordinates), where, and its profile "
                "along the axis");
  sub->callback([args] {
    // A device, FIFO, link or folder at --png is refused before anything is printed.
    if (!args->png.empty()) CheckWritableTarget(args->png);
    Table t = LoadAnyTable(args->file);
    if (args->json) {
      if (!args->png.empty()) writeFalseColourPng(args->png, t);
      std::fputs(InspectJson(args->file, t, args->png).c_str(), stdout);
      return;
    }
    std::printf("file            %s\n", args->file.c_str());
    std::printf("name            %s\n", t.name.c_str());
    std::printf("generator       %s (format %d)\n", t.generator.c_str(), kFormatVersion);
    std::printf("model           %s\n", t.model.c_str());
    std::printf("quantity        %s\n", t.quantity.c_str());
    std::printf("params          %s\n", t.params.empty() ? "(none)" : t.params.c_str());
    for (int d = 0; d < t.dims(); ++d) {
      const TableAxis& a = t.axes[d];
      std::printf("axis %d          %s [%.17g, %.17g] %d nodes, %s warp", d, a.name.c_str(),
                  a.axis.lo, a.axis.hi, a.axis.size, warpName(a.axis.warp));
      if (a.axis.hasConstantSplit()) std::printf(", split at %.17g", a.axis.split);
      std::printf("\n");
    }
    std::printf("method          %s\n", t.method.c_str());
    std::printf("tolerance       %.3g\n", t.tolerance);
    std::printf("bake error      %.3g\n", t.bakeError);
    std::printf("lookup error    max %.3g rms %.3g (%s) at %s\n", t.lookupError.max,
                t.lookupError.rms, t.lookupError.filter.c_str(), t.lookupError.where.c_str());
    if (t.lookupError.cubicMax >= 0)
      std::printf("lookup cubic    max %.3g rms %.3g (same points)\n", t.lookupError.cubicMax,
                  t.lookupError.cubicRms);
    if (t.fitError.max >= 0)
      std::printf("fit error       max %.3g rms %.3g; polygon max %.3g rms %.3g (%s)\n",
                  t.fitError.max, t.fitError.rms, t.fitError.polygonMax, t.fitError.polygonRms,
                  t.fitError.method.c_str());
    std::printf("spec hash       %s\n", t.specHash.c_str());
    size_t nc = t.channels.size();
    const std::vector<std::string> exrNames = ExrChannelsOf(args->file, t);
    for (size_t c = 0; c < nc; ++c) {
      double lo = INFINITY, hi = -INFINITY;
      for (size_t i = c; i < t.data.size(); i += nc) {
        lo = std::min(lo, static_cast<double>(t.data[i]));
        hi = std::max(hi, static_cast<double>(t.data[i]));
      }
      // EXR channel = kiln name (kiln.channels), range, meaning (kiln.channel_meanings).
      std::printf("channel %s = %-8s [%.9g, %.9g]  %s\n", exrNames[c].c_str(),
                  t.channels[c].c_str(), lo, hi,
                  c < t.channelMeanings.size() ? t.channelMeanings[c].c_str() : "");
    }
    if (args->axes) {
      for (const AxisBudget& b : AxisErrorBudget(t.view())) {
        std::printf(
            "budget %s along %s: max %.3g at node (%d, %d, %d) =", t.channels[b.channel].c_str(),
            t.axes[b.axis].name.c_str(), b.max, b.node[0], b.node[1], b.node[2]);
        for (int d = 0; d < t.dims(); ++d)
          std::printf(" %s=%.6g", t.axes[d].name.c_str(), b.where[d]);
        std::printf("\n  profile:");
        for (double p : b.profile) std::printf(" %.2g", p);
        std::printf("\n");
      }
    }
    if (!args->png.empty()) {
      writeFalseColourPng(args->png, t);
      std::printf("png             %s\n", args->png.c_str());
    }
  });
}

}  // namespace kiln::cli
