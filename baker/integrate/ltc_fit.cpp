// The LTC fit (Heitz, Dupuy, Hill & Neubelt 2016): see ltc_fit.h for the conventions. Written
// for kiln from the paper's description (the published fitting program was read for facts only).
//
// The derivation, once:
// - The target is the normalised lobe f(l) = f(o, l) mu_l / norm (F = 1), a density on the
//   sphere. The LTC is D(l) = D_o(l') |dl'/dl| with l' = M^-1 l / |M^-1 l|, D_o(l') =
//   max(0, l'.z) / pi and |dl'/dl| = |det M^-1| / |M^-1 l|^3, i.e. D(l) = q.z |det M^-1| /
//   (pi |q|^4) for q = M^-1 l (LtcMatrix::Eval, no root).
// - M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]] with Z the lobe's average direction
//   (the f / p weighted mean of its samples, y cleared), X = (Z.z, 0, -Z.x), Y = +y; at a view
//   along the normal the lobe is symmetric about z: Z = z, m22 = m11, m13 = 0 (1 parameter).
//   The search runs over (ln m11, ln m22, m13 / m11) (scale-free, positive widths).
// - The objective is the L^p distance E_p = integral |f - D|^p dl (p = 2 by default; the paper
//   uses p = 3). Where f = 0 the integrand is D^p, so
//       E_p = integral_{f > 0} (|f - D|^p - D^p) dl + integral D^p dl.
//   The first term is estimated with n x n stratified samples of the lobe's proposal (its
//   D cos(theta_m) normals reflected about o): those points, f and the proposal's density are
//   fixed per texel. The second is the LTC's own expectation of D^(p-1): integral D^p dl =
//   E_{l ~ D}[D(l)^(p-1)], by m x m stratified cosine directions c mapped to l = M c / |M c|,
//   where D(l) = c.z |det M^-1| |M c|^3 / pi (no lobe evaluation at all). A step of the search
//   costs n^2 + m^2 LTC densities and no BRDF evaluation. Unlike a fixed quadrature of D at the
//   lobe's points alone, the LTC cannot "hide" between the points: a narrow or misplaced LTC
//   pays its full integral D^p (the cause of the old fit's total misses at grazing views).
//   With p = 3 the two terms nearly cancel for narrow lobes (values ~ 1 / alpha^2, cubed) and the
//   estimate loses its sign; p = 2 keeps it stable (E_2 = integral f^2 - 2 integral f D +
//   integral D^2).
// - Order (the paper's): the view along the normal first, from roughness 1 down to 0, each
//   texel from the previous one's solution scaled by the ratio of the alphas; then each
//   roughness column from its first texel towards grazing, each from its neighbour's solution,
//   the columns in parallel (the same bits for any thread count). Two Nelder-Mead runs of at
//   most maxIterations steps (the second from the first's result frees a collapsed simplex),
//   then a free-frame stage of at most frameSteps: the frame's rotation about y as a fourth
//   parameter (the full family of M^-1 = [[a, 0, c], [0, 1, 0], [b, 0, d]] up to scale), from
//   the three-parameter result, which the simplex keeps as a vertex: it cannot lose. The
//   average direction is a good frame for the search to start from, not the best one: the
//   stage halves the fit error at mid views (docs/models.md "LTC").
// - The declared error is measured independently of the objective: L1 = integral |f - D| over
//   the sphere (at most 2: two disjoint densities), by the paper's MIS of the lobe's proposal
//   and the fitted LTC's own samples, the norm from the same lobe samples (LtcFitError).
#include "baker/integrate/ltc_fit.h"
#include "baker/integrate/ltc_objective.h"
#include "baker/util/threads.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <type_traits>

