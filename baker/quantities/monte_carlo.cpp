#include "baker/quantities/monte_carlo.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <variant>

#include "baker/models/fresnel.h"

namespace kiln {
namespace {

/// The GGX half vectors of one roughness, for the view-independent part of every sample:
/// hx = sin(theta_h) cos(phi_h), hz = cos(theta_h), and weight / hz (v.y = 0, so h.y is unused).
struct GGXHalfVectors {
  std::vector<double> hx, hz, wOverHz;
  GGXHalfVectors(const PointSet& p, double alpha) : hx(p.size()), hz(p.size()), wOverHz(p.size()) {
    double a2 = alpha * alpha;
    for (size_t j = 0; j < p.size(); ++j) {
      double u = p.u2[j], den = 1 + (a2 - 1) * u;
      double cosT = std::sqrt((1 - u) / den), sinT = std::sqrt(a2 * u / den);
      hx[j] = sinT * p.cosPhi[j];
      hz[j] = cosT;
      wOverHz[j] = p.weight[j] / cosT;
    }
  }
};

/// The importance-sampled microfacet sum at view mu: calls add(g, v.h) for every sample above
/// the horizon with g = weight * f mu_l / pdf (F = 1).
template <class Add>
void SumGGX(const GGXHalfVectors& h, double mu, double alpha, Add&& add) {
  double sv = SafeSqrt(1 - mu * mu), a2 = alpha * alpha;
  double lambdaV = std::sqrt(mu * mu * (1 - a2) + a2);
  for (size_t j = 0; j < h.hz.size(); ++j) {
    double voh = sv * h.hx[j] + mu * h.hz[j];
    double nol = 2 * voh * h.hz[j] - mu;
    if (!(nol > 0) || !(voh > 0)) continue;
    // Height-correlated Smith: Vis = G / (4 mu_o mu_l) = 0.5 / (mu_l Lv + mu_o Ll).
    double lambdaL = std::sqrt(nol * nol * (1 - a2) + a2);
    double vis = 0.5 / (nol * lambdaV + mu * lambdaL);
    add(4 * vis * nol * voh * h.wOverHz[j], voh);
  }
}

std::array<double, 2> DFGAt(const GGXHalfVectors& h, double mu, double alpha) {
  double a = 0, b = 0;
  SumGGX(h, mu, alpha, [&](double g, double voh) {
    double fc = Pow5(1 - voh);
    a += (1 - fc) * g;
    b += fc * g;
  });
  return {a, b};
}

double FresnelAlbedoAt(const GGXHalfVectors& h, double mu, double alpha, double eta) {
  double e = 0;
  SumGGX(h, mu, alpha, [&](double g, double voh) { e += g * FrDielectric(voh, eta); });
  return e;
}

/// Cosine-weighted light directions of a point set: phi = 2 pi u1, cos(theta) = sqrt(1 - u2)
/// (Filament's hemisphereCosSample), so the point u2 = 0 is the normal, never the horizon.
struct CosineDirections {
  std::vector<Vec3> l;
  std::vector<double> weight;
  explicit CosineDirections(const PointSet& p) : l(p.size()), weight(p.weight) {
    for (size_t j = 0; j < p.size(); ++j) {
      double s = std::sqrt(p.u2[j]);
      l[j] = {s * p.cosPhi[j], s * p.sinPhi[j], SafeSqrt(1 - p.u2[j])};
    }
  }
};

template <class M>
RhoParts DiffuseAt(const CosineDirections& d, const M& m, double mu) {
  Vec3 wo = ViewDirection(mu);
  double lin = 0, quad = 0;
  for (size_t j = 0; j < d.l.size(); ++j) {
    RhoParts f = m.Parts(wo, d.l[j]);
    lin += d.weight[j] * f.lin;
    quad += d.weight[j] * f.quad;
  }
  return {Pi * lin, Pi * quad};
}

/// The model at roughness r, clamped to the model's range (as EvaluateSpec does).
AnyModel ModelAt(const std::string& id, double r) {
  const ModelInfo* info = FindModel(id);
  if (!info) throw std::invalid_argument("unknown model '" + id + "'");
  ModelParams p;
  for (const ParamInfo& q : info->params)
    if (q.name == "roughness") p.roughness = Clamp(r, q.lo, q.hi);
  return MakeModel(id, p);
}

}  // namespace

PointSet HammersleyPoints(int n) {
  PointSet p;
  for (int i = 0; i < n; ++i) {
    double phi = 2 * Pi * i / n;
    p.cosPhi.push_back(std::cos(phi));
    p.sinPhi.push_back(std::sin(phi));
    p.u2.push_back(RadicalInverse2(static_cast<uint32_t>(i)));
    p.weight.push_back(1.0 / n);
  }
  return p;
}

PointSet GaussLegendrePoints(int n) {
  std::vector<double> x, w;
  GaussLegendre01(n, x, w);
  PointSet p;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      p.cosPhi.push_back(std::cos(2 * Pi * x[i]));
      p.sinPhi.push_back(std::sin(2 * Pi * x[i]));
      p.u2.push_back(x[k]);
      p.weight.push_back(w[i] * w[k]);
    }
  return p;
}

