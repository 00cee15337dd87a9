// The atlas's table approximations: the list, the measurement, the CSV, PNG and tables.md.
#include "baker/atlas/atlas_tables.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "baker/fit/engine_approximations.h"
#include "baker/integrate/hemisphere.h"
#include "baker/tables/catalogue.h"

namespace kiln {
namespace {

/// The sheen tables: Filament and three.js evaluate the Charlie lobe with Neubelt's visibility
/// (`charlie-dfg`); the glTF sheen extension with Estevez and Kulla's Smith term
/// (`charlie-smith-dfg`).
const char* kSheenNote =
    "E, the sheen lobe's directional albedo at F = 1 (the shader multiplies it by the sheen "
    "colour and the radiance). three.js's direct-light sheen (BRDF_Sheen) is Charlie D with "
    "Neubelt's visibility V_Neubelt, kiln's `charlie`, so its table `charlie-dfg` is the one this "
    "stands for; the fit's comment cites Estevez and Kulla 2017, whose own visibility is kiln's "
    "`charlie-smith`: the row against `charlie-smith-dfg` gives that comparison";

}  // namespace

const std::vector<TableApproximation>& TableApproximations() {
  using W = FitWarp;
  static const std::vector<TableApproximation> list = {
      {"karis-envbrdfapprox", "EnvBRDFApprox",
       "Karis 2014, \"Physically Based Shading on Mobile\" (Unreal Engine 4's mobile path; "
       "three.js's former DFGApprox)",
       "ggx-dfg", KarisEnvBrdfApprox, W::Layer, W::Sqrt,
       "(A, B) of GGX at the perceptual roughness (alpha = r^2), the published formula in float"},
      {"three-dfg-lut", "DFGLUTData (16 x 16)",
       "three.js, src/renderers/shaders/DFGLUTData.js (MIT; the texels in "
       "baker/fit/three_dfg_lut_data.cpp)",
       "ggx-dfg", ThreeDfgLutLookup, W::Layer, W::Sqrt,
       "(A, B) = the RG16F texture sampled bilinearly at texel centres (i + 0.5) / 16, clamp to "
       "edge, u = roughness, v = mu"},
      {"lazarov-environment-brdf", "EnvironmentBRDF (gloss)",
       "Lazarov 2013, \"Getting More Physical in Call of Duty: Black Ops II\" (SIGGRAPH course; "
       "the form Karis 2014 quotes)",
       "ggx-dfg", LazarovEnvironmentBrdf, W::Layer, W::Sqrt,
       "gloss g = log(2/r^4 - 2) / log(8192) clamped to [0, 1]: Black Ops's Blinn-Phong exponent "
       "n = 8192^g (Lazarov 2011, 2013) matched to alpha = r^2 by n = 2/alpha^2 - 2 (Walter et al. "
       "2007); B = saturate(a0) (its result at f0 = 0), A = saturate(a1) - B (f0 = 1). Lazarov "
       "fitted his own Blinn-Phong lobe, not GGX: this measures it as the GGX DFG it replaces"},
      {"three-sheen", "IBLSheenBRDF",
       "three.js, lights_physical_pars_fragment.glsl.js (MIT), the "
       "releases with DFGLUTData",
       "charlie-dfg", ThreeSheenAlbedo, W::Sqrt, W::Root4,
       std::string("E = saturate(exp(a mu + b)) (the shader multiplies it by irradiance / pi); ") +
           kSheenNote},
      {"three-sheen-vs-charlie-smith", "IBLSheenBRDF", "as three-sheen", "charlie-smith-dfg",
       ThreeSheenAlbedo, W::Sqrt, W::Root4, "three-sheen against Estevez and Kulla's visibility"},
      {"three-sheen-former", "IBLSheenBRDF (former)",
       "three.js, lights_physical_pars_fragment.glsl.js (MIT), the releases with DFGApprox",
       "charlie-dfg", ThreeSheenAlbedoFormer, W::Sqrt, W::Root4,
       std::string("E = pi saturate(DG / pi), DG the two-branch fit (split at r = 0.25; the "
                   "shader multiplies saturate(DG / pi) by the irradiance); ") +
           kSheenNote},
      {"three-sheen-former-vs-charlie-smith", "IBLSheenBRDF (former)", "as three-sheen-former",
       "charlie-smith-dfg", ThreeSheenAlbedoFormer, W::Sqrt, W::Root4,
       "three-sheen-former against Estevez and Kulla's visibility"},
  };
  return list;
}

TableApproximationResult ComputeTableApproximation(const TableApproximation& approx,
                                                   const AtlasOptions& opt) {
  const TableSpec spec = CatalogueTable(approx.table);
  if (spec.axes.size() != 2 || spec.axes[0].name != "mu" || spec.axes[1].name != "roughness")
    throw std::invalid_argument("atlas: table '" + approx.table + "' is not (mu, roughness)");
  if (opt.muNodes < 2 || opt.roughnessNodes < 2)
    throw std::invalid_argument("atlas: the grid needs at least two nodes per axis");
  TableApproximationResult res;
  res.approx = approx;
  res.channels = Skeleton(spec).channels;
  res.report = MeasureFitError(spec, ProbeForm(spec, approx.muWarp, approx.roughnessWarp),
                               std::max(1, opt.threads), approx.eval);
  TableSpec off = spec;
  off.axes[0].lo = kTableApproxOffGrazingMu;
  res.offGrazing = MeasureFitError(off, ProbeForm(off, approx.muWarp, approx.roughnessWarp),
                                   std::max(1, opt.threads), approx.eval);
  res.method = spec.Method();
  res.nMu = opt.muNodes;
  res.nR = opt.roughnessNodes;
  const size_t n = static_cast<size_t>(res.nMu) * res.nR, nc = res.channels.size();
  res.mu.resize(n);
  res.roughness.resize(n);
  res.exact.resize(n * nc);
  res.approximate.resize(n * nc);
  const double lo = spec.axes[1].lo, hi = spec.axes[1].hi;
  auto point = [&](size_t k) {
    const int j = static_cast<int>(k % res.nMu), i = static_cast<int>(k / res.nMu);
    // The point in float (what the approximation sees), the exact integral there.
    const float xf[2] = {static_cast<float>(double(j) / (res.nMu - 1)),
                         static_cast<float>(lo + (hi - lo) * i / (res.nR - 1))};
    const double x[2] = {xf[0], xf[1]};
    IntegrationStats stats;
    const std::vector<double> e = EvaluateSpec(spec, x, stats);
    float a[4] = {0, 0, 0, 0};
    approx.eval(FitForm(), xf, a);
    res.mu[k] = x[0];
    res.roughness[k] = x[1];
    for (size_t c = 0; c < nc; ++c) {
      res.exact[k * nc + c] = e[c];
      res.approximate[k * nc + c] = a[c];
    }
  };
  tbb::task_arena arena(std::max(1, opt.threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t k = r.begin(); k != r.end(); ++k) point(k);
    });
  });
  return res;
}