namespace kiln {
namespace {

constexpr double kInvPi = kLtcInvPi;

/// The cosine-weighted direction at (u1, u2): sin^2 = u1.
Vec3 CosineSample(double u1, double u2) {
  double s = std::sqrt(u1), phi = 2 * Pi * u2;
  return {s * std::cos(phi), s * std::sin(phi), SafeSqrt(1 - u1)};
}

bool Invert3(const double* m, double* inv, double* det) {
  double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8],
         c02 = m[3] * m[7] - m[4] * m[6];
  double d = m[0] * c00 + m[1] * c01 + m[2] * c02;
  if (d == 0 || !std::isfinite(d)) return false;
  double id = 1 / d;
  inv[0] = c00 * id;
  inv[1] = (m[2] * m[7] - m[1] * m[8]) * id;
  inv[2] = (m[1] * m[5] - m[2] * m[4]) * id;
  inv[3] = c01 * id;
  inv[4] = (m[0] * m[8] - m[2] * m[6]) * id;
  inv[5] = (m[2] * m[3] - m[0] * m[5]) * id;
  inv[6] = c02 * id;
  inv[7] = (m[1] * m[6] - m[0] * m[7]) * id;
  inv[8] = (m[0] * m[4] - m[1] * m[3]) * id;
  *det = d;
  return true;
}

Vec3 Mul(const double* m, Vec3 v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

Vec3 Cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The parameters of the Nelder-Mead search: (ln m11, ln m22, m13 / m11) and, in the free-frame
/// stage, x[3] = the frame's rotation about y (radians) from the lobe's average direction z.
LtcFrameParams FromSearch(const double* x, int dim, bool isotropic, Vec3 z) {
  LtcFrameParams p;
  p.z = z;
  p.m11 = std::exp(x[0]);
  p.m22 = isotropic ? p.m11 : std::exp(x[1]);
  p.m13 = isotropic ? 0 : x[2] * p.m11;
  if (dim == 4) {
    double c = std::cos(x[3]), s = std::sin(x[3]);
    p.z = Vec3{z.x * c + z.z * s, 0, z.z * c - z.x * s};
  }
  return p;
}

}  // namespace

// --- The lobe ---------------------------------------------------------------------------------

LtcLobe::LtcLobe(const std::string& model, double r, double mu) {
  ModelParams p;
  if (const ModelInfo* info = FindModel(model)) {
    for (const ParamInfo& q : info->params)
      if (q.name == "roughness") p.roughness = Clamp(r, q.lo, q.hi);
  }
  model_ = MakeModel(model, p);  // F = 1: no f0 or eta given
  wo_ = ViewDirection(mu);
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, MicrofacetBRDF<GGXDistribution>>) {
          kind_ = 1;
          alpha_ = m.dist.alpha;
        } else if constexpr (std::is_same_v<T, MicrofacetBRDF<BeckmannDistribution>>) {
          kind_ = 2;
          alpha_ = m.dist.alpha;
        } else if constexpr (std::is_same_v<T, MicrofacetBRDF<BlinnPhongDistribution>>) {
          kind_ = 3;
          alpha_ = m.dist.alpha;
        }
        if constexpr (std::is_same_v<T, CharlieSheen> || std::is_same_v<T, CharlieSmithSheen>) {
          kind_ = 4;
          alpha_ = m.alpha;
        }
        if constexpr (std::is_same_v<T, CharlieSmithSheen>)
          sheenLambdaO_ = CharlieSheenLambda(CosTheta(wo_), m.alpha);
        // Unity's GGX lobes: the D of Unity's a, no narrower than where the epsilons of its
        // formulas flatten the peak (fixed_rule_microfacet.h: alpha_q).
        if constexpr (std::is_same_v<T, UnityBRDF1>) {
          kind_ = 1;
          alpha_ = std::max(m.a, std::pow(1e-7, 0.25));
        }
        if constexpr (std::is_same_v<T, UnityBRDF2>) {
          kind_ = 1;
          alpha_ = std::max(m.a, std::sqrt(1e-5));
        }
        if constexpr (std::is_same_v<T, WardBRDF>) {  // exp(-tan^2 / alpha^2): Beckmann's
          kind_ = 2;
          alpha_ = m.alpha;
        }
        if constexpr (std::is_same_v<T, LafortuneBRDF> || std::is_same_v<T, UnityBRDF3>) {
          kind_ = 5;
          if constexpr (std::is_same_v<T, LafortuneBRDF>) {
            phongN_ = m.lobe.n;
            wCos_ = wMirror_ = 0.5;
          } else {
            phongN_ = UnitySpecPower(m.r) / 4;
            phongTwin_ = true;
            wCos_ = wTwin_ = 0.25;
            wMirror_ = 0.5;
          }
          phongAlpha_ = std::sqrt(2 / (4 * phongN_ + 2));
        }
        if constexpr (std::is_same_v<T, AshikhminVelvet>) {
          kind_ = 6;
          alpha_ = m.alpha;
        }
        if constexpr (std::is_same_v<T, MicrofacetBRDF<GGXDistribution>> ||
                      std::is_same_v<T, MicrofacetBRDF<BeckmannDistribution>> ||
                      std::is_same_v<T, MicrofacetBRDF<BlinnPhongDistribution>>) {
          if (m.form == SmithForm::HeightCorrelated && wo_.z > 0)
            muLambdaO_ = wo_.z + m.dist.MuLambda(wo_.z);
        }
      },
      model_);
}

double LtcLobe::Eval(Vec3 wi) const {
  if (wi.z <= 0) return 0;
  if (muLambdaO_ >= 0) {  // the fused form's f, with mu_o Lambda(o) kept: Evaluate's bits
    double f, pdf;
    EvalPdf(wi, &f, &pdf);
    return f;
  }
  // charlie-smith with its view's Lambda kept: Evaluate's bits.
  const double value =
      sheenLambdaO_ >= 0 ? std::get<CharlieSmithSheen>(model_).FGivenLambdaO(wo_, wi, sheenLambdaO_)
                         : Evaluate(model_, wo_, wi);
  double f = value * wi.z;
  return std::isfinite(f) ? f : 0;
}

double LtcLobe::DCos(Vec3 wm) const {
  if (wm.z <= 0) return 0;
  switch (kind_) {
    case 1:
      return GGXDistribution{alpha_}.D(wm) * wm.z;
    case 2:
      return BeckmannDistribution{alpha_}.D(wm) * wm.z;
    case 3:
      return BlinnPhongDistribution{alpha_}.D(wm) * wm.z;
  }
  return 0;
}

namespace {

/// The normal m of the upper hemisphere with Reflect(o, m) = wi, from h = o + wi (len = |h| > 0):
/// h / len or -h / len (Reflect(o, m) = Reflect(o, -m) = 2 (o.m) m - o). A sampler that reflects
/// o about its normals m (z > 0) also draws normals with o.m < 0, whose wi has o + wi = 2 (o.m) m
/// pointing down; the map m -> wi is one-to-one from the upper hemisphere with Jacobian
/// 4 |o.m|, so the sampler's density at wi is D cos(theta_m) / (4 |o.m|) with this m.
Vec3 HalfOfReflection(Vec3 h, double len) {
  Vec3 wm = (1 / len) * h;
  return wm.z >= 0 ? wm : -1 * wm;
}

/// The direction at (u1, u2) of the Phong lobe (n + 1) / (2 pi) max(0, a.l)^n about the unit
/// axis a (in the xz plane): cos = u1^(1 / (n + 1)).
Vec3 PhongSample(Vec3 a, double n, double u1, double u2) {
  double c = std::pow(u1, 1 / (n + 1)), s = SafeSqrt(1 - c * c), phi = 2 * Pi * u2;
  Vec3 t1{a.z, 0, -a.x}, t2{0, 1, 0};
  return (s * std::cos(phi)) * t1 + (s * std::sin(phi)) * t2 + c * a;
}

/// Its density over solid angle at l.
double PhongPdf(Vec3 a, double n, Vec3 l) {
  double c = Dot(a, l);
  return c > 0 ? (n + 1) / (2 * Pi) * std::pow(c, n) : 0;
}

/// The horizon density: mu_l = u^3, the azimuth uniform, i.e. mu_l^(-2/3) / (6 pi) over solid
/// angle (upper hemisphere; density 1/3 mu^(-2/3) in mu, 1 / (2 pi) in the azimuth): a sheen's lobe
/// at small roughness is a sliver along the horizon (mu_l below ~0.05 at alpha = 0.002), which
/// neither the cosine nor the reflected NDF reaches.
double HorizonPdf(double mu) { return mu > 0 ? std::pow(mu, -2.0 / 3) / (6 * Pi) : 0; }

/// Velvet's inverted-Gaussian term (Ashikhmin & Premoze 2007) as a density of normals:
/// 4 exp(-cot^2 / alpha^2) / sin^4 times cos(theta_m), normalised (its integral is 4 pi alpha^2):
/// in x = cot(theta_m) it is the Rayleigh density 2 x / alpha^2 exp(-x^2 / alpha^2), so over
/// solid angle x exp(-x^2 / alpha^2) / (pi alpha^2 sin^3 theta_m).
double VelvetNormalPdf(double alpha, Vec3 wm) {
  double c = wm.z, s2 = 1 - c * c;
  if (!(c > 0) || !(s2 > 0) || !(alpha > 0)) return 0;
  double s = std::sqrt(s2), x = c / s;
  return x * std::exp(-x * x / (alpha * alpha)) / (Pi * alpha * alpha * s2 * s);
}

}  // namespace

