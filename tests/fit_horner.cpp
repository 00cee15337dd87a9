// Specification: the Horner (power-basis) form of a one-axis `kiln fit` (baker/fit/,
// docs/fits.md): c0 + t (c1 + t (c2 + ...)) in t = warp(v - lo), whose emitted C++ computes the
// bits kiln measured, whose form line makes `kiln verify` re-measure the Horner evaluation, and
// which brings a one-axis fit under a bilinear fetch's address arithmetic.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "baker/fit/fit_writer.h"
#include "baker/tables/catalogue.h"
#include "cli_util.h"
#include "fit_emitted.h"
#include "test_util.h"

namespace {
using namespace kiln;

/// The table of the in-process fits below: its average albedo's Horner fit is fast to fit and to
/// search, and under a bilinear fetch's address ops.
const char* const kHornerTable = "fujii-normalized-albedo-avg";

/// The bilinear fetch's address arithmetic of a one-axis table at a linear warp, counted as
/// docs/fits.md counts it: clamp (2), (x - lo) / (hi - lo) (2), w (n - 1) (1), floor (1), the
/// weight (1), the neighbour's index min(i + 1, n - 1) (2).
constexpr int kFetchAddressOpsLinear1D = 2 + 2 + 1 + 1 + 1 + 2;

/// kiln fit kHornerTable --max-error 1e-3, fitted once.
const FitResult& HornerFit() {
  static const FitResult fit = [] {
    FitOptions opt;
    opt.maxError = 1e-3;
    opt.threads = 2;
    return FitTable(CatalogueTable(kHornerTable), opt);
  }();
  return fit;
}

/// Points across [lo, hi] and beyond it (the clamp), the ends included.
std::vector<float> AxisPoints(double lo, double hi) {
  std::vector<float> xs = {static_cast<float>(lo), static_cast<float>(hi),
                           static_cast<float>(lo - 0.5), static_cast<float>(hi + 0.5)};
  test::Rng rng(34);
  for (int i = 0; i < 200; ++i) xs.push_back(static_cast<float>(lo + (hi - lo) * rng.Uniform()));
  return xs;
}

/// Checks that the emitted C++ of each of `fits` (forms of one table) gives EvaluateFit's bits at
/// AxisPoints, the forms compiled into one program (test::RunEmittedFits).
void CheckEmittedBits(const std::vector<FitResult>& fits, const std::string& dir) {
  REQUIRE(!fits.empty());
  const FitForm& first = fits[0].form;
  const std::vector<float> xs = AxisPoints(first.axes[0].lo, first.axes[0].hi);
  std::vector<std::string> headers;
  for (const FitResult& fit : fits) {
    REQUIRE(fit.form.table == first.table);  // one function name
    headers.push_back(FitCppHeader(fit, "test"));
  }
  const std::vector<std::vector<float>> emitted =
      test::RunEmittedFits(headers, FitFunctionName(first.table), 1, xs, dir);
  for (size_t k = 0; k < fits.size(); ++k) {
    const FitForm& f = fits[k].form;
    for (size_t i = 0; i < xs.size(); ++i) {
      float own[4];
      EvaluateFit(f, &xs[i], own);
      for (size_t c = 0; c < f.channels.size(); ++c) {
        INFO(f.table << " warp " << FitWarpName(f.axes[0].warp) << " lo " << f.axes[0].lo << " at "
                     << xs[i] << " channel " << c);
        CHECK(emitted[k][4 * i + c] == own[c]);
      }
    }
  }
}
}  // namespace

TEST_CASE(
    "The emitted Horner C++ gives kiln's bits for a domain not starting at 0, the sqrt and "
    "root4 warps and two channels",
    "[fit][horner]") {
  // Forms built by hand (the writer and the evaluator, not the fitting): t = warp(v - lo), or v
  // for a linear axis.
  FitResult fit;
  fit.form.table = "charlie-albedo-avg";
  fit.form.channels = {"A", "B"};
  fit.form.basis = FitBasis::Power;
  FitAxis axis;
  axis.name = "roughness";
  axis.lo = 0.045;
  axis.hi = 1;
  axis.degree = 4;
  fit.form.axes = {axis};
  fit.form.coefficients = {0.9f, -0.31f, 0.27f, -0.11f, 0.013f, 0.1f, 0.21f, -0.3f, 0.05f, 0.7f};
  fit.error.where = {0.5};
  std::vector<FitResult> forms;  // one compile for the six
  for (FitWarp warp : {FitWarp::Linear, FitWarp::Sqrt, FitWarp::Root4})
    for (double lo : {0.045, 0.0}) {
      fit.form.axes[0].warp = warp;
      fit.form.axes[0].lo = lo;
      forms.push_back(fit);
    }
  CheckEmittedBits(forms, test::TempDir("fit_horner_warps"));
  // The count: the clamp, v - lo (a warped axis not starting at 0), the warp's sqrt, a
  // multiply and an add per degree and channel. A linear axis's t is v: its shift is folded in.
  fit.form.axes[0].lo = 0.045;
  fit.form.axes[0].warp = FitWarp::Root4;
  CHECK(fit.form.OperationCount() == 2 + 1 + 2 + 2 * 2 * 4);
  fit.form.axes[0].warp = FitWarp::Linear;
  CHECK(fit.form.OperationCount() == 2 + 2 * 2 * 4);
  CHECK(FitCppHeader(fit, "test").find("float t = v;") != std::string::npos);
}

