#include "baker/fit/fit_writer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace kiln {

namespace {
/// Shading languages the writer emits besides C++.
enum class Dialect { Cpp, Glsl, Hlsl };

/// %.9g of a float: reads back to the same float.
std::string F9(float v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", static_cast<double>(v));
  std::string s = b;
  if (s.find_first_of(".eni") == std::string::npos) s += ".0";
  return s;
}

std::string G3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

/// The Power form's variable t of the clamped value v, in the dialect's syntax (`sq` its sqrt).
std::string PowerVariableText(const FitAxis& a, const std::string& lo, const std::string& sq) {
  const std::string d = PowerSubtractsLo(a) ? "(v - " + lo + ")" : "v";
  const std::string arg = d[0] == '(' ? d : "(" + d + ")";
  if (a.warp == FitWarp::Sqrt) return sq + arg;
  if (a.warp == FitWarp::Root4) return sq + "(" + sq + arg + ")";
  return d;
}

/// The comment block every file starts with (`c` the line comment of the dialect).
std::string Preamble(const FitResult& fit, const std::string& version) {
  const FitForm& f = fit.form;
  std::ostringstream o;
  o << "// kiln fit of table " << f.table << ": a closed form of its exact integrals "
    << "(docs/fits.md).\n";
  o << "// max error E = " << G3(StatedBound(fit.error.max)) << " over the whole declared domain";
  for (size_t d = 0; d < f.axes.size(); ++d)
    o << (d ? " x " : " ") << f.axes[d].name << " in [" << f.axes[d].lo << ", " << f.axes[d].hi
      << "]";
  o << ",\n//   found by kiln's search against the exact integrals (" << fit.error.points
    << " points; worst at";
  for (size_t d = 0; d < f.axes.size(); ++d)
    o << " " << f.axes[d].name << "=" << fit.error.where[d];
  o << "; median " << G3(fit.error.median) << ").\n";
  const bool etaJump = f.axes.size() == 2 && f.axes[1].name == "eta";
  if (fit.error.maxOffJump != fit.error.max && !etaJump)
    o << "// max error off the mirror's jump = " << G3(StatedBound(fit.error.maxOffJump))
      << ": leaving out roughness exactly 0 with mu < 1e-9, where kiln's exact integrals jump\n"
      << "//   from the grazing layer of its smallest alpha (1e-12) to the mirror's values.\n";
  if (fit.error.maxOffJump != fit.error.max && etaJump)
    o << "// max error off the jump = " << G3(StatedBound(fit.error.maxOffJump))
      << ": leaving out eta exactly 1 with mu < 0.02, where F = 0 (no interface) while at\n"
      << "//   the next float, 1 + 2^-23, a grazing layer of width 4.9e-4 rises to 1.\n";
  if (f.basis == FitBasis::Power)
    o << "// form: c0 + t (c1 + t (c2 + ...)) by Horner's rule, t = "
      << PowerVariableText(f.axes[0], F9(static_cast<float>(f.axes[0].lo)), "sqrt")
      << ", v = " << f.axes[0].name << " clamped to its domain.\n";
  o << "// operations: " << f.OperationCount() << " per evaluation of all channels ("
    << f.SqrtCount() << " sqrt), " << f.TermsPerChannel() << " coefficients per channel.\n";
  o << "// source: kiln " << version << ", table " << f.table << ", spec " << fit.specHash
    << "; channels";
  for (const std::string& c : f.channels) o << " " << c;
  o << ".\n// kiln-fit-form: table=" << f.table << " form=" << FitBasisName(f.basis)
    << " spec=" << fit.specHash << " channels=";
  for (size_t c = 0; c < f.channels.size(); ++c) o << (c ? "," : "") << f.channels[c];
  o << " axes=";
  for (size_t d = 0; d < f.axes.size(); ++d) {
    char b[160];
    std::snprintf(b, sizeof b, "%s%s:%.17g:%.17g:%s:%d", d ? "," : "", f.axes[d].name.c_str(),
                  f.axes[d].lo, f.axes[d].hi, FitWarpName(f.axes[d].warp), f.axes[d].degree);
    o << b;
  }
  o << " max-error=" << G3(StatedBound(fit.error.max))
    << " max-error-off-jump=" << G3(StatedBound(fit.error.maxOffJump)) << "\n";
  return o.str();
}

/// The coefficient array c[] in the dialect's syntax.
std::string CoefficientArray(const FitForm& f, Dialect d) {
  const std::string flt = d == Dialect::Cpp ? "f" : "";
  std::ostringstream o;
  const int total = static_cast<int>(f.coefficients.size());
  if (d == Dialect::Glsl)
    o << "  const float c[" << total << "] = float[" << total << "](";
  else
    o << "  static const float c[" << total << "] = {";
  for (int k = 0; k < total; ++k)
    o << (k % 6 ? " " : "\n      ") << F9(f.coefficients[k]) << flt << (k + 1 < total ? "," : "");
  o << (d == Dialect::Glsl ? ");\n" : "};\n");
  return o.str();
}

/// The body of a one-axis Power form: the clamp, t, and per channel Horner's rule
/// c[0] + t * (c[1] + t * (... + t * c[n])), the float steps of EvaluateFit.
std::string PowerBody(const FitForm& f, Dialect d) {
  const std::string flt = d == Dialect::Cpp ? "f" : "";
  const FitAxis& ax = f.axes[0];
  const std::string lo = F9(static_cast<float>(ax.lo)) + flt,
                    hi = F9(static_cast<float>(ax.hi)) + flt;
  std::ostringstream o;
  o << CoefficientArray(f, d);
  o << "  float v = "
    << (d == Dialect::Cpp ? "std::min(std::max(x[0], " + lo + "), " + hi + ")"
                          : "clamp(xa[0], " + lo + ", " + hi + ")")
    << ";\n";
  o << "  float t = " << PowerVariableText(ax, lo, d == Dialect::Cpp ? "std::sqrt" : "sqrt")
    << ";\n";
  const int n = ax.degree + 1;
  for (size_t ch = 0; ch < f.channels.size(); ++ch) {
    const size_t base = ch * n;
    o << "  " << (d == Dialect::Cpp ? "out[" : "o[") << ch << "] = ";
    for (int k = 0; k < n - 1; ++k) o << "c[" << base + k << "] + t * " << (k < n - 2 ? "(" : "");
    o << "c[" << base + n - 1 << "]" << std::string(n - 2, ')') << ";\n";
  }
  return o.str();
}

/// The body shared by the three dialects: warped coordinates, Chebyshev values, sums.
std::string Body(const FitForm& f, Dialect d) {
  if (f.basis == FitBasis::Power) return PowerBody(f, d);
  const std::string flt = d == Dialect::Cpp ? "f" : "";
  auto lit = [&](float v) { return F9(v) + flt; };
  std::ostringstream o;
  const int n0 = f.axes[0].degree + 1, n1 = f.axes.size() == 2 ? f.axes[1].degree + 1 : 1;
  o << CoefficientArray(f, d);
  const std::string sq = d == Dialect::Cpp ? "std::sqrt" : "sqrt";
  for (size_t a = 0; a < f.axes.size(); ++a) {
    const FitAxis& ax = f.axes[a];
    const std::string lo = lit(static_cast<float>(ax.lo)), hi = lit(static_cast<float>(ax.hi)),
                      i = std::to_string(a);
    o << "  float v" << i << " = "
      << (d == Dialect::Cpp ? "std::min(std::max(x[" + i + "], " + lo + "), " + hi + ")"
                            : "clamp(xa[" + i + "], " + lo + ", " + hi + ")")
      << ";\n";
  }
  for (size_t a = 0; a < f.axes.size(); ++a) {
    const FitAxis& ax = f.axes[a];
    const int n = ax.degree + 1;
    const std::string t = "t" + std::to_string(a), lo = lit(static_cast<float>(ax.lo));
    o << "  float " << t << "[" << n << "];\n  {\n";
    o << "    float u = (v" << a << " - " << lo << ") * "
      << lit(static_cast<float>(1.0 / (ax.hi - ax.lo))) << ";\n";
    if (ax.warp == FitWarp::Sqrt) o << "    u = " << sq << "(u);\n";
    if (ax.warp == FitWarp::Root4) o << "    u = " << sq << "(" << sq << "(u));\n";
    const std::string mx = d == Dialect::Cpp ? "std::max" : "max";
    if (ax.warp == FitWarp::Layer)
      o << "    float lc = " << mx << "(v1 * v1, " << lit(1e-12f) << ");\n";
    if (ax.warp == FitWarp::LayerEta)
      o << "    float lc = " << mx << "(" << sq << "(" << (d == Dialect::Cpp ? "std::abs" : "abs")
        << "(v1 * v1 - " << lit(1.0f) << ")), " << lit(4.8828137e-4f) << ");\n";
    if (IsLayerWarp(ax.warp))
      o << "    u = (" << sq << "(" << sq << "(u)) + u * (" << lit(1.0f) << " + lc) / (u + lc)) * "
        << lit(0.5f) << ";\n";
    o << "    float s = u * " << lit(2.0f) << " - " << lit(1.0f) << ";\n";
    o << "    " << t << "[0] = " << lit(1.0f) << ";\n    " << t << "[1] = s;\n";
    o << "    float s2 = s + s;\n";
    o << "    for (int k = 2; k < " << n << "; ++k) " << t << "[k] = s2 * " << t << "[k - 1] - "
      << t << "[k - 2];\n  }\n";
  }
  o << "  for (int ch = 0; ch < " << f.channels.size() << "; ++ch) {\n";
  o << "    float sum = " << lit(0.0f) << ";\n";
  o << "    for (int i = 0; i < " << n0 << "; ++i) {\n";
  if (f.axes.size() == 1) {
    o << "      sum += c[ch * " << n0 << " + i] * t0[i];\n";
  } else {
    o << "      float inner = " << lit(0.0f) << ";\n";
    o << "      for (int j = 0; j < " << n1 << "; ++j) inner += c[(ch * " << n0 << " + i) * " << n1
      << " + j] * t1[j];\n";
    o << "      sum += t0[i] * inner;\n";
  }
  o << "    }\n    " << (d == Dialect::Cpp ? "out[ch]" : "o[ch]") << " = sum;\n  }\n";
  return o.str();
}

/// A shader function: floatN NAME(floatD x) around Body.
std::string Shader(const FitResult& fit, const std::string& version, Dialect d) {
  const FitForm& f = fit.form;
  const size_t nc = f.channels.size(), dims = f.axes.size();
  if (nc > 4) throw std::invalid_argument("fit: shaders take at most 4 channels");
  auto vec = [&](size_t n) {
    if (n == 1) return std::string("float");
    return (d == Dialect::Glsl ? "vec" : "float") + std::to_string(n);
  };
  std::ostringstream o;
  o << Preamble(fit, version);
  o << "// x: " << f.axes[0].name << (dims == 2 ? ", " + f.axes[1].name : "") << "; returns";
  for (const std::string& c : f.channels) o << " " << c;
  o << ".\n" << vec(nc) << " " << FitFunctionName(f.table) << "(" << vec(dims) << " x) {\n";
  o << "  float xa[" << dims << "];\n";
  for (size_t a = 0; a < dims; ++a)
    o << "  xa[" << a << "] = x" << (dims == 1 ? "" : a == 0 ? ".x" : ".y") << ";\n";
  o << "  float o[" << nc << "];\n" << Body(f, d);
  o << "  return " << vec(nc) << "(";
  for (size_t c = 0; c < nc; ++c) o << (c ? ", " : "") << "o[" << c << "]";
  o << ");\n}\n";
  return o.str();
}
}  // namespace

