// Every model kiln knows, by id: what it is, its parameters and their valid ranges, which of the
// physical properties it keeps, and a factory that builds the value type from CLI-style parameters.
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "baker/custom/custom_model.h"
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

namespace kiln {

/// A model parameter as the CLI and the tables name it, with its valid range and default.
struct ParamInfo {
  std::string name;  ///< "roughness", "rho", "f0", "eta", "k", "rs", "nu", "nv"
  double lo, hi, def;
  std::string doc;
};

/// What a model is and which properties it keeps (the tests check every flag both ways).
struct ModelInfo {
  std::string id;
  std::string summary;    ///< one line: the formula family and the source
  std::string roughness;  ///< what the roughness parameter means, e.g. "alpha = r^2"
  std::vector<ParamInfo> params;
  bool reciprocal;        ///< f(o, l) = f(l, o)
  bool energyConserving;  ///< E(mu) <= 1 for every mu at rho = 1, F = 1
  bool nonNegative;       ///< f >= 0 everywhere above the horizon, for every rho in [0, 1]
  bool hasRho2;           ///< has a term quadratic in rho (tables get a separate channel)
  IntegrationDomain domain;
  bool specular() const { return domain == IntegrationDomain::HalfVector; }
  /// A BSDF (reflection and transmission, models/dielectric_bsdf.h): not in AllModels() or
  /// AnyModel (whose models are BRDFs over the upper hemisphere), listed by AllBsdfModels().
  bool bsdf = false;
  /// Non-null: why the model has no hemispherical tables nor `kiln integrate` integrals over the
  /// normal's hemisphere (a fibre model, whose natural axes are angles to its tangent).
  const char* noTables = nullptr;
};

/// Parameters as given on a command line; unset ones take the model's defaults.
struct ModelParams {
  std::optional<double> roughness, rho, f0, eta, k, rs, nu, nv;
};

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

/// Every model, in catalogue order.
const std::vector<ModelInfo>& AllModels();
/// The model with this id, or nullptr.
const ModelInfo* FindModel(const std::string& id);
/// Every BSDF model (ModelInfo::bsdf): the rough dielectric, ggx-dielectric.
const std::vector<ModelInfo>& AllBsdfModels();
/// The BSDF model with this id, or nullptr.
const ModelInfo* FindBsdfModel(const std::string& id);
/// Builds model `id`. Throws std::invalid_argument with one line naming the problem for an
/// unknown id, a parameter the model does not take, or a value outside its range.
AnyModel MakeModel(const std::string& id, const ModelParams& params);
/// f(wo, wi) of any model (no cosine).
double Evaluate(const AnyModel& model, Vec3 wo, Vec3 wi);
/// f split into rho^1 and rho^2 parts at rho = 1.
RhoParts EvaluateParts(const AnyModel& model, Vec3 wo, Vec3 wi);
/// Fresnel term from parameters: f0 -> Schlick, eta (and k > 0) -> exact, none -> F = 1.
Fresnel FresnelFromParams(const ModelParams& p);
/// Sets a specular model's Fresnel term (no-op for diffuse models).
void SetFresnel(AnyModel& model, const Fresnel& fresnel);

}  // namespace kiln