Vec3 LtcLobe::Sample(double u1, double u2) const {
  if (kind_ == 0) return CosineSample(u1, u2);
  if (kind_ == 5) {
    const Vec3 m{-wo_.x, 0, wo_.z};
    if (u1 < wCos_) return CosineSample(u1 / wCos_, u2);
    if (u1 < wCos_ + wMirror_) return PhongSample(m, phongN_, (u1 - wCos_) / wMirror_, u2);
    return PhongSample(-1 * m, phongN_, (u1 - wCos_ - wMirror_) / wTwin_, u2);
  }
  if (kind_ == 6) {
    // Half the points from the clamped cosine, half from the inverted-Gaussian normals
    // (x = cot(theta_m) = alpha sqrt(-ln(1 - u))) reflected about o.
    if (u1 < 0.5 || !(alpha_ > 0)) return CosineSample(alpha_ > 0 ? 2 * u1 : u1, u2);
    double x = alpha_ * std::sqrt(-std::log(1 - (2 * u1 - 1)));
    double s = 1 / std::sqrt(1 + x * x);
    Vec3 wm = SphericalDirection(s, x * s, 2 * Pi * u2);
    return Reflect(wo_, wm);
  }
  if (kind_ == 4) {
    // A quarter of the points from the clamped cosine, a quarter from the horizon density
    // (mu_l = u^3), half from the Charlie NDF's D cos(theta_h) (its CDF in theta_h is
    // sin^(1/alpha + 2): sin = u^(1 / (1/alpha + 2))) reflected about o.
    if (u1 < 0.25) return CosineSample(4 * u1, u2);
    if (u1 < 0.5) {
      double u = 4 * u1 - 1, mu = u * u * u;
      return SphericalDirection(SafeSqrt(1 - mu * mu), mu, 2 * Pi * u2);
    }
    double s = std::pow(2 * u1 - 1, 1 / (1 / alpha_ + 2));
    Vec3 wm = SphericalDirection(s, SafeSqrt(1 - s * s), 2 * Pi * u2);
    return Reflect(wo_, wm);
  }
  PolarParam h = kind_ == 1   ? GGXDistribution{alpha_}.FromV(1 - u1)
                 : kind_ == 2 ? BeckmannDistribution{alpha_}.FromV(1 - u1)
                              : BlinnPhongDistribution{alpha_}.FromV(1 - u1);
  Vec3 wm = SphericalDirection(h.sinTheta, h.cosTheta, 2 * Pi * u2);
  return Reflect(wo_, wm);
}

std::vector<Vec3> LtcLobe::SampleGrid(int n) const {
  std::vector<Vec3> out;
  out.reserve(size_t(std::max(n, 0)) * size_t(std::max(n, 0)));
  if (!(kind_ >= 1 && kind_ <= 4)) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) out.push_back(Sample((i + 0.5) / n, (j + 0.5) / n));
    return out;
  }
  // Sample's direction of column i is {a cos(phi), a sin(phi), b} (SphericalDirection or
  // CosineSample) at phi = 2 pi u2, reflected about o where `reflect`.
  struct Column {
    double a, b;
    bool reflect;
  };
  std::vector<Column> cols(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double u1 = (i + 0.5) / n;
    Column& c = cols[size_t(i)];
    if (kind_ == 4 && u1 < 0.25) {  // Sample's branches, in its order
      c = {std::sqrt(4 * u1), SafeSqrt(1 - 4 * u1), false};
    } else if (kind_ == 4 && u1 < 0.5) {
      const double u = 4 * u1 - 1, mu = u * u * u;
      c = {SafeSqrt(1 - mu * mu), mu, false};
    } else if (kind_ == 4) {
      const double sn = std::pow(2 * u1 - 1, 1 / (1 / alpha_ + 2));
      c = {sn, SafeSqrt(1 - sn * sn), true};
    } else {
      const PolarParam h = kind_ == 1   ? GGXDistribution{alpha_}.FromV(1 - u1)
                           : kind_ == 2 ? BeckmannDistribution{alpha_}.FromV(1 - u1)
                                        : BlinnPhongDistribution{alpha_}.FromV(1 - u1);
      c = {h.sinTheta, h.cosTheta, true};
    }
  }
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * Pi * ((j + 0.5) / n), cp = std::cos(phi), sp = std::sin(phi);
    for (const Column& c : cols) {
      const Vec3 d{c.a * cp, c.a * sp, c.b};
      out.push_back(c.reflect ? Reflect(wo_, d) : d);
    }
  }
  return out;
}

