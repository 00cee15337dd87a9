// Fitting a table's closed form (fit.h): samples, weighted least squares, Lawson's reweighting,
// the choice of warps and degrees.
#include "baker/fit/fit.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baker/fit/least_squares.h"

namespace kiln {

/// The form's skeleton for `spec`: its name, channels and axes (domain), degrees 0.
FitForm Skeleton(const TableSpec& spec) {
  FitForm form;
  form.table = spec.name;
  form.channels = spec.channels;
  for (const AxisSpec& a : spec.axes) {
    FitAxis f;
    f.name = a.name;
    f.lo = a.lo;
    f.hi = a.hi;
    form.axes.push_back(f);
  }
  return form;
}

namespace {
constexpr int kMaxDegree2D = 16;  ///< largest degree per axis of a 2D fit
constexpr int kMaxDegree1D = 30;  ///< largest degree of a 1D fit
/// Largest degree of a 1D Power (Horner) form: beyond it the monomials' least squares loses
/// accuracy, and a Chebyshev form of lower degree has fewer operations anyway.
constexpr int kMaxDegreePower = 12;
constexpr int kSamples2D = 48;         ///< Chebyshev samples per axis of a 2D fit
constexpr int kSamples1D = 256;        ///< samples of a 1D fit
constexpr int kWarpSamples2D = 33;     ///< check points per axis (and grid) choosing the warps
constexpr int kWarpFitSamples2D = 24;  ///< fit samples per axis when choosing the warps
constexpr int kWarpDegree2D = 8;       ///< degree per axis when choosing the warps
constexpr int kWarpDegree1D = 12;      ///< degree when choosing a 1D warp
constexpr int kLawsonIterations = 24;  ///< minimax reweighting passes
/// A candidate is searched when its sample max is within this factor of the bound (Lawson's
/// passes usually take a third off the least-squares max).
constexpr double kScreenFactor = 1.5;

/// Exact values of a table at a product grid of Chebyshev-Lobatto points in the warped axes.
struct Samples {
  std::vector<double> x;       ///< dims values per point
  std::vector<double> values;  ///< channels values per point
  size_t count = 0;
};

Samples SampleExact(const TableSpec& spec, const std::vector<FitAxis>& axes, int perAxis,
                    int threads) {
  const size_t dims = axes.size(), channels = spec.channels.size();
  std::vector<double> nodes(perAxis);
  for (int k = 0; k < perAxis; ++k) nodes[k] = -std::cos(M_PI * k / (perAxis - 1));
  Samples s;
  s.count = dims == 1 ? perAxis : static_cast<size_t>(perAxis) * perAxis;
  s.x.resize(s.count * dims);
  s.values.resize(s.count * channels);
  FitForm form;
  form.axes = axes;
  for (size_t i = 0; i < s.count; ++i) {
    const double w[2] = {nodes[i / (dims == 1 ? 1 : perAxis)], nodes[i % perAxis]};
    PointAtWarped(form, w, &s.x[i * dims]);
    // The samples of a Layer fit at roughness 0 are taken just above it: the lobes' layer
    // keeps the width of kiln's smallest alpha there, the mirror at exactly 0 jumps from it
    // (below mu ~ 1e-10; fit.h kLayerJumpMu).
    if (axes[0].warp == FitWarp::Layer && s.x[i * dims + 1] == 0)
      s.x[i * dims + 1] = kLayerRoughnessFloor;
    // Likewise eta below the float just above 1 (fit.h kEtaLayerFloor).
    if (axes[0].warp == FitWarp::LayerEta && s.x[i * dims + 1] < kEtaLayerFloor)
      s.x[i * dims + 1] = kEtaLayerFloor;
  }
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), s.count, [&](size_t i) {
      IntegrationStats stats;
      std::vector<double> v = EvaluateSpec(spec, &s.x[i * dims], stats);
      for (size_t c = 0; c < channels; ++c) s.values[i * channels + c] = v[c];
    });
  });
  return s;
}

