// Specification: the GLSL and HLSL snippets compile as an engine would use them, and every value
// in the GLSL snippet is highp. A fragment shader that calls every kilnSample* function is
// compiled by glslangValidator (Khronos' reference compiler, Debian's glslang-tools, which
// scripts/setup.sh installs) as GLSL ES 3.00 with `precision mediump float` as the shader's
// default (the snippet must not depend on the default), as desktop GLSL 3.30, and the HLSL
// snippet as a Shader Model 5 pixel shader through glslang's HLSL front end.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>

#include "cli_util.h"

namespace {

const std::string kShaders = std::string(KILN_SOURCE_DIR) + "/runtime/shaders/";

std::string Source(const std::string& name) { return kiln::test::ReadFile(kShaders + name); }

struct Compiled {
  int exitCode = -1;
  std::string log;  ///< what the compiler printed
};

/// Compiles `text` (written to a temporary file with extension `ext`) with glslangValidator
/// `flags` (validation only, or SPIR-V with -V, written to a temporary file and removed).
Compiled Compile(const std::string& text, const std::string& ext, const std::string& flags) {
  std::string base = "/tmp/kiln_shader_test_" + std::to_string(getpid());
  std::ofstream(base + ext) << text;
  std::string out = flags.find("-V") != std::string::npos ? " -o " + base + ".spv" : "";
  std::string cmd =
      "glslangValidator " + flags + " " + base + ext + out + " >" + base + ".log 2>&1";
  int status = std::system(cmd.c_str());
  Compiled c;
  c.log = kiln::test::ReadFile(base + ".log");
  std::remove((base + ext).c_str());
  std::remove((base + ".spv").c_str());
  std::remove((base + ".log").c_str());
  c.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return c;
}

const char* kGlslMain = R"(
uniform sampler2D lut1; uniform sampler2D lut2; uniform sampler2D lut3;
uniform KilnAxis a0; uniform KilnAxis a1; uniform KilnAxis a2;
in vec3 x;
out vec4 color;
void main() {
    color = kilnSample1D(lut1, x.x, a0) + kilnSample2D(lut2, x.xy, a0, a1)
          + kilnSample3D(lut3, x, a0, a1, a2) + kilnSample2DExact(lut2, x.xy, a0, a1)
          + kilnSample3DExact(lut3, x, a0, a1, a2)
          + kilnSample2D(lut2, x.xy, a0, a1, 0.4) + kilnSample2DExact(lut2, x.xy, a0, a1, 0.4)
          + kilnSample3D(lut3, x, a0, a1, a2).r + kilnFresnelAlbedoClosedForm(x.x, x.y, x.z)
          + kilnDielectricAlbedoClosedForm(x.x, x.y, x.z, true)
          + kilnDielectricAlbedoClosedForm(x.x, x.y, x.z, false)
          + kilnDielectricExitClosedForm(x.x, x.y, x.z, true)
          + kilnDielectricExitClosedForm(x.x, x.y, x.z, false)
          + kilnBtdfSplitSum(lut3, x.x, x.y, x.z, 1.0, a0, a1, a2);
}
)";

const char* kHlslMain = R"(
Texture2D<float4> lut1; Texture2D<float4> lut2; Texture2D<float4> lut3; SamplerState linearClamp;
cbuffer Axes { KilnAxis a0; KilnAxis a1; KilnAxis a2; };
float4 main(float3 x : TEXCOORD0) : SV_Target {
    return kilnSample1D(lut1, linearClamp, x.x, a0) + kilnSample2D(lut2, linearClamp, x.xy, a0, a1)
         + kilnSample3D(lut3, linearClamp, x, a0, a1, a2) + kilnSample2DExact(lut2, x.xy, a0, a1)
         + kilnSample3DExact(lut3, x, a0, a1, a2)
         + kilnSample2D(lut2, linearClamp, x.xy, a0, a1, 0.4) + kilnSample2DExact(lut2, x.xy, a0, a1, 0.4)
         + kilnSample3D(lut3, linearClamp, x, a0, a1, a2).r + kilnFresnelAlbedoClosedForm(x.x, x.y, x.z)
         + kilnDielectricAlbedoClosedForm(x.x, x.y, x.z, true)
         + kilnDielectricAlbedoClosedForm(x.x, x.y, x.z, false)
         + kilnDielectricExitClosedForm(x.x, x.y, x.z, true)
         + kilnDielectricExitClosedForm(x.x, x.y, x.z, false)
         + kilnBtdfSplitSum(lut3, linearClamp, x.x, x.y, x.z, 1.0, a0, a1, a2);
}
)";

}  // namespace

TEST_CASE("The GLSL snippet compiles as GLSL ES 3.00 under a mediump default and as GLSL 3.30",
          "[runtime][shaders]") {
  REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
  std::string es =
      "#version 300 es\nprecision mediump float;\n" + Source("kiln_lut.glsl") + kGlslMain;
  Compiled c = Compile(es, ".frag", "-S frag");
  INFO(c.log);
  CHECK(c.exitCode == 0);
  std::string desktop = "#version 330\n" + Source("kiln_lut.glsl") + kGlslMain;
  Compiled d = Compile(desktop, ".frag", "-S frag");
  INFO(d.log);
  CHECK(d.exitCode == 0);
  // The check can fail: a call to a function the snippet does not define is refused.
  CHECK(Compile(desktop + "\nvoid other() { kilnSample4D(); }\n", ".frag", "-S frag").exitCode !=
        0);
}

TEST_CASE("Every float, vector and sampler the GLSL snippet declares is highp",
          "[runtime][shaders]") {
  std::istringstream lines(Source("kiln_lut.glsl"));
  std::regex declaration(R"((^|[^A-Za-z_])(float|vec[234]|ivec2|sampler2D) [A-Za-z_])");
  std::string line;
  int declarations = 0;
  while (std::getline(lines, line)) {
    std::string code = line.substr(0, line.find("//"));
    for (std::sregex_iterator m(code.begin(), code.end(), declaration), end; m != end; ++m) {
      ++declarations;
      size_t at = static_cast<size_t>(m->position(2));
      INFO(line);
      CHECK(at >= 6);
      CHECK(code.compare(at >= 6 ? at - 6 : 0, 6, "highp ") == 0);
    }
  }
  CHECK(declarations > 40);
}

TEST_CASE("The HLSL snippet compiles as a pixel shader", "[runtime][shaders]") {
  REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
  Compiled c = Compile(Source("kiln_lut.hlsl") + kHlslMain, ".hlsl", "-D -V -e main -S frag");
  INFO(c.log);
  CHECK(c.exitCode == 0);
}