std::string TableApproximationCsv(const TableApproximationResult& r) {
  std::string out = "mu,roughness";
  for (const std::string& c : r.channels) out += ",exact_" + c;
  for (const std::string& c : r.channels) out += ",approx_" + c;
  out += ",max_abs_err\n";
  const size_t nc = r.channels.size();
  for (size_t k = 0; k < r.mu.size(); ++k) {
    out += AtlasNumber(r.mu[k], "%.9g") + "," + AtlasNumber(r.roughness[k], "%.9g");
    double worst = 0;
    for (size_t c = 0; c < nc; ++c) out += "," + AtlasNumber(r.exact[k * nc + c], "%.9g");
    for (size_t c = 0; c < nc; ++c) {
      out += "," + AtlasNumber(r.approximate[k * nc + c], "%.9g");
      worst = std::max(worst, std::abs(r.approximate[k * nc + c] - r.exact[k * nc + c]));
    }
    out += "," + AtlasNumber(worst, "%.9g") + "\n";
  }
  return out;
}

std::string TableApproximationPng(const TableApproximationResult& r) {
  const size_t nc = r.channels.size();
  std::vector<HeatmapPanel> panels;
  for (size_t c = 0; c < nc; ++c) {
    HeatmapPanel p{"approx - exact, " + r.channels[c], {}, false, "error"};
    for (size_t k = 0; k < r.mu.size(); ++k)
      p.values.push_back(r.approximate[k * nc + c] - r.exact[k * nc + c]);
    panels.push_back(std::move(p));
  }
  // A log scale shows the error away from a singular corner (the sheen's grazing rim).
  HeatmapPanel worst{"max abs error over the channels", {}, true, "abs error"};
  for (size_t k = 0; k < r.mu.size(); ++k) {
    double w = 0;
    for (size_t c = 0; c < nc; ++c)
      w = std::max(w, std::abs(r.approximate[k * nc + c] - r.exact[k * nc + c]));
    worst.values.push_back(w);
  }
  panels.push_back(std::move(worst));
  return HeatmapPng(r.approx.name + ":  " + r.approx.label + "  vs  " + r.approx.table, panels,
                    r.nMu, r.nR, r.mu.front(), r.mu.back(), r.roughness.front(), r.roughness.back(),
                    "roughness");
}

