// Every model kiln knows, by id: what it is, its parameters and their valid ranges, which of the
// physical properties it keeps, and a factory that builds the value type from CLI-style parameters.
#pragma once
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "baker/models/custom_lobe.h"
#include "baker/models/coupled_diffuse.h"
#include "baker/models/disney_diffuse.h"
#include "baker/models/fujii.h"
#include "baker/models/gotanda.h"
#include "baker/models/hammon.h"
#include "baker/models/oren_nayar.h"
#include "baker/models/sheen.h"
#include "baker/models/specular.h"
#include "baker/models/kajiya_kay.h"
#include "baker/models/lafortune.h"
#include "baker/models/unity.h"
#include "baker/models/ward.h"
#include "kiln/lut.h"

namespace kiln {

/// A model parameter as the CLI and the tables name it, with its valid range and default.
struct ParamInfo {
  std::string name;  ///< "roughness", "rho", "f0", "eta", "k", "rs", "nu", "nv"
  double lo, hi, def;
  std::string doc;
};

/// Every BRDF kiln builds, as a value.
using AnyModel =
    std::variant<Lambert, BurleyDiffuse, FrostbiteDiffuse, OrenNayar, OrenNayarQualitative,
                 FujiiOrenNayar, GotandaFresnelDiffuse, GotandaGGXDiffuse, HammonDiffuse,
                 ShirleyDiffuse, AshikhminShirleyDiffuse, TriAceLambert,
                 MicrofacetBRDF<GGXDistribution>, MicrofacetBRDF<BeckmannDistribution>,
                 MicrofacetBRDF<BlinnPhongDistribution>, NormalizedBlinnPhong,
                 AshikhminShirleySpecular,
                 // issue #16: Unity's BRDFs, Ward, Lafortune, Kajiya-Kay
                 UnityBRDF1, UnityBRDF2, UnityBRDF3, WardBRDF, LafortuneBRDF, KajiyaKay,
                 // issue #15: sheen lobes
                 CharlieSheen, CharlieSmithSheen, AshikhminVelvet,
                 // a user's lobe (baker/custom/)
                 CustomDiffuseModel, CustomSpecularModel>;

/// Which fixed integration rule bakes a model's albedo-family tables (dfg, albedo, albedo-avg,
/// ltc norm). Stated per model: a model is never baked by a rule it does not name. None: no
/// fixed rule; the tables take adaptive quadrature (integrate/hemisphere.h) and say so in their
/// method text.
enum class RuleFamily {
  None,        ///< adaptive quadrature only
  Diffuse,     ///< light space tensor rule (integrate/fixed_rule_diffuse.h)
  Microfacet,  ///< visible-normal space rule (integrate/fixed_rule_microfacet.h, fixed_rule_dfg.h)
  Sheen,       ///< light space rule graded towards the mirror (integrate/fixed_rule_sheen.h)
  Ward,        ///< half-vector rule of the Ward lobes (integrate/fixed_rule_ward.h)
  MirrorLobe,  ///< one integral about the mirror direction (integrate/fixed_rule_lobe.h)
};

/// The NDF a Microfacet-family model hands the microfacet fixed rule.
enum class MicrofacetNdf { GGX, Beckmann, BlinnPhong, UnityBRDF1, UnityBRDF2 };

/// A Microfacet-family model's dfg kernel: the GGX kernels (integrate/fixed_rule_dfg.h) or the
/// generic microfacet rule with the model's NDF and Smith term.
enum class MicrofacetKernel { Generic, GgxHeightCorrelated, GgxSeparable };

/// A Sheen-family model's node counts: the Neubelt-visibility lobes' or the fitted Smith
/// Lambda's (kCharlieSmithRuleOptions, integrate/fixed_rule_sheen.h).
enum class SheenRule { Neubelt, FittedSmith };

/// A MirrorLobe-family model's lobe: normalised Phong about the mirror direction (Lafortune) or
/// Unity's unity_NHxRoughness texture form with its twin lobe (UnityBRDF3).
enum class MirrorLobeForm { Phong, UnityNHxRoughness };

/// Where a model's per-model tables (dfg, albedo, albedo-avg) are listed: not at all, or in the
/// default catalogue's group of that name (kiln list --tables, luts/).
enum class CatalogueGroup { None, Microfacet, Diffuse, Sheen };

/// An axis default a model states for itself (the axis name comes from its use).
struct AxisDefault {
  double lo = 0, hi = 1;
  int size = 2;
  Warp warp = Warp::Linear;
  double split = std::numeric_limits<double>::quiet_NaN();  ///< AxisSpec::split
};

/// The physical parameters a factory builds a model from: MakeModel checks the given ones
/// against ModelInfo::params and fills the others with their defaults (0 where the model does
/// not take the parameter).
struct ModelArgs {
  double roughness = 0, rho = 0, f0 = 0, rs = 0;
  double eta = 0, k = 0;         ///< as given or defaulted (a user's lobe takes them as numbers)
  double alpha = 0;              ///< max(roughness^2, MinAlpha)
  Fresnel fresnel;               ///< FresnelFromParams: f0 -> Schlick, eta (k) -> exact, else 1
  std::optional<double> nu, nv;  ///< as given
};

/// Builds a model's value type from checked parameters.
using ModelFactory = std::function<AnyModel(const ModelArgs&)>;

/// A model descriptor: the one place that says what a model is, how it is built, which fixed
/// rule bakes its tables and which tables it has. Every field is named; a descriptor is written
/// field by field in its own function (models/*_models.cpp) and listed once in
/// models/model_list.inc. The tests check every property flag both ways.
struct ModelInfo {
  std::string id;
  std::string summary;    ///< one line: the formula family and the source
  std::string roughness;  ///< what the roughness parameter means, e.g. "alpha = r^2"
  std::vector<ParamInfo> params;
  bool reciprocal = false;        ///< f(o, l) = f(l, o)
  bool energyConserving = false;  ///< E(mu) <= 1 for every mu at rho = 1, F = 1
  bool nonNegative = false;       ///< f >= 0 everywhere above the horizon, for every rho in [0, 1]
  bool hasRho2 = false;           ///< has a term quadratic in rho (tables get a separate channel)
  IntegrationDomain domain = IntegrationDomain::Light;
  bool specular() const { return domain == IntegrationDomain::HalfVector; }
  /// A BSDF (reflection and transmission, models/dielectric_bsdf.h): not in AllModels() or
  /// AnyModel (whose models are BRDFs over the upper hemisphere), listed by AllBsdfModels().
  bool bsdf = false;
  /// Non-null: why the model has no hemispherical tables nor `kiln integrate` integrals over the
  /// normal's hemisphere (a fibre model, whose natural axes are angles to its tangent).
  const char* noTables = nullptr;
  /// Builds the model (MakeModel calls it after checking the parameters).
  ModelFactory make;
  /// A run-time model's code hash (a user's lobe, baker/custom/: its source's or library's
  /// FNV-1a 64 in hex); "" for a built-in model. Part of its tables' spec hash and method text,
  /// so that an edited lobe makes its tables stale.
  std::string codeHash;

