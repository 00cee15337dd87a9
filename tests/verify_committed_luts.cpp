// Every committed table in luts/ passes `kiln verify`: its declared lookup error against adaptive
// quadrature (independent of the fixed rules the tables were baked with) on a strided sample of
// its cells, and its declared bake error at the corners and the worst-departing nodes. The
// catalogue is dealt into shards by the cost of its tables, one test each, so that no test
// carries more than a few costly tables.
#include <catch2/catch.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_util.h"
#include "committed_luts.h"
#include "test_util.h"

using kiln::test::LutsDir;

namespace {

/// The shards of the verify check: CTest runs each as a test of its own (in parallel with -j).
/// 14: each glass average alone in its shard (its search is ~20 s of CPU, spread over the
/// shard's two threads: integrate/dielectric_albedo_avg.h, DielectricAlbedoAverage), the other
/// shards cost 10 (~8 s; 16 cost ~15 s).
constexpr int kVerifyShards = 14;

/// One committed table: its name and its first file (a table in parts: part 1, whose loading
/// reads the others).
struct CommittedTable {
  std::string name, file;
};

std::vector<CommittedTable> CommittedTables() {
  auto manifest = nlohmann::json::parse(kiln::test::ReadFile(LutsDir() + "/manifest.json"));
  std::vector<CommittedTable> out;
  for (auto& t : manifest["tables"])
    out.push_back({t["name"].get<std::string>(), t["file"].get<std::string>()});
  std::sort(out.begin(), out.end(),
            [](const CommittedTable& a, const CommittedTable& b) { return a.name < b.name; });
  return out;
}

/// The relative cost of verifying table `name` (1: a table whose references are single
/// integrals, about a second of one core). An average's reference is an integral over mu of E,
/// itself an integral, and its search stops at the automatic integrand budget (2e7): the glass
/// averages' E is the rough dielectric's (~4e5 integrand evaluations a point, ~20 s of one core
/// a table), charlie-smith's is graded towards its mirror lobe (~10 s); the other averages cost
/// one to five seconds.
int VerifyCost(const std::string& name) {
  auto endsWith = [&](const char* s) {
    const std::string t = s;
    return name.size() >= t.size() && name.compare(name.size() - t.size(), t.size(), t) == 0;
  };
  if (name.rfind("ggx-dielectric-albedo", 0) == 0 && endsWith("-avg")) return 16;
  if (name == "charlie-smith-albedo-avg") return 8;
  if (endsWith("-avg")) return 2;
  return 1;
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

// `kiln verify` on one shard's tables: the lookup search's reference is adaptive quadrature at
// 1e-6 (--tol), 8 cells (the corner cells first, then edge and inner cells by the error their
// node values predict, worst first), 4 seeded random points and the point the table declares as
// its worst (where the bake's own search found its max); the bake-error check at the
// corners and the worst-departing nodes only (--bake-nodes 0; the sampled nodes: `kiln verify
// luts`).
void VerifyShard(int shard) {
  const std::vector<CommittedTable> tables = VerifyShardTables(CommittedTables(), shard);
  REQUIRE(!tables.empty());
  std::string paths;
  for (const CommittedTable& t : tables) paths += " " + LutsDir() + "/" + t.file;
  auto r = kiln::test::RunKiln("verify" + paths +
                               " --points 4 --cells 8 --tol 1e-6 --bake-nodes 0 -j 2");
  INFO(r.out << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find(std::to_string(tables.size()) + " tables, 0 over their bound") !=
        std::string::npos);
}

}  // namespace

TEST_CASE("The verify shards take every committed table once, the costly ones apart",
          "[luts][verify]") {
  const std::vector<CommittedTable> tables = CommittedTables();
  REQUIRE(tables.size() >= 50);
  std::vector<std::string> dealt;
  int costliest = 0;
  for (int shard = 0; shard < kVerifyShards; ++shard) {
    int cost = 0, glassAverages = 0;
    for (const CommittedTable& t : VerifyShardTables(tables, shard)) {
      dealt.push_back(t.name);
      cost += VerifyCost(t.name);
      glassAverages += VerifyCost(t.name) == 16;
    }
    INFO("shard " << shard + 1 << " cost " << cost);
    CHECK(glassAverages <= 1);                  // the four glass averages lie in four shards
    CHECK((glassAverages == 0 || cost == 16));  // ... each with no other table
    costliest = std::max(costliest, cost);
  }
  std::sort(dealt.begin(), dealt.end());
  std::vector<std::string> names;
  for (const CommittedTable& t : tables) names.push_back(t.name);
  CHECK(dealt == names);  // each table once
  // Balanced: no shard costs more than the larger of the costliest table and the mean by more
  // than one average (cost 2); dealt by name, round robin, the shards cost 7 to 26.
  // And each glass average alone: its shard's cost is the table's.
  int total = 0;
  for (const CommittedTable& t : tables) total += VerifyCost(t.name);
  const int mean = (total + kVerifyShards - 1) / kVerifyShards;
  CHECK(costliest <= std::max(16, mean) + 2);
}

TEST_CASE("Every committed table passes kiln verify, shard 1 of 14", "[luts][verify]") {
  VerifyShard(0);
}
TEST_CASE("Every committed table passes kiln verify, shard 2 of 14", "[luts][verify]") {
  VerifyShard(1);
}
TEST_CASE("Every committed table passes kiln verify, shard 3 of 14", "[luts][verify]") {
  VerifyShard(2);
}
TEST_CASE("Every committed table passes kiln verify, shard 4 of 14", "[luts][verify]") {
  VerifyShard(3);
}
TEST_CASE("Every committed table passes kiln verify, shard 5 of 14", "[luts][verify]") {
  VerifyShard(4);
}
TEST_CASE("Every committed table passes kiln verify, shard 6 of 14", "[luts][verify]") {
  VerifyShard(5);
}
TEST_CASE("Every committed table passes kiln verify, shard 7 of 14", "[luts][verify]") {
  VerifyShard(6);
}
TEST_CASE("Every committed table passes kiln verify, shard 8 of 14", "[luts][verify]") {
  VerifyShard(7);
}
TEST_CASE("Every committed table passes kiln verify, shard 9 of 14", "[luts][verify]") {
  VerifyShard(8);
}
TEST_CASE("Every committed table passes kiln verify, shard 10 of 14", "[luts][verify]") {
  VerifyShard(9);
}
TEST_CASE("Every committed table passes kiln verify, shard 11 of 14", "[luts][verify]") {
  VerifyShard(10);
}
TEST_CASE("Every committed table passes kiln verify, shard 12 of 14", "[luts][verify]") {
  VerifyShard(11);
}
TEST_CASE("Every committed table passes kiln verify, shard 13 of 14", "[luts][verify]") {
  VerifyShard(12);
}
TEST_CASE("Every committed table passes kiln verify, shard 14 of 14", "[luts][verify]") {
  VerifyShard(13);
}