TEST_CASE("kiln verify re-measures a Horner header and fails one whose coefficient was raised 1 %",
          "[fit][horner][cli]") {
  // fresnel-dielectric-avg: its fit within 1e-3 is a Horner form too (4 terms), and its exact
  // values (a 1D integral) cost little, so the fit, its search and the three re-measurements
  // take a fraction of a second.
  const std::string table = "fresnel-dielectric-avg";
  const std::string dir = test::TempDir("fit_horner_verify");
  test::CommandResult r =
      test::RunKiln("fit " + table + " --max-error 1e-3 --out " + dir + " -j 2");
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.out.find("horner form") != std::string::npos);
  const std::string path = dir + "/" + table + "-fit.h";
  r = test::RunKiln("verify " + path + " -j 2");
  INFO(r.out << r.err);
  CHECK(r.exitCode == 0);
  const std::string text = test::ReadFile(path);
  ParsedFit parsed = ParseFitHeader(text, path);
  REQUIRE(parsed.form.basis == FitBasis::Power);
  // The constant term 1 % larger: the re-measured max exceeds the stated one.
  const size_t open = text.find('{', text.find("static const float c["));
  const size_t close = text.find('}', open);
  std::string list;
  for (size_t k = 0; k < parsed.form.coefficients.size(); ++k) {
    char b[40];
    std::snprintf(b, sizeof b, "%s%.9gf", k ? ", " : "",
                  parsed.form.coefficients[k] * (k == 0 ? 1.01f : 1.0f));
    list += b;
  }
  std::ofstream(path) << text.substr(0, open + 1) + list + text.substr(close);
  r = test::RunKiln("verify " + path + " -j 2");
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("exceeds the stated") != std::string::npos);
  // The same coefficients read as a Chebyshev form are another function: verify measures the
  // form the line names.
  std::string relabelled = text;
  relabelled.replace(relabelled.find("form=horner"), 11, "form=chebyshev");
  std::ofstream(path) << relabelled;
  r = test::RunKiln("verify " + path + " -j 2");
  CHECK(r.exitCode != 0);
  CHECK(r.err.find("exceeds the stated") != std::string::npos);
}

// One test for the three claims on one fit (HornerFit, ~1 s of CPU that each CTest process would
// spend again): what the form is and its emitted C++ computes, its operation count, its shaders.
TEST_CASE(
    "A one-axis fit within 1e-3 is a Horner form: its emitted C++ gives kiln's bits, it is under "
    "a bilinear fetch's address ops, its GLSL and HLSL compile with glslangValidator",
    "[fit][horner][shaders]") {
  SECTION("A one-axis fit within 1e-3 is a Horner form whose emitted C++ gives kiln's bits") {
    const FitResult& fit = HornerFit();
    REQUIRE(fit.form.basis == FitBasis::Power);
    CHECK(fit.error.max <= 1e-3);
    const std::string header = FitCppHeader(fit, "test");
    CHECK(header.find("form=horner") != std::string::npos);
    CHECK(header.find("out[0] = c[0] + t * (c[1] + t * c[2]);") != std::string::npos);
    CheckEmittedBits({fit}, test::TempDir("fit_horner_cpp"));
  }
  SECTION("A Horner fit of fujii-normalized-albedo-avg is under a bilinear fetch's address ops") {
    // Its table's warp is linear: 9 operations before the fetch's memory reads. The Chebyshev form
    // of the same degree spends more than that (6 per axis for the clamp, normalisation and
    // s = 2 w - 1, then the recurrence and 2 per term).
    REQUIRE(CatalogueTable(kHornerTable).axes[0].warp == Warp::Linear);
    const FitResult& fit = HornerFit();
    CHECK(fit.error.maxOffJump <= 1e-3);
    CHECK(fit.form.OperationCount() < kFetchAddressOpsLinear1D);
    FitForm chebyshev = fit.form;
    chebyshev.basis = FitBasis::Chebyshev;
    CHECK(chebyshev.OperationCount() > kFetchAddressOpsLinear1D);
  }
  SECTION("A Horner fit's GLSL and HLSL compile with glslangValidator") {
    REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
    const FitResult& fit = HornerFit();
    const std::string dir = test::TempDir("fit_horner_shaders");
    const std::string name = FitFunctionName(fit.form.table);
    auto glslang = [&](const std::string& text, const std::string& ext, const std::string& flags) {
      std::ofstream(dir + "/shader" + ext) << text;
      const std::string cmd = "glslangValidator " + flags + " " + dir + "/shader" + ext + " > " +
                              dir + "/glslang.log 2>&1";
      const int status = std::system(cmd.c_str());
      INFO(test::ReadFile(dir + "/glslang.log"));
      CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    };
    const std::string glslMain =
        "\nin float p; out vec4 color;\nvoid main() { color = vec4(" + name + "(p)); }\n";
    glslang("#version 300 es\nprecision highp float;\n" + FitGlsl(fit, "test") + glslMain, ".frag",
            "-S frag");
    glslang("#version 330\n" + FitGlsl(fit, "test") + glslMain, ".frag", "-S frag");
    const std::string hlslMain =
        "\nfloat4 main(float p : TEXCOORD0) : SV_Target { return float4(" + name + "(p).xxxx); }\n";
    glslang(FitHlsl(fit, "test") + hlslMain, ".hlsl",
            "-D -V -e main -S frag -o " + dir + "/shader.spv");
  }
}