double LtcLobe::Pdf(Vec3 wi) const {
  if (kind_ == 0) return std::max(0.0, wi.z) * kInvPi;
  if (kind_ == 5) {
    const Vec3 m{-wo_.x, 0, wo_.z};
    double p = wCos_ * std::max(0.0, wi.z) * kInvPi + wMirror_ * PhongPdf(m, phongN_, wi);
    if (wTwin_ > 0) p += wTwin_ * PhongPdf(-1 * m, phongN_, wi);
    return std::isfinite(p) ? p : 0;
  }
  if (kind_ == 6) {
    double w = alpha_ > 0 ? 0.5 : 1;
    double p = w * std::max(0.0, wi.z) * kInvPi;
    if (!(alpha_ > 0)) return p;
    Vec3 h = wo_ + wi;
    double len = Length(h);
    if (!(len > 0)) return p;
    Vec3 wm = HalfOfReflection(h, len);
    double oh = std::fabs(Dot(wo_, wm));
    if (oh <= 0) return p;
    double q = 0.5 * VelvetNormalPdf(alpha_, wm) / (4 * oh);
    return std::isfinite(q) ? p + q : p;
  }
  if (kind_ == 4) {
    double p = 0.25 * std::max(0.0, wi.z) * kInvPi + 0.25 * HorizonPdf(wi.z);
    Vec3 h = wo_ + wi;
    double len = Length(h);
    if (!(len > 0)) return p;
    Vec3 wm = HalfOfReflection(h, len);
    double oh = std::fabs(Dot(wo_, wm));
    if (oh <= 0 || wm.z <= 0) return p;
    double q = 0.5 * CharlieD(alpha_, wm.x * wm.x + wm.y * wm.y) * wm.z / (4 * oh);
    return std::isfinite(q) ? p + q : p;
  }
  Vec3 h = wo_ + wi;
  double len = Length(h);
  if (len <= 0) return 0;
  // The height-correlated microfacet lobes (ggx, beckmann, blinn-phong: the catalogue's tables,
  // whose bytes this keeps) count only the normals facing o; the others the sampler's full
  // density (either sign of o + wi).
  Vec3 wm = muLambdaO_ >= 0 ? (1 / len) * h : HalfOfReflection(h, len);
  double oh = muLambdaO_ >= 0 ? Dot(wo_, wm) : std::fabs(Dot(wo_, wm));
  if (oh <= 0) return 0;
  double p = DCos(wm) / (4 * oh);
  return std::isfinite(p) ? p : 0;
}

void LtcLobe::EvalPdf(Vec3 wi, double* f, double* pdf) const {
  bool done = false;
  if (muLambdaO_ >= 0) {
    std::visit(
        [&](const auto& m) {
          using T = std::decay_t<decltype(m)>;
          if constexpr (std::is_same_v<T, MicrofacetBRDF<GGXDistribution>> ||
                        std::is_same_v<T, MicrofacetBRDF<BeckmannDistribution>> ||
                        std::is_same_v<T, MicrofacetBRDF<BlinnPhongDistribution>>) {
            // Pdf's and Parts' half vector (Normalize is (1 / len) h), D once; Parts' product
            // with G = mu_o / (mu_o + mu_o Lambda(o) + mu_o mu_l Lambda(l) / mu_l) as GOverMuO.
            Vec3 h = wo_ + wi;
            double len = Length(h);
            *f = *pdf = 0;
            done = true;
            if (len <= 0) return;
            Vec3 wm = (1 / len) * h;
            double oh = Dot(wo_, wm), mu_o = wo_.z, mu_l = wi.z;
            double d = wm.z > 0 ? m.dist.D(wm) : 0;
            if (oh > 0) {
              double p = d * wm.z / (4 * oh);
              *pdf = std::isfinite(p) ? p : 0;
            }
            if (mu_l <= 0) return;
            double g = mu_o * (1 / (muLambdaO_ + mu_o * m.dist.MuLambda(mu_l) / mu_l));
            double value = d * g * m.fresnel(oh) / (4 * mu_o * mu_l);
            double v = (std::isfinite(value) ? value : 0) * mu_l;
            *f = std::isfinite(v) ? v : 0;
          }
        },
        model_);
  }
  if (!done) {
    *f = Eval(wi);
    *pdf = Pdf(wi);
  }
}

// --- The LTC ----------------------------------------------------------------------------------

LtcMatrix LtcMatrix::From(const LtcFrameParams& p) {
  Vec3 Z = Normalize(Vec3{p.z.x, 0, p.z.z}), X{Z.z, 0, -Z.x}, Y{0, 1, 0};
  // [X Y Z] (columns) times [[m11, 0, m13], [0, m22, 0], [0, 0, 1]].
  LtcMatrix out{};
  const double A[9] = {p.m11, 0, p.m13, 0, p.m22, 0, 0, 0, 1};
  const double B[9] = {X.x, Y.x, Z.x, X.y, Y.y, Z.y, X.z, Y.z, Z.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += B[3 * i + k] * A[3 * k + j];
      out.m[3 * i + j] = s;
    }
  double det = 0;
  if (!Invert3(out.m, out.inv, &det)) {
    for (int i = 0; i < 9; ++i) out.inv[i] = i % 4 == 0 ? 1 : 0;
    det = 1;
  }
  out.detInv = std::fabs(1 / det);
  return out;
}

double LtcMatrix::Eval(Vec3 l) const {
  // D_o(q / |q|) |det M^-1| / |q|^3 with q = M^-1 l, D_o = z / pi: q.z / |q|^4 (no root).
  Vec3 q = Mul(inv, l);
  double len2 = Dot(q, q);
  if (!(len2 > 0) || q.z <= 0) return 0;
  return q.z * kInvPi * detInv / (len2 * len2);
}

LtcMatrix LtcMatrix::FromInverse(const double minv[4]) {
  LtcMatrix out{};
  const double inv[9] = {minv[0], 0, minv[2], 0, 1, 0, minv[1], 0, minv[3]};
  double det = 0;
  for (int i = 0; i < 9; ++i) out.inv[i] = inv[i];
  if (!Invert3(inv, out.m, &det)) {
    for (int i = 0; i < 9; ++i) out.m[i] = out.inv[i] = i % 4 == 0 ? 1 : 0;
    det = 1;
  }
  out.detInv = std::fabs(det);
  return out;
}