std::array<double, 2> EstimateDFG(const PointSet& points, double mu, double alpha) {
  return DFGAt(GGXHalfVectors(points, alpha), mu, alpha);
}

double EstimateFresnelAlbedo(const PointSet& points, double mu, double alpha, double eta) {
  return FresnelAlbedoAt(GGXHalfVectors(points, alpha), mu, alpha, eta);
}

RhoParts EstimateDiffuseAlbedo(const PointSet& points, const AnyModel& model, double mu) {
  CosineDirections d(points);
  return std::visit([&](const auto& m) { return DiffuseAt(d, m, mu); }, model);
}

namespace {

/// True when the spec's axes are exactly `names`, in order.
bool AxesNamed(const TableSpec& spec, std::initializer_list<const char*> names) {
  if (spec.axes.size() != names.size()) return false;
  size_t i = 0;
  for (const char* n : names)
    if (spec.axes[i++].name != n) return false;
  return true;
}

/// The nodes of a (mu, roughness[, eta]) table's rows: row k is roughness node k % rSize (eta
/// node k / rSize), its mu nodes placed by the root4-layer scale of that roughness.
struct Rows {
  Axis mu, r;
  int width, rSize;
  explicit Rows(const TableSpec& spec)
      : mu(spec.axes[0].ToAxis()),
        r(spec.axes[1].ToAxis()),
        width(spec.axes[0].size),
        rSize(spec.axes[1].size) {}
  double Roughness(size_t k) const { return r.node(static_cast<int>(k % rSize)); }
  double LayerScale(double rk) const {
    return mu.warp == Warp::Root4Layer ? layerScale(r.lo, r.hi, rk) : 1e-12;
  }
};

bool GgxDfgSupports(const TableSpec& spec) {
  const ModelInfo* m = FindModel(spec.model);
  return m && m->kernel == MicrofacetKernel::GgxHeightCorrelated &&
         AxesNamed(spec, {"mu", "roughness"});
}

MonteCarloRows GgxDfgRows(const TableSpec& spec, const PointSet& points) {
  return [rows = Rows(spec), &points](size_t k, float* out) {
    double r = rows.Roughness(k), c = rows.LayerScale(r), alpha = MonteCarloAlpha(r);
    GGXHalfVectors h(points, alpha);
    for (int i = 0; i < rows.width; ++i) {
      auto ab = DFGAt(h, rows.mu.node(i, c), alpha);
      out[2 * i] = static_cast<float>(ab[0]);
      out[2 * i + 1] = static_cast<float>(ab[1]);
    }
  };
}

bool GgxFresnelAlbedoSupports(const TableSpec& spec) {
  return AxesNamed(spec, {"mu", "roughness", "eta"});
}

MonteCarloRows GgxFresnelAlbedoRows(const TableSpec& spec, const PointSet& points) {
  return [rows = Rows(spec), etaAxis = spec.axes[2].ToAxis(), &points](size_t k, float* out) {
    double r = rows.Roughness(k), c = rows.LayerScale(r), alpha = MonteCarloAlpha(r);
    GGXHalfVectors h(points, alpha);
    double eta = etaAxis.node(static_cast<int>(k / rows.rSize));
    for (int i = 0; i < rows.width; ++i)
      out[i] = static_cast<float>(FresnelAlbedoAt(h, rows.mu.node(i, c), alpha, eta));
  };
}

bool DiffuseAlbedoSupports(const TableSpec& spec) {
  const ModelInfo* info = FindModel(spec.model);
  return info && !info->specular() && AxesNamed(spec, {"mu", "roughness"});
}

MonteCarloRows DiffuseAlbedoRows(const TableSpec& spec, const PointSet& points) {
  // Shared by every row of a diffuse table; built once, outside the rows.
  auto cosine = std::make_shared<const CosineDirections>(points);
  size_t nc = spec.channels.size();
  return [rows = Rows(spec), cosine, nc, model = spec.model](size_t k, float* out) {
    double r = rows.Roughness(k), c = rows.LayerScale(r);
    std::visit(
        [&](const auto& m) {
          for (int i = 0; i < rows.width; ++i) {
            RhoParts e = DiffuseAt(*cosine, m, rows.mu.node(i, c));
            if (nc == 2) {
              out[2 * i] = static_cast<float>(e.lin);
              out[2 * i + 1] = static_cast<float>(e.quad);
            } else {
              out[i] = static_cast<float>(e.lin + e.quad);
            }
          }
        },
        ModelAt(model, r));
  };
}

}  // namespace

const MonteCarloEstimator kGgxDfgMonteCarlo = {GgxDfgSupports, GgxDfgRows};
const MonteCarloEstimator kGgxFresnelAlbedoMonteCarlo = {GgxFresnelAlbedoSupports,
                                                         GgxFresnelAlbedoRows};
const MonteCarloEstimator kDiffuseAlbedoMonteCarlo = {DiffuseAlbedoSupports, DiffuseAlbedoRows};

bool EstimatorSupports(const TableSpec& spec) {
  const MonteCarloEstimator* mc = Describe(spec.quantity).monteCarlo;
  return mc && mc->supports(spec);
}

}  // namespace kiln
