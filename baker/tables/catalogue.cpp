#include "baker/tables/catalogue.h"

#include <algorithm>
#include <stdexcept>

#include "baker/custom/custom_tables.h"
#include "baker/models/model_names.h"
#include "baker/models/registry.h"
#include "baker/models/sheen.h"
#include "baker/util/did_you_mean.h"

namespace kiln {
namespace {

const ModelInfo& Info(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (!m) throw std::invalid_argument(UnknownModelMessage(model));
  return *m;
}

void Resize(TableSpec& spec, int size) {
  if (size <= 0) return;
  for (AxisSpec& a : spec.axes) {
    if (a.size > 2 || a.name != "roughness") a.size = size;  // a roughness-less model keeps 2
    // root4-layer-split needs N - 1 a multiple of 8 (its piece ends are nodes): round up
    if (a.warp == Warp::Root4LayerSplit) a.size = std::max(9, (size + 6) / 8 * 8 + 1);
    // root4-layer-split2 needs N - 1 a multiple of 32 (its piece ends and middles are nodes)
    if (a.warp == Warp::Root4LayerSplit2) a.size = std::max(33, (size + 30) / 32 * 32 + 1);
  }
}

}  // namespace

const std::vector<std::string>& CatalogueMicrofacetModels() {
  static const std::vector<std::string> models = {"ggx", "ggx-separable", "beckmann",
                                                  "beckmann-separable", "blinn-phong"};
  return models;
}

const std::vector<std::string>& CatalogueDiffuseModels() {
  static const std::vector<std::string> models = {"lambert",
                                                  "burley",
                                                  "frostbite",
                                                  "oren-nayar",
                                                  "oren-nayar-qualitative",
                                                  "oren-nayar-qualitative-ir",
                                                  "fujii",
                                                  "fujii-normalized",
                                                  "gotanda-fresnel",
                                                  "gotanda-ggx",
                                                  "hammon",
                                                  "shirley",
                                                  "ashikhmin-shirley-diffuse",
                                                  "triace-lambert"};
  return models;
}

const std::vector<std::string>& CatalogueSheenModels() {
  static const std::vector<std::string> models = {"charlie", "charlie-smith", "ashikhmin-velvet"};
  return models;
}

bool SheenTableInDefaultCatalogue(const std::string& name) {
  static const char* const kDefault[] = {"charlie-dfg",
                                         "charlie-albedo",
                                         "ashikhmin-velvet-dfg",
                                         "ashikhmin-velvet-albedo",
                                         "ashikhmin-velvet-albedo-avg",
                                         "charlie-albedo-avg",
                                         "charlie-smith-dfg",
                                         "charlie-smith-albedo",
                                         "charlie-smith-albedo-avg"};
  for (const char* n : kDefault)
    if (name == n) return true;
  return false;
}

namespace {
bool IsCatalogueSheen(const std::string& model) {
  for (const std::string& m : CatalogueSheenModels())
    if (m == model) return true;
  return false;
}
}  // namespace

// Sizes and warps (docs/catalogue.md gives the measured lookup errors; each quantity's
// descriptor in baker/quantities/ states its own axes):
// - mu: near grazing a microfacet albedo is a function of mu / alpha (a layer of width
//   alpha = r^2 at mu = 0) and a dielectric Fresnel term of mu / sqrt(eta - 1). The microfacet
//   dfg and albedo tables take the root4-layer warp (lut.h): half of the nodes follow the layer
//   at every roughness, so the corner (mu, r) -> (0, 0) interpolates like the rest (a fixed warp
//   cannot: the layer's width goes to 0 with r). The Fresnel tables take root4, nodes at
//   mu = (i/(N-1))^4, which resolves the layer down to small eta - 1. sqrt for the diffuse
//   albedos (polynomials in 1 - mu) and the BRDF tables.
// - roughness: sqrt for the microfacet tables (the layer above moves with r^2), linear for the
//   diffuse ones; eta: sqrt (dense near 1, same reason); n, k: linear; Blinn-Phong's s: log.

/// The mu axis of a diffuse albedo table. Most diffuse models are polynomials in mu and 1 - mu
/// (Burley, Frostbite, Shirley, ...) and bend most near grazing: sqrt. The Oren-Nayar qualitative
/// family, normalised Fujii and Gotanda's GGX diffuse are smooth in the angles instead, so their
/// albedo has a square-root point at mu = 1 (sin(theta_o) terms): angle, nodes uniform in theta_o
/// (measured: oren-nayar-qualitative 8.3e-3 with sqrt, 3.5e-4 with angle; the polynomial models
/// err 2-10x more with angle than with sqrt).
AxisSpec DiffuseMuAxis(const std::string& model) {
  // Sheen: E(mu) has a layer of width ~ r at mu = 0 (the lobe at grazing) and, inside it, the
  // mu ln mu of the Neubelt pole (charlie, velvet): root4. The Charlie pair's layer is steepest
  // (E(0) = 8.9 at r = 0.045): 192 nodes keep the lookup error below 1e-3 (measured in trial
  // bakes with 128 log-warped roughness nodes: 1.7e-3 with 128, 9.9e-4 with 192); the velvet
  // 48 (7.7e-4 with 48 x 48). charlie-smith starts at mu = 1e-4, Filament's MIN_N_DOT_V: below
  // it the fitted Lambda's clamp V <= 1 makes E jump (1.63 at mu = 1e-8, 0.82 at 1e-6, 0.59 at
  // 1e-4 for r = 0.386: `kiln integrate albedo --model charlie-smith --mu M --roughness 0.386`),
  // a layer of the fit no renderer looks up; a lookup below reads the edge. Without the
  // grazing peak of E(0) its grid can be smaller: 112 mu x 96 roughness nodes declare 7.7e-4
  // (trial bakes `kiln bake --only charlie-smith-dfg -j 2`: 5.8e-4 with 128 x 128, 7.5e-4 with
  // 128 x 96, 1.0e-3 with 96 x 128 and with 128 x 80).
  if (IsCatalogueSheen(model)) {
    if (model == "ashikhmin-velvet") return {"mu", 0, 1, 48, Warp::Root4};
    if (model == "charlie-smith") return {"mu", kCharlieSmithMinMu, 1, 112, Warp::Root4};
    return {"mu", 0, 1, 192, Warp::Root4};
  }
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
  // Sheen: the Charlie models' E(0) ~ 0.4 / r, relative error h^2 / (4 r^2) under linear
  // interpolation: a log axis (constant h / r), 128 nodes (2.6e-3 of lookup error with 64). The
  // velvet is smooth in r: 48 linear nodes. Both from kSheenTableMinRoughness (models/sheen.h).
  // charlie-smith: 96 (its E(0) is bounded; see DiffuseMuAxis for the trial bakes).
  if (IsCatalogueSheen(model)) {
    if (model == "ashikhmin-velvet")
      return {"roughness", kSheenTableMinRoughness, 1, 48, Warp::Linear};
    if (model == "charlie-smith") return {"roughness", kSheenTableMinRoughness, 1, 96, Warp::Log};
    return {"roughness", kSheenTableMinRoughness, 1, 128, Warp::Log};
  }
  for (const ParamInfo& p : m.params)
    if (p.name == "roughness")
      return m.specular() ? AxisSpec{"roughness", 0, p.hi, 128, Warp::Sqrt}
                          : AxisSpec{"roughness", 0, p.hi, 64, Warp::Linear};
  return {"roughness", 0, 1, 2, Warp::Linear};  // no roughness: constant along this axis
}

AxisSpec DefaultEtaAxis() { return {"eta", 1, 3, 24, Warp::Sqrt}; }

namespace {

std::vector<TableSpec> CatalogueEntries(const CatalogueOptions& opt, bool onRequestToo) {
  std::vector<TableSpec> out;
  for (const QuantityInfo* q : AllQuantities())
    if (q->catalogue && (q->inDefaultCatalogue || onRequestToo))
      for (TableSpec& s : q->catalogue(opt)) out.push_back(std::move(s));
  if (onRequestToo)
    for (const QuantityInfo* q : AllQuantities())
      if (q->onRequest)
        for (TableSpec& s : q->onRequest(opt)) out.push_back(std::move(s));
  for (TableSpec& s : out) Resize(s, opt.size);
  return out;
}

}  // namespace

std::vector<TableSpec> DefaultCatalogue(const CatalogueOptions& opt) {
  return CatalogueEntries(opt, false);
}

std::vector<TableSpec> OnRequestTables(const CatalogueOptions& opt) {
  std::vector<TableSpec> out;
  for (TableSpec& s : CatalogueEntries(opt, true))
    if (!Describe(s.quantity).inDefaultCatalogue) out.push_back(std::move(s));
  for (const QuantityInfo* q : AllQuantities())
    if (q->onRequest)
      for (TableSpec& s : q->onRequest(opt)) {
        Resize(s, opt.size);
        out.push_back(std::move(s));
      }
  return out;
}

TableSpec CatalogueTable(const std::string& name, const CatalogueOptions& opt) {
  std::vector<std::string> names;
  for (TableSpec& s : CatalogueEntries(opt, true)) {
    if (s.name == name) return s;
    names.push_back(s.name);
  }
  for (TableSpec& s : CustomModelTables()) {  // a user's lobe loaded this run (baker/custom/)
    Resize(s, opt.size);
    if (s.name == name) return s;
    names.push_back(s.name);
  }
  throw std::invalid_argument("unknown table '" + name + "'" + DidYouMean(name, names) +
                              " (see `kiln list --tables`)");
}

}  // namespace kiln
