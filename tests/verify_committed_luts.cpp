// Every committed table in luts/ passes `kiln verify`: its declared lookup error against adaptive
// quadrature (independent of the fixed rules the tables were baked with) at its corner cells and
// the cells its node values predict worst (each probed, a climb to the local maximum in the half
// whose probes erred most: SearchBudget), seeded random points and the point it declares as its
// worst, and its declared bake error at the corners and the worst-departing nodes. An average
// (an integral over mu of E) takes, at its search's cells and random points, the reference its
// bake-error check takes (adaptive quadrature over mu of E by its 3D table's rule): nested
// adaptive quadrature costs ~0.3 s of one core a point for the glass averages
// (tests/verify_outer_reference.cpp holds the two together and shows a wrong average failing).
// The catalogue is dealt into shards by the cost of its tables, one test each.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "baker/io/exr_writer.h"
#include "baker/io/texture_readers.h"
#include "baker/tables/quantity.h"
#include "cli_util.h"
#include "committed_luts.h"
#include "test_util.h"

using kiln::test::LutsDir;

namespace {

/// The shards of the verify check: CTest runs each as a test of its own (in parallel with -j).
/// 12: about 9 cost units (~3.6 s of one core, VerifyCost) each, the costliest table alone.
constexpr int kVerifyShards = 12;

/// ggx-fresnel-albedo-avg's outer reference integrates an E that is itself adaptive (its 3D
/// table has no fixed rule at every node): costlier than the nested reference, which it keeps.
constexpr const char* kNestedAverage = "ggx-fresnel-albedo-avg";

/// One committed table: its name, its first file (a table in parts: part 1, whose loading
/// reads the others), its axes and whether its search takes the outer reference
/// (kAverageFlags: a kind with a verification reference of its own,
/// QuantityInfo::verifyReference, an average).
struct CommittedTable {
  std::string name, file;
  bool outer = false;
  int dims = 0;
};

std::vector<CommittedTable> CommittedTables() {
  auto manifest = nlohmann::json::parse(kiln::test::ReadFile(LutsDir() + "/manifest.json"));
  std::vector<CommittedTable> out;
  for (auto& t : manifest["tables"]) {
    const kiln::QuantityInfo* q = kiln::FindQuantity(t["quantity"].get<std::string>());
    const std::string name = t["name"].get<std::string>();
    out.push_back({name, t["file"].get<std::string>(),
                   q != nullptr && q->verifyReference != nullptr && name != kNestedAverage,
                   static_cast<int>(t["axes"].size())});
  }
  std::sort(out.begin(), out.end(),
            [](const CommittedTable& a, const CommittedTable& b) { return a.name < b.name; });
  return out;
}

/// The cost of verifying table `name` in units of about 0.4 s of one core, measured (`kiln
/// verify` with the shards' options, VerifyFlags, -j 2, user + system time on a loaded machine,
/// the mean of two runs); 1 for the tables not listed (most take well under that).
int VerifyCost(const std::string& name) {
  static const std::map<std::string, int> measured = {
      {"ggx-fresnel-albedo-avg", 9},
      {"ggx-dielectric-albedo-r-avg", 5},
      {"ggx-dielectric-albedo-t-exit-avg", 5},
      {"blinn-phong-albedo", 3},
      {"blinn-phong-dfg", 3},
      {"charlie-albedo", 3},
      {"charlie-dfg", 3},
      {"ggx-dielectric-albedo-r-exit-avg", 3},
      {"ashikhmin-velvet-albedo", 2},
      {"ashikhmin-velvet-dfg", 2},
      {"charlie-smith-albedo-avg", 2},
      {"ggx-albedo", 2},
      {"ggx-dielectric-albedo-r", 2},
      {"ggx-dielectric-albedo-t", 2},
      {"ggx-fresnel-albedo", 2},
      {"ggx-separable-albedo", 2},
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
/// declared worst point keeps nested adaptive quadrature).
constexpr const char* kAverageFlags = " --outer-reference";

/// The search's reference evaluations in one cell of a table of `dims` axes: its probes (the
/// centre, the 2^d points at 0.2 / 0.8, the 2d points at 0.05 / 0.95 on one axis) and one climb
/// (coordinate-wise golden section from the worst probe, 22 points an axis).
constexpr long long kProbes[4] = {0, 5, 9, 15};
constexpr long long kClimb[4] = {0, 22, 44, 66};
/// The search's cells (--cells) and the cells of those it climbs in: the cells whose probes
/// erred most, worst first (the search climbs in that order). Every cell is probed; a climb
/// starts from its cell's worst probe, so the cells whose probes erred least, where no climb
/// rose above the bound on any committed table at 8 climbs (the same max, measured), are the
/// ones left unclimbed.
constexpr long long kSearchCells = 8;
constexpr long long kClimbedCells = 4;
/// A glass average's search budget: all 8 cells probed, climbs in 3 (9 + 44 points each): by
/// the automatic budget (kLookupBudgetIntegrand integrand evaluations) its nested reference
/// reaches one cell and one climb, and its outer reference (a mu integral of the glass E rule a
/// point) is the costliest of the catalogue.
constexpr long long kGlassAverageBudget = 220;

/// The tables whose automatic budget (kLookupBudgetIntegrand integrand evaluations: a costly
/// reference) stopped the search before kClimbedCells climbs when it was 2e7: they keep it (an
/// explicit budget would add points). At a smaller automatic budget a table left off this list
/// gets the explicit one, so more points, never fewer climbs.
bool ReferenceLimited(const std::string& name) {
  static const char* const limited[] = {"ggx-albedo",
                                        "ggx-separable-albedo",
                                        "ggx-dielectric-albedo-r",
                                        "ggx-dielectric-albedo-t",
                                        "ggx-dielectric-albedo-r-exit",
                                        "ggx-dielectric-albedo-t-exit",
                                        "ggx-fresnel-albedo-avg",
                                        "blinn-phong-albedo",
                                        "blinn-phong-dfg"};
  for (const char* n : limited)
    if (name == n) return true;
  return false;
}

/// The search budget of table `t` (--budget; 0: the automatic one): every cell probed, climbs
/// in the kClimbedCells cells whose probes erred most (a glass average: kGlassAverageBudget).
/// The random points and the declared worst point come on top.
long long SearchBudget(const CommittedTable& t) {
  if (ReferenceLimited(t.name) || t.dims < 1 || t.dims > 3) return 0;
  if (t.outer && t.name.rfind("ggx-dielectric-albedo", 0) == 0) return kGlassAverageBudget;
  return kSearchCells * kProbes[t.dims] + kClimbedCells * kClimb[t.dims];
}

/// The options of table `t`'s check (kVerifyFlags, kAverageFlags, SearchBudget).
std::string VerifyFlags(const CommittedTable& t) {
  std::string flags = kVerifyFlags;
  if (t.outer) flags += kAverageFlags;
  if (const long long budget = SearchBudget(t)) flags += " --budget " + std::to_string(budget);
  return flags;
}

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

/// `kiln verify` on one shard's tables: one run for the tables of the same options
/// (VerifyFlags).
void VerifyShard(int shard) {
  const std::vector<CommittedTable> tables = VerifyShardTables(CommittedTables(), shard);
  REQUIRE(!tables.empty());
  std::map<std::string, std::vector<CommittedTable>> byFlags;
  for (const CommittedTable& t : tables) byFlags[VerifyFlags(t)].push_back(t);
  for (const auto& [flags, group] : byFlags) VerifyTables(group, flags);
}

}  // namespace

TEST_CASE("The verify shards take every committed table once, the costly ones apart",
          "[luts][verify]") {
  const std::vector<CommittedTable> tables = CommittedTables();
  REQUIRE(tables.size() >= 50);
  std::vector<std::string> dealt;
  int costliest = 0, total = 0, maxTable = 0;
  std::string costliestTable;
  for (const CommittedTable& t : tables) {
    total += VerifyCost(t.name);
    if (VerifyCost(t.name) > maxTable) costliestTable = t.name;
    maxTable = std::max(maxTable, VerifyCost(t.name));
  }
  for (int shard = 0; shard < kVerifyShards; ++shard) {
    int cost = 0, glassAverages = 0;
    const std::vector<CommittedTable> shardTables = VerifyShardTables(tables, shard);
    for (const CommittedTable& t : shardTables) {
      if (t.name == costliestTable) CHECK(shardTables.size() == 1);  // it sits alone
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
  // than a middling table (cost 2); dealt by name, round robin, they would cost 7 to 15.
  const int mean = (total + kVerifyShards - 1) / kVerifyShards;
  CHECK(costliest <= std::max(maxTable, mean) + 2);
}

TEST_CASE("A committed table with one texel raised past its declared bound fails the shards' check",
          "[luts][verify]") {
  // fresnel-dielectric (2D) and fresnel-conductor (3D), copied with one texel raised: by 1.3x
  // the declared bound at the inner node of a corner cell (a cell every search takes), by 10x at
  // the middle node (a 2D table's search ranks its cells worst by their node values; a 3D
  // table's 8 cells are its corners, and the bake-error check's worst-departing nodes take it).
  // Each fails the shards' options (VerifyFlags: every cell probed, the climbs in half of them);
  // the unchanged copies pass them.
  const std::string dir = kiln::test::TempDir("verify_committed_raised");
  for (const char* name : {"fresnel-dielectric", "fresnel-conductor"}) {
    const std::vector<CommittedTable> all = CommittedTables();
    auto it = std::find_if(all.begin(), all.end(),
                           [&](const CommittedTable& t) { return t.name == name; });
    REQUIRE(it != all.end());
    const CommittedTable& entry = *it;
    const kiln::Table clean = kiln::LoadAnyTable(LutsDir() + "/" + entry.file);
    REQUIRE(clean.lookupError.max > 0);
    const std::string file = dir + "/" + entry.file;
    kiln::writeTable(file, clean, false);
    auto r = kiln::test::RunKiln("verify " + file + VerifyFlags(entry));
    INFO(name << " unchanged\n" << r.out << r.err);
    CHECK(r.exitCode == 0);
    size_t stride = 1, inner = 0, middle = 0;  // node (1, 1, ...) and (n/2, n/2, ...)
    for (const kiln::TableAxis& a : clean.axes) {
      inner += stride;
      middle += stride * static_cast<size_t>(a.axis.size / 2);
      stride *= static_cast<size_t>(a.axis.size);
    }
    for (const auto& [node, factor] : {std::pair<size_t, double>{inner, 1.3}, {middle, 10.0}}) {
      kiln::Table bad = clean;
      bad.data[node * bad.channels.size()] += static_cast<float>(factor * clean.lookupError.max);
      kiln::writeTable(file, bad, false);
      r = kiln::test::RunKiln("verify " + file + VerifyFlags(entry));
      INFO(name << " texel " << node << " raised by " << factor << " x its bound\n"
                << r.out << r.err);
      CHECK(r.exitCode == 1);
      if (node == inner) CHECK(r.out.find("EXCEEDS BOUND") != std::string::npos);
    }
  }
  std::filesystem::remove_all(dir);
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
