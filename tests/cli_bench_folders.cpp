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

// One catalogue run for the command line's claims (each run times its yardstick three times, a
// fixed ~2 s that a second run would spend again): where it writes without --out, and what it
// prints and writes there.
TEST_CASE(
    "kiln bench --catalogue without --out writes bench/catalogue/ (the kind rows and the "
    "yardstick) and leaves bench/bench.csv alone, its two flags are refused without --catalogue",
    "[bench][cli]") {
  std::string dir = test::TempDir("bench_folders");
  fs::create_directories(dir + "/bench");
  { std::ofstream(dir + "/bench/bench.csv") << "committed results\n"; }
  fs::path cwd = fs::current_path();
  fs::current_path(dir);
  test::CommandResult r =
      test::RunKiln("bench --catalogue --only lambert-albedo --no-reference --samples 1 -j 1");
  fs::current_path(cwd);
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(fs::exists(dir + "/bench/catalogue/catalogue.csv"));
  CHECK(!fs::exists(dir + "/bench/catalogue.csv"));
  CHECK(test::ReadFile(dir + "/bench/bench.csv") == "committed results\n");
  // What the run prints and writes: the kind rows, the total and the yardstick.
  CHECK(r.out.find("yardstick: 1024-sample Monte Carlo") != std::string::npos);
  CHECK(r.out.find("\nalbedo ") != std::string::npos);
  CHECK(r.out.find("x the yardstick (texels ") != std::string::npos);
  const std::string csv = test::ReadFile(dir + "/bench/catalogue/catalogue.csv");
  CHECK(csv.find("\nkind,albedo,") != std::string::npos);
  CHECK(csv.find("\ntotal,total,") != std::string::npos);
  CHECK(csv.find("\nyardstick,") != std::string::npos);

  test::CommandResult empty = test::RunKiln("bench --quick --out ''");
  CHECK(empty.exitCode != 0);
  CHECK(empty.err.find("--out '' names no folder") != std::string::npos);
  for (const char* flag : {"--no-reference", "--no-lookup-error"}) {
    test::CommandResult bad = test::RunKiln(std::string("bench --quick ") + flag);
    INFO(flag << ": " << bad.err);
    CHECK(bad.exitCode != 0);
    CHECK(test::CountLines(bad.err) == 1);
    CHECK(bad.err.find("need --catalogue") != std::string::npos);
  }
  fs::remove_all(dir);
}
