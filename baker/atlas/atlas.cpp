// The error atlas (issue #16): sides, albedo by the bake's methods, the max search, the grid.
#include "baker/atlas/atlas.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "baker/integrate/quantities.h"
#include "baker/tables/spec.h"

namespace kiln {
namespace {

/// "f0=0.04,eta=1.5" as ModelParams; throws naming the pair's side on a bad entry.
ModelParams ParseParams(const std::string& text) {
  ModelParams p;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    size_t eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("parameter '" + item + "' has no '='");
    std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    char* end = nullptr;
    double x = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(x))
      throw std::invalid_argument("parameter '" + item + "' is not a number");
    std::optional<double>* slot = key == "roughness" ? &p.roughness
                                  : key == "rho"     ? &p.rho
                                  : key == "f0"      ? &p.f0
                                  : key == "eta"     ? &p.eta
                                  : key == "k"       ? &p.k
                                  : key == "rs"      ? &p.rs
                                  : key == "nu"      ? &p.nu
                                  : key == "nv"      ? &p.nv
                                                     : nullptr;
    if (!slot) throw std::invalid_argument("unknown parameter '" + key + "'");
    *slot = x;
  }
  return p;
}

bool HasRoughness(const std::string& model) {
  const ModelInfo* info = FindModel(model);
  if (!info) return false;
  for (const ParamInfo& q : info->params)
    if (q.name == "roughness") return true;
  return false;
}

/// The side's own roughness at atlas coordinate r.
double SideRoughness(const AtlasSide& side, double r) {
  return side.map == AtlasRoughnessMap::FujiiSigmaPrime ? FujiiSigmaPrime(r) : r;
}

double RescaleFactor(const AtlasSide& side, const AnyModel& model) {
  if (side.rescale != AtlasRescale::BlinnPhong204) return 1;
  double s = std::get<NormalizedBlinnPhong>(model).s;
  return NormalizedBlinnPhong::NormalizationApprox(s) / NormalizedBlinnPhong::Normalization(s);
}

/// A spec of quantity q for the side's model over (mu[, roughness]) with the side's params.
TableSpec SideSpec(Quantity q, const AtlasSide& side, const ModelParams& p, double tol) {
  std::vector<AxisSpec> axes = {{"mu", 0, 1, 2, Warp::Linear}};
  if (HasRoughness(side.model)) axes.push_back({"roughness", 0, 1, 2, Warp::Linear});
  TableSpec spec = Describe(q).makeSpec(side.model, axes);
  if (p.eta) spec.params["eta"] = *p.eta;
  spec.tol = tol;
  return spec;
}

}  // namespace

double FujiiSigmaPrime(double sigma) {
  double s2 = sigma * sigma;
  double A = 1 - 0.5 * s2 / (s2 + 0.33) + 0.17 * s2 / (s2 + 0.13);
  double B = 0.45 * s2 / (s2 + 0.09);
  return B / A;
}

AnyModel AtlasModel(const AtlasSide& side, double r) {
  ModelParams p = ParseParams(side.params);
  if (HasRoughness(side.model)) p.roughness = SideRoughness(side, r);
  AnyModel m = MakeModel(side.model, p);
  if (side.rescale == AtlasRescale::BlinnPhong204 &&
      !std::holds_alternative<NormalizedBlinnPhong>(m))
    throw std::invalid_argument("the 2.04 rescale needs blinn-phong-normalized, not '" +
                                side.model + "'");
  return m;
}

double AtlasF(const AtlasSide& side, const AnyModel& model, Vec3 wo, Vec3 wi) {
  return Evaluate(model, wo, wi) * RescaleFactor(side, model);
}

