// Every committed table in luts/ passes `kiln verify`: its declared lookup error against adaptive
// quadrature (independent of the fixed rules the tables were baked with) at its corner cells, the
// cells its node values predict worst, seeded random points and the point it declares as its
// worst, and its declared bake error at the corners and the worst-departing nodes. An average
// (an integral over mu of E) takes, at its search's cells and random points, the reference its
// bake-error check takes (adaptive quadrature over mu of E by its 3D table's rule): nested
// adaptive quadrature costs ~0.3 s of one core a point for the glass averages
// (tests/verify_outer_reference.cpp holds the two together and shows a wrong average failing).
// The catalogue is dealt into shards by the cost of its tables, one test each.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "baker/tables/quantity.h"
#include "cli_util.h"
#include "committed_luts.h"
#include "test_util.h"

using kiln::test::LutsDir;

namespace {

/// The shards of the verify check: CTest runs each as a test of its own (in parallel with -j).
/// 12: about 11 cost units (~5 s of one core, VerifyCost) each.
constexpr int kVerifyShards = 12;

/// ggx-fresnel-albedo-avg's outer reference integrates an E that is itself adaptive (its 3D
/// table has no fixed rule at every node): costlier than the nested reference, which it keeps.
constexpr const char* kNestedAverage = "ggx-fresnel-albedo-avg";

/// One committed table: its name, its first file (a table in parts: part 1, whose loading
/// reads the others) and whether its search takes the outer reference (kAverageFlags: a kind
/// with a verification reference of its own, QuantityInfo::verifyReference, an average).
struct CommittedTable {
  std::string name, file;
  bool outer = false;
};

std::vector<CommittedTable> CommittedTables() {
  auto manifest = nlohmann::json::parse(kiln::test::ReadFile(LutsDir() + "/manifest.json"));
  std::vector<CommittedTable> out;
  for (auto& t : manifest["tables"]) {
    const kiln::QuantityInfo* q = kiln::FindQuantity(t["quantity"].get<std::string>());
    const std::string name = t["name"].get<std::string>();
    out.push_back({name, t["file"].get<std::string>(),
                   q != nullptr && q->verifyReference != nullptr && name != kNestedAverage});
  }
  std::sort(out.begin(), out.end(),
            [](const CommittedTable& a, const CommittedTable& b) { return a.name < b.name; });
  return out;
}

/// The cost of verifying table `name` in units of about half a second of one core, measured
/// (`kiln verify` with the shards' options, --json "seconds", on a loaded machine scaled by its
/// CPU time); 1 for the tables not listed (most take well under that).
int VerifyCost(const std::string& name) {
  static const std::map<std::string, int> measured = {
      {"ggx-dielectric-albedo-r-exit-avg", 8},
      {"ggx-dielectric-albedo-t-exit-avg", 7},
      {"ggx-dielectric-albedo-r", 6},
      {"ggx-dielectric-albedo-t-avg", 6},
      {"charlie-smith-albedo-avg", 5},
      {"ggx-fresnel-albedo-avg", 5},
      {"gotanda-ggx-albedo-avg", 4},
      {"oren-nayar-qualitative-ir-albedo-avg", 4},
      {"blinn-phong-albedo", 3},
      {"blinn-phong-dfg", 3},
      {"ggx-dielectric-albedo-r-avg", 3},
      {"ggx-dielectric-albedo-r-exit", 3},
      {"oren-nayar-qualitative-albedo-avg", 3},
      {"beckmann-dfg", 2},
      {"blinn-phong-albedo-avg", 2},
      {"charlie-albedo", 2},
      {"charlie-albedo-avg", 2},
      {"charlie-dfg", 2},
      {"ggx-dfg", 2},
      {"ggx-dielectric-albedo-t", 2},
      {"ggx-fresnel-albedo", 2},
      {"oren-nayar-albedo-avg", 2},
  };
  auto it = measured.find(name);
  return it == measured.end() ? 1 : it->second;
}

/// The tables of shard `shard`: longest processing time first (the costliest table not yet
/// dealt goes to the shard of least cost so far; ties by name and by shard index), so the
/// costly tables spread over the shards and the cheap ones fill up behind them. Every table
/// lands in exactly one shard (checked below).
std::vector<CommittedTable> VerifyShardTables(const std::vector<CommittedTable>& tables,
                                              int shard) {
  std::vector<CommittedTable> order = tables;
  std::stable_sort(order.begin(), order.end(),
                   [](const CommittedTable& a, const CommittedTable& b) {
                     return VerifyCost(a.name) > VerifyCost(b.name);
                   });
  std::vector<int> load(kVerifyShards, 0);
  std::vector<CommittedTable> out;
  for (const CommittedTable& t : order) {
    const int k = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[k] += VerifyCost(t.name);
    if (k == shard) out.push_back(t);
  }
  return out;
}

/// The options of every table's check: the lookup search's reference by adaptive quadrature at
/// 1e-6 (--tol), 8 cells (the corner cells first, then edge and inner cells by the error their
/// node values predict, worst first), 4 seeded random points and the point the table declares
/// as its worst (where the bake's own search found its max); the bake-error check at the corners
/// and the worst-departing nodes only (--bake-nodes 0; the sampled nodes: `kiln verify luts`).
constexpr const char* kVerifyFlags = " --points 4 --cells 8 --tol 1e-6 --bake-nodes 0 -j 2";
/// The averages' search besides: the outer reference at its cells and random points (the
/// declared worst point keeps nested adaptive quadrature) and a budget of 220 reference
/// evaluations, which probes all 8 cells and climbs in every one of a 1D table's (5 + 22 a
/// cell), in 3 of a 2D table's (9 + 44): by the automatic budget of 2e7 integrand evaluations
/// the glass averages' nested reference reached one cell and one climb.
constexpr const char* kAverageFlags = " --outer-reference --budget 220";

/// `kiln verify` on `tables` with `flags`: passes, and says so for every table.
void VerifyTables(const std::vector<CommittedTable>& tables, const std::string& flags) {
  if (tables.empty()) return;
  std::string paths;
  for (const CommittedTable& t : tables) paths += " " + LutsDir() + "/" + t.file;
  auto r = kiln::test::RunKiln("verify" + paths + flags);
  INFO(r.out << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find(std::to_string(tables.size()) + " tables, 0 over their bound") !=
        std::string::npos);
}

/// `kiln verify` on one shard's tables: the averages in one run (kAverageFlags), the others in
/// another.
void VerifyShard(int shard) {
  const std::vector<CommittedTable> tables = VerifyShardTables(CommittedTables(), shard);
  REQUIRE(!tables.empty());
  std::vector<CommittedTable> averages, others;
  for (const CommittedTable& t : tables) (t.outer ? averages : others).push_back(t);
  VerifyTables(averages, std::string(kVerifyFlags) + kAverageFlags);
  VerifyTables(others, kVerifyFlags);
}

}  // namespace

