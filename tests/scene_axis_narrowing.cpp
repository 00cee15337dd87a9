// Narrowed axes keep the catalogue's node density: fewer nodes for a narrower range, at least 2.
#include <catch2/catch.hpp>

#include "baker/scene/axis_narrowing.h"

using namespace kiln;

namespace {
double MaxCell(const AxisSpec& a) {
  double m = 0;
  for (int i = 0; i + 1 < a.size; ++i) m = std::max(m, a.ToAxis().node(i + 1) - a.ToAxis().node(i));
  return m;
}
}  // namespace

TEST_CASE("NarrowAxis: no cell wider than the catalogue's, fewer nodes, at least 2",
          "[scene][axis]") {
  AxisSpec full{"roughness", 0, 1, 64, Warp::Linear};
  CHECK(NarrowAxis(full, 0, 1).size == 64);
  int previous = 65;
  for (double width : {0.9, 0.5, 0.3, 0.1, 0.02, 0.001}) {
    AxisSpec a = NarrowAxis(full, 0.05, 0.05 + width);
    INFO(width);
    CHECK(a.lo == 0.05);
    CHECK(a.hi == 0.05 + width);
    CHECK(a.size >= 2);
    CHECK(a.size <= previous);
    CHECK(MaxCell(a) <= 1.0 / 63 * (1 + 1e-9));
    if (a.size > 2) {  // and not one node more than that needs
      AxisSpec fewer = a;
      --fewer.size;
      CHECK(MaxCell(fewer) > 1.0 / 63);
    }
    previous = a.size;
  }
}

TEST_CASE("NarrowAxis beyond the catalogue range uses its end cells", "[scene][axis]") {
  AxisSpec eta{"eta", 1, 3, 16, Warp::Linear};
  AxisSpec a = NarrowAxis(eta, 2.5, 4.0);
  CHECK(a.size == 13);  // 1.5 / (2/15) = 11.25 cells -> 12 cells
  AxisSpec s{"s", 1, 10000, 64, Warp::Log};
  AxisSpec b = NarrowAxis(s, 10, 100);
  CHECK(b.warp == Warp::Log);  // the catalogue's warp when it needs no more nodes than linear
  CHECK(b.size == 17);         // one decade of four at 63 cells: 15.75 -> 16 cells
}

TEST_CASE("SliceAxis: 2 nodes, one exactly at the value", "[scene][axis]") {
  AxisSpec full{"roughness", 0, 1, 64, Warp::Linear};
  AxisSpec a = SliceAxis(full, 0.3);
  CHECK(a.size == 2);
  CHECK(a.ToAxis().node(0) == 0.3);
  CHECK(a.hi == full.ToAxis().node(19));  // the next catalogue node
  AxisSpec end = SliceAxis(full, 1.0);
  CHECK(end.ToAxis().node(1) == 1.0);
  CHECK(end.lo == full.ToAxis().node(62));
  AxisSpec beyond = SliceAxis(AxisSpec{"eta", 1, 3, 16, Warp::Linear}, 4.0);
  CHECK(beyond.hi == 4.0);
  CHECK(beyond.ToAxis().valid());
}
