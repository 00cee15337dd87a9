// Where `kiln bench` writes when no --out is given: the full run's committed results in bench/ are
// never overwritten by a smoke run or a catalogue report.
#include <catch2/catch.hpp>

#include <filesystem>

#include "baker/cli/bench_commands.h"
#include "cli_util.h"

using namespace kiln;
namespace fs = std::filesystem;

TEST_CASE(
    "kiln bench: the smoke run and the catalogue report each default to a folder of their own",
    "[bench][cli]") {
  CHECK(cli::DefaultBenchFolder(false, false) == "bench");
  CHECK(cli::DefaultBenchFolder(true, false) == "bench/quick");
  CHECK(cli::DefaultBenchFolder(false, true) == "bench/catalogue");
}

TEST_CASE("kiln bench --catalogue without --out leaves bench/bench.csv alone", "[bench][cli]") {
  std::string dir = test::TempDir("bench_folders");
  fs::create_directories(dir + "/bench");
  { std::ofstream(dir + "/bench/bench.csv") << "committed results\n"; }
  fs::path cwd = fs::current_path();
  fs::current_path(dir);
  test::CommandResult r = test::RunKiln("bench --catalogue --only lambert-albedo --samples 1 -j 1");
  fs::current_path(cwd);
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(fs::exists(dir + "/bench/catalogue/catalogue.csv"));
  CHECK(!fs::exists(dir + "/bench/catalogue.csv"));
  CHECK(test::ReadFile(dir + "/bench/bench.csv") == "committed results\n");

  test::CommandResult empty = test::RunKiln("bench --quick --out ''");
  CHECK(empty.exitCode != 0);
  CHECK(empty.err.find("--out '' names no folder") != std::string::npos);
  fs::remove_all(dir);
}
