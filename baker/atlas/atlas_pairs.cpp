// The atlas's one list: every comparison, one line each ({name, cheap side, reference side, axis,
// lo, hi, note}). A side is {model, "param=value,...", roughness map, rescale}; the atlas
// roughness coordinate runs over [lo, hi]. Adding a comparison is adding a line here.
#include <cmath>
#include <cstdio>

#include "baker/atlas/atlas.h"
#include "baker/math/constants.h"

namespace kiln {
namespace {

using M = AtlasRoughnessMap;
using R = AtlasRescale;

/// "f0=F" with F = ((eta - 1)/(eta + 1))^2, the normal reflectance of index eta, %.17g.
std::string F0Of(double eta) {
  char b[64];
  std::snprintf(b, sizeof b, "f0=%.17g", std::pow((eta - 1) / (eta + 1), 2));
  return b;
}
std::string EtaOf(double eta) {
  char b[64];
  std::snprintf(b, sizeof b, "eta=%.17g", eta);
  return b;
}

/// GGX (alpha = r^2, height-correlated Smith) with Schlick F at f0 = ((eta-1)/(eta+1))^2 against
/// exact dielectric Fresnel at eta. r starts at 0.1: at r = 0 the lobe is a delta (max_df
/// unbounded) and below 0.1 (alpha = 0.01) the peak grows like 1/alpha^2.
AtlasPair Schlick(const char* name, double eta) {
  return {name,
          {"ggx", F0Of(eta)},
          {"ggx", EtaOf(eta)},
          "roughness r (alpha = r^2)",
          0.1,
          1,
          "Schlick f0 vs exact dielectric Fresnel at the same normal reflectance"};
}

}  // namespace

const std::vector<AtlasPair>& AtlasPairs() {
  // clang-format off
  static const std::vector<AtlasPair> pairs = {
      Schlick("ggx-schlick-vs-exact-eta1.33", 1.33),
      Schlick("ggx-schlick-vs-exact-eta1.5", 1.5),
      Schlick("ggx-schlick-vs-exact-eta2", 2.0),
      {"oren-nayar-qualitative", {"oren-nayar-qualitative"}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "same sigma"},
      {"oren-nayar-qualitative-ir", {"oren-nayar-qualitative-ir"}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "same sigma"},
      {"fujii", {"fujii"}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "same sigma"},
      {"fujii-normalized", {"fujii-normalized", "", M::FujiiSigmaPrime}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "sigma' = B/A of Fujii's fit to the full model at rho = 1"},
      {"gotanda-fresnel", {"gotanda-fresnel"}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "same sigma; f0 = 0 (its default)"},
      {"gotanda-ggx", {"gotanda-ggx"}, {"oren-nayar"}, "sigma = alpha_GGX", 0, 1, "the fit's parameter is GGX's alpha (= r^2), compared with Oren-Nayar at sigma = alpha (kiln's choice); the fit's range [0, 1]; f0 = 0 (its default)"},
      {"lambert", {"lambert"}, {"oren-nayar"}, "sigma (rad)", 0, HalfPi, "Lambert has no roughness"},
      {"unity-brdf2", {"unity-brdf2", "rs=1"}, {"unity-brdf1", "f0=1"}, "perceptual roughness r", 0.1, 1, "Unity's low-end lobe against its high-end one at white specular (rs = f0 = 1): modified GGX with V F ~ 1/(4 LdotH^2 (a + 0.5)) vs GGX, approximate Smith-joint V, Schlick"},
      {"unity-brdf3", {"unity-brdf3", "rs=1"}, {"unity-brdf1", "f0=1"}, "perceptual roughness r", 0.1, 1, "Unity's lowest-end lobe (normalised Phong in RDF form, unity_NHxRoughness) against BRDF1 at white specular (rs = f0 = 1)"},
      {"blinn-phong-2.04", {"blinn-phong-normalized", "", M::Same, R::BlinnPhong204}, {"blinn-phong-normalized"}, "roughness r (s = 2/r^4 - 2)", 0.1, 1, "(s + 2.04)/(8 pi) in place of the exact N(s); F = 1, R_s = 1"},
  };
  // clang-format on
  return pairs;
}

}  // namespace kiln