Vec3 LtcMatrix::Sample(double u1, double u2) const {
  return Normalize(Mul(m, CosineSample(u1, u2)));
}

// --- Nelder-Mead -------------------------------------------------------------------------------

double NelderMead(const std::function<double(const double*)>& f, int dim, double* x, double step,
                  int maxIter, double tol) {
  const int n = dim;
  double s[5][4] = {}, v[5] = {};
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j < n; ++j) s[i][j] = x[j] + (i == j + 1 ? step : 0.0);
    v[i] = f(s[i]);
  }
  auto order = [&] {  // insertion sort by value (ties keep index order: deterministic)
    for (int i = 1; i <= n; ++i)
      for (int k = i; k > 0 && v[k] < v[k - 1]; --k) {
        std::swap(v[k], v[k - 1]);
        for (int j = 0; j < n; ++j) std::swap(s[k][j], s[k - 1][j]);
      }
  };
  for (int it = 0; it < maxIter; ++it) {
    order();
    if (std::fabs(v[n] - v[0]) <= tol * (std::fabs(v[0]) + 1e-300)) break;
    double c[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) c[j] += s[i][j] / n;
    double r[4], e[4], k[4];
    for (int j = 0; j < n; ++j) r[j] = c[j] + (c[j] - s[n][j]);
    double fr = f(r);
    if (fr < v[0]) {
      for (int j = 0; j < n; ++j) e[j] = c[j] + 2 * (c[j] - s[n][j]);
      double fe = f(e);
      const double* keep = fe < fr ? e : r;
      for (int j = 0; j < n; ++j) s[n][j] = keep[j];
      v[n] = std::min(fe, fr);
      continue;
    }
    if (fr < v[n - 1]) {
      for (int j = 0; j < n; ++j) s[n][j] = r[j];
      v[n] = fr;
      continue;
    }
    bool outside = fr < v[n];
    for (int j = 0; j < n; ++j)
      k[j] = outside ? c[j] + 0.5 * (r[j] - c[j]) : c[j] + 0.5 * (s[n][j] - c[j]);
    double fk = f(k);
    if (fk < (outside ? fr : v[n])) {
      for (int j = 0; j < n; ++j) s[n][j] = k[j];
      v[n] = fk;
      continue;
    }
    for (int i = 1; i <= n; ++i) {  // shrink towards the best
      for (int j = 0; j < n; ++j) s[i][j] = s[0][j] + 0.5 * (s[i][j] - s[0][j]);
      v[i] = f(s[i]);
    }
  }
  order();
  for (int j = 0; j < n; ++j) x[j] = s[0][j];
  return v[0];
}

// --- The fit ------------------------------------------------------------------------------------

void LtcLobeMoments(const LtcLobe& lobe, int n, double* norm, Vec3* averageDir) {
  double sum = 0;
  Vec3 dir{0, 0, 0};
  for (Vec3 l : lobe.SampleGrid(n)) {
    double p, f;
    lobe.EvalPdf(l, &f, &p);
    if (!(p > 0) || f <= 0) continue;
    double w = f / p;
    sum += w;
    dir = dir + w * l;
  }
  *norm = sum / (double(n) * n);
  dir.y = 0;
  *averageDir = Length(dir) > 0 ? Normalize(dir) : Vec3{0, 0, 1};
}