std::string FitFunctionName(const std::string& table) {
  std::string n = "kiln_fit_" + table;
  for (char& ch : n)
    if (ch == '-' || ch == '.') ch = '_';
  return n;
}

double StatedBound(double measured) {
  if (!(measured > 0)) return 0;
  const double scale = std::pow(10.0, std::floor(std::log10(measured)) - 2);
  double b = std::ceil(measured / scale) * scale;
  // The %.3g text must read back to at least the measured value.
  while (std::strtod(G3(b).c_str(), nullptr) < measured) b += scale;
  return std::strtod(G3(b).c_str(), nullptr);
}

std::string FitCppHeader(const FitResult& fit, const std::string& version) {
  std::ostringstream o;
  o << Preamble(fit, version) << "#pragma once\n#include <algorithm>\n#include <cmath>\n\n";
  o << "// x: axis values (";
  for (size_t d = 0; d < fit.form.axes.size(); ++d) o << (d ? ", " : "") << fit.form.axes[d].name;
  o << "); out: channels (";
  for (size_t c = 0; c < fit.form.channels.size(); ++c)
    o << (c ? ", " : "") << fit.form.channels[c];
  o << ").\ninline void " << FitFunctionName(fit.form.table) << "(const float* x, float* out) {\n"
    << Body(fit.form, Dialect::Cpp) << "}\n";
  return o.str();
}

