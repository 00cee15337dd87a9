// Specification of the C++ header writer: the generated header compiles on
// its own (kiln/lut.h only) and samples exactly like the runtime.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "baker/io/cpp_header_writer.h"
#include "baker/io/exr_writer.h"
#include "kiln/exr_loader.h"

namespace fs = std::filesystem;

namespace {

/// A fresh, empty folder under the system temp folder, removed at the end.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() / ("kiln-test-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The compiler to build the generated header with: $CXX, else c++; empty
/// when none runs.
std::string findCompiler() {
  const char* fromEnvironment = std::getenv("CXX");
  for (std::string candidate : {std::string(fromEnvironment ? fromEnvironment : ""),
                                std::string("c++"), std::string("g++"), std::string("clang++")}) {
    if (candidate.empty()) continue;
    if (std::system(("command -v '" + candidate + "' >/dev/null 2>&1").c_str()) == 0)
      return candidate;
  }
  return std::string();
}

std::uint32_t bitsOf(float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

/// A 3D table with awkward values: thirds, a denormal, -0, large magnitudes,
/// metadata strings that need escaping.
kiln::Table makeTable() {
  kiln::Table t;
  t.generator = "kiln 0.1.0";
  t.name = "ggx-dfg";
  t.model = "ggx";
  t.quantity = "dfg";
  t.channels = {"scale", "bias"};
  t.channelMeanings = {"F0 \"scale\" term", "bias\\term"};
  t.axes = {{"mu", {0.0, 1.0, 6, kiln::Warp::Sqrt}},
            {"roughness", {0.0, 1.0, 5, kiln::Warp::Square}},
            {"eta", {1.1, 2.5, 3, kiln::Warp::Log}}};
  t.params = "f0=0.04";
  t.method = "adaptive gauss-legendre";
  t.tolerance = 1e-7;
  t.bakeError = 2.5e-8;
  t.lookupError = {1.25e-3, 3e-4, "mu=0.01\nroughness=0", "cubic"};
  t.specHash = "deadbeef";
  std::uint32_t state = 5;
  const float special[] = {1.0f / 3.0f, 1e-40f, -0.0f, 123456.78f, -2.0f / 7.0f, 1.0f};
  t.data.resize(6 * 5 * 3 * 2);
  for (std::size_t k = 0; k < t.data.size(); ++k) {
    state = state * 1664525u + 1013904223u;
    t.data[k] = k % 5 == 0 ? special[(k / 5) % 6] : float(state >> 8) / float(1u << 24) - 0.5f;
  }
  return t;
}

}  // namespace

TEST_CASE("table names become C++ identifiers", "[io][cpp-header]") {
  CHECK(kiln::cppIdentifier("ggx-dfg") == "ggx_dfg");
  CHECK(kiln::cppIdentifier("ggx--dfg v2") == "ggx_dfg_v2");
  CHECK(kiln::cppIdentifier("2d.table") == "t_2d_table");
  CHECK(kiln::cppIdentifier("-x") == "t__x");
  CHECK(kiln::cppIdentifier("") == "t_");
  CHECK(kiln::cppIdentifier("default") == "default_");
  CHECK(kiln::cppIdentifier("Already_Fine9") == "Already_Fine9");
}

TEST_CASE("the header needs no OpenEXR and is written through a temporary file",
          "[io][cpp-header]") {
  ScratchDir dir("cpp-header-text");
  const kiln::Table table = makeTable();
  const std::string path = dir.file("ggx_dfg.h");
  kiln::writeCppHeader(path, table);
  const std::string text = readText(path);
  CHECK(text == kiln::cppHeaderText(table));
  CHECK_THAT(text, Catch::Contains("#include <kiln/lut.h>"));
  CHECK_THAT(text, Catch::Contains("namespace ggx_dfg"));
  CHECK_THAT(text, !Catch::Contains("#include <OpenEXR") && !Catch::Contains("Imf::"));
  CHECK_FALSE(fs::exists(path + ".tmp"));

  kiln::Table broken = table;
  broken.data.pop_back();
  CHECK_THROWS_WITH(kiln::writeCppHeader(path, broken),
                    Catch::Contains(path) && Catch::Contains("data holds"));
  CHECK(readText(path) == text);  // the old header is left intact
}

TEST_CASE("a generated header compiles and samples exactly like the runtime", "[io][cpp-header]") {
  const std::string compiler = findCompiler();
  if (compiler.empty()) {
    WARN("no C++ compiler found ($CXX, c++, g++, clang++): skipping the compile test");
    return;
  }
  ScratchDir dir("cpp-header-compile");
  const kiln::Table table = makeTable();
  kiln::writeCppHeader(dir.file("ggx_dfg.h"), table);

  // The runtime path: the same table through an EXR file.
  kiln::writeTable(dir.file("ggx_dfg.exr"), table, false);
  const kiln::Table loaded = kiln::loadTable(dir.file("ggx_dfg.exr"));
  const kiln::LutView runtime = loaded.view();

  // Query points: every node, points between nodes, outside the domain.
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 3; ++k)
        points.push_back(
            {runtime.axis[0].node(i), runtime.axis[1].node(j), runtime.axis[2].node(k)});
  for (int n = 0; n < 40; ++n)
    points.push_back({-0.1 + 1.2 * n / 39.0, 0.37 + 0.01 * n, 1.0 + 0.04 * n});

