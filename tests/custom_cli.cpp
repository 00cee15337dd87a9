// Specification: the commands that take a model take a user's lobe too, by --model-source
// FILE.cpp or --model-library FILE.so: eval and integrate print its values, bake --only
// <id>-albedo writes a self-describing table (model id and hash in its header) that a second
// bake finds up to date and `kiln verify` checks, plan reads a kiln scene naming the id, list
// shows the lobe and its tables (baked by adaptive quadrature). A lobe that does not compile is
// one error with the compiler's lines; a lobe that crashes the process mid-bake leaves every
// file that was there intact.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "baker/custom/compiler.h"
#include "cli_util.h"
#include "custom_util.h"
#include "kiln/exr_loader.h"

using namespace kiln;
using namespace kiln::test;
using Catch::Matchers::Contains;

namespace {

/// `kiln ARGS` with the tests' compile cache (the lobes compiled once per process).
CommandResult Kiln(const std::string& args) { return RunKiln(args); }

std::string Q(const std::string& s) { return "'" + s + "'"; }

/// The example lobe `file`'s path.
std::string Example(const std::string& file) {
  return std::string(KILN_SOURCE_DIR) + "/examples/models/" + file;
}

/// The lobes compile into CustomCache(); kiln finds them there through XDG_CACHE_HOME, set for
/// this process (RunKiln's children inherit it).
void UseTestCache() { setenv("XDG_CACHE_HOME", CacheHome().c_str(), 1); }

}  // namespace

TEST_CASE("kiln eval and integrate take a lobe by --model-source or --model-library",
          "[custom][cli]") {
  UseTestCache();
  const std::string src = Example("user_ggx.cpp");
  CommandResult user = Kiln("eval --model-source " + Q(src) +
                            " --model user-ggx --mu-o 0.5 --mu-l 0.7 --phi 2.5 -r 0.4");
  CommandResult ggx = Kiln("eval --model ggx --mu-o 0.5 --mu-l 0.7 --phi 2.5 -r 0.4");
  REQUIRE(user.exitCode == 0);
  CHECK(std::stod(user.out) == Approx(std::stod(ggx.out)).epsilon(1e-12));
  const std::string library = CompileModelSource(src, CustomCache());
  CommandResult lib =
      Kiln("integrate albedo --model-library " + Q(library) + " --model user-ggx --mu 0.5 -r 0.4");
  CommandResult ref = Kiln("integrate albedo --model ggx --mu 0.5 -r 0.4");
  REQUIRE(lib.exitCode == 0);
  CHECK(std::stod(lib.out) == Approx(std::stod(ref.out)).margin(1e-8));
  CommandResult unknown = Kiln("eval --model user-ggx --mu-o 0.5 --mu-l 0.7");
  CHECK(unknown.exitCode != 0);  // not loaded: an unknown model
}

TEST_CASE("kiln bake --only <id>-albedo bakes a table naming the lobe, verify checks it",
          "[custom][cli]") {
  UseTestCache();
  // 6 nodes an axis: what is checked (the table's model and method, the skip, verify with and
  // without the lobe) is the same for any size; the bake and verify's search scale with the cells.
  const std::string dir = TempDir("custom_bake"), src = Example("normalized_phong.cpp");
  const std::string bake = "bake --model-source " + Q(src) +
                           " --only phong-normalized-albedo --size 6 -j 2 --out " + Q(dir);
  CommandResult first = Kiln(bake);
  INFO(first.err);
  REQUIRE(first.exitCode == 0);
  const Table t = loadTable(dir + "/phong-normalized-albedo.exr");
  CHECK(t.model == "phong-normalized");
  CHECK_THAT(t.method, Contains("adaptive") && Contains(FileHash(src)));
  CHECK(t.bakeError >= 0);
  CommandResult again = Kiln(bake);
  CHECK_THAT(again.out + again.err, Contains("0 baked, 1 skipped"));
  CommandResult verify = Kiln("verify --model-source " + Q(src) + " --budget 200 -j 2 " + Q(dir));
  INFO(verify.out << verify.err);
  CHECK(verify.exitCode == 0);
  CommandResult unloaded = Kiln("verify --budget 200 -j 2 " + Q(dir));
  CHECK(unloaded.exitCode != 0);  // the model is needed to check its table
}

TEST_CASE("kiln plan reads a kiln scene naming a lobe's id", "[custom][cli]") {
  UseTestCache();
  const std::string dir = TempDir("custom_plan"), scene = dir + "/scene.kiln.json";
  std::ofstream(scene) << R"({"kiln_scene": 1, "materials": [)"
                       << R"({"name": "cloth", "model": "soft-sheen", "roughness": [0.3, 0.6],)"
                       << R"( "tables": ["albedo"]}]})";
  CommandResult plan = Kiln("plan --model-source " + Q(Example("custom_sheen.cpp")) + " " +
                            Q(scene) + " --out " + Q(dir));
  INFO(plan.out << plan.err);
  REQUIRE(plan.exitCode == 0);
  CHECK_THAT(plan.out, Contains("soft-sheen-albedo"));
}

TEST_CASE("a lobe that does not compile is one error with the compiler's lines", "[custom][cli]") {
  UseTestCache();
  const std::string src = WriteLobe("cli_broken", "cli-broken", false, "return undeclared_x;");
  CommandResult r = Kiln("eval --model-source " + Q(src) + " --model cli-broken --mu-o 1 --mu-l 1");
  CHECK(r.exitCode != 0);
  CHECK(r.err.rfind("kiln: error: cannot compile " + src, 0) == 0);
  CHECK_THAT(r.err, Contains("undeclared_x"));
}