TEST_CASE("The verify shards take every committed table once, the costly ones apart",
          "[luts][verify]") {
  const std::vector<CommittedTable> tables = CommittedTables();
  REQUIRE(tables.size() >= 50);
  std::vector<std::string> dealt;
  int costliest = 0, total = 0, maxTable = 0;
  for (const CommittedTable& t : tables) {
    total += VerifyCost(t.name);
    maxTable = std::max(maxTable, VerifyCost(t.name));
  }
  for (int shard = 0; shard < kVerifyShards; ++shard) {
    int cost = 0, glassAverages = 0;
    for (const CommittedTable& t : VerifyShardTables(tables, shard)) {
      dealt.push_back(t.name);
      cost += VerifyCost(t.name);
      glassAverages += t.name.rfind("ggx-dielectric-albedo", 0) == 0 &&
                       t.name.compare(t.name.size() - 4, 4, "-avg") == 0;
    }
    INFO("shard " << shard + 1 << " cost " << cost);
    CHECK(glassAverages <= 1);  // the four glass averages lie in four shards
    costliest = std::max(costliest, cost);
  }
  std::sort(dealt.begin(), dealt.end());
  std::vector<std::string> names;
  for (const CommittedTable& t : tables) names.push_back(t.name);
  CHECK(dealt == names);  // each table once
  // Balanced: no shard costs more than the larger of the costliest table and the mean by more
  // than a middling table (cost 2); dealt by name, round robin, they would cost 4 to 21.
  const int mean = (total + kVerifyShards - 1) / kVerifyShards;
  CHECK(costliest <= std::max(maxTable, mean) + 2);
}

TEST_CASE("Every committed table passes kiln verify, shard 1 of 12", "[luts][verify]") {
  VerifyShard(0);
}
TEST_CASE("Every committed table passes kiln verify, shard 2 of 12", "[luts][verify]") {
  VerifyShard(1);
}
TEST_CASE("Every committed table passes kiln verify, shard 3 of 12", "[luts][verify]") {
  VerifyShard(2);
}
TEST_CASE("Every committed table passes kiln verify, shard 4 of 12", "[luts][verify]") {
  VerifyShard(3);
}
TEST_CASE("Every committed table passes kiln verify, shard 5 of 12", "[luts][verify]") {
  VerifyShard(4);
}
TEST_CASE("Every committed table passes kiln verify, shard 6 of 12", "[luts][verify]") {
  VerifyShard(5);
}
TEST_CASE("Every committed table passes kiln verify, shard 7 of 12", "[luts][verify]") {
  VerifyShard(6);
}
TEST_CASE("Every committed table passes kiln verify, shard 8 of 12", "[luts][verify]") {
  VerifyShard(7);
}
TEST_CASE("Every committed table passes kiln verify, shard 9 of 12", "[luts][verify]") {
  VerifyShard(8);
}
TEST_CASE("Every committed table passes kiln verify, shard 10 of 12", "[luts][verify]") {
  VerifyShard(9);
}
TEST_CASE("Every committed table passes kiln verify, shard 11 of 12", "[luts][verify]") {
  VerifyShard(10);
}
TEST_CASE("Every committed table passes kiln verify, shard 12 of 12", "[luts][verify]") {
  VerifyShard(11);
}
