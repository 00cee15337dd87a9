// Table kinds ("quantities": dfg, albedo, fresnel-dielectric, ...) as a closed, compile-time set.
// Everything kiln knows about a kind is in its descriptor, one file per kind under
// baker/quantities/: its name, channels, the models it accepts, its default axes and catalogue
// entries, how one texel is evaluated (the fixed rule where there is one, the adaptive reference
// always), its method text, how scenes ask for it and what `kiln integrate` prints for it. The
// spec, catalogue, planner, scene readers, CLI and bench ask Describe() instead of comparing
// names; a name read from a file or a command line is looked up once, with FindQuantity.
// Adding a kind: docs/adding-a-table-kind.md.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kiln {

struct AxisSpec;
struct TableSpec;
struct CatalogueOptions;
struct ModelInfo;
struct ModelParams;
struct IntegrationStats;
struct MonteCarloEstimator;
struct Table;

/// Every table kind, in registry order (baker/tables/quantity_list.inc).
enum class Quantity {
#define KILN_QUANTITY(id) id,
#include "baker/tables/quantity_list.inc"
#undef KILN_QUANTITY
};

/// What `kiln integrate NAME ...` asks of a quantity. The CLI has already checked --tol and
/// whether --mu is given as the quantity needs.
struct IntegrateRequest {
  std::string name;   ///< the command's name of the quantity (QuantityInfo::integrateName)
  std::string model;  ///< --model; "" when not given
  double mu = 1;      ///< --mu, cos(theta_o) in [0, 1] (only when integrateNeedsMu)
  double tol = 1e-9;  ///< absolute tolerance
};

/// One table kind. Function pointers left null mean "not offered" (see each field).
struct QuantityInfo {
  Quantity id{};
  const char* name = "";         ///< kiln.quantity, the manifest's "quantity", a scene's "tables"
  const char* description = "";  ///< one line, what a table of this kind is for (`kiln plan`)

  // --- The table -------------------------------------------------------------------------
  /// The spec of this kind for `model` over `axes` (the kind's axis order): file name, model,
  /// quantity, channels and their meanings (which may depend on the model), axes.
  TableSpec (*makeSpec)(const std::string& model, std::vector<AxisSpec> axes) = nullptr;
  /// The default axes (sizes and warps) for `model`: a table the catalogue does not list.
  std::vector<AxisSpec> (*defaultAxes)(const std::string& model) = nullptr;
  /// This kind's entries of the default catalogue, before CatalogueOptions::size is applied.
  std::vector<TableSpec> (*catalogue)(const CatalogueOptions& opt) = nullptr;
  /// False: the kind's catalogue entries are baked only on request (`kiln bake --only NAME`, a
  /// scene that needs them), not by a plain `kiln bake` nor kept in `luts/`: kinds whose bake
  /// is still slow or whose declared lookup error is still above the catalogue's 1e-3.
  bool inDefaultCatalogue = true;
  /// Entries of this kind baked only on request even though the kind is in the default
  /// catalogue (null: none): e.g. the albedo tables of the Unity models (issue #16), whose
  /// `kiln bake --only NAME` works while a plain `kiln bake` leaves them out.
  std::vector<TableSpec> (*onRequest)(const CatalogueOptions& opt) = nullptr;

  // --- One texel ---------------------------------------------------------------------------
  /// True when the bake takes `spec`'s texels with a fixed rule (null: never).
  bool (*usesFixedRule)(const TableSpec& spec) = nullptr;
  /// The channel values at x (one coordinate per axis) by the fixed rule; sets
  /// stats.errorEstimate to the rule's declared bound. Called only when usesFixedRule.
  std::vector<double> (*fixedRule)(const TableSpec& spec, const double* x,
                                   IntegrationStats& stats) = nullptr;
  /// The channel values at x by adaptive quadrature to the absolute tolerance `tol` (exact
  /// evaluation for a closed form): the reference every bake and lookup error is measured with.
  /// Throws std::invalid_argument for a model the kind cannot take.
  std::vector<double> (*evaluate)(const TableSpec& spec, const double* x, double tol,
                                  IntegrationStats& stats) = nullptr;
  /// The smooth limit: when x has roughness exactly 0 and the model is a microfacet lobe
  /// (alpha = 0, a mirror or smooth interface), writes the exact channel values there to `out`
  /// and returns true; otherwise returns false (null: never). EvaluateSpec asks it first, so
  /// neither the fixed rules nor the adaptive integrator see roughness 0. The albedo kinds also
  /// answer lafortune's roughness 1 here, where the tables hold the limit r -> 1- in closed form
  /// (MirrorLobeLimitAt).
  bool (*smoothLimit)(const TableSpec& spec, const double* x, std::vector<double>& out) = nullptr;
  /// The method text (kiln.method) of the fixed rule, when it applies.
  std::string (*fixedRuleMethod)(const TableSpec& spec) = nullptr;
  /// The method text (kiln.method) when the fixed rule does not apply.
  std::string (*method)(const TableSpec& spec) = nullptr;