TEST_CASE("a lobe that crashes mid-bake leaves every existing file intact", "[custom][cli]") {
  UseTestCache();
  const std::string dir = TempDir("custom_crash");
  REQUIRE(Kiln("bake --only fresnel-dielectric-avg --size 8 -j 1 --out " + Q(dir)).exitCode == 0);
  // The same id as a good lobe whose table is already there: the crash must not touch it.
  const std::string good = WriteLobe("crash_good", "crashy", false, "return 0.2;");
  REQUIRE(
      Kiln("bake --model-source " + Q(good) + " --only crashy-albedo --size 6 -j 1 --out " + Q(dir))
          .exitCode == 0);
  std::map<std::string, std::string> before;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    before[e.path().filename()] = ReadFile(e.path());
  const std::string bad = WriteLobe("crash_bad", "crashy", false,
                                    "if (r > 0.5) { volatile int* p = nullptr; *p = 1; }\n"
                                    "return 0.3;");
  CommandResult crash =
      Kiln("bake --model-source " + Q(bad) + " --only crashy-albedo --size 6 -j 1 --out " + Q(dir));
  CHECK(crash.exitCode != 0);
  std::map<std::string, std::string> after;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() != ".tmp") after[e.path().filename()] = ReadFile(e.path());
  CHECK(after == before);
}

TEST_CASE(
    "kiln list with --model-source lists the lobe among the models and its tables with their "
    "method, adaptive quadrature",
    "[custom][cli][list]") {
  UseTestCache();
  const std::string load = "--model-source " + Q(Example("user_ggx.cpp"));
  for (const std::string& models : {"list " + load, "list --models " + load}) {
    CommandResult r = Kiln(models);
    INFO(models << "\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK_THAT(r.out, Contains("\nuser-ggx roughness=") && Contains("custom model from"));
    CHECK_THAT(r.out, Contains("\nggx "));  // the built-in models are still there
  }
  CommandResult text = Kiln("list --tables " + load);
  REQUIRE(text.exitCode == 0);
  for (const char* name : {"user-ggx-albedo", "user-ggx-albedo-avg", "user-ggx-dfg"})
    CHECK_THAT(text.out, Contains(std::string("\n") + name + "  [on request]  "));
  CHECK_THAT(text.out, Contains("; method: half-vector space: adaptive Gauss-Kronrod"));
  CHECK_THAT(text.out,
             Contains("custom model 'user-ggx', hash " + FileHash(Example("user_ggx.cpp"))));
  CommandResult json = Kiln("list --tables --json " + load);
  REQUIRE(json.exitCode == 0);
  std::map<std::string, nlohmann::json> byName;
  for (const auto& t : nlohmann::json::parse(json.out)) byName[t.at("name")] = t;
  REQUIRE(byName.count("user-ggx-dfg") == 1);
  const nlohmann::json& albedo = byName.at("user-ggx-albedo");
  CHECK(albedo.at("model") == "user-ggx");
  CHECK(albedo.at("custom_model").get<bool>());
  CHECK_FALSE(albedo.at("default_catalogue").get<bool>());
  CHECK_THAT(albedo.at("method").get<std::string>(), Contains("adaptive"));
  // The average quotes its E table's method: the lobe's id and hash once.
  const std::string avgMethod = byName.at("user-ggx-albedo-avg").at("method");
  const size_t first = avgMethod.find("custom model 'user-ggx'");
  REQUIRE(first != std::string::npos);
  CHECK(avgMethod.find("custom model 'user-ggx'", first + 1) == std::string::npos);
  CHECK_FALSE(byName.at("ggx-albedo").at("custom_model").get<bool>());
  CHECK_THAT(byName.at("ggx-albedo").at("method").get<std::string>(), Contains("fixed"));
  CommandResult plain = Kiln("list --tables");
  CHECK_THAT(plain.out, !Contains("user-ggx"));  // only when loaded
  CHECK(Kiln("list --models --tables").exitCode != 0);
}

TEST_CASE(
    "kiln bench --custom-lobe times a lobe's albedo against a built-in model's in interleaved "
    "rounds and prints the medians and their ratio",
    "[custom][cli][bench]") {
  UseTestCache();
  const std::string lobe = "--custom-lobe " + Q(Example("user_ggx.cpp"));
  CommandResult r = Kiln("bench " + lobe + " --size 4 --rounds 2 -j 1");
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Contains("user-ggx-albedo against ggx-albedo, 4 x 4 nodes, adaptive"));
  CHECK_THAT(r.out, Contains("round 1: user-ggx-albedo ") && Contains("round 2: user-ggx-albedo "));
  CHECK_THAT(r.out, Contains("median: user-ggx-albedo ") && Contains("; ratio "));
  CHECK_THAT(r.out, Contains("max node difference"));
  CHECK(Kiln("bench " + lobe + " --quick").exitCode != 0);
  CommandResult alone = Kiln("bench --rounds 2 --quick");
  CHECK(alone.exitCode != 0);
  CHECK_THAT(alone.err, Contains("--rounds needs --custom-lobe"));
  CHECK(Kiln("bench " + lobe + " --against no-such-model --size 4").exitCode != 0);
}
