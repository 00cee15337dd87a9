// A lookup at a grid node returns the stored texel bit for bit: on every node of every
// committed table, through LutSampler (one point, the batch call and sampleDouble) and
// LutView::sample, for the linear and the cubic filter. Nodes no lookup reaches are left out: the
// layer-limit nodes of a collapsed row (Axis::holdsLayerLimit at layer scale 0) and nodes that
// share their position with a neighbour (a Root4LayerSplit2 row whose middle pieces have zero
// width).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "committed_luts.h"
#include "kiln/exr_loader.h"
#include "float_bits.h"
#include "kiln/lut.h"
#include "kiln/table.h"

using namespace kiln;

namespace {

using test::Bits;

/// The nodes of v that a lookup reaches, dims values each, and their (i0, i1, i2).
void ReachableNodes(const LutView& v, std::vector<double>& xs, std::vector<int>& ids) {
  const int n0 = v.size(0), n1 = v.size(1), n2 = v.size(2);
  const size_t nodes = static_cast<size_t>(n0) * n1 * n2;
  xs.reserve(nodes * static_cast<size_t>(v.dims));
  ids.reserve(nodes * 3);
  std::vector<double> row(static_cast<size_t>(n0));
  for (int i2 = 0; i2 < n2; ++i2)
    for (int i1 = 0; i1 < n1; ++i1) {
      double x[3] = {0.0, v.dims >= 2 ? v.axis[1].node(i1) : 0.0,
                     v.dims >= 3 ? v.axis[2].node(i2) : 0.0};
      const double c = v.layerScaleAt(x), split = v.splitAt(x);
      const Axis& a = v.axis[0];
      for (int i0 = 0; i0 < n0; ++i0) row[i0] = a.node(i0, c, split);
      for (int i0 = 0; i0 < n0; ++i0) {
        x[0] = row[i0];
        const double t = n0 > 1 ? static_cast<double>(i0) / (n0 - 1) : 0.0;
        if (c == 0.0 && isLayerWarp(a.warp) && a.holdsLayerLimit(t)) continue;
        if ((i0 > 0 && row[i0 - 1] == x[0]) || (i0 + 1 < n0 && row[i0 + 1] == x[0])) continue;
        xs.insert(xs.end(), x, x + v.dims);
        ids.insert(ids.end(), {i0, i1, i2});
      }
    }
}

/// The number of reachable nodes of v at which a lookup of `filter` does not return the
/// stored texel bit for bit (one point, batch call, LutView::sample).
int NodeMisses(const LutView& v, Filter filter) {
  std::vector<double> xs;
  std::vector<int> ids;
  ReachableNodes(v, xs, ids);
  const LutSampler sampler(v);
  const std::size_t count = ids.size() / 3, nc = static_cast<std::size_t>(v.channels);
  std::vector<float> batch(count * nc), one(nc), viaView(nc), twice(nc);
  sampler.sample(xs.data(), count, batch.data(), filter);
  int misses = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double* x = &xs[k * static_cast<std::size_t>(v.dims)];
    sampler.sample(x, one.data(), filter);
    v.sample(x, viaView.data(), filter);
    sampler.sampleDouble(x, twice.data(), filter);
    for (std::size_t c = 0; c < nc; ++c) {
      const uint32_t stored =
          Bits(v.at(ids[3 * k], ids[3 * k + 1], ids[3 * k + 2], static_cast<int>(c)));
      const bool miss = Bits(one[c]) != stored || Bits(batch[k * nc + c]) != stored ||
                        Bits(viaView[c]) != stored || Bits(twice[c]) != stored;
      if (miss && misses < 3)
        UNSCOPED_INFO(
            "node (" << ids[3 * k] << ", " << ids[3 * k + 1] << ", " << ids[3 * k + 2]
                     << ") channel " << c << ": stored "
                     << v.at(ids[3 * k], ids[3 * k + 1], ids[3 * k + 2], static_cast<int>(c))
                     << ", sampler " << one[c] << ", batch " << batch[k * nc + c] << ", view "
                     << viaView[c]);
      misses += miss;
    }
  }
  return misses;
}

}  // namespace

TEST_CASE("Every reachable node of every committed table is looked up exactly",
          "[runtime][sampler][luts][nodes]") {
  const auto files = test::LutFiles();
  REQUIRE(files.size() >= 50);
  int floatTables = 0;
  for (const std::string& name : files) {
    INFO(name);
    Table t = loadTable(test::LutsDir() + "/" + name);
    const LutView v = t.view();
    REQUIRE(v.valid());
    floatTables += LutSampler(v).floatPath();
    CHECK(NodeMisses(v, Filter::Linear) == 0);
    CHECK(NodeMisses(v, Filter::Cubic) == 0);
  }
  CHECK(floatTables >= 40);  // the float path is what most of the catalogue takes
}