namespace {

/// The lobe's n x n stratified proposal samples with f and the proposal's density (zeros kept).
struct LobeSample {
  Vec3 l;
  double f, pl;
};

std::vector<LobeSample> LobeSamples(const LtcLobe& lobe, int n) {
  std::vector<LobeSample> ls;
  ls.reserve(size_t(n) * n);
  for (Vec3 l : lobe.SampleGrid(n)) {
    LobeSample s{l, 0, 0};
    lobe.EvalPdf(l, &s.f, &s.pl);
    ls.push_back(s);
  }
  return ls;
}

/// The n x n stratified clamped-cosine directions CosineSample((i + 0.5) / n, (j + 0.5) / n) at
/// index i + n j: the same for every texel, computed once per n (thread-safe).
const std::vector<Vec3>& CosineGrid(int n) {
  static std::mutex mutex;
  static std::map<int, std::vector<Vec3>> grids;  // (a map's elements stay where they are)
  std::lock_guard<std::mutex> lock(mutex);
  std::vector<Vec3>& g = grids[n];
  if (g.empty() && n > 0) {
    g.reserve(size_t(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) g.push_back(CosineSample((i + 0.5) / n, (j + 0.5) / n));
  }
  return g;
}

/// The MIS points of an error integral between a lobe and an LTC, in one order: the lobe's
/// samples `ls` (LobeSamples), then the LTC's n x n stratified samples; add(l, f, pl) with the
/// lobe's value f (cosine included) and its proposal's density pl at each.
template <class Add>
void ForEachMisSample(const std::vector<LobeSample>& ls, const LtcLobe& lobe, const LtcMatrix& ltc,
                      int n, Add& add) {
  for (const LobeSample& s : ls) add(s.l, s.f, s.pl);
  const std::vector<Vec3>& cosines = CosineGrid(n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // LtcMatrix::Sample((i + 0.5) / n, (j + 0.5) / n), its cosine direction from the grid.
      Vec3 l = Normalize(Mul(ltc.m, cosines[size_t(i) + size_t(n) * j]));
      double f, pl;
      lobe.EvalPdf(l, &f, &pl);
      add(l, f, pl);
    }
}

/// LtcFitError from the lobe's own n x n samples `ls` (LobeSamples(lobe, n)).
double FitErrorFrom(const std::vector<LobeSample>& ls, const LtcLobe& lobe, double norm,
                    const LtcMatrix& ltc, int p, int n) {
  // The lobe's samples first (their f / p give the norm when it is not given).
  double sum = 0;
  for (const LobeSample& s : ls)
    if (s.pl > 0 && s.f > 0) sum += s.f / s.pl;
  if (!(norm > 0)) norm = sum / (double(n) * n);
  double err = 0;
  auto add = [&](Vec3 l, double f, double pl) {
    double fl = f / norm, d = ltc.Eval(l);
    double den = pl + d;
    if (!(den > 0)) return;
    double e = std::fabs(fl - d);
    err += (p == 3 ? e * e * e : e) / den;
  };
  ForEachMisSample(ls, lobe, ltc, n, add);
  return err / (double(n) * n);
}

}  // namespace

double LtcFitError(const LtcLobe& lobe, double norm, const LtcMatrix& ltc, int p, int n) {
  return FitErrorFrom(LobeSamples(lobe, n), lobe, norm, ltc, p, n);
}

namespace {

/// LtcOverlapError from the lobe's own n x n samples `ls` (LobeSamples(lobe, n)); norm > 0.
double OverlapErrorFrom(const std::vector<LobeSample>& ls, const LtcLobe& lobe, double norm,
                        const LtcMatrix& ltc, int n) {
  double overlap = 0;
  auto add = [&](Vec3 l, double f, double pl) {
    double d = ltc.Eval(l), den = pl + d;
    if (den > 0) overlap += std::min(f / norm, d) / den;
  };
  ForEachMisSample(ls, lobe, ltc, n, add);
  return 2 - 2 * overlap / (double(n) * n);
}

/// The LTC of a texel's coefficients rounded to float (what a table stores).
LtcMatrix StoredMatrix(const LtcTexel& t) {
  const double stored[4] = {float(t.minv[0]), float(t.minv[1]), float(t.minv[2]), float(t.minv[3])};
  return LtcMatrix::FromInverse(stored);
}

}  // namespace

double LtcOverlapError(const LtcLobe& lobe, double norm, const LtcMatrix& ltc, int n) {
  if (!(norm > 0)) throw std::invalid_argument("ltc: the overlap error needs the lobe's norm");
  return OverlapErrorFrom(LobeSamples(lobe, n), lobe, norm, ltc, n);
}

namespace {

/// FitLtc from the lobe's opt.fitSamples^2 samples `all` (LobeSamples(lobe, opt.fitSamples)).
LtcTexel FitLtcFrom(const LtcLobe& lobe, const std::vector<LobeSample>& all, double norm,
                    const LtcFrameParams& start, bool isotropic, const LtcFitOptions& opt) {
  // The lobe's fixed points: n x n stratified samples of its proposal, with the normalised lobe
  // and its proposal density, evaluated once; the frame's Z from the same points.
  const int n = opt.fitSamples;
  struct Point {
    Vec3 l;
    double f, w;  // normalised lobe value, 1 / (N p_lobe)
  };
  std::vector<Point> pts;
  pts.reserve(size_t(n) * n);
  Vec3 z{0, 0, 0};
  double sum = 0;
  for (const LobeSample& ls : all) {
    Vec3 l = ls.l;
    double pl = ls.pl, f = ls.f;
    if (!(pl > 0) || !(f > 0)) continue;
    pts.push_back({l, f, 1 / (double(n) * n * pl)});
    z = z + (f / pl) * l;
    sum += f / pl;
  }
  if (!(norm > 0)) norm = sum / (double(n) * n);
  for (Point& q : pts) q.f /= norm;
  z.y = 0;
  z = isotropic || !(Length(z) > 0) ? Vec3{0, 0, 1} : Normalize(z);
  // The LTC's own fixed points: m x m stratified clamped-cosine directions, mapped by M.
  const int m = opt.ltcSamples;
  std::vector<double> cx, cy, cz;
  for (Vec3 c : CosineGrid(m)) {
    cx.push_back(c.x);
    cy.push_back(c.y);
    cz.push_back(c.z);
  }
  const int p = opt.power;
  auto pw = [p](double v) { return p == 2 ? v * v : v * v * v; };
  // integral |f - D|^p = integral over the lobe's support (|f - D|^p - D^p) + integral D^p, the
  // first by the lobe's points, the second as the LTC's expectation of D^(p-1) by its own points.
  int dim = isotropic ? 1 : 3;
  // With p = 2 the lobe's term is sum (f^2 - 2 f D) w: a constant and a weighted sum of D at
  // fixed points, in a lean loop over the points' coordinates (M^-1 keeps y apart: D needs five
  // products per point).
  std::vector<double> px, py, pz, pc;
  double fConst = 0;
  if (p == 2) {
    for (const Point& q : pts) {
      px.push_back(q.l.x);
      py.push_back(q.l.y);
      pz.push_back(q.l.z);
      pc.push_back(2 * q.f * q.w);
      fConst += q.f * q.f * q.w;
    }
  }
  const size_t np = px.size();
  auto objective = [&](const double* x) {
    LtcMatrix mt = LtcMatrix::From(FromSearch(x, dim, isotropic, z));
    double sum = 0;
    if (p == 2) {
      sum = fConst - LtcCrossSum(mt, px.data(), py.data(), pz.data(), pc.data(), np);
    } else {
      for (const Point& q : pts) {
        double d = mt.Eval(q.l);
        sum += (pw(std::fabs(q.f - d)) - pw(d)) * q.w;
      }
    }
    // At l = M c / |M c| (c a cosine direction): D(l) = c.z / pi |det M^-1| |M c|^3 (M keeps y
    // apart too).
    const double own = LtcOwnSum(mt, cx.data(), cy.data(), cz.data(), cx.size(), p);
    return sum + own / (double(m) * m);
  };
  double x[4] = {std::log(std::max(start.m11, 1e-9)), std::log(std::max(start.m22, 1e-9)),
                 start.m13 / std::max(start.m11, 1e-9), 0};
  LtcTexel t;
  // Nelder-Mead, then once more from its result (a restart frees a collapsed simplex).
  NelderMead(objective, dim, x, opt.step, opt.maxIterations, opt.tolerance);
  t.l3 = NelderMead(objective, dim, x, opt.step / 2, opt.maxIterations, opt.tolerance);
  t.lobeL2 = fConst;
  t.params = FromSearch(x, dim, isotropic, z);
  t.chain = t.params;
  // Then the frame's rotation about y as a fourth parameter, from that result (whose objective
  // is the new simplex's first vertex: the stage cannot lose in the objective). The next
  // texel starts from the three-parameter result (t.chain): a rotated frame is no start for a
  // neighbour whose own frame differs.
  if (!isotropic && opt.frameSteps > 0) {
    dim = 4;
    t.l3 = NelderMead(objective, dim, x, opt.step / 2, opt.frameSteps, opt.tolerance);
    t.params = FromSearch(x, dim, isotropic, z);
  }
  LtcMatrix mt = LtcMatrix::From(t.params);
  double s = mt.inv[4];  // (M^-1)_11 = 1 / m22: the published normalisation
  t.minv[0] = mt.inv[0] / s;
  t.minv[1] = mt.inv[6] / s;
  t.minv[2] = mt.inv[2] / s;
  t.minv[3] = mt.inv[8] / s;
  if (opt.errorSamples > 0 && opt.storedError) {
    // At the float coefficients a table stores, the norm from the measure's own samples: the
    // lobe's samples are the fit's when the counts agree.
    LtcMatrix st = StoredMatrix(t);
    t.l1 = opt.errorSamples == n ? FitErrorFrom(all, lobe, -1, st, 1, n)
                                 : LtcFitError(lobe, -1, st, 1, opt.errorSamples);
  } else {
    t.l1 = opt.errorSamples > 0 ? LtcFitError(lobe, norm, mt, 1, opt.errorSamples) : -1;
  }
  return t;
}

}  // namespace

LtcTexel FitLtc(const LtcLobe& lobe, double norm, const LtcFrameParams& start, bool isotropic,
                const LtcFitOptions& opt) {
  return FitLtcFrom(lobe, LobeSamples(lobe, opt.fitSamples), norm, start, isotropic, opt);
}

double LtcFitMu(double mu) { return std::max(mu, std::cos(1.57)); }

std::vector<LtcTexel> FitLtcGrid(const std::string& model, const std::vector<double>& rs,
                                 const std::vector<double>& mus, double alphaFloor, int threads,
                                 const LtcFitOptions& opt) {
  const size_t nr = rs.size(), nm = mus.size();
  if (nr < 1 || nm < 1)
    throw std::invalid_argument("ltc: the table needs at least 1 node per axis");
  std::vector<LtcTexel> out(nr * nm);
  auto lobeAt = [&](size_t ir, size_t im) {
    return LtcLobe(model, std::max(rs[ir], std::sqrt(alphaFloor)), LtcFitMu(mus[im]));
  };
  // With the overlap form the fit measures no error of its own (measured below instead).
  LtcFitOptions fitOpt = opt;
  if (opt.overlapNorm) fitOpt.errorSamples = 0;
  auto fitOne = [&](size_t ir, size_t im, const LtcFrameParams& start) {
    LtcLobe lobe = lobeAt(ir, im);
    // The lobe's samples once per texel: the fit, its retries and the overlap error share them.
    const std::vector<LobeSample> samples = LobeSamples(lobe, opt.fitSamples);
    LtcTexel t = FitLtcFrom(lobe, samples, -1, start, mus[im] >= 1, fitOpt);
    if (opt.retryMisses && opt.power == 2 && im > 0 && t.l3 > 0.5 * t.lobeL2) {
      // A miss: again from the column's first texel and from the clamped cosine.
      for (const LtcFrameParams& s : {out[ir].chain, LtcFrameParams{}}) {
        LtcTexel u = FitLtcFrom(lobe, samples, -1, s, mus[im] >= 1, fitOpt);
        if (u.l3 < t.l3) t = u;
      }
    }
    if (opt.overlapNorm) {
      const double norm = opt.overlapNorm(ir, im);
      const int ne = opt.errorSamples;
      t.l1 = !(norm > 0) || ne <= 0 ? -1
             : ne == opt.fitSamples ? OverlapErrorFrom(samples, lobe, norm, StoredMatrix(t), ne)
                                    : LtcOverlapError(lobe, norm, StoredMatrix(t), ne);
    }
    return t;
  };
  // The first view row, from the largest roughness down, sequentially; each start is the
  // previous solution scaled by the ratio of the alphas (an LTC's width follows alpha), so that
  // a large step in roughness starts near the lobe (a lobe without tails, Beckmann's, gives the
  // search nothing to follow from far away).
  LtcFrameParams start;
  double prevAlpha = -1;
  for (size_t k = nr; k-- > 0;) {
    double alpha = lobeAt(k, 0).Alpha();
    if (prevAlpha > 0) {
      double s = alpha / prevAlpha;
      start.m11 *= s;
      start.m22 *= s;
      start.m13 *= s;
    }
    out[k] = fitOne(k, 0, start);
    start = out[k].chain;
    prevAlpha = alpha;
  }
  // Each roughness column along the views, from its first-row texel; columns in parallel.
  tbb::task_arena arena(ThreadCount(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nr, 1),
                      [&](const tbb::blocked_range<size_t>& rg) {
                        for (size_t ir = rg.begin(); ir != rg.end(); ++ir) {
                          LtcFrameParams p = out[ir].params;
                          for (size_t im = 1; im < nm; ++im) {
                            out[ir + nr * im] = fitOne(ir, im, p);
                            p = out[ir + nr * im].chain;
                          }
                        }
                      });
  });
  return out;
}