std::string FitGlsl(const FitResult& fit, const std::string& v) {
  return Shader(fit, v, Dialect::Glsl);
}
std::string FitHlsl(const FitResult& fit, const std::string& v) {
  return Shader(fit, v, Dialect::Hlsl);
}

namespace {
/// The value of `key=` in a space-separated form line ("" when absent).
std::string Field(const std::string& line, const std::string& key) {
  size_t p = line.find(" " + key + "=");
  if (p == std::string::npos) return "";
  p += key.size() + 2;
  return line.substr(p, line.find(' ', p) - p);
}

std::vector<std::string> Split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  return out;
}

/// strtod of the whole of `s`, or throws naming the file.
double Number(const std::string& s, const std::string& path) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw std::invalid_argument(path + ": cannot read '" + s + "'");
  return v;
}
}  // namespace

ParsedFit ParseFitHeader(const std::string& text, const std::string& path) {
  const std::string tag = "// kiln-fit-form:";
  const size_t at = text.find(tag);
  if (at == std::string::npos)
    throw std::invalid_argument(path + ": not a kiln fit (no '// kiln-fit-form:' line)");
  const std::string line = text.substr(at + tag.size(), text.find('\n', at) - at - tag.size());
  ParsedFit p;
  p.form.table = Field(line, "table");
  const std::string basis = Field(line, "form");
  p.form.basis = basis.empty() ? FitBasis::Chebyshev : FitBasisFromName(basis);
  p.specHash = Field(line, "spec");
  p.form.channels = Split(Field(line, "channels"), ',');
  p.statedMax = Number(Field(line, "max-error"), path);
  p.statedOffJump = Number(Field(line, "max-error-off-jump"), path);
  for (const std::string& a : Split(Field(line, "axes"), ',')) {
    std::vector<std::string> f = Split(a, ':');
    if (f.size() != 5) throw std::invalid_argument(path + ": cannot read axis '" + a + "'");
    FitAxis axis;
    axis.name = f[0];
    axis.lo = Number(f[1], path);
    axis.hi = Number(f[2], path);
    axis.warp = FitWarpFromName(f[3]);
    axis.degree = static_cast<int>(Number(f[4], path));
    if (axis.degree < 1 || axis.degree > 30 || !(axis.hi > axis.lo))
      throw std::invalid_argument(path + ": axis '" + a + "' out of range");
    p.form.axes.push_back(axis);
  }
  if (p.form.table.empty() || p.form.channels.empty() || p.form.channels.size() > 16 ||
      p.form.axes.empty() || p.form.axes.size() > 2)
    throw std::invalid_argument(path + ": incomplete kiln-fit-form line");
  // The coefficients: the list after "static const float c[N] = {".
  const std::string open = "static const float c[";
  size_t c = text.find(open, at);
  size_t brace = c == std::string::npos ? c : text.find('{', c);
  size_t close = brace == std::string::npos ? brace : text.find('}', brace);
  if (close == std::string::npos) throw std::invalid_argument(path + ": no coefficients");
  for (std::string v : Split(text.substr(brace + 1, close - brace - 1), ',')) {
    v.erase(0, v.find_first_not_of(" \n"));
    v.erase(v.find_last_not_of(" \n") + 1);
    if (!v.empty() && v.back() == 'f') v.pop_back();
    p.form.coefficients.push_back(static_cast<float>(Number(v, path)));
  }
  if (p.form.coefficients.size() != p.form.channels.size() * p.form.TermsPerChannel())
    throw std::invalid_argument(path + ": " + std::to_string(p.form.coefficients.size()) +
                                " coefficients, the form needs " +
                                std::to_string(p.form.channels.size() * p.form.TermsPerChannel()));
  return p;
}

}  // namespace kiln