/// The design matrix row of point x: T_i(s_0) T_j(s_1), axis 0's index slowest.
void DesignRow(const FitForm& form, const double* x, double* row) {
  const std::vector<FitAxis>& axes = form.axes;
  double t0[kMaxDegree1D + 1], t1[kMaxDegree1D + 1] = {1}, s[2];
  if (form.basis == FitBasis::Power) {
    const double v = std::min(std::max(x[0], axes[0].lo), axes[0].hi);
    const double t = PowerVariable(axes[0], v);
    row[0] = 1;
    for (int k = 1; k <= axes[0].degree; ++k) row[k] = row[k - 1] * t;
    return;
  }
  WarpedCoordinates(form, x, s);
  ChebyshevRow(axes[0].degree, s[0], t0);
  const int n1 = axes.size() == 2 ? axes[1].degree + 1 : 1;
  if (axes.size() == 2) ChebyshevRow(axes[1].degree, s[1], t1);
  for (int i = 0; i <= axes[0].degree; ++i)
    for (int j = 0; j < n1; ++j) row[i * n1 + j] = t0[i] * t1[j];
}

/// One channel's coefficients by least squares, then `lawson` passes of Lawson's minimax
/// reweighting (w_i <- w_i |r_i|, normalised); returns the coefficients of the pass with the
/// smallest sample max and sets `maxError` to it. `a` and `b` are scratch space of the design's
/// and the samples' sizes.
std::vector<double> FitChannel(const std::vector<double>& design, const Samples& s, size_t channel,
                               size_t channels, int terms, int lawson, double& maxError,
                               std::vector<double>& a, std::vector<double>& b) {
  const int rows = static_cast<int>(s.count);
  std::vector<double> w(rows, 1.0 / rows), best;
  maxError = INFINITY;
  for (int pass = 0; pass <= lawson; ++pass) {
    for (int i = 0; i < rows; ++i) {
      const double sw = std::sqrt(w[i]);
      for (int j = 0; j < terms; ++j) a[i * terms + j] = sw * design[i * terms + j];
      b[i] = sw * s.values[i * channels + channel];
    }
    std::vector<double> c = SolveLeastSquaresInPlace(a, b, rows, terms);
    double mx = 0, sum = 0;
    std::vector<double> r(rows);
    for (int i = 0; i < rows; ++i) {
      double v = 0;
      for (int j = 0; j < terms; ++j) v += design[i * terms + j] * c[j];
      r[i] = std::fabs(v - s.values[i * channels + channel]);
      mx = std::max(mx, r[i]);
    }
    if (mx < maxError) {
      maxError = mx;
      best = c;
    }
    for (int i = 0; i < rows; ++i) sum += w[i] * r[i];
    if (sum <= 0) break;
    for (int i = 0; i < rows; ++i) w[i] = w[i] * r[i] / sum;
  }
  return best;
}

/// Fits every channel of `form` (its axes set) to the samples; returns the sample max error.
double FitCoefficients(FitForm& form, const Samples& s, int lawson) {
  const int terms = form.TermsPerChannel();
  const size_t dims = form.axes.size(), channels = form.channels.size();
  std::vector<double> design(s.count * terms);
  for (size_t i = 0; i < s.count; ++i) DesignRow(form, &s.x[i * dims], &design[i * terms]);
  form.coefficients.clear();
  std::vector<double> a(design.size()), b(s.count);  // every channel's and pass's scratch
  double mx = 0;
  for (size_t c = 0; c < channels; ++c) {
    double e = 0;
    for (double v : FitChannel(design, s, c, channels, terms, lawson, e, a, b))
      form.coefficients.push_back(static_cast<float>(v));
    mx = std::max(mx, e);
  }
  return mx;
}

