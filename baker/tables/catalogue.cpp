#include "baker/tables/catalogue.h"

#include <stdexcept>

#include "baker/models/registry.h"

namespace kiln {
namespace {

const char* kMicrofacetModels[] = {"ggx", "ggx-separable", "beckmann", "beckmann-separable",
                                   "blinn-phong"};
const char* kDiffuseModels[] = {"lambert", "burley", "frostbite", "oren-nayar",
                                "oren-nayar-qualitative", "oren-nayar-qualitative-ir", "fujii",
                                "fujii-normalized", "gotanda-fresnel", "gotanda-ggx", "hammon",
                                "shirley", "ashikhmin-shirley-diffuse", "triace-lambert"};

bool HasRho2(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  return m && m->hasRho2;
}

const ModelInfo& Info(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (!m) throw std::invalid_argument("unknown model '" + model + "'");
  return *m;
}

void Resize(TableSpec& spec, int size) {
  if (size <= 0) return;
  for (AxisSpec& a : spec.axes)
    if (a.size > 2 || a.name != "roughness") a.size = size;  // a roughness-less model keeps 2
}

}  // namespace

// Sizes and warps (README "The catalogue" gives the measured lookup errors):
// - mu: near grazing a microfacet albedo is a function of mu / alpha (a layer of width
//   alpha = r^2 at mu = 0) and a dielectric Fresnel term of mu / sqrt(eta - 1). The microfacet
//   dfg and albedo tables take the root4-layer warp (lut.h): half of the nodes follow the layer
//   at every roughness, so the corner (mu, r) -> (0, 0) interpolates like the rest (a fixed warp
//   cannot: the layer's width goes to 0 with r). The Fresnel tables take root4, nodes at
//   mu = (i/(N-1))^4, which resolves the layer down to small eta - 1. sqrt for the diffuse
//   albedos (polynomials in 1 - mu) and the BRDF tables.
// - roughness: sqrt for the microfacet tables (the layer above moves with r^2), linear for the
//   diffuse ones; eta: sqrt (dense near 1, same reason); n, k: linear; Blinn-Phong's s: log.
AxisSpec DefaultMuAxis(const std::string& quantity) {
  if (quantity == "fresnel-albedo") return {"mu", 0, 1, 48, Warp::Root4};
  if (quantity == "fresnel-conductor") return {"mu", 0, 1, 32, Warp::Root4};
  if (quantity == "dfg" || quantity == "albedo") return {"mu", 0, 1, 128, Warp::Root4Layer};
  return {"mu", 0, 1, 128, Warp::Root4};
}

/// The mu axis of a diffuse albedo table. Most diffuse models are polynomials in mu and 1 - mu
/// (Burley, Frostbite, Shirley, ...) and bend most near grazing: sqrt. The Oren-Nayar qualitative
/// family, normalised Fujii and Gotanda's GGX diffuse are smooth in the angles instead, so their
/// albedo has a square-root point at mu = 1 (sin(theta_o) terms): angle, nodes uniform in theta_o
/// (measured: oren-nayar-qualitative 8.3e-3 with sqrt, 3.5e-4 with angle; the polynomial models
/// err 2-10x more with angle than with sqrt).
AxisSpec DiffuseMuAxis(const std::string& model) {
  if (model == "gotanda-ggx") return {"mu", 0, 1, 128, Warp::Angle};
  if (model == "oren-nayar-qualitative" || model == "oren-nayar-qualitative-ir" ||
      model == "fujii-normalized")
    return {"mu", 0, 1, 64, Warp::Angle};
  return {"mu", 0, 1, 64, Warp::Sqrt};
}

AxisSpec DefaultRoughnessAxis(const std::string& model) {
  const ModelInfo& m = Info(model);
  // blinn-phong's albedo climbs to sqrt(pi) at r = 1 with a curvature of ~70: 128 sqrt nodes
  // (spacing 2 / 127 there) left 2e-3 of lookup error, so it gets 256 (a linear axis errs more
  // near r = 0: 1e-2 in its first cell, measured).
  if (model == "blinn-phong") return {"roughness", 0, 1, 256, Warp::Sqrt};
  for (const ParamInfo& p : m.params)
    if (p.name == "roughness")
      return m.specular() ? AxisSpec{"roughness", 0, p.hi, 128, Warp::Sqrt}
                          : AxisSpec{"roughness", 0, p.hi, 64, Warp::Linear};
  return {"roughness", 0, 1, 2, Warp::Linear};  // no roughness: constant along this axis
}

AxisSpec DefaultEtaAxis() { return {"eta", 1, 3, 24, Warp::Sqrt}; }

TableSpec DfgSpec(const std::string& model, AxisSpec mu, AxisSpec roughness) {
  TableSpec s;
  s.name = model + "-dfg";
  s.model = model;
  s.quantity = "dfg";
  s.channels = {"A", "B"};
  s.meanings = {"A = integral f/F (1 - (1 - o.h)^5) mu_l dl (scales F0)",
                "B = integral f/F (1 - o.h)^5 mu_l dl (bias), albedo = F0 A + B"};
  s.axes = {mu, roughness};
  return s;
}

TableSpec AlbedoSpec(const std::string& model, AxisSpec mu, AxisSpec roughness) {
  TableSpec s;
  s.name = model + "-albedo";
  s.model = model;
  s.quantity = "albedo";
  if (HasRho2(model)) {
    s.channels = {"E_rho", "E_rho2"};
    s.meanings = {"directional albedo, rho^1 part", "rho^2 part: E = rho E_rho + rho^2 E_rho2"};
  } else {
    s.channels = {"E"};
    s.meanings = {"directional albedo E(mu) at rho = 1, F = 1"};
  }
  s.axes = {mu, roughness};
  return s;
}

TableSpec AlbedoAvgSpec(const std::string& model, AxisSpec roughness) {
  TableSpec s;
  s.name = model + "-albedo-avg";
  s.model = model;
  s.quantity = "albedo-avg";
  if (HasRho2(model)) {
    s.channels = {"E_avg_rho", "E_avg_rho2"};
    s.meanings = {"average albedo, rho^1 part", "rho^2 part"};
  } else {
    s.channels = {"E_avg"};
    s.meanings = {"average albedo 2 int E(mu) mu dmu at rho = 1, F = 1"};
  }
  s.axes = {roughness};
  return s;
}

TableSpec FresnelAlbedoSpec(AxisSpec mu, AxisSpec roughness, AxisSpec eta) {
  TableSpec s;
  s.name = "ggx-fresnel-albedo";
  s.model = "ggx";
  s.quantity = "fresnel-albedo";
  s.channels = {"E"};
  s.meanings = {"GGX albedo with exact dielectric Fresnel at index eta"};
  s.axes = {mu, roughness, eta};
  return s;
}

TableSpec FresnelAlbedoAvgSpec(AxisSpec roughness, AxisSpec eta) {
  TableSpec s = FresnelAlbedoSpec({}, roughness, eta);
  s.name = "ggx-fresnel-albedo-avg";
  s.quantity = "fresnel-albedo-avg";
  s.channels = {"E_avg"};
  s.meanings = {"average of ggx-fresnel-albedo over mu (2 int E mu dmu)"};
  s.axes = {roughness, eta};
  return s;
}

TableSpec FresnelDielectricSpec(AxisSpec mu, AxisSpec eta) {
  TableSpec s;
  s.name = "fresnel-dielectric";
  s.model = "none";
  s.quantity = "fresnel-dielectric";
  s.channels = {"F"};
  s.meanings = {"exact unpolarized dielectric Fresnel reflectance"};
  s.axes = {mu, eta};
  return s;
}

TableSpec FresnelDielectricAvgSpec(AxisSpec eta) {
  TableSpec s;
  s.name = "fresnel-dielectric-avg";
  s.model = "none";
  s.quantity = "fresnel-dielectric-avg";
  s.channels = {"F_avg"};
  s.meanings = {"2 int F(mu) mu dmu"};
  s.axes = {eta};
  return s;
}

TableSpec FresnelConductorSpec(AxisSpec mu, AxisSpec n, AxisSpec k) {
  TableSpec s;
  s.name = "fresnel-conductor";
  s.model = "none";
  s.quantity = "fresnel-conductor";
  s.channels = {"F"};
  s.meanings = {"exact conductor Fresnel reflectance, eta = n + i k"};
  s.axes = {mu, n, k};
  return s;
}

TableSpec BlinnPhongNormalizationSpec(AxisSpec sAxis) {
  TableSpec s;
  s.name = "blinn-phong-normalization";
  s.model = "blinn-phong-normalized";
  s.quantity = "blinn-phong-normalization";
  s.channels = {"exact", "approx"};
  s.meanings = {"(s + 2) / (4 pi (2 - 2^(-s/2)))", "(s + 2.04) / (8 pi)"};
  s.axes = {sAxis};
  return s;
}

TableSpec BrdfSpec(const std::string& model, double roughness, AxisSpec mu_l, AxisSpec mu_o,
                   AxisSpec phi) {
  TableSpec s;
  s.name = model + "-brdf";
  s.model = model;
  s.quantity = "brdf";
  if (HasRho2(model)) {
    s.channels = {"f_rho", "f_rho2"};
    s.meanings = {"BRDF (no cosine), rho^1 part", "rho^2 part: f = rho f_rho + rho^2 f_rho2"};
  } else {
    s.channels = {"f"};
    s.meanings = {"BRDF value at rho = 1, cosine excluded"};
  }
  s.axes = {mu_l, mu_o, phi};
  s.params["roughness"] = roughness;
  return s;
}

std::vector<TableSpec> DefaultCatalogue(const CatalogueOptions& opt) {
  std::vector<TableSpec> out;
  for (const char* m : kMicrofacetModels) {
    out.push_back(DfgSpec(m, DefaultMuAxis("dfg"), DefaultRoughnessAxis(m)));
    out.push_back(AlbedoSpec(m, DefaultMuAxis("albedo"), DefaultRoughnessAxis(m)));
    AxisSpec rAvg = DefaultRoughnessAxis(m);
    rAvg.size = 64;
    out.push_back(AlbedoAvgSpec(m, rAvg));
  }
  AxisSpec r3 = DefaultRoughnessAxis("ggx"), rAvg = r3, etaAvg = DefaultEtaAxis();
  r3.size = 48;
  rAvg.size = 24;
  etaAvg.size = 16;
  out.push_back(FresnelAlbedoSpec(DefaultMuAxis("fresnel-albedo"), r3, DefaultEtaAxis()));
  out.push_back(FresnelAlbedoAvgSpec(rAvg, etaAvg));
  for (const char* m : kDiffuseModels) {
    out.push_back(AlbedoSpec(m, DiffuseMuAxis(m), DefaultRoughnessAxis(m)));
    out.push_back(AlbedoAvgSpec(m, DefaultRoughnessAxis(m)));
  }
  out.push_back(FresnelDielectricSpec(DefaultMuAxis("fresnel-dielectric"), {"eta", 1, 3, 128, Warp::Sqrt}));
  out.push_back(FresnelDielectricAvgSpec({"eta", 1, 3, 128, Warp::Sqrt}));
  out.push_back(FresnelConductorSpec(DefaultMuAxis("fresnel-conductor"), {"n", 0.1, 4, 32, Warp::Linear},
                                     {"k", 0, 8, 32, Warp::Linear}));
  out.push_back(BlinnPhongNormalizationSpec({"s", 1, 10000, 1024, Warp::Log}));
  for (const char* m : {"oren-nayar", "gotanda-ggx"}) {
    // mu from 0.02: Oren-Nayar's tan(beta) is unbounded as both directions reach the horizon.
    AxisSpec mu{"mu_l", 0.02, 1, 32, Warp::Sqrt}, muo{"mu_o", 0.02, 1, 32, Warp::Sqrt};
    out.push_back(BrdfSpec(m, opt.brdfRoughness, mu, muo, {"phi", 0, Pi, 32, Warp::Linear}));
  }
  for (TableSpec& s : out) Resize(s, opt.size);
  return out;
}

TableSpec CatalogueTable(const std::string& name, const CatalogueOptions& opt) {
  for (TableSpec& s : DefaultCatalogue(opt))
    if (s.name == name) return s;
  throw std::invalid_argument("unknown table '" + name + "' (see the README's catalogue)");
}

}  // namespace kiln