std::vector<LtcTexel> FitLtcTable(const std::string& model, int n, double alphaFloor, int threads,
                                  const LtcFitOptions& opt) {
  if (n < 2) throw std::invalid_argument("ltc: the table needs at least 2 nodes per axis");
  std::vector<double> rs(n), mus(n);
  for (int i = 0; i < n; ++i) {
    double t = double(i) / (n - 1);
    rs[i] = t;
    mus[i] = 1 - t * t;
  }
  return FitLtcGrid(model, rs, mus, alphaFloor, threads, opt);
}

// --- Direct integration over a polygon -------------------------------------------------------

namespace {

struct PolygonIntegrator {
  const LtcLobe& lobe;
  Vec3 peak;
  double width;
  long long evals = 0;

  /// integral over the spherical triangle (a, b, c) (unit vectors) of the lobe by the degree-5
  /// 7-point rule on the planar triangle, dw = h dA / |p|^3.
  double Rule(Vec3 a, Vec3 b, Vec3 c) {
    Vec3 nrm = Cross(b - a, c - a);
    double area2 = Length(nrm);
    if (!(area2 > 0)) return 0;
    double h = std::fabs(Dot(nrm, a)) / area2;
    static const double kW[3] = {0.225, 0.132394152788506, 0.125939180544827};
    static const double kA[3] = {1.0 / 3, 0.059715871789770, 0.797426985353087};
    static const double kB[3] = {1.0 / 3, 0.470142064105115, 0.101286507323456};
    double sum = 0;
    for (int g = 0; g < 3; ++g) {
      int m = g == 0 ? 1 : 3;
      for (int k = 0; k < m; ++k) {
        double l0 = k == 0 ? kA[g] : kB[g], l1 = k == 1 ? kA[g] : kB[g];
        double l2 = 1 - l0 - l1;
        if (g == 0) l0 = l1 = l2 = 1.0 / 3;
        Vec3 p = l0 * a + l1 * b + l2 * c;
        double r = Length(p);
        sum += kW[g] * lobe.Eval((1 / r) * p) * h / (r * r * r);
        ++evals;
      }
    }
    return sum * area2 / 2;
  }

