// The atlas's plots (two heatmaps per pair, io/png_writer + io/bitmap_font) and its README.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "baker/atlas/atlas.h"
#include "baker/io/bitmap_font.h"
#include "baker/io/png_writer.h"

namespace kiln {
namespace {

const std::uint8_t kWhite[3] = {230, 230, 230};
const std::uint8_t kGrey[3] = {150, 150, 150};

/// One heatmap panel: values v (mu fastest) coloured over [lo, hi] with viridis.
struct Panel {
  std::string title;
  std::vector<double> v;
  double lo, hi;
  bool log10;
};

Panel MakePanel(const std::string& title, std::vector<double> v, bool allowLog) {
  double lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
  Panel p{title, std::move(v), lo, hi, false};
  if (allowLog && hi > 0 && (lo <= 0 || hi / lo > 1e3)) {
    // Spans more than three decades (or reaches 0): log10, floored six decades below the top.
    double floor = hi * 1e-6;
    for (double& x : p.v) x = std::log10(std::max(x, floor));
    p.lo = *std::min_element(p.v.begin(), p.v.end());
    p.hi = std::log10(hi);
    p.log10 = true;
    p.title = "log10 " + p.title;
  }
  return p;
}

void Fill(std::vector<std::uint8_t>& img, int width, int x0, int y0, int w, int h,
          const std::uint8_t rgb[3]) {
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x)
      for (int c = 0; c < 3; ++c) img[(static_cast<size_t>(y) * width + x) * 3 + c] = rgb[c];
}

}  // namespace

std::string AtlasNumber(double x, const char* fmt) {
  char b[64];
  std::snprintf(b, sizeof b, fmt, x);
  return b;
}

std::string HeatmapPng(const std::string& heading, const std::vector<HeatmapPanel>& in, int nMu,
                       int nR, double muFirst, double muLast, double rFirst, double rLast,
                       const std::string& axis) {
  std::vector<Panel> panels;
  for (const HeatmapPanel& h : in) panels.push_back(MakePanel(h.title, h.values, h.allowLog));
  const int cellW = std::max(1, 256 / nMu), cellH = std::max(1, 256 / nR);
  const int imgW = cellW * nMu, imgH = cellH * nR;
  const int left = 64, gap = 40, top = 52;
  const int panelW = left + imgW + gap;
  const int slots = std::max<int>(2, static_cast<int>(panels.size()));
  const int width = slots * panelW + 16, height = top + imgH + 80;
  std::vector<std::uint8_t> img(static_cast<size_t>(width) * height * 3, 24);
  DrawText(img, width, height, 8, 6, heading, kWhite);
  for (size_t k = 0; k < panels.size(); ++k) {
    const Panel& p = panels[k];
    const int x0 = static_cast<int>(k) * panelW + left;
    DrawText(img, width, height, x0, 22, p.title, kWhite);
    DrawText(img, width, height, x0 - left + 4, 38, axis + " (up)", kGrey);
    double span = p.hi - p.lo;
    for (int i = 0; i < nR; ++i)
      for (int j = 0; j < nMu; ++j) {
        double t = span > 0 ? (p.v[static_cast<size_t>(i) * nMu + j] - p.lo) / span : 0.5;
        std::uint8_t rgb[3];
        viridis(t, rgb);
        Fill(img, width, x0 + j * cellW, top + (nR - 1 - i) * cellH, cellW, cellH, rgb);
      }
    // y axis: roughness, first node at the bottom.
    DrawText(img, width, height, x0 - TextWidth(AtlasNumber(rLast)) - 4, top, AtlasNumber(rLast),
             kWhite);
    DrawText(img, width, height, x0 - TextWidth(AtlasNumber(rFirst)) - 4, top + imgH - 7,
             AtlasNumber(rFirst), kWhite);
    // x axis: mu.
    const int xa = top + imgH + 4;
    DrawText(img, width, height, x0, xa, AtlasNumber(muFirst), kWhite);
    DrawText(img, width, height, x0 + imgW - TextWidth(AtlasNumber(muLast)), xa,
             AtlasNumber(muLast), kWhite);
    DrawText(img, width, height, x0 + imgW / 2 - TextWidth("mu (view)") / 2, xa, "mu (view)",
             kGrey);
    // Colour bar with its ends.
    const int yb = xa + 16;
    for (int x = 0; x < imgW; ++x) {
      std::uint8_t rgb[3];
      viridis(imgW > 1 ? double(x) / (imgW - 1) : 0.5, rgb);
      Fill(img, width, x0 + x, yb, 1, 10, rgb);
    }
    std::string lo = AtlasNumber(p.lo, "%.3g"), hi = AtlasNumber(p.hi, "%.3g");
    DrawText(img, width, height, x0, yb + 14, lo, kWhite);
    DrawText(img, width, height, x0 + imgW - TextWidth(hi), yb + 14, hi, kWhite);
    const std::string unit = p.log10 ? "log10 " + in[k].unit : in[k].unit;
    DrawText(img, width, height, x0 + imgW / 2 - TextWidth(unit) / 2, yb + 14, unit, kGrey);
  }
  return encodePngRgb8(width, height, img);
}

