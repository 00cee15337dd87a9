// On-request albedo tables of the Unity / Ward / Lafortune models (unity_tables.h).
#include "baker/quantities/unity_tables.h"

#include <algorithm>

#include "baker/integrate/fixed_rule_lobe.h"
#include "baker/integrate/quantities.h"
#include "baker/models/lafortune.h"
#include "baker/models/registry.h"
#include "baker/models/unity.h"
#include "baker/quantities/common.h"
#include "baker/tables/quantity.h"
#include "baker/tables/catalogue.h"

namespace kiln {

const std::vector<std::string>& OnRequestAlbedoModels() {
  static const std::vector<std::string> models = [] {
    std::vector<const ModelInfo*> on;
    for (const ModelInfo& m : AllModels())
      if (m.onRequestAlbedo > 0) on.push_back(&m);
    std::stable_sort(on.begin(), on.end(), [](const ModelInfo* a, const ModelInfo* b) {
      return a->onRequestAlbedo < b->onRequestAlbedo;
    });
    std::vector<std::string> ids;
    for (const ModelInfo* m : on) ids.push_back(m->id);
    return ids;
  }();
  return models;
}

namespace {

/// An axis `name` from a model's stated default (ModelInfo::onRequestMu, onRequestRoughness).
AxisSpec FromDefault(const char* name, const AxisDefault& d, int size) {
  AxisSpec a{name, d.lo, d.hi, size, d.warp};
  a.split = d.split;
  return a;
}

/// The roughness axis of `model`'s on-request tables at `size` nodes (lobe_models.cpp says
/// where each starts and why).
AxisSpec RoughnessAxis(const std::string& model, int size) {
  return FromDefault("roughness", FindModel(model)->onRequestRoughness, size);
}

/// The mu axis of `model`'s on-request albedo table: root4-layer over 128 nodes unless the
/// model states its own (ward's 192, unity-brdf2's root4-layer-split at its kink).
AxisSpec MuAxis(const std::string& model) {
  const AxisDefault& mu = FindModel(model)->onRequestMu;
  return FromDefault("mu", mu, mu.size);
}

}  // namespace

std::vector<TableSpec> OnRequestAlbedoTables(const CatalogueOptions&) {
  const QuantityInfo& q = Describe(Quantity::Albedo);
  std::vector<TableSpec> out;
  for (const std::string& m : OnRequestAlbedoModels())
    out.push_back(q.makeSpec(m, {MuAxis(m), RoughnessAxis(m, 256)}));
  return out;
}

std::vector<TableSpec> OnRequestAlbedoAvgTables(const CatalogueOptions&) {
  const QuantityInfo& q = Describe(Quantity::AlbedoAvg);
  std::vector<TableSpec> out;
  for (const std::string& m : OnRequestAlbedoModels()) {
    out.push_back(q.makeSpec(m, {RoughnessAxis(m, FindModel(m)->onRequestAvgRoughnessSize)}));
  }
  return out;
}

bool MirrorLobeRuleApplies(const TableSpec& spec) {
  const ModelInfo* m = FindModel(spec.model);
  return m && m->rule == RuleFamily::MirrorLobe && spec.axes.size() == 2 &&
         spec.axes[0].name == "mu" && spec.axes[1].name == "roughness";
}

namespace {
/// A MirrorLobe model in Unity's unity_NHxRoughness form (with its twin lobe).
bool IsUnityNHxRoughness(const TableSpec& spec) {
  const ModelInfo* m = FindModel(spec.model);
  return m && m->mirrorLobe == MirrorLobeForm::UnityNHxRoughness;
}
}  // namespace

std::vector<double> MirrorLobeRuleAt(const TableSpec& spec, const double* x,
                                     IntegrationStats& stats) {
  const double r = std::min(1.0, std::max(0.0, x[1]));
  stats.errorEstimate = kMirrorLobeRuleBound;
  if (IsUnityNHxRoughness(spec))
    return {FixedRuleUnityBRDF3Albedo(x[0], UnitySpecPower(r) / 4, &stats.evals)};
  return {FixedRuleMirrorLobeAlbedo(x[0], LafortuneBRDF::ExponentFromPerceptual(r), &stats.evals)};
}

bool MirrorLobeLimitAt(const TableSpec& spec, const double* x, std::vector<double>& out) {
  const ModelInfo* m = FindModel(spec.model);
  if (!m || m->rule != RuleFamily::MirrorLobe || m->mirrorLobe != MirrorLobeForm::Phong)
    return false;
  const bool albedo = MirrorLobeRuleApplies(spec);
  const bool average = spec.axes.size() == 1 && spec.axes[0].name == "roughness";
  if (!albedo && !average) return false;
  const double r = std::min(1.0, std::max(0.0, x[albedo ? 1 : 0]));
  if (LafortuneBRDF::ExponentFromPerceptual(r) != 0) return false;
  const double mu = std::min(1.0, std::max(0.0, x[0]));
  out = quantity_detail::RhoChannels(spec, RhoParts{albedo ? (1 + mu) / 2 : 5.0 / 6.0, 0.0});
  return true;
}

std::string MirrorLobeRuleMethod(const TableSpec& spec) {
  if (IsUnityNHxRoughness(spec))
    return "fixed rule: one integral over the lobe angle about the mirror direction, the lobe "
           "and its twin about -m summed, the azimuth in closed form, a panel boundary at the "
           "texture's saturation (integrate/fixed_rule_lobe.cpp), declared to 6e-7";
  return "fixed rule: one integral over the lobe angle about the mirror direction, the azimuth "
         "in closed form (integrate/fixed_rule_lobe.cpp), declared to 6e-7; roughness 1 (n = 0) "
         "holds the limit n -> 0+, the half-space m.l > 0";
}

}  // namespace kiln