  double Recurse(Vec3 a, Vec3 b, Vec3 c, double whole, double tol, int depth) {
    Vec3 ab = Normalize(a + b), bc = Normalize(b + c), ca = Normalize(c + a);
    double i0 = Rule(a, ab, ca), i1 = Rule(ab, b, bc), i2 = Rule(ca, bc, c), i3 = Rule(ab, bc, ca);
    double parts = i0 + i1 + i2 + i3;
    Vec3 centre = Normalize(a + b + c);
    double radius = std::max({std::acos(Clamp(Dot(centre, a), -1.0, 1.0)),
                              std::acos(Clamp(Dot(centre, b), -1.0, 1.0)),
                              std::acos(Clamp(Dot(centre, c), -1.0, 1.0))});
    bool nearPeak =
        radius > width && std::acos(Clamp(Dot(centre, peak), -1.0, 1.0)) < radius + 20 * width;
    if (depth >= 24 || (!nearPeak && std::fabs(parts - whole) <= tol)) return parts;
    return Recurse(a, ab, ca, i0, tol / 2, depth + 1) + Recurse(ab, b, bc, i1, tol / 2, depth + 1) +
           Recurse(ca, bc, c, i2, tol / 2, depth + 1) + Recurse(ab, bc, ca, i3, tol / 2, depth + 1);
  }
};

}  // namespace

double IntegrateLobeOverPolygon(const LtcLobe& lobe, const Vec3* p, int count, double tol,
                                long long* evals) {
  std::vector<Vec3> c;
  for (int i = 0; i < count; ++i) {
    Vec3 a = Normalize(p[i]), b = Normalize(p[(i + 1) % count]);
    if (a.z >= 0) c.push_back(a);
    if ((a.z >= 0) != (b.z >= 0)) {
      double t = a.z / (a.z - b.z);
      Vec3 h = a + t * (b - a);
      h.z = 0;
      c.push_back(Normalize(h));
    }
  }
  if (c.size() < 3) return 0;
  Vec3 centre{0, 0, 0};
  for (Vec3 v : c) centre = centre + v;
  centre = Normalize(centre);
  Vec3 wo = lobe.wo();
  PolygonIntegrator in{lobe, Vec3{-wo.x, -wo.y, wo.z}, 0, 0};
  // The lobe's width in light space: twice the microfacet alpha, at least 1e-4 rad.
  in.width = std::max(2 * lobe.Alpha(), 1e-4);
  double sum = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    Vec3 a = c[i], b = c[(i + 1) % c.size()];
    sum += in.Recurse(centre, a, b, in.Rule(centre, a, b), tol / c.size(), 0);
  }
  if (evals) *evals += in.evals;
  return sum;
}

std::vector<std::vector<Vec3>> LtcTestPolygons() {
  return {
      {{-1e3, -1e3, 1}, {1e3, -1e3, 1}, {1e3, 1e3, 1}, {-1e3, 1e3, 1}},
      {{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}},
      {{-1.2, -0.4, 1}, {-0.5, -0.4, 1}, {-0.5, 0.4, 1}, {-1.2, 0.4, 1}},
      {{-1, -0.6, -0.2}, {-0.3, -0.6, 0.5}, {-0.3, 0.6, 0.5}, {-1, 0.6, -0.2}},
      {{-2, -0.05, 1}, {2, -0.05, 1}, {2, 0.05, 1}, {-2, 0.05, 1}},
      {{1, 0.6, -0.3}, {1, -0.6, -0.3}, {1, -0.6, 0.5}, {1, 0.6, 0.5}},
      {{-0.6, 1, -0.3}, {0.6, 1, -0.3}, {0.6, 1, 0.5}, {-0.6, 1, 0.5}},
      {{-1, -0.8, -0.5}, {-1, 0.8, -0.5}, {-1, 0.8, 0.1}, {-1, -0.8, 0.1}},
      {{-1, -1, 0.01}, {-1, 1, 0.01}, {-1, 1, 0.1}, {-1, -1, 0.1}},
  };
}

std::vector<Vec3> LtcNearMirrorPolygon(Vec3 wo) {
  // The mirror direction m of wo about the normal, and two unit tangents of the sphere at m.
  const Vec3 m = Normalize(Vec3{-wo.x, -wo.y, wo.z});
  const Vec3 side = Cross(Vec3{0, 0, 1}, m);  // zero when m is the normal
  const Vec3 u = Length(side) > 0 ? Normalize(side) : Vec3{0, 1, 0};
  const Vec3 v = Cross(m, u);
  const double h = kLtcNearMirrorHalfSize;
  return {m - h * u - h * v, m + h * u - h * v, m + h * u + h * v, m - h * u + h * v};
}

}  // namespace kiln