  std::ostringstream program;
  program.precision(17);
  program
      << "#include <cstdio>\n#include <cstring>\n#include <cstdint>\n#include \"ggx_dfg.h\"\n"
      << "namespace lut = kiln::baked::ggx_dfg;\n"
      << "static_assert(lut::kChannels == 2 && lut::kDims == 3, \"shape\");\n"
      << "static unsigned bits(float v) { std::uint32_t b; std::memcpy(&b, &v, 4); return b; }\n"
      << "int main() {\n"
      << "  static const double points[][3] = {\n";
  for (const auto& p : points) program << "    {" << p[0] << ", " << p[1] << ", " << p[2] << "},\n";
  program << "  };\n"
          << "  std::printf(\"%s|%s|%s|%s|%s|%s|%s|%.17g|%.17g\\n\", lut::kName, lut::kModel, "
             "lut::kQuantity, lut::kChannelNames[1], lut::kChannelMeanings[0], lut::kAxisNames[2], "
             "lut::kLookupErrorWhere, lut::kLookupErrorMax, lut::kTolerance);\n"
          << "  for (float v : lut::kData) std::printf(\"%08x\\n\", bits(v));\n"
          << "  for (const auto& p : points) {\n"
          << "    float a[2], b[2];\n"
          << "    lut::kLut.sample(p, a, kiln::Filter::Linear);\n"
          << "    lut::kLut.sample(p, b, kiln::Filter::Cubic);\n"
          << "    std::printf(\"%08x %08x %08x %08x\\n\", bits(a[0]), bits(a[1]), bits(b[0]), "
             "bits(b[1]));\n"
          << "  }\n"
          << "}\n";
  {
    std::ofstream out(dir.file("main.cpp"));
    out << program.str();
  }
  const std::string command = "'" + compiler +
                              "' -std=c++17 -O2 -Wall -Wextra -Wpedantic -Werror -I'" +
                              std::string(KILN_SOURCE_DIR) + "/runtime/include' -I'" +
                              dir.path.string() + "' '" + dir.file("main.cpp") + "' -o '" +
                              dir.file("probe") + "' > '" + dir.file("compile.log") + "' 2>&1";
  const int compiled = std::system(command.c_str());
  INFO("compiler output:\n" << readText(dir.file("compile.log")));
  REQUIRE(compiled == 0);
  REQUIRE(std::system(("'" + dir.file("probe") + "' > '" + dir.file("out.txt") + "'").c_str()) ==
          0);

  std::istringstream out(readText(dir.file("out.txt")));
  std::string line, second;
  // The metadata record spans two lines: kLookupErrorWhere holds a line break.
  std::getline(out, line);
  std::getline(out, second);
  CHECK(line + "\n" + second ==
        "ggx-dfg|ggx|dfg|bias|F0 \"scale\" "
        "term|eta|mu=0.01\nroughness=0|0.00125|9.9999999999999995e-08");
  for (float v : table.data) {
    REQUIRE(std::getline(out, line));
    CHECK(std::stoul(line, nullptr, 16) == bitsOf(v));  // every float round-trips exactly
  }
  for (const auto& p : points) {
    REQUIRE(std::getline(out, line));
    float a[2], b[2];
    runtime.sample(p.data(), a, kiln::Filter::Linear);
    runtime.sample(p.data(), b, kiln::Filter::Cubic);
    char expected[64];
    std::snprintf(expected, sizeof expected, "%08x %08x %08x %08x", unsigned(bitsOf(a[0])),
                  unsigned(bitsOf(a[1])), unsigned(bitsOf(b[0])), unsigned(bitsOf(b[1])));
    INFO("point " << p[0] << ", " << p[1] << ", " << p[2]);
    CHECK(line == expected);
  }
}
