#include "baker/fit/engine_approximations.h"

#include <algorithm>
#include <cmath>

namespace kiln {

void KarisEnvBrdfApprox(const FitForm&, const float* x, float* out) {
  const float mu = x[0], r = x[1];
  const float rx = r * -1.0f + 1.0f, ry = r * -0.0275f + 0.0425f;
  const float rz = r * -0.572f + 1.04f, rw = r * 0.022f - 0.04f;
  const float a = std::min(rx * rx, std::exp2(-9.28f * mu)) * rx + ry;
  out[0] = -1.04f * a + rz;
  out[1] = 1.04f * a + rw;
}

FitForm DfgProbeForm(const TableSpec& spec) {
  FitForm form = Skeleton(spec);
  for (FitAxis& f : form.axes) {
    f.degree = 1;
    f.warp = f.name == "mu" ? FitWarp::Layer : FitWarp::Sqrt;
  }
  return form;
}

}  // namespace kiln