  // --- Scenes ------------------------------------------------------------------------------
  bool sceneKind = false;            ///< a scene may ask for it; the planner narrows its axes
  const char* sceneModel = nullptr;  ///< model of a scene's table: null = the material's model
  /// Axes a material bounds: {table axis, material parameter}; a pair whose parameter the
  /// material's model does not take is left out (the axis spans its whole range).
  std::vector<std::pair<std::string, std::string>> sceneAxes;
  /// Why a material of model `material` cannot ask for this kind, one line ("" when it can;
  /// null: every model can).
  std::string (*sceneProblem)(const ModelInfo& material) = nullptr;
  /// When set, the default axes are the kind's whole domain: the planner refuses a material
  /// whose sceneAxes values leave them, and this says what the domain is (e.g. "metals in the
  /// visible"). Null: the planner may extend an axis to a material's value.
  const char* sceneDomain = nullptr;
  /// The planner drops an axis cut to one value into the spec's params (evaluate reads it
  /// there), instead of keeping a 2-node slice.
  bool readsParams = false;

  // --- kiln integrate ----------------------------------------------------------------------
  const char* integrateName = nullptr;  ///< the command's name for it; null: not offered
  const char* integrateHelp = "";       ///< e.g. "albedo (E at rho = 1, F = 1)"
  bool integrateNeedsMu = false;        ///< takes --mu (required), or refuses it
  /// The integral the command prints, on one line at full precision (%.17g, space-separated).
  /// Throws std::invalid_argument for missing or refused options, naming the command.
  std::string (*integrate)(const IntegrateRequest& request, const ModelParams& params,
                           IntegrationStats& stats) = nullptr;

  // --- kiln bench --------------------------------------------------------------------------
  /// The Monte Carlo estimator the bench compares kiln with (quantities/monte_carlo.h); null: none.
  const MonteCarloEstimator* monteCarlo = nullptr;

  // --- Rule version and the lookup-error search's reference (issue #13) --------------------
  /// The version of this kind's fixed rule, part of the spec hash of the tables it bakes
  /// ("|fixed-rule:" + this): bump it when the rule changes its texels, and only this kind's
  /// tables become stale. "2" for every kind that had the one shared tag "fixed-rule:2".
  const char* fixedRuleVersion = "2";
  /// A verification-grade form of fixedRule for the lookup-error search's points (null: the
  /// search evaluates fixedRule itself). Called only when usesFixedRule. Sets
  /// stats.errorEstimate to how far it may lie from fixedRule's value (0 where it is fixedRule),
  /// which the search adds to the max it finds, and stats.evals to its integrand evaluations
  /// charged at the bake rule's rate (kSearch*Charge: the search's budget buys the same points).
  std::vector<double> (*searchRule)(const TableSpec& spec, const double* x,
                                    IntegrationStats& stats) = nullptr;
  /// Before the lookup-error search evaluates a batch of points (`n` points of 3 coordinates,
  /// axis order), lets the kind integrate them together (a column of etas shared by the points of
  /// one roughness) into a memo its fixed rule reads: the same bits and evaluation counts as one
  /// point at a time, only sooner. Called only when the search evaluates the fixed rule. Null:
  /// none.
  void (*prepareSearch)(const TableSpec& spec, const double* points, size_t n) = nullptr;
  /// The fixed rule spreads one point's integral over the calling oneTBB arena's threads (a
  /// glass average's mu nodes, its kernel's nodes): the lookup-error search's climbs then give
  /// a lone climb the threads instead of evaluating its next point ahead on them.
  bool parallelPoint = false;
  // --- Tables derived from another table's nodes (issue #13) ------------------------------
  /// A kind whose node values follow from another table's at the same nodes (a microfacet
  /// albedo is A + B of its dfg table): fills `source` with that table's spec and returns true
  /// (null or false: the kind computes its own). A bake that has just baked `source` in the same
  /// run derives this table's texels from its node values (derive) instead of integrating again;
  /// derive must give the float32 texels the kind's own rule gives at every node, so the file
  /// does not depend on what else was baked (tests/bake_derived.cpp).
  bool (*derivedFrom)(const TableSpec& spec, TableSpec& source) = nullptr;
  /// This kind's channel values at one node (`out`, spec.channels.size() of them) from the
  /// source table's (`source`, in double, before the float32 store).
  void (*derive)(const TableSpec& spec, const double* source, double* out) = nullptr;

