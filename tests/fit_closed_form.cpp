// Specification: `kiln fit` (baker/fit/): a closed form of a table's exact integrals whose
// stated max error holds for the emitted C++ (compiled here with the system compiler), whose
// shaders compile, which is the same for any thread count, and which `kiln verify` re-measures.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>

#include "baker/fit/engine_approximations.h"
#include "baker/fit/fit_verify.h"
#include "baker/fit/least_squares.h"
#include "baker/tables/catalogue.h"
#include "cli_util.h"
#include "fit_emitted.h"
#include "test_util.h"

namespace {
using namespace kiln;

/// The ggx-dfg fit of the goal (2e-3 off the mirror's jump), fitted once for the tests below.
const FitResult& GgxDfgFit() {
  static const FitResult fit = [] {
    FitOptions opt;
    opt.maxError = 2e-3;
    opt.threads = 2;
    return FitTable(CatalogueTable("ggx-dfg"), opt);
  }();
  return fit;
}

/// A ggx-dfg fit of at most 12 coefficients a channel: a 2D fit has one basis (Chebyshev) and
/// the warps the table's axes choose whatever its degrees, so its shaders are written by the same
/// code as the goal's fit; it takes a fraction of the goal's search.
FitResult SmallGgxDfgFit() {
  FitOptions opt;
  opt.terms = 12;
  opt.threads = 2;
  return FitTable(CatalogueTable("ggx-dfg"), opt);
}

/// glslangValidator on `text` in a file ending in `ext` with `flags`: its exit code.
int Glslang(const std::string& text, const std::string& ext, const std::string& flags,
            const std::string& dir, std::string& log) {
  std::ofstream(dir + "/shader" + ext) << text;
  std::string cmd =
      "glslangValidator " + flags + " " + dir + "/shader" + ext + " > " + dir + "/glslang.log 2>&1";
  int status = std::system(cmd.c_str());
  log = test::ReadFile(dir + "/glslang.log");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST_CASE("Householder least squares recovers an exact fit and the residual-minimising one",
          "[fit]") {
  // 5 points on y = 1 + 2 t - 3 t^2: exact in the basis (1, t, t^2).
  std::vector<double> a, b;
  for (int i = 0; i < 5; ++i) {
    double t = i / 4.0;
    a.insert(a.end(), {1, t, t * t});
    b.push_back(1 + 2 * t - 3 * t * t);
  }
  std::vector<double> x = SolveLeastSquares(a, b, 5, 3);
  CHECK(x[0] == Approx(1).margin(1e-14));
  CHECK(x[1] == Approx(2).margin(1e-13));
  CHECK(x[2] == Approx(-3).margin(1e-13));
  // A constant fitted to 0, 0, 3: the mean, 1.
  x = SolveLeastSquares({1, 1, 1}, {0, 0, 3}, 3, 1);
  CHECK(x[0] == Approx(1).margin(1e-15));
}

TEST_CASE(
    "A ggx-dfg fit is within 2e-3 of the exact integrals off the mirror's jump, in the "
    "emitted C++ as measured",
    "[fit][ggx]") {
  const FitResult& fit = GgxDfgFit();
  CHECK(fit.error.maxOffJump <= 2e-3);
  CHECK(fit.error.max >= fit.error.maxOffJump);
  const std::string dir = test::TempDir("fit_cpp");
  const std::string header = FitCppHeader(fit, "test");
  CHECK(header.find("inline void kiln_fit_ggx_dfg(const float* x, float* out)") !=
        std::string::npos);
  CHECK(header.find("// max error E = ") != std::string::npos);
  // Random points, a third of them in the grazing, low-roughness corner.
  test::Rng rng(33);
  std::vector<std::array<float, 2>> points;
  std::vector<float> flat;
  for (int i = 0; i < 300; ++i) {
    double u = rng.Uniform(), v = rng.Uniform();
    if (i % 3 == 0) u = std::pow(u, 8), v = std::pow(v, 4);
    points.push_back({static_cast<float>(u), static_cast<float>(v)});
    flat.insert(flat.end(), {points.back()[0], points.back()[1]});
  }
  const std::vector<float> out = test::RunEmittedFit(header, "kiln_fit_ggx_dfg", 2, flat, dir);
  const double stated = StatedBound(fit.error.maxOffJump);
  for (size_t i = 0; i < points.size(); ++i) {
    const std::array<float, 2>& p = points[i];
    const float emitted[2] = {out[4 * i], out[4 * i + 1]};
    float own[2];
    EvaluateFit(fit.form, p.data(), own);
    INFO("mu " << p[0] << " roughness " << p[1]);
    CHECK(emitted[0] == own[0]);  // the bits kiln measured
    CHECK(emitted[1] == own[1]);
    const double x[2] = {p[0], p[1]};
    IntegrationStats stats;
    std::vector<double> exact = EvaluateSpec(CatalogueTable("ggx-dfg"), x, stats);
    if (p[1] == 0 && p[0] < kLayerJumpMu) continue;  // on the jump: the whole-domain bound
    CHECK(std::fabs(emitted[0] - exact[0]) <= stated);
    CHECK(std::fabs(emitted[1] - exact[1]) <= stated);
  }
}

TEST_CASE("A fit's GLSL and HLSL compile with glslangValidator", "[fit][shaders]") {
  REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
  const FitResult fit = SmallGgxDfgFit();
  CHECK(fit.form.basis == FitBasis::Chebyshev);
  const std::string dir = test::TempDir("fit_shaders");
  std::string log;
  const std::string glslMain =
      "\nin vec2 p; out vec4 color;\nvoid main() { color = vec4(kiln_fit_ggx_dfg(p), 0, 1); }\n";
  const std::string glsl = FitGlsl(fit, "test");
  int code = Glslang("#version 300 es\nprecision highp float;\n" + glsl + glslMain, ".frag",
                     "-S frag", dir, log);
  if (code != 0) FAIL_CHECK("GLSL ES 3.00: " << log);
  code = Glslang("#version 330\n" + glsl + glslMain, ".frag", "-S frag", dir, log);
  if (code != 0) FAIL_CHECK("GLSL 3.30: " << log);
  const std::string hlslMain =
      "\nfloat4 main(float2 p : TEXCOORD0) : SV_Target { return float4(kiln_fit_ggx_dfg(p), 0, "
      "1); }\n";
  code = Glslang(FitHlsl(fit, "test") + hlslMain, ".hlsl",
                 "-D -V -e main -S frag -o " + dir + "/shader.spv", dir, log);
  if (code != 0) FAIL_CHECK("HLSL: " << log);
  // The check can fail: a call to a function the file does not define is refused.
  CHECK(Glslang("#version 330\n" + glsl + glslMain + "void f() { kiln_fit_other(); }\n", ".frag",
                "-S frag", dir, log) != 0);
}

TEST_CASE("A fit is the same for any thread count", "[fit]") {
  FitOptions opt;
  opt.terms = 25;
  opt.threads = 1;
  // A cheap 1D exact integral: the samples are evaluated in parallel all the same.
  const TableSpec spec = CatalogueTable("fresnel-dielectric-avg");
  FitResult one = FitTable(spec, opt);
  opt.threads = 2;
  FitResult two = FitTable(spec, opt);
  CHECK(FitCppHeader(one, "test") == FitCppHeader(two, "test"));
  CHECK(one.form.TermsPerChannel() <= 25);
}

TEST_CASE("kiln verify re-measures a fit header and fails one whose coefficients were changed",
          "[fit][cli]") {
  // fresnel-dielectric-avg: a one-axis table of integrals whose exact values (a 1D integral)
  // cost little, so the fit, its search and both re-measurements take a fraction of a second.
  const std::string dir = test::TempDir("fit_verify");
  test::CommandResult r =
      test::RunKiln("fit fresnel-dielectric-avg --terms 12 --out " + dir + " -j 2");
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  for (const char* ext : {".h", ".glsl", ".hlsl"})
    CHECK(std::ifstream(dir + "/fresnel-dielectric-avg-fit" + ext).good());
  const std::string path = dir + "/fresnel-dielectric-avg-fit.h";
  r = test::RunKiln("verify " + path + " -j 2");
  INFO(r.out << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("ok") != std::string::npos);
  // Every coefficient 1% larger: the re-measured max exceeds the stated one.
  ParsedFit parsed = ParseFitHeader(test::ReadFile(path), path);
  std::string text = test::ReadFile(path);
  const size_t open = text.find('{', text.find("static const float c["));
  const size_t close = text.find('}', open);
  std::string list;
  for (size_t k = 0; k < parsed.form.coefficients.size(); ++k) {
    char b[40];
    std::snprintf(b, sizeof b, "%s%.9gf", k ? ", " : "", parsed.form.coefficients[k] * 1.01);
    list += b;
  }
  std::ofstream(path) << text.substr(0, open + 1) + list + text.substr(close);
  r = test::RunKiln("verify " + path + " -j 2");
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("exceeds the stated") != std::string::npos);
  // A header without its form line is no fit.
  std::ofstream(path) << "inline void f() {}\n";
  r = test::RunKiln("verify " + path);
  CHECK(r.exitCode != 0);
  CHECK(test::CountLines(r.err) == 1);
  CHECK(r.err.find("kiln: error:") == 0);
}

TEST_CASE("kiln fit refuses a table it cannot fit with one line and writes nothing", "[fit][cli]") {
  const std::string dir = test::TempDir("fit_refuse");
  for (const std::string& args :
       {std::string("fit ggx-fresnel-albedo --out ") + dir, "fit no-such-table --out " + dir,
        "fit ggx-dfg --out " + dir + "/missing", "fit ggx-dfg --max-error 0 --out " + dir}) {
    test::CommandResult r = test::RunKiln(args);
    INFO(args << ": " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(test::CountLines(r.err) == 1);
    CHECK(r.err.find("kiln: error:") == 0);
  }
  CHECK(std::filesystem::is_empty(dir));
}

TEST_CASE("Karis's EnvBRDFApprox errs 0.5 at most against the exact GGX DFG", "[fit][engines]") {
  // Karis 2014, "Physically Based Shading on Mobile" (UE4's EnvBRDFApprox; three.js's former
  // DFGApprox): the numbers docs/fits.md lists.
  const TableSpec spec = CatalogueTable("ggx-dfg");
  const float smooth[2] = {1.0f, 0.0f}, rough[2] = {0.5f, 1.0f};
  float ab[2];
  KarisEnvBrdfApprox(FitForm(), smooth, ab);  // mirror at normal incidence: A = 1, B = 0
  CHECK(ab[0] == Approx(1.0).margin(0.01));
  CHECK(ab[1] == Approx(0.0).margin(0.01));
  KarisEnvBrdfApprox(FitForm(), rough, ab);
  CHECK(ab[0] + ab[1] < 1);
  FitErrorReport rep = MeasureFitError(spec, DfgProbeForm(spec), 2, KarisEnvBrdfApprox);
  CHECK(rep.maxOffJump == Approx(0.500).margin(1e-3));
  CHECK(rep.median > 0.01);
  CHECK(rep.median < 0.1);
}

TEST_CASE("three.js's 16 x 16 DFGLUTData, sampled bilinearly, measured against the exact GGX DFG",
          "[fit][engines]") {
  // The texels: tests/atlas_engine_tables.cpp checks them against tests/engines/three_dfg_lut.csv.
  const TableSpec spec = CatalogueTable("ggx-dfg");
  FitErrorReport rep = MeasureFitError(spec, DfgProbeForm(spec), 2, ThreeDfgLutLookup);
  INFO("max " << rep.max << " at mu " << rep.where[0] << " roughness " << rep.where[1]
              << ", median " << rep.median);
  // Far from the fits' bounds, as docs/fits.md lists.
  CHECK(rep.max > 0.01);
  CHECK(rep.median < 0.05);
}

TEST_CASE(
    "A fresnel-dielectric fit follows the grazing layer near eta = 1 (layer-eta warp), in the "
    "emitted C++ and shaders as measured",
    "[fit][fresnel]") {
  // Dielectric Fresnel's grazing layer has width sqrt(eta^2 - 1): a fixed-degree form in mu
  // misses it near eta = 1 (0.51 off eta = 1 with the plain warps); the layer-eta warp follows it
  // down to the float just above 1, leaving only eta = 1 itself (F = 0, no interface).
  FitOptions opt;
  opt.terms = 64;
  opt.threads = 2;
  const FitResult fit = FitTable(CatalogueTable("fresnel-dielectric"), opt);
  CHECK(fit.form.axes[0].warp == FitWarp::LayerEta);
  CHECK(fit.error.maxOffJump < 0.03);
  CHECK(fit.error.median < 0.01);
  const std::string dir = test::TempDir("fit_fresnel");
  const std::string header = FitCppHeader(fit, "test");
  CHECK(header.find("layer-eta") != std::string::npos);
  // Points near eta = 1 and at grazing, the float just above 1 among them.
  const float points[][2] = {{1e-4f, 1.00000012f}, {3e-4f, 1.0001f}, {0.01f, 1.01f},
                             {0.5f, 1.5f},         {0.05f, 1.2f},    {1.0f, 3.0f}};
  std::vector<float> flat;
  for (auto& p : points) flat.insert(flat.end(), {p[0], p[1]});
  const std::vector<float> out =
      test::RunEmittedFit(header, "kiln_fit_fresnel_dielectric", 2, flat, dir);
  const double stated = StatedBound(fit.error.maxOffJump);
  for (size_t i = 0; i < std::size(points); ++i) {
    const float* p = points[i];
    const float emitted = out[4 * i];
    float own[1];
    EvaluateFit(fit.form, p, own);
    INFO("mu " << p[0] << " eta " << p[1]);
    CHECK(emitted == own[0]);  // the bits kiln measured
    const double x[2] = {p[0], p[1]};
    IntegrationStats stats;
    const double exact = EvaluateSpec(CatalogueTable("fresnel-dielectric"), x, stats)[0];
    CHECK(std::fabs(emitted - exact) <= stated);
  }
  std::string log;
  const std::string glslMain =
      "\nin vec2 p; out vec4 color;\nvoid main() { color = vec4(kiln_fit_fresnel_dielectric(p)); "
      "}\n";
  int code = Glslang("#version 300 es\nprecision highp float;\n" + FitGlsl(fit, "test") + glslMain,
                     ".frag", "-S frag", dir, log);
  if (code != 0) FAIL_CHECK("GLSL ES 3.00: " << log);
  const std::string hlslMain =
      "\nfloat4 main(float2 p : TEXCOORD0) : SV_Target { return "
      "float4(kiln_fit_fresnel_dielectric(p).xxxx); }\n";
  code = Glslang(FitHlsl(fit, "test") + hlslMain, ".hlsl",
                 "-D -V -e main -S frag -o " + dir + "/shader.spv", dir, log);
  if (code != 0) FAIL_CHECK("HLSL: " << log);
}
