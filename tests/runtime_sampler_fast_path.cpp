// LutSampler (kiln/lut.h) and its batch call against the generic-stencil lookup in double
// (tests/runtime_sample_reference.h) on every committed table and on every warp: float for
// float on the double path (cubic lookups, linear ones on axes the float path does not take,
// and always LutSampler::sampleDouble and LutView::sample), within the float path's stated
// bound (tests/runtime_float_bound.h) on the float path, where one point and the batch call
// agree bit for bit.
#include <catch2/catch.hpp>
#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "committed_luts.h"
#include "kiln/exr_loader.h"
#include "float_bits.h"
#include "kiln/lut.h"
#include "kiln/table.h"
#include "runtime_float_bound.h"
#include "runtime_sample_reference.h"

using namespace kiln;
using kiln::test::LutFiles;
using kiln::test::LutsDir;

namespace {

using test::Bits;

/// Random lookup points of a view, `dims` values per point: mostly inside the axes, some on
/// nodes, at the ends, outside them and NaN, and (for a layer warp) at r = 0 / eta = 1.
std::vector<double> Points(const LutView& v, int count, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xs;
  for (int k = 0; k < count; ++k) {
    for (int d = 0; d < v.dims; ++d) {
      const Axis& a = v.axis[d];
      const double pick = u(rng);
      double x = a.lo + (a.hi - a.lo) * u(rng);
      if (pick < 0.05)
        x = a.lo;
      else if (pick < 0.10)
        x = a.hi;
      else if (pick < 0.13)
        x = a.lo - 0.5 * (a.hi - a.lo) * u(rng);
      else if (pick < 0.16)
        x = a.hi + 0.5 * (a.hi - a.lo) * u(rng);
      else if (pick < 0.17)
        x = std::numeric_limits<double>::quiet_NaN();
      else if (pick < 0.20 && d == 1 && a.lo < 1.0 && 1.0 < a.hi)
        x = 1.0;  // eta = 1
      else if (pick < 0.30 && d != 0)
        x = a.node(static_cast<int>(u(rng) * a.size));
      xs.push_back(x);
    }
  }
  return xs;
}

/// Every point of xs: LutView::sample and LutSampler::sampleDouble equal the reference bit for
/// bit; LutSampler::sample and the batch call give the same floats, equal to the reference bit
/// for bit on the double path and within FloatPathBound of it on the float path (a linear
/// lookup of a floatPath() sampler). Returns the number of floats that break this.
int CountMismatches(const LutView& v, const std::vector<double>& xs, Filter filter) {
  const int nd = v.dims, nc = v.channels;
  const size_t count = xs.size() / static_cast<size_t>(nd);
  const LutSampler sampler(v);
  const bool floatPath = sampler.floatPath() && filter == Filter::Linear;
  std::vector<double> bound(nc, 0.0);
  if (floatPath)
    for (int c = 0; c < nc; ++c) bound[c] = test::FloatPathBound(v, c);
  std::vector<float> batch(count * static_cast<size_t>(nc));
  sampler.sample(xs.data(), count, batch.data(), filter);
  std::vector<float> ref(nc), one(nc), viaView(nc), twice(nc);
  int bad = 0;
  for (size_t k = 0; k < count; ++k) {
    const double* x = &xs[k * static_cast<size_t>(nd)];
    test::ReferenceSample(v, x, ref.data(), filter);
    sampler.sample(x, one.data(), filter);
    v.sample(x, viaView.data(), filter);
    sampler.sampleDouble(x, twice.data(), filter);
    for (int c = 0; c < nc; ++c) {
      const float b = batch[k * static_cast<size_t>(nc) + c];
      const bool agree = Bits(one[c]) == Bits(b) && Bits(viaView[c]) == Bits(ref[c]) &&
                         Bits(twice[c]) == Bits(ref[c]);
      const bool close = floatPath ? std::fabs(double(one[c]) - double(ref[c])) <= bound[c]
                                   : Bits(one[c]) == Bits(ref[c]);
      if (!(agree && close) && bad < 3) {
        UNSCOPED_INFO("point " << k << " x0 " << x[0] << " channel " << c << ": reference "
                               << ref[c] << ", sampler " << one[c] << ", view " << viaView[c]
                               << ", batch " << b << ", bound " << bound[c]);
      }
      bad += !(agree && close);
    }
  }
  return bad;
}

/// A view over `data` (filled with random values, some -0) of the given axes and channels.
LutView Synthetic(std::vector<float>& data, int channels, std::vector<Axis> axes, uint32_t seed) {
  LutView v;
  v.channels = channels;
  v.dims = static_cast<int>(axes.size());
  for (int d = 0; d < v.dims; ++d) v.axis[d] = axes[d];
  data.assign(v.valueCount(), 0.0f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  for (size_t i = 0; i < data.size(); ++i) data[i] = i % 7 == 3 ? -0.0f : u(rng);
  v.data = data.data();
  return v;
}

}  // namespace

TEST_CASE(
    "LutSampler, its batch call and LutView::sample match the reference lookup on every "
    "committed table",
    "[runtime][sampler][luts]") {
  const auto files = LutFiles();
  REQUIRE(files.size() >= 50);
  for (const std::string& name : files) {
    INFO(name);
    Table t = loadTable(LutsDir() + "/" + name);
    const LutView v = t.view();
    REQUIRE(v.valid());
    const std::vector<double> xs = Points(v, 3000, 7);
    CHECK(CountMismatches(v, xs, Filter::Linear) == 0);
    CHECK(CountMismatches(v, xs, Filter::Cubic) == 0);
  }
}

TEST_CASE("LutSampler matches the reference lookup on every warp, coupled or not",
          "[runtime][sampler]") {
  struct Case {
    const char* what;
    std::vector<Axis> axes;
  };
  const std::vector<Case> cases = {
      {"linear 1D, range not a power of two", {{0.1, 0.7, 17, Warp::Linear}}},
      {"sqrt, square, log", {{0.0, 1.0, 9, Warp::Sqrt}, {-1.0, 3.0, 5, Warp::Square}}},
      {"log 1D", {{0.01, 100.0, 33, Warp::Log}}},
      {"root4, angle, arcsine",
       {{0.0, 2.0, 12, Warp::Root4}, {0.0, 1.0, 10, Warp::Angle}, {0.0, 1.0, 7, Warp::Arcsine}}},
      {"root4-layer over sqrt", {{0.0, 1.0, 16, Warp::Root4Layer}, {0.0, 1.0, 8, Warp::Sqrt}}},
      {"root4-layer, range 0.5", {{0.0, 0.5, 15, Warp::Root4Layer}, {0.0, 1.0, 6, Warp::Linear}}},
      {"layer-eta", {{0.0, 1.0, 20, Warp::LayerEta}, {0.5, 2.0, 9, Warp::Linear}}},
      {"root4-layer-angle",
       {{0.0, 1.0, 14, Warp::Root4LayerAngle},
        {0.0, 1.0, 6, Warp::Sqrt},
        {0.4, 1.6, 5, Warp::Sqrt}}},
      {"root4-layer-split at the critical cosine",
       {{0.0, 1.0, 17, Warp::Root4LayerSplit},
        {0.0, 1.0, 6, Warp::Sqrt},
        {0.3, 1.5, 7, Warp::Linear}}},
      {"root4-layer-split at a constant",
       {{0.0, 1.0, 25, Warp::Root4LayerSplit, 0.3}, {0.0, 1.0, 5, Warp::Sqrt}}},
      {"root4-layer-split2",
       {{0.0, 1.0, 33, Warp::Root4LayerSplit2},
        {0.0, 1.0, 6, Warp::Arcsine},
        {0.3, 1.5, 6, Warp::Angle}}},
      {"axes of one and two nodes",
       {{0.0, 1.0, 1, Warp::Linear}, {0.0, 1.0, 2, Warp::Sqrt}, {-2.0, 5.0, 1, Warp::Linear}}},
  };
  uint32_t seed = 1;
  for (const Case& c : cases) {
    INFO(c.what);
    for (int channels : {1, 3}) {
      std::vector<float> data;
      const LutView v = Synthetic(data, channels, c.axes, ++seed);
      REQUIRE(v.valid());
      const std::vector<double> xs = Points(v, 4000, seed);
      CHECK(CountMismatches(v, xs, Filter::Linear) == 0);
      CHECK(CountMismatches(v, xs, Filter::Cubic) == 0);
    }
  }
}

TEST_CASE("LutSampler returns the stored texel at every node, -0 included, on both paths",
          "[runtime][sampler]") {
  const std::vector<std::vector<Axis>> shapes = {
      {{0.0, 1.0, 9, Warp::Sqrt}, {0.25, 3.0, 7, Warp::Log}, {0.0, 1.0, 3, Warp::Linear}},
      {{0.0, 1.0, 9, Warp::Root4}, {0.25, 3.0, 7, Warp::Sqrt}, {-1.0, 0.7, 3, Warp::Linear}}};
  for (const std::vector<Axis>& axes : shapes) {
    std::vector<float> data;
    const LutView v = Synthetic(data, 2, axes, 5);
    const LutSampler sampler(v);
    CHECK(sampler.floatPath() == (axes[1].warp != Warp::Log));
    for (Filter filter : {Filter::Linear, Filter::Cubic}) {
      for (int i2 = 0; i2 < 3; ++i2)
        for (int i1 = 0; i1 < 7; ++i1)
          for (int i0 = 0; i0 < 9; ++i0) {
            const double x[3] = {v.axis[0].node(i0), v.axis[1].node(i1), v.axis[2].node(i2)};
            float out[2];
            sampler.sample(x, out, filter);
            for (int c = 0; c < 2; ++c) REQUIRE(Bits(out[c]) == Bits(v.at(i0, i1, i2, c)));
          }
    }
  }
}

TEST_CASE("Linear lookups take the float path on linear, sqrt, root4 and root4-layer axes only",
          "[runtime][sampler]") {
  const float data[64 * 3] = {};
  auto path = [&](std::vector<Axis> axes) {
    LutView v;
    v.data = data;
    v.channels = 1;
    v.dims = static_cast<int>(axes.size());
    for (int d = 0; d < v.dims; ++d) v.axis[d] = axes[d];
    return LutSampler(v).floatPath();
  };
  CHECK(path({{0.0, 1.0, 8, Warp::Root4Layer}, {0.0, 1.0, 8, Warp::Sqrt}}));  // ggx-dfg's form
  CHECK(path(
      {{0.0, 1.0, 4, Warp::Root4Layer}, {0.0, 1.0, 4, Warp::Sqrt}, {1.0, 3.0, 4, Warp::Sqrt}}));
  CHECK(path({{0.0, 1.0, 64, Warp::Linear}}));
  CHECK(path({{0.0, 1.0, 8, Warp::Sqrt}, {0.0, 1.0, 8, Warp::Linear}}));
  CHECK_FALSE(path({{0.0, 1.0, 8, Warp::Root4}, {0.5, 1.0, 8, Warp::Log}}));
  CHECK_FALSE(path({{0.0, 1.0, 8, Warp::Angle}, {0.0, 1.0, 8, Warp::Linear}}));
  CHECK_FALSE(path({{0.0, 1.0, 8, Warp::LayerEta}, {0.5, 2.0, 8, Warp::Linear}}));
  CHECK_FALSE(LutSampler().floatPath());
}

TEST_CASE("The batch call reads packed points and writes interleaved channels",
          "[runtime][sampler]") {
  // A 1D table of 3 nodes over [0, 2] with 2 channels: (0, 10), (1, 20), (4, 30).
  const float data[] = {0, 10, 1, 20, 4, 30};
  LutView v;
  v.data = data;
  v.channels = 2;
  v.dims = 1;
  v.axis[0] = Axis{0.0, 2.0, 3, Warp::Linear};
  const double xs[] = {0.0, 0.5, 1.5, 2.0};
  float out[8];
  LutSampler(v).sample(xs, 4, out);
  const float expect[] = {0, 10, 0.5f, 15, 2.5f, 25, 4, 30};
  for (int i = 0; i < 8; ++i) CHECK(out[i] == expect[i]);
}

TEST_CASE("An invalid view samples to zeros, one point or a batch", "[runtime][sampler]") {
  const float data[] = {1, 2, 3, 4};
  LutView v;
  v.data = data;
  v.channels = 2;
  v.dims = 1;
  v.axis[0] = Axis{1.0, 1.0, 2, Warp::Linear};  // lo == hi: invalid
  const LutSampler sampler(v);
  CHECK_FALSE(sampler.valid());
  const double xs[] = {1.0, 0.5, 2.0};
  float out[6] = {9, 9, 9, 9, 9, 9};
  sampler.sample(xs, 3, out);
  for (float f : out) CHECK(f == 0.0f);
  float one[2] = {9, 9};
  sampler.sample(xs, one, Filter::Cubic);
  CHECK(one[0] == 0.0f);
  CHECK(one[1] == 0.0f);
  CHECK_FALSE(LutSampler().valid());
}

TEST_CASE(
    "The float path departs from the double path by at most a fifth of every committed "
    "table's declared lookup error, or 2 float ulps",
    "[runtime][sampler][luts]") {
  int floatTables = 0;
  double worstShare = 0.0;
  std::string worstTable;
  for (const std::string& name : LutFiles()) {
    Table t = loadTable(LutsDir() + "/" + name);
    const LutView v = t.view();
    const LutSampler sampler(v);
    if (!sampler.floatPath()) continue;
    ++floatTables;
    INFO(name);
    REQUIRE(t.lookupError.max > 0.0);
    const std::vector<double> xs = Points(v, 3000, 11);
    std::vector<float> fast(v.channels), exact(v.channels);
    double departure = 0.0;
    for (size_t k = 0; k < xs.size(); k += v.dims) {
      sampler.sample(&xs[k], fast.data());
      sampler.sampleDouble(&xs[k], exact.data());
      for (int c = 0; c < v.channels; ++c)
        departure = std::fmax(departure, std::fabs(double(fast[c]) - double(exact[c])));
    }
    // Measured against a fifth of the declared error plus 2 float ulps of the largest texel
    // (a table whose interpolation is exact declares an error below float rounding).
    float vmax = 0.0f;
    for (size_t k = 0; k < v.valueCount(); ++k) vmax = std::fmax(vmax, std::fabs(v.data[k]));
    const double ulp = std::nextafter(vmax, std::numeric_limits<float>::infinity()) - vmax;
    const double share = departure / (0.2 * t.lookupError.max + 2.0 * ulp);
    if (share > worstShare) {
      worstShare = share;
      worstTable = name;
    }
  }
  INFO("largest departure / (declared lookup error / 5 + 2 ulps): " << worstShare << " ("
                                                                    << worstTable << ")");
  CHECK(floatTables >= 40);
  CHECK(worstShare <= 1.0);
}