  // --- Fitted tables (ltc) -----------------------------------------------------------------
  /// When set, the bake fills every texel at once (a fit that starts each texel from its
  /// neighbour's solution) instead of EvaluateSpec per texel: writes table.data (and
  /// table.fitError), each texel's integrand evaluations to evals and its declared error
  /// (IntegrationStats::errorEstimate of its integral channels) to errors. The same bits for any
  /// thread count.
  void (*bakeTable)(const TableSpec& spec, int threads, Table& table, std::vector<long long>& evals,
                    std::vector<double>& errors) = nullptr;
  /// The channels before this one are not integrals (fitted coefficients): the bake-error and
  /// lookup-error checks compare only the channels from here on (evaluate returns 0 for the
  /// others).
  int firstIntegralChannel = 0;
  /// An extra check `kiln verify` runs on a table of this kind (null: none): "" when it passes,
  /// else one line naming the problem; `summary` gets one line of what it measured.
  std::string (*verifyTable)(const Table& table, int threads, std::string& summary) = nullptr;
  /// `kiln verify`'s bake-error reference at x to the absolute tolerance `tol`, where adaptive
  /// quadrature of the whole integral (evaluate) costs millions of integrand evaluations a node
  /// (null: evaluate). Never the kind's own fixed rule (baker/verify/bake_error.h).
  std::vector<double> (*verifyReference)(const TableSpec& spec, const double* x, double tol,
                                         IntegrationStats& stats) = nullptr;
  /// The fixed-rule version of one spec of this kind, when its rule changes for some models only
  /// (null: fixedRuleVersion for every spec): those models' tables re-bake, the others keep their
  /// hashes.
  const char* (*fixedRuleVersionOf)(const TableSpec& spec) = nullptr;
  /// A derived kind (derivedFrom) whose table `spec` has at every node the float32 texels of its
  /// source, the same axes and the same lookup-error search reference at every point (a sheen
  /// albedo and its cloth DFG: one integral, one rule): true lets a bake that has just searched
  /// the source copy its lookup-error report instead of repeating the same search (the
  /// deterministic search gives the same report; `kiln verify` repeats it). Null: never.
  bool (*sharesSourceLookupError)(const TableSpec& spec) = nullptr;
  /// A derived kind whose table `spec` has, at every point off the smooth limit, `derive` of its
  /// source's lookup-error search reference as its own (the same bits and stats: a microfacet
  /// albedo sums the A and B of the one rule its DFG evaluates): true lets its search read the
  /// references its source's search evaluated where the two searches' points coincide
  /// (lookup_error.h, SearchMemo). Null: never.
  bool (*searchDerivesFromSource)(const TableSpec& spec) = nullptr;
};

/// The descriptor of `q`.
const QuantityInfo& Describe(Quantity q);

/// Every descriptor, in registry order.
const std::vector<const QuantityInfo*>& AllQuantities();

/// The descriptor named `name` (as files, scenes and manifests write it), or nullptr.
const QuantityInfo* FindQuantity(std::string_view name);

/// The name of `q`, as files write it.
inline const char* QuantityName(Quantity q) { return Describe(q).name; }

/// The file name of a table of kind `q` for `model` with the kind's default axes (e.g.
/// ggx-dfg, fresnel-dielectric).
std::string TableName(Quantity q, const std::string& model);

}  // namespace kiln