double AtlasAlbedo(const AtlasSide& side, double mu, double r, double tol, std::string* method) {
  ModelParams p = ParseParams(side.params);
  AnyModel model = AtlasModel(side, r);
  const double factor = RescaleFactor(side, model);
  const double rs = SideRoughness(side, r);
  const double x[2] = {mu, rs};
  IntegrationStats stats;
  const bool onlyF0 = p.f0 && !p.eta && !p.rho && !p.k && !p.rs && !p.nu && !p.nv;
  const bool onlyEta = p.eta && !p.f0 && !p.rho && !p.k && !p.rs && !p.nu && !p.nv;
  const bool none = !p.f0 && !p.eta && !p.rho && !p.k && !p.rs && !p.nu && !p.nv;
  const ModelInfo* info = FindModel(side.model);
  if (onlyEta && info && info->fresnelTables && *p.eta >= 1) {
    TableSpec spec = SideSpec(Quantity::FresnelAlbedo, side, p, tol);
    if (method) *method = spec.Method();
    return factor * EvaluateSpec(spec, x, stats)[0];
  }
  if (onlyF0) {
    TableSpec spec = SideSpec(Quantity::Dfg, side, p, tol);
    if (UsesFixedRule(spec) || (HasRoughness(side.model) && rs == 0)) {
      std::vector<double> ab = EvaluateSpec(spec, x, stats);
      if (method) *method = spec.Method() + "; E = f0 A + B";
      return factor * (*p.f0 * ab[0] + ab[1]);
    }
  }
  if (none) {
    TableSpec spec = SideSpec(Quantity::Albedo, side, p, tol);
    std::vector<double> e = EvaluateSpec(spec, x, stats);
    double sum = 0;
    for (double v : e) sum += v;  // E_rho + E_rho2 at rho = 1
    if (method) *method = spec.Method();
    return factor * sum;
  }
  IntegrationOptions opt;
  opt.tol = tol;
  if (method)
    *method = std::string("adaptive quadrature in ") +
              (FindModel(side.model)->specular() ? "half-vector" : "light") + " space to " +
              [&] {
                char b[32];
                std::snprintf(b, sizeof b, "%g", tol);
                return std::string(b);
              }() +
              " abs";
  return factor * DirectionalAlbedo(model, mu, opt, stats).At(p.rho.value_or(1));
}

void CheckAtlasPair(const AtlasPair& pair) {
  if (pair.name.empty()) throw std::invalid_argument("atlas: a pair has no name");
  if (!(pair.lo <= pair.hi) || !std::isfinite(pair.lo) || !std::isfinite(pair.hi))
    throw std::invalid_argument("atlas pair '" + pair.name + "': bad roughness range");
  for (const AtlasSide* side : {&pair.cheap, &pair.ref}) {
    try {
      if (!FindModel(side->model))
        throw std::invalid_argument("unknown model '" + side->model + "' (see `kiln list`)");
      AtlasModel(*side, pair.lo);
      AtlasModel(*side, pair.hi);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("atlas pair '" + pair.name + "': " + e.what());
    }
  }
}