  // --- How its tables are integrated -------------------------------------------------------
  /// The fixed rule of its dfg / albedo / albedo-avg / ltc-norm tables; None: adaptive only.
  RuleFamily rule = RuleFamily::None;
  MicrofacetNdf microfacetNdf = MicrofacetNdf::GGX;      ///< Microfacet: the rule's NDF
  bool separableSmith = false;                           ///< Microfacet: G2 = G1(o) G1(l)
  MicrofacetKernel kernel = MicrofacetKernel::Generic;   ///< Microfacet: dfg kernel
  SheenRule sheenRule = SheenRule::Neubelt;              ///< Sheen: node counts
  WardNormalization ward = WardNormalization::Ward1992;  ///< Ward: the lobe's normalisation
  MirrorLobeForm mirrorLobe = MirrorLobeForm::Phong;     ///< MirrorLobe: the lobe's form
  /// The fixed rule's version in the spec hash (QuantityInfo::fixedRuleVersion) of its dfg,
  /// albedo and ltc tables.
  const char* fixedRuleVersion = "2";
  /// The albedo-avg rule's version; nullptr: fixedRuleVersion.
  const char* averageRuleVersion = nullptr;
  /// The albedo-avg rule's mu panels: a kink of E(mu) to split at (-1: none), graded on both
  /// sides over alpha for a specular model; a sheen's first layer (its E's layer at mu = 0).
  double averageKink = -1;
  double averageSheenLayer = 1e-2;