/// Exact values at the warp-choice check points: a grid uniform in root4 of each axis (dense at
/// the low ends, where the tables change fastest) and one uniform in the axis values.
Samples CheckPoints(const TableSpec& spec, const FitForm& skeleton, int threads) {
  FitForm grid = skeleton;
  Samples a, b;
  for (FitAxis& ax : grid.axes) ax.warp = FitWarp::Root4;
  a = SampleExact(spec, grid.axes, kWarpSamples2D, threads);
  for (FitAxis& ax : grid.axes) ax.warp = FitWarp::Linear;
  b = SampleExact(spec, grid.axes, kWarpSamples2D, threads);
  a.x.insert(a.x.end(), b.x.begin(), b.x.end());
  a.values.insert(a.values.end(), b.values.begin(), b.values.end());
  a.count += b.count;
  // A (mu, eta) table's points below the float just above 1 are on the jump (fit.h
  // kEtaLayerFloor) or between floats: left out.
  if (skeleton.axes.size() == 2 && skeleton.axes[0].name == "mu" &&
      skeleton.axes[1].name == "eta") {
    const size_t channels = a.values.size() / a.count;
    Samples kept;
    for (size_t i = 0; i < a.count; ++i) {
      if (a.x[i * 2 + 1] < kEtaLayerFloor) continue;
      kept.x.insert(kept.x.end(), a.x.begin() + i * 2, a.x.begin() + i * 2 + 2);
      kept.values.insert(kept.values.end(), a.values.begin() + i * channels,
                         a.values.begin() + (i + 1) * channels);
      ++kept.count;
    }
    return kept;
  }
  return a;
}

/// The max over `check`'s points and channels of |form - exact| (double evaluation).
double CheckError(const FitForm& form, const Samples& check) {
  const int terms = form.TermsPerChannel();
  const size_t dims = form.axes.size(), channels = form.channels.size();
  std::vector<double> row(terms);
  double mx = 0;
  for (size_t i = 0; i < check.count; ++i) {
    DesignRow(form, &check.x[i * dims], row.data());
    for (size_t c = 0; c < channels; ++c) {
      double v = 0;
      for (int j = 0; j < terms; ++j) v += row[j] * form.coefficients[c * terms + j];
      mx = std::max(mx, std::fabs(v - check.values[i * channels + c]));
    }
  }
  return mx;
}

/// The warps with the smallest max at the check points at a middle degree, fitted by least
/// squares to samples at kWarpFitSamples Chebyshev points per axis (every combination in a fixed
/// order: ties keep the earlier).
std::vector<FitWarp> ChooseWarps(const TableSpec& spec, int threads) {
  const FitWarp all[] = {FitWarp::Linear, FitWarp::Sqrt, FitWarp::Root4, FitWarp::Layer,
                         FitWarp::LayerEta};
  FitForm form = Skeleton(spec);
  const bool twoD = form.axes.size() == 2;
  // The Layer warp only on mu before roughness.
  const bool layer = twoD && form.axes[0].name == "mu" && form.axes[1].name == "roughness";
  // The LayerEta warp only on mu before eta.
  const bool layerEta = twoD && form.axes[0].name == "mu" && form.axes[1].name == "eta";
  const Samples check = CheckPoints(spec, form, threads);
  std::vector<FitWarp> best;
  double bestError = INFINITY;
  for (FitWarp w0 : all)
    for (FitWarp w1 : all) {
      if (IsLayerWarp(w1) || (w0 == FitWarp::Layer && !layer) ||
          (w0 == FitWarp::LayerEta && !layerEta))
        continue;
      if (!twoD && w1 != FitWarp::Linear) continue;
      form.axes[0].warp = w0;
      form.axes[0].degree = twoD ? kWarpDegree2D : kWarpDegree1D;
      if (twoD) {
        form.axes[1].warp = w1;
        form.axes[1].degree = kWarpDegree2D;
      }
      Samples s = SampleExact(spec, form.axes, twoD ? kWarpFitSamples2D : kSamples1D, threads);
      FitCoefficients(form, s, 0);
      double e = CheckError(form, check);
      if (e < bestError) {
        bestError = e;
        best = {w0};
        if (twoD) best.push_back(w1);
      }
    }
  return best;
}