HemisphereMax MaxOverHemisphere(const std::function<double(double, double)>& g,
                                const MaxSearchOptions& opt,
                                const std::vector<std::pair<double, double>>& seeds) {
  const double thetaMax = Pi / 2, phiMax = Pi;
  auto eval = [&](double t, double p) {
    double v = g(t, p);
    return std::isnan(v) ? -INFINITY : v;
  };
  struct Point {
    double value, theta, phi;
  };
  std::vector<Point> pts;
  for (int i = 0; i < opt.thetaNodes; ++i)
    for (int j = 0; j < opt.phiNodes; ++j) {
      double t = (i + 0.5) / opt.thetaNodes * thetaMax;
      double p = opt.phiNodes > 1 ? j * phiMax / (opt.phiNodes - 1) : 0;
      pts.push_back({eval(t, p), t, p});
    }
  for (const auto& [t0, p0] : seeds) {
    double t = Clamp(t0, 0.0, thetaMax), p = Clamp(p0, 0.0, phiMax);
    pts.push_back({eval(t, p), t, p});
  }
  // Best first; ties by position, so the order never depends on anything but the values.
  std::stable_sort(pts.begin(), pts.end(),
                   [](const Point& a, const Point& b) { return a.value > b.value; });
  HemisphereMax best;
  best.value = -INFINITY;
  const double step0 = thetaMax / opt.thetaNodes;
  const int starts = std::min<int>(opt.starts, static_cast<int>(pts.size()));
  for (int s = 0; s < starts; ++s) {
    Point cur = pts[s];
    double step = step0;
    while (step >= opt.minStep) {
      bool moved = false;
      // Diagonals too: a ridge along a kink (theta_i = theta_o) is climbed along its length.
      const double dirs[8][2] = {{1, 0}, {-1, 0},  {0, 1},  {0, -1},
                                 {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
      for (const auto& d : dirs) {
        double t = Clamp(cur.theta + d[0] * step, 0.0, thetaMax);
        double p = Clamp(cur.phi + d[1] * step, 0.0, phiMax);
        double v = eval(t, p);
        if (v > cur.value) {
          cur = {v, t, p};
          moved = true;
          break;
        }
      }
      if (!moved) step /= 2;
    }
    if (cur.value > best.value) best = {cur.value, cur.theta, cur.phi};
  }
  if (!(best.value > -INFINITY)) best.value = 0;
  return best;
}

HemisphereMax AtlasMaxDf(const AtlasPair& pair, double mu, double r, const MaxSearchOptions& opt) {
  AnyModel cheap = AtlasModel(pair.cheap, r), ref = AtlasModel(pair.ref, r);
  Vec3 wo = ViewDirection(mu);
  auto g = [&](double theta, double phi) {
    Vec3 wi = SphericalDirection(std::sin(theta), std::cos(theta), phi);
    double d = AtlasF(pair.cheap, cheap, wo, wi) - AtlasF(pair.ref, ref, wo, wi);
    return std::abs(d) * wi.z;
  };
  // The mirror direction and rings around it at widths from 1e-3 to 0.3 rad: a sharp specular
  // lobe is narrower than the grid.
  double theta_o = std::acos(Clamp(mu, 0.0, 1.0));
  std::vector<std::pair<double, double>> seeds = {{theta_o, Pi}, {0, 0}};
  // The diffuse models bend where theta_i = theta_o and at phi_i = pi/2: seeds along both.
  for (int k = 0; k <= 24; ++k) {
    seeds.push_back({theta_o, k * Pi / 24});
    seeds.push_back({k * (Pi / 2) / 24, Pi / 2});
  }
  for (double w = 1e-3; w < 0.4; w *= 3)
    for (int k = 0; k < 8; ++k) {
      double a = k * Pi / 4;
      double t = theta_o + w * std::cos(a),
             p = Pi + w * std::sin(a) / std::max(std::sin(theta_o), 1e-3);
      if (t < 0) {
        t = -t;
        p -= Pi;
      }
      seeds.push_back({t, std::min(p, Pi)});
    }
  return MaxOverHemisphere(g, opt, seeds);
}

AtlasResult ComputeAtlas(const AtlasPair& pair, const AtlasOptions& opt) {
  CheckAtlasPair(pair);
  if (opt.muNodes < 1 || opt.roughnessNodes < 1)
    throw std::invalid_argument("atlas: the grid needs at least one node per axis");
  AtlasResult res;
  res.pair = pair;
  res.nMu = opt.muNodes;
  res.nR = opt.roughnessNodes;
  res.cells.resize(static_cast<size_t>(res.nMu) * res.nR);
  AtlasAlbedo(pair.cheap, 0.5, pair.hi, opt.tol, &res.cheapMethod);
  AtlasAlbedo(pair.ref, 0.5, pair.hi, opt.tol, &res.refMethod);
  auto cell = [&](size_t index) {
    int j = static_cast<int>(index % res.nMu), i = static_cast<int>(index / res.nMu);
    AtlasCell c;
    c.mu = double(j + 1) / res.nMu;
    c.roughness = res.nR > 1 ? pair.lo + (pair.hi - pair.lo) * i / (res.nR - 1) : pair.lo;
    c.eRef = AtlasAlbedo(pair.ref, c.mu, c.roughness, opt.tol);
    c.eCheap = AtlasAlbedo(pair.cheap, c.mu, c.roughness, opt.tol);
    c.dE = c.eCheap - c.eRef;
    HemisphereMax m = AtlasMaxDf(pair, c.mu, c.roughness, opt.search);
    c.maxDf = m.value;
    c.argMu = std::cos(m.theta);
    c.argPhi = m.phi;
    res.cells[index] = c;
  };
  tbb::task_arena arena(std::max(1, opt.threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, res.cells.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t k = range.begin(); k != range.end(); ++k) cell(k);
                      });
  });
  return res;
}

std::string AtlasCsv(const AtlasResult& result) {
  std::string out = "mu,roughness,E_ref,E_cheap,dE,max_df,argmax_mu_i,argmax_phi_i\n";
  char line[512];
  for (const AtlasCell& c : result.cells) {
    std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", c.mu, c.roughness,
                  c.eRef, c.eCheap, c.dE, c.maxDf, c.argMu, c.argPhi);
    out += line;
  }
  return out;
}

}  // namespace kiln
