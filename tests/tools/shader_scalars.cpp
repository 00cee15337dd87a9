// shader_scalars: writes the scalar part of a kiln shader snippet (runtime/shaders/kiln_lut.glsl
// or .hlsl) as C++ in float, so that tests/runtime_shader_scalars.cpp can evaluate the very
// functions an engine compiles (the warps, the Fresnel terms, the stored forms' closed forms)
// against kiln/lut.h and kiln/stored.h. Usage: shader_scalars NAMESPACE SNIPPET > HEADER.
//
// What it does: drops comments; splits the text into top-level items (a preprocessor line, a
// declaration ending in ';', a function or struct ending at its closing brace); keeps the items
// that use no vector, matrix, texture or sampler type; removes precision qualifiers, turns a GLSL
// array constructor `float[N](...)` into a brace initializer and every floating literal into a
// float literal (GLSL highp and HLSL float are 32-bit), and wraps the rest in a namespace with
// the built-ins it calls (clamp, min, max, sqrt, ...) defined for float.
#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string StripComments(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
      out += '\n';
    } else if (s.compare(i, 2, "/*") == 0) {
      const std::size_t end = s.find("*/", i + 2);
      i = end == std::string::npos ? s.size() : end + 1;
    } else {
      out += s[i];
    }
  }
  return out;
}

/// Top-level items: preprocessor lines, and text up to a ';' or a closing '}' at depth 0 (a
/// following ';', as after a struct, belongs to the item).
std::vector<std::string> Items(const std::string& s) {
  std::vector<std::string> items;
  std::string cur;
  int depth = 0, parens = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (depth == 0 && parens == 0 && c == '#' &&
        cur.find_first_not_of(" \t\n\r") == std::string::npos) {
      const std::size_t end = s.find('\n', i);
      items.push_back(s.substr(i, end - i));
      i = end == std::string::npos ? s.size() : end;
      cur.clear();
      continue;
    }
    cur += c;
    if (c == '(') ++parens;
    if (c == ')') --parens;
    if (c == '{') ++depth;
    if (c == '}' && --depth == 0) {
      std::size_t j = i + 1;
      while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
      if (j < s.size() && s[j] == ';') {
        cur += ';';
        i = j;
      }
      items.push_back(cur);
      cur.clear();
    } else if (c == ';' && depth == 0 && parens == 0) {
      items.push_back(cur);
      cur.clear();
    }
  }
  return items;
}

bool IsIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool UsesVectorTypes(const std::string& item) {
  std::string word;
  for (std::size_t i = 0; i <= item.size(); ++i) {
    const char c = i < item.size() ? item[i] : ' ';
    if (IsIdent(c)) {
      word += c;
      continue;
    }
    if (!word.empty()) {
      for (const char* t : {"vec", "ivec", "uvec", "bvec", "mat", "sampler", "Texture", "texture",
                            "SamplerState", "float2", "float3", "float4", "int2", "int3", "int4",
                            "precision", "textureLod", "texelFetch"})
        if (word.rfind(t, 0) == 0) return true;
      word.clear();
    }
  }
  return false;
}

/// Removes highp/mediump/lowp, `float[N](a, b)` -> `{a, b}`, and suffixes floating literals with f.
std::string ToCpp(const std::string& item) {
  std::string s;
  for (std::size_t i = 0; i < item.size();) {
    bool replaced = false;
    for (const char* q : {"highp ", "mediump ", "lowp "}) {
      const std::size_t n = std::string(q).size();
      if (item.compare(i, n, q) == 0 && (i == 0 || !IsIdent(item[i - 1]))) {
        i += n;
        replaced = true;
      }
    }
    if (replaced) continue;
    if (item.compare(i, 6, "float[") == 0 && (i == 0 || !IsIdent(item[i - 1]))) {
      const std::size_t open = item.find('(', i);
      int depth = 0;
      std::size_t close = open;
      for (; close < item.size(); ++close) {
        if (item[close] == '(') ++depth;
        if (item[close] == ')' && --depth == 0) break;
      }
      s += "{" + ToCpp(item.substr(open + 1, close - open - 1)) + "}";
      i = close + 1;
      continue;
    }
    const char c = item[i];
    if (std::isdigit(static_cast<unsigned char>(c)) &&
        (i == 0 || (!IsIdent(item[i - 1]) && item[i - 1] != '.'))) {
      std::size_t j = i;
      bool floating = false;
      while (j < item.size() && std::isdigit(static_cast<unsigned char>(item[j]))) ++j;
      if (j < item.size() && item[j] == '.') {
        floating = true;
        ++j;
        while (j < item.size() && std::isdigit(static_cast<unsigned char>(item[j]))) ++j;
      }
      if (j < item.size() && (item[j] == 'e' || item[j] == 'E')) {
        floating = true;
        ++j;
        if (j < item.size() && (item[j] == '+' || item[j] == '-')) ++j;
        while (j < item.size() && std::isdigit(static_cast<unsigned char>(item[j]))) ++j;
      }
      s += item.substr(i, j - i);
      if (floating && !(j < item.size() && (item[j] == 'f' || item[j] == 'F'))) s += 'f';
      i = j;
      continue;
    }
    s += c;
    ++i;
  }
  return s;
}

const char* kBuiltins =
    R"(inline float clamp(float x, float a, float b) { return std::min(std::max(x, a), b); }
inline float saturate(float x) { return clamp(x, 0.0f, 1.0f); }
inline float min(float a, float b) { return std::min(a, b); }
inline float max(float a, float b) { return std::max(a, b); }
inline float abs(float x) { return std::fabs(x); }
inline float sqrt(float x) { return std::sqrt(x); }
inline float rsqrt(float x) { return 1.0f / std::sqrt(x); }
inline float inversesqrt(float x) { return 1.0f / std::sqrt(x); }
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float tan(float x) { return std::tan(x); }
inline float asin(float x) { return std::asin(x); }
inline float acos(float x) { return std::acos(x); }
inline float atan(float x) { return std::atan(x); }
inline float atan(float y, float x) { return std::atan2(y, x); }
inline float atan2(float y, float x) { return std::atan2(y, x); }
inline float log(float x) { return std::log(x); }
inline float exp(float x) { return std::exp(x); }
inline float pow(float x, float y) { return std::pow(x, y); }
inline float floor(float x) { return std::floor(x); }
)";

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: shader_scalars NAMESPACE SNIPPET\n";
    return 2;
  }
  std::ifstream in(argv[2]);
  if (!in) {
    std::cerr << "shader_scalars: cannot read " << argv[2] << "\n";
    return 1;
  }
  std::stringstream text;
  text << in.rdbuf();
  std::cout << "// Generated by tests/tools/shader_scalars.cpp from " << argv[2]
            << ": do not edit.\n#pragma once\n#include <algorithm>\n#include <cmath>\n"
            << "namespace " << argv[1] << " {\n"
            << kBuiltins;
  int kept = 0;
  for (const std::string& item : Items(StripComments(text.str()))) {
    if (item.find_first_not_of(" \t\n\r") == std::string::npos || UsesVectorTypes(item)) continue;
    std::cout << ToCpp(item) << "\n";
    ++kept;
  }
  std::cout << "}  // namespace " << argv[1] << "\n";
  return kept > 0 ? 0 : 1;
}
