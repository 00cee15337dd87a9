// Specification: the LTC shader snippets (runtime/shaders/kiln_ltc.glsl, kiln_ltc.hlsl) compile
// as an engine would use them: a fragment shader that reads both LTC textures and integrates a
// quad, by glslangValidator as GLSL ES 3.00 under a mediump default, as GLSL 3.30, and the HLSL
// as a Shader Model 5 pixel shader through glslang's HLSL front end.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

#include "cli_util.h"

namespace {

std::string Snippet(const std::string& name) {
  return kiln::test::ReadFile(std::string(KILN_SOURCE_DIR) + "/runtime/shaders/" + name);
}

/// glslangValidator `flags` on `text` (in a temporary file ending in `ext`); its exit code, and
/// what it printed in `log`.
int Compile(const std::string& text, const std::string& ext, const std::string& flags,
            std::string& log) {
  std::string base = "/tmp/kiln_ltc_shader_test_" + std::to_string(getpid());
  std::ofstream(base + ext) << text;
  std::string out = flags.find("-V") != std::string::npos ? " -o " + base + ".spv" : "";
  std::string cmd =
      "glslangValidator " + flags + " " + base + ext + out + " >" + base + ".log 2>&1";
  int status = std::system(cmd.c_str());
  log = kiln::test::ReadFile(base + ".log");
  std::remove((base + ext).c_str());
  std::remove((base + ".spv").c_str());
  std::remove((base + ".log").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const char* kGlslMain = R"(
uniform sampler2D ltc1; uniform sampler2D ltc2;
in vec3 N; in vec3 V; in vec3 P;
out vec4 color;
void main() {
    vec2 uv = kilnLtcUv(0.5, dot(N, V), 64.0);
    mat3 minv = kilnLtcInverse(texture(ltc1, uv), N, V);
    vec2 nf = texture(ltc2, uv).xy;
    float e = kilnLtcQuad(minv, P, P + vec3(1, 0, 0), P + vec3(1, 1, 0), P + vec3(0, 1, 0), true);
    color = vec4(e * (0.04 * nf.x + 0.96 * nf.y));
}
)";

const char* kHlslMain = R"(
Texture2D<float4> ltc1; Texture2D<float4> ltc2; SamplerState linearClamp;
float4 main(float3 N : TEXCOORD0, float3 V : TEXCOORD1, float3 P : TEXCOORD2) : SV_Target {
    float2 uv = kilnLtcUv(0.5, dot(N, V), 64.0);
    float3x3 minv = kilnLtcInverse(ltc1.Sample(linearClamp, uv), N, V);
    float2 nf = ltc2.Sample(linearClamp, uv).xy;
    float e = kilnLtcQuad(minv, P, P + float3(1, 0, 0), P + float3(1, 1, 0), P + float3(0, 1, 0),
                          true);
    return float4(e * (0.04 * nf.x + 0.96 * nf.y), 0, 0, 1);
}
)";

}  // namespace

TEST_CASE("The LTC GLSL snippet compiles as GLSL ES 3.00 (mediump default) and GLSL 3.30",
          "[runtime][shaders][ltc]") {
  REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
  std::string log;
  std::string es =
      "#version 300 es\nprecision mediump float;\n" + Snippet("kiln_ltc.glsl") + kGlslMain;
  int code = Compile(es, ".frag", "-S frag", log);
  INFO(log);
  CHECK(code == 0);
  std::string desktop = "#version 330\n" + Snippet("kiln_ltc.glsl") + kGlslMain;
  code = Compile(desktop, ".frag", "-S frag", log);
  INFO(log);
  CHECK(code == 0);
  // The check can fail: a call to a function the snippet does not define is refused.
  CHECK(Compile(desktop + "\nvoid other() { kilnLtcPentagon(); }\n", ".frag", "-S frag", log) != 0);
}

TEST_CASE("The LTC HLSL snippet compiles as a pixel shader", "[runtime][shaders][ltc]") {
  REQUIRE(std::system("command -v glslangValidator >/dev/null") == 0);
  std::string log;
  int code = Compile(Snippet("kiln_ltc.hlsl") + kHlslMain, ".hlsl", "-D -V -e main -S frag", log);
  INFO(log);
  CHECK(code == 0);
}