/// The candidate forms in the order they are tried: by operation count (stable: a 1D Power
/// form before the Chebyshev form of as many operations, then degree 0 first).
std::vector<FitForm> Candidates(const FitForm& skeleton) {
  std::vector<FitForm> out;
  auto add = [&](FitBasis basis, const std::vector<int>& degrees) {
    FitForm f = skeleton;
    f.basis = basis;
    for (size_t k = 0; k < degrees.size(); ++k) f.axes[k].degree = degrees[k];
    out.push_back(f);
  };
  if (skeleton.axes.size() == 1) {
    for (int n = 1; n <= kMaxDegreePower; ++n) add(FitBasis::Power, {n});
    for (int n = 1; n <= kMaxDegree1D; ++n) add(FitBasis::Chebyshev, {n});
  } else {
    for (int a = 1; a <= kMaxDegree2D; ++a)
      for (int b = 1; b <= kMaxDegree2D; ++b)
        if (std::abs(a - b) <= 4) add(FitBasis::Chebyshev, {a, b});
  }
  std::stable_sort(out.begin(), out.end(), [](const FitForm& x, const FitForm& y) {
    return x.OperationCount() < y.OperationCount();
  });
  return out;
}

}  // namespace

bool Fittable(const TableSpec& spec) {
  return (spec.axes.size() == 1 || spec.axes.size() == 2) &&
         Describe(spec.quantity).firstIntegralChannel == 0 && spec.channels.size() <= 4;
}

FitResult FitTable(const TableSpec& spec, const FitOptions& opt) {
  if (!Fittable(spec))
    throw std::invalid_argument("fit: table '" + spec.name +
                                "' is not fittable (one or two axes of integrals only)");
  FitForm skeleton = Skeleton(spec);
  std::vector<FitWarp> warps = ChooseWarps(spec, opt.threads);
  for (size_t d = 0; d < warps.size(); ++d) skeleton.axes[d].warp = warps[d];
  const bool twoD = skeleton.axes.size() == 2;
  Samples s = SampleExact(spec, skeleton.axes, twoD ? kSamples2D : kSamples1D, opt.threads);
  FitResult result;
  result.specHash = spec.Hash();
  const std::vector<FitForm> candidates = Candidates(skeleton);
  if (opt.terms > 0) {
    // The Chebyshev candidate with at most `terms` coefficients and the smallest sample max.
    double best = INFINITY;
    for (FitForm f : candidates) {
      if (f.basis != FitBasis::Chebyshev || f.TermsPerChannel() > opt.terms) continue;
      double e = FitCoefficients(f, s, 0);
      if (e < best) {
        best = e;
        result.form = f;
      }
    }
    if (result.form.axes.empty())
      throw std::invalid_argument("fit: --terms " + std::to_string(opt.terms) + " is too few");
    FitCoefficients(result.form, s, kLawsonIterations);
    result.error = MeasureFitError(spec, result.form, opt.threads);
    // A one-axis table: the Power form of the same degree when its searched max is no larger.
    if (!twoD && result.form.axes[0].degree <= kMaxDegreePower) {
      FitForm power = result.form;
      power.basis = FitBasis::Power;
      FitCoefficients(power, s, kLawsonIterations);
      FitErrorReport rep = MeasureFitError(spec, power, opt.threads);
      if (rep.max <= result.error.max) result = {power, rep, result.specHash};
    }
    return result;
  }
  double bestFound = INFINITY;
  for (FitForm f : candidates) {
    if (FitCoefficients(f, s, 0) > kScreenFactor * opt.maxError) continue;
    FitCoefficients(f, s, kLawsonIterations);
    FitErrorReport rep = MeasureFitError(spec, f, opt.threads);
    bestFound = std::min(bestFound, rep.maxOffJump);
    if (rep.maxOffJump <= opt.maxError) {
      result.form = f;
      result.error = rep;
      return result;
    }
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", bestFound);
  throw std::invalid_argument(
      "fit: no form of '" + spec.name + "' up to degree " +
      std::to_string(twoD ? kMaxDegree2D : kMaxDegree1D) + " meets --max-error " +
      std::to_string(opt.maxError) +
      (std::isfinite(bestFound) ? std::string(" (best found ") + buf + ")" : std::string("")));
}

}  // namespace kiln
