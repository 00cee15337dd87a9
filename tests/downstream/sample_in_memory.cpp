// Uses kiln::lut alone (no OpenEXR, no allocation): a 3 x 2 table in memory, sampled at its nodes
// (exact) and between them (the linear blend). Exits 0 when every value is as expected.
#include <cstdio>

#include "kiln/lut.h"

int main() {
  // f(x, y) = x + 10 y on x in {0, 0.5, 1}, y in {0, 1}: linear, so linear sampling is exact.
  static const float data[] = {0.0f, 0.5f, 1.0f, 10.0f, 10.5f, 11.0f};
  kiln::LutView lut;
  lut.data = data;
  lut.channels = 1;
  lut.dims = 2;
  lut.axis[0] = kiln::Axis{0.0, 1.0, 3, kiln::Warp::Linear};
  lut.axis[1] = kiln::Axis{0.0, 1.0, 2, kiln::Warp::Linear};
  if (!lut.valid()) return std::puts("invalid view"), 1;
  const double points[][2] = {{0, 0}, {0.5, 1}, {1, 1}, {0.25, 0.5}, {0.8, 0.3}};
  for (const auto& p : points) {
    float v = 0;
    lut.sample(p, &v);
    double expected = p[0] + 10 * p[1];
    if (v != static_cast<float>(expected) && (v - expected) * (v - expected) > 1e-10) {
      std::printf("f(%g, %g) = %.9g, expected %.9g\n", p[0], p[1], v, expected);
      return 1;
    }
  }
  std::puts("kiln::lut: ok");
  return 0;
}