  // --- Which tables it has, over which axes ---------------------------------------------------
  CatalogueGroup catalogue = CatalogueGroup::None;
  /// Its <id>-albedo, <id>-albedo-avg and, for a specular model, <id>-dfg tables on their
  /// kinds' default axes resolve by name (`bake --only`, `verify`, `plan`) although no catalogue
  /// lists them (a user's lobe, baker/custom/).
  bool tablesByName = false;
  /// Its albedo is rho exactly (Lambert): a scene needs no table for it.
  bool albedoIsRho = false;
  /// The exact-Fresnel albedo kinds (fresnel-albedo, fresnel-albedo-avg) are baked for it.
  bool fresnelTables = false;
  /// The mu and roughness axes of its catalogue dfg / albedo / albedo-avg tables where they are
  /// not the family's (catalogue.cpp: DiffuseMuAxis, DefaultRoughnessAxis).
  std::optional<AxisDefault> muAxis, roughnessAxis;
  /// > 0: its albedo and albedo-avg tables are on request (unity_tables.h), listed in this
  /// order; the axes of those and the albedo-avg's roughness node count.
  int onRequestAlbedo = 0;
  AxisDefault onRequestMu{0, 1, 128, Warp::Root4Layer};
  AxisDefault onRequestRoughness{0, 1, 256, Warp::Sqrt};
  int onRequestAvgRoughnessSize = 256;
  /// > 0: its ltc table in the published layout is in the default catalogue (ltcCatalogue) or
  /// on request (ltcOnRequest), listed in this order; either gives it an `ltc-M-kiln` table on
  /// request too.
  int ltcCatalogue = 0, ltcOnRequest = 0;
  /// LTC: the lobe takes a Schlick F0 term (its ltc fresnel channel is the split sum's B).
  bool schlickFresnel = true;
  /// LTC: the published layout's first roughness; the largest roughness the fit and norm read.
  double ltcRoughnessLo = 0;
  double ltcRoughnessHi = 1;
  /// LTC: > 0: the smallest mu the norm channel reads (a lobe singular at grazing): the N.V = 0
  /// row holds the norm there, where the model's albedo table starts; ltcNormNote says so in
  /// the file (appended to the channel's meaning) and ltcRuleVersion names the rule.
  double ltcNormMuLo = 0;
  const char* ltcNormNote = nullptr;
  const char* ltcRuleVersion = nullptr;
  /// LTC: the declared fit error is the self-normalised MIS estimate (the catalogue's first
  /// three tables) instead of the overlap form.
  bool ltcSelfNormalisedError = false;
};

/// The descriptor of a model (the same type; the name used where it is resolved from an id).
using ModelDescriptor = ModelInfo;

/// Parameters as given on a command line; unset ones take the model's defaults.
struct ModelParams {
  std::optional<double> roughness, rho, f0, eta, k, rs, nu, nv;
};

/// Every model: the built-in ones (models/model_list.inc) in catalogue order, then those
/// registered at run time in their order. A deque: pointers to its elements stay valid.
const std::deque<ModelInfo>& AllModels();
/// The model with this id, or nullptr: the one place a model id is looked up (a map keyed by
/// id). Callers resolve an id once, where it enters (CLI, scene, file header).
const ModelInfo* FindModel(const std::string& id);
/// True when `id` names a model of the sheen rule family (charlie, charlie-smith,
/// ashikhmin-velvet): light-space integrals, no smooth limit.
bool IsSheen(const std::string& id);
/// Adds a model at run time (a user's model loaded from a shared library, a test's model) so
/// that FindModel, MakeModel, `kiln list` and the table kinds see it like a built-in one. The
/// descriptor needs an id no other model (BRDF or BSDF) has, a factory, and its parameters;
/// a model with rule family None is baked by adaptive quadrature. Throws std::invalid_argument
/// naming the problem (empty or taken id, no factory). Not thread-safe: register before any
/// bake or lookup starts. Returns the stored descriptor (valid until UnregisterModel).
const ModelInfo& RegisterModel(ModelInfo descriptor);
/// Removes a model registered with RegisterModel (built-in ones stay); false when `id` is not
/// one. Invalidates pointers to run-time models registered after it. Not thread-safe.
bool UnregisterModel(const std::string& id);
/// Every BSDF model (ModelInfo::bsdf): the rough dielectric, ggx-dielectric.
const std::vector<ModelInfo>& AllBsdfModels();
/// The BSDF model with this id, or nullptr.
const ModelInfo* FindBsdfModel(const std::string& id);
/// Builds model `id`. Throws std::invalid_argument with one line naming the problem for an
/// unknown id, a parameter the model does not take, or a value outside its range.
AnyModel MakeModel(const std::string& id, const ModelParams& params);
/// Builds the model `info` describes (its factory) after the same checks.
AnyModel MakeModel(const ModelInfo& info, const ModelParams& params);
/// f(wo, wi) of any model (no cosine).
double Evaluate(const AnyModel& model, Vec3 wo, Vec3 wi);
/// f split into rho^1 and rho^2 parts at rho = 1.
RhoParts EvaluateParts(const AnyModel& model, Vec3 wo, Vec3 wi);
/// Fresnel term from parameters: f0 -> Schlick, eta (and k > 0) -> exact, none -> F = 1.
Fresnel FresnelFromParams(const ModelParams& p);
/// Sets a specular model's Fresnel term (no-op for diffuse models).
void SetFresnel(AnyModel& model, const Fresnel& fresnel);

}  // namespace kiln