std::string AtlasPng(const AtlasResult& r) {
  std::vector<double> dE, df;
  for (const AtlasCell& c : r.cells) {
    dE.push_back(c.dE);
    df.push_back(c.maxDf);
  }
  auto sideText = [](const AtlasSide& x) {
    std::string t = x.params.empty() ? x.model : x.model + " " + x.params;
    if (x.rescale == AtlasRescale::BlinnPhong204) t += " (s+2.04)/(8 pi)";
    if (x.map == AtlasRoughnessMap::FujiiSigmaPrime) t += " with sigma prime = B/A";
    return t;
  };
  const std::vector<HeatmapPanel> panels = {
      {"dE = E_cheap - E_ref", dE, false, "dE"},
      {"max_wi (f_cheap - f_ref) mu_i  abs", df, true, "max_df"}};
  const AtlasCell& first = r.cells.front();
  const AtlasCell& last = r.cells.back();
  return HeatmapPng(r.pair.name + ":  " + sideText(r.pair.cheap) + "  vs  " + sideText(r.pair.ref),
                    panels, r.nMu, r.nR, first.mu, last.mu, first.roughness, last.roughness,
                    r.pair.axis);
}

std::string AtlasReadme(const std::vector<AtlasResult>& results, const AtlasOptions& opt,
                        const std::string& command) {
  std::string s;
  s += "# Error atlas of the cheap approximations\n\n";
  s += "Generated by `" + command + "` (baker/atlas/; this file too: do not edit by hand).\n\n";
  s += "For each pair, over a grid of " + std::to_string(opt.muNodes) + " view cosines mu = j/" +
       std::to_string(opt.muNodes) + " (j = 1.." + std::to_string(opt.muNodes) + ") by " +
       std::to_string(opt.roughnessNodes) +
       " roughness values (lo..hi, ends included), at rho = 1:\n\n";
  s += "- `dE = E_cheap - E_ref`, the directional albedos by kiln's integrators: the bake's fixed "
       "rule where the table kind has one, adaptive quadrature to " +
       AtlasNumber(opt.tol) + " absolute otherwise (the method of each side is listed below);\n";
  s += "- `max_df = max over wi of |f_cheap(wo, wi) - f_ref(wo, wi)| mu_i`: cosine-weighted (the "
       "radiance difference under a unit directional light), so that the 1/mu blow-ups of some "
       "models at a grazing light stay comparable. Found by a search: a " +
       std::to_string(opt.search.thetaNodes) + " x " + std::to_string(opt.search.phiNodes) +
       " grid in (theta_i, phi_i) over [0, pi/2] x [0, pi] (the models are isotropic) plus the "
       "mirror direction, rings around it and the rows theta_i = theta_o and phi_i = pi/2, then "
       "a pattern search (axis and diagonal steps) down to " +
       AtlasNumber(opt.search.minStep) + " rad from the " + std::to_string(opt.search.starts) +
       " best points. `argmax_mu_i`, `argmax_phi_i` give where (phi_i = 0 on the view's side, "
       "pi the mirror side).\n\n";
  s += "Per pair: `<name>.csv` (columns mu, roughness, E_ref, E_cheap, dE, max_df, argmax_mu_i, "
       "argmax_phi_i) and `<name>.png` (dE and max_df over (mu, roughness); max_df on a log10 "
       "scale where it spans more than three decades, zeros floored six decades below its "
       "maximum). Method and mappings: [docs/models.md, \"Error atlas\"](../models.md#error-atlas)."
       " The approximations engines ship in place of a whole table (EnvBRDFApprox, three.js's "
       "DFG and sheen approximations, Lazarov's EnvironmentBRDF) are measured against kiln's "
       "exact integrals in [tables.md](tables.md).\n\n";
  s += "| pair | cheap | reference | roughness axis | worst abs(dE) | at (mu, r) | worst max_df | "
       "at (mu, r) | argmax (mu_i, phi_i) |\n";
  s += "|---|---|---|---|---|---|---|---|---|\n";
  auto side = [](const AtlasSide& x) {
    std::string t = "`" + x.model + "`";
    if (!x.params.empty()) t += " " + x.params;
    if (x.rescale == AtlasRescale::BlinnPhong204) t += " with (s + 2.04)/(8 pi)";
    if (x.map == AtlasRoughnessMap::FujiiSigmaPrime) t += " at sigma' = B/A";
    return t;
  };
  for (const AtlasResult& r : results) {
    const AtlasCell* wE = &r.cells[0];
    const AtlasCell* wF = &r.cells[0];
    for (const AtlasCell& c : r.cells) {
      if (std::abs(c.dE) > std::abs(wE->dE)) wE = &c;
      if (c.maxDf > wF->maxDf) wF = &c;
    }
    s += "| [" + r.pair.name + "](" + r.pair.name + ".png) | " + side(r.pair.cheap) + " | " +
         side(r.pair.ref) + " | " + r.pair.axis + " in [" + AtlasNumber(r.pair.lo) + ", " +
         AtlasNumber(r.pair.hi) + "] | " + AtlasNumber(std::abs(wE->dE), "%.3g") + " | (" +
         AtlasNumber(wE->mu, "%.3g") + ", " + AtlasNumber(wE->roughness, "%.3g") + ") | " +
         AtlasNumber(wF->maxDf, "%.3g") + " | (" + AtlasNumber(wF->mu, "%.3g") + ", " +
         AtlasNumber(wF->roughness, "%.3g") + ") | (" + AtlasNumber(wF->argMu, "%.3g") + ", " +
         AtlasNumber(wF->argPhi, "%.3g") + ") |\n";
  }
  s += "\n## Pairs, mappings and methods\n\n";
  for (const AtlasResult& r : results) {
    s += "- **" + r.pair.name + "**: " + r.pair.note + ".\n";
    s += "  E_cheap: " + r.cheapMethod + ".\n";
    s += "  E_ref: " + r.refMethod + ".\n";
  }
  s += "\nRegenerate: `" + command + "`.\n";
  return s;
}

}  // namespace kiln