std::string TableApproximationsReadme(const std::vector<TableApproximationResult>& results,
                                      const AtlasOptions& opt, const std::string& command) {
  std::string s = "# Error atlas: table approximations\n\n";
  s += "Generated by `" + command +
       "` (baker/atlas/atlas_tables.cpp; this file too: do not edit "
       "by hand). The pairs of BRDFs are in [README.md](README.md).\n\n";
  s +=
      "Closed forms and small tables engines ship in place of one of kiln's tables, each against "
      "the exact integrals of the kiln table it stands for (`kiln list --tables`; the table's "
      "own method, never its interpolation). `max` and `median` of |approx - exact| (the "
      "largest over the channels) come from the search `kiln fit` and `kiln verify` use "
      "(docs/fits.md): a 129 x 129 grid uniform in the probe warps of (mu, roughness), edges "
      "included, 2048 fixed-seed random points, then climbs from the 12 worst; the median is "
      "over the grid, so it depends on the warps (`layer` and `root4` put most points at "
      "grazing and low roughness). Per approximation: `<name>.csv` on a " +
      std::to_string(opt.muNodes) + " x " + std::to_string(opt.roughnessNodes) + " grid (mu = j/" +
      std::to_string(opt.muNodes - 1) +
      ", roughness over the table's domain, ends included; columns mu, roughness, exact_<ch>, "
      "approx_<ch>, max_abs_err) and `<name>.png` (approx - exact per channel, then the max abs "
      "error over the channels, on a log10 scale where it spans more than three decades). `max, mu "
      ">= 1/4` "
      "is the same search over views with mu >= 1/4 only: there Neubelt's sheen visibility "
      "1 / (4 (mu_o + mu_l - mu_o mu_l)) is at most 1 for every light, so three.js's saturate of "
      "it never acts (kiln's `charlie`, like Filament's, has no clamp); for the GGX tables it is "
      "the max off grazing. Filament ships no closed form for its cloth or sheen: its shaders read "
      "the cloth DFG from the DFG texture's third channel (PrefilteredDFG_LUT), a table measured "
      "against kiln in [docs/engines.md](../engines.md).\n\n";
  s += "`max off the jump` leaves out the segment roughness = 0, mu < 1e-9 of a microfacet "
       "table, where kiln's exact integrals jump to the mirror's (docs/fits.md, \"The mirror's "
       "jump\"); for the other tables it equals `max`.\n\n";
  s += "| approximation | engine / source | kiln table | probe warps (mu x r) | max | max off the "
       "jump | median | max at (mu, r) | max, mu >= 1/4 | at (mu, r) |\n";
  s += "|---|---|---|---|---|---|---|---|---|---|\n";
  auto at = [](const FitErrorReport& e) {
    return e.where.size() == 2 ? "(" + AtlasNumber(e.where[0], "%.3g") + ", " +
                                     AtlasNumber(e.where[1], "%.3g") + ")"
                               : std::string();
  };
  for (const TableApproximationResult& r : results) {
    const FitErrorReport& e = r.report;
    s += "| [" + r.approx.name + "](" + r.approx.name + ".png) `" + r.approx.label + "` | " +
         r.approx.source + " | `" + r.approx.table + "` | " + FitWarpName(r.approx.muWarp) + " x " +
         FitWarpName(r.approx.roughnessWarp) + " | " + AtlasNumber(e.max, "%.3f") + " | " +
         AtlasNumber(e.maxOffJump, "%.3f") + " | " + AtlasNumber(e.median, "%.3g") + " | " + at(e) +
         " | " + AtlasNumber(r.offGrazing.max, "%.3f") + " | " + at(r.offGrazing) + " |\n";
  }
  s += "\n## What is compared\n\n";
  for (const TableApproximationResult& r : results) {
    s += "- **" + r.approx.name + "**: " + r.approx.note + ".\n";
    s += "  Exact: `" + r.approx.table + "`, " + r.method + ".\n";
  }
  s += "\nRegenerate: `" + command + "`.\n";
  return s;
}

}  // namespace kiln
