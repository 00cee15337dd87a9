// The lookup-error search evaluates its reference through PreparedReference
// (baker/tables/prepared_reference.h): the kind, the fixed rule's applicability and a sheen
// table's roughness clamp resolved once per table. At every point it must give what
// SearchReference and EvaluateSpec give, to the bit, with the same statistics.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "baker/tables/catalogue.h"
#include "baker/tables/engine_layout.h"
#include "baker/tables/prepared_reference.h"

using namespace kiln;

namespace {

bool SameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool SameStats(const IntegrationStats& a, const IntegrationStats& b) {
  return a.evals == b.evals &&
         std::memcmp(&a.errorEstimate, &b.errorEstimate, sizeof a.errorEstimate) == 0;
}

/// Points of `spec` in warped coordinates: the lower corner (the smooth limit where a table has
/// one), the upper corner and two inside, off the nodes.
std::vector<std::vector<double>> PointsOf(const TableSpec& spec) {
  std::vector<std::vector<double>> points;
  for (double t : {0.0, 1.0, 0.3183, 0.7071}) {
    double w[3] = {t, t, t}, x[3] = {0, 0, 0};
    if (t == 0.3183) w[1] = 0.5772;  // not on the diagonal
    PointAtWarped(spec, w, x);
    points.emplace_back(x, x + spec.axes.size());
  }
  return points;
}

void CheckSameAsUnprepared(const TableSpec& spec) {
  const PreparedReference prepared(spec);
  for (const std::vector<double>& x : PointsOf(spec)) {
    IntegrationStats a, b, c, d;
    CHECK(SameBits(prepared.Search(x.data(), a), SearchReference(spec, x.data(), b)));
    CHECK(SameStats(a, b));
    CHECK(SameBits(prepared.Bake(x.data(), c), EvaluateSpec(spec, x.data(), d)));
    CHECK(SameStats(c, d));
  }
}

}  // namespace

TEST_CASE("The prepared search reference gives SearchReference's and EvaluateSpec's bits",
          "[lookup][search][prepared-reference]") {
  for (const TableSpec& spec : DefaultCatalogue()) {
    INFO(spec.name);
    CheckSameAsUnprepared(spec);
  }
}

TEST_CASE("The prepared search reference clamps a sheen table's roughness as EvaluateSpec does",
          "[lookup][search][prepared-reference]") {
  for (const TableSpec& catalogued : DefaultCatalogue()) {
    if (catalogued.name != "charlie-dfg" && catalogued.name != "charlie-albedo") continue;
    TableSpec spec = catalogued;
    spec.params[kSheenRoughnessMinParam] = 0.35;  // below it, the clamp moves the point
    INFO(spec.name);
    CheckSameAsUnprepared(spec);
  }
}
