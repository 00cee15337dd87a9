#include "baker/tables/catalogue.h"

#include <algorithm>
#include <stdexcept>

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

namespace {

/// The ids of the models in catalogue group `group`, in registry order.
std::vector<std::string> GroupIds(CatalogueGroup group) {
  std::vector<std::string> ids;
  for (const ModelInfo& m : AllModels())
    if (m.catalogue == group) ids.push_back(m.id);
  return ids;
}

/// The axis `name` a model states for itself.
AxisSpec FromDefault(const char* name, const AxisDefault& d) {
  AxisSpec a{name, d.lo, d.hi, d.size, d.warp};
  a.split = d.split;
  return a;
}

}  // namespace

const std::vector<std::string>& CatalogueMicrofacetModels() {
  static const std::vector<std::string> models = GroupIds(CatalogueGroup::Microfacet);
  return models;
}

const std::vector<std::string>& CatalogueDiffuseModels() {
  static const std::vector<std::string> models = GroupIds(CatalogueGroup::Diffuse);
  return models;
}

const std::vector<std::string>& CatalogueSheenModels() {
  static const std::vector<std::string> models = GroupIds(CatalogueGroup::Sheen);
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
///
/// Sheen: E(mu) has a layer of width ~ r at mu = 0 (the lobe at grazing) and, inside it, the
/// mu ln mu of the Neubelt pole (charlie, velvet): root4, each lobe's node count and start in its
/// descriptor (models/sheen_models.cpp, with the trial bakes that chose them). Any model may
/// state its own (ModelInfo::muAxis).
AxisSpec DiffuseMuAxis(const std::string& model) {
  const ModelInfo* m = FindModel(model);
  if (m && m->muAxis) return FromDefault("mu", *m->muAxis);
  return {"mu", 0, 1, 64, Warp::Sqrt};
}

/// sqrt over 128 nodes for a specular model, linear over 64 for the others, unless the model
/// states its own (ModelInfo::roughnessAxis: blinn-phong's 256, the sheens' log and linear axes
/// from kSheenTableMinRoughness, models/sheen.h).
AxisSpec DefaultRoughnessAxis(const std::string& model) {
  const ModelInfo& m = Info(model);
  if (m.roughnessAxis) return FromDefault("roughness", *m.roughnessAxis);
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

/// The tables of the models with ModelInfo::tablesByName (a user's lobe): albedo, albedo-avg
/// and, for a specular model, dfg, on their kinds' default axes, before any size override.
std::vector<TableSpec> TablesByName() {
  std::vector<TableSpec> out;
  for (const ModelInfo& m : AllModels()) {
    if (!m.tablesByName) continue;
    std::vector<Quantity> kinds = {Quantity::Albedo, Quantity::AlbedoAvg};
    if (m.specular()) kinds.push_back(Quantity::Dfg);
    for (Quantity k : kinds) {
      const QuantityInfo& q = Describe(k);
      out.push_back(q.makeSpec(m.id, q.defaultAxes(m.id)));
    }
  }
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
  for (TableSpec& s : TablesByName()) {  // a user's lobe loaded this run (baker/custom/)
    Resize(s, opt.size);
    if (s.name == name) return s;
    names.push_back(s.name);
  }
  throw std::invalid_argument("unknown table '" + name + "'" + DidYouMean(name, names) +
                              " (see `kiln list --tables`)");
}

}  // namespace kiln
