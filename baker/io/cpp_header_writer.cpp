// Embeds a kiln table in a C++ header (Filament embeds its DFG table this way).
#include "baker/io/cpp_header_writer.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "baker/io/atomic_write.h"

namespace kiln {

namespace {

/// Values per line of the data array.
constexpr int kValuesPerLine = 8;

bool isCppKeyword(const std::string& word) {
  static const std::set<std::string> keywords = {"alignas",       "alignof",     "and",
                                                 "and_eq",        "asm",         "auto",
                                                 "bitand",        "bitor",       "bool",
                                                 "break",         "case",        "catch",
                                                 "char",          "char16_t",    "char32_t",
                                                 "char8_t",       "class",       "compl",
                                                 "concept",       "const",       "const_cast",
                                                 "consteval",     "constexpr",   "constinit",
                                                 "continue",      "co_await",    "co_return",
                                                 "co_yield",      "decltype",    "default",
                                                 "delete",        "do",          "double",
                                                 "dynamic_cast",  "else",        "enum",
                                                 "explicit",      "export",      "extern",
                                                 "false",         "float",       "for",
                                                 "friend",        "goto",        "if",
                                                 "inline",        "int",         "long",
                                                 "mutable",       "namespace",   "new",
                                                 "noexcept",      "not",         "not_eq",
                                                 "nullptr",       "operator",    "or",
                                                 "or_eq",         "private",     "protected",
                                                 "public",        "register",    "reinterpret_cast",
                                                 "requires",      "return",      "short",
                                                 "signed",        "sizeof",      "static",
                                                 "static_assert", "static_cast", "struct",
                                                 "switch",        "template",    "this",
                                                 "thread_local",  "throw",       "true",
                                                 "try",           "typedef",     "typeid",
                                                 "typename",      "union",       "unsigned",
                                                 "using",         "virtual",     "void",
                                                 "volatile",      "wchar_t",     "while",
                                                 "xor",           "xor_eq"};
  return keywords.count(word) != 0;
}

/// A C++ string literal for `text` (quotes included); anything outside
/// printable ASCII is written as a 3-digit octal escape.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    const unsigned char byte = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (byte < 0x20 || byte >= 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\%03o", static_cast<unsigned>(byte));
      out += escape;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

/// `text` with line breaks replaced, safe inside a // comment.
std::string commentSafe(std::string text) {
  for (char& ch : text)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return text;
}

/// True when a printed number already reads as floating point.
bool looksFloating(const char* text) {
  for (const char* p = text; *p != '\0'; ++p)
    if (*p == '.' || *p == 'e' || *p == 'E') return true;
  return false;
}

/// A double literal that reads back as exactly `value`.
std::string doubleLiteral(double value) {
  if (std::isnan(value)) return "std::numeric_limits<double>::quiet_NaN()";
  if (std::isinf(value))
    return value > 0 ? "std::numeric_limits<double>::infinity()"
                     : "-std::numeric_limits<double>::infinity()";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return std::string(text) + (looksFloating(text) ? "" : ".0");
}

/// A float literal that reads back as exactly `value` (finite).
std::string floatLiteral(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return std::string(text) + (looksFloating(text) ? "f" : ".0f");
}

std::string warpEnumerator(Warp warp) {
  switch (warp) {
    case Warp::Linear:
      return "kiln::Warp::Linear";
    case Warp::Sqrt:
      return "kiln::Warp::Sqrt";
    case Warp::Square:
      return "kiln::Warp::Square";
    case Warp::Root4:
      return "kiln::Warp::Root4";
    case Warp::Root4Layer:
      return "kiln::Warp::Root4Layer";
    case Warp::Angle:
      return "kiln::Warp::Angle";
    case Warp::LayerEta:
      return "kiln::Warp::LayerEta";
    case Warp::Root4LayerSplit:
      return "kiln::Warp::Root4LayerSplit";
    case Warp::Root4LayerAngle:
      return "kiln::Warp::Root4LayerAngle";
    case Warp::Root4LayerSplit2:
      return "kiln::Warp::Root4LayerSplit2";
    case Warp::Arcsine:
      return "kiln::Warp::Arcsine";
    case Warp::Log:
      return "kiln::Warp::Log";
  }
  throw std::runtime_error("unknown warp");
}

std::string stringArray(const std::vector<std::string>& items) {
  std::string out = "{";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i > 0 ? ", " : "") + quoted(items[i]);
  return out + "}";
}

}  // namespace

std::string cppIdentifier(const std::string& tableName) {
  std::string id;
  for (char ch : tableName) {
    const bool word = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '_';
    const char mapped = word ? ch : '_';
    if (mapped == '_' && !id.empty() && id.back() == '_') continue;
    id += mapped;
  }
  if (id.empty() || id[0] == '_' || (id[0] >= '0' && id[0] <= '9')) id = "t_" + id;
  if (isCppKeyword(id)) id += '_';
  return id;
}

std::string cppHeaderText(const Table& table) {
  std::string problem;
  if (!validateTable(table, problem)) throw std::runtime_error("invalid table: " + problem);
  const std::string id = cppIdentifier(table.name);
  const int dims = table.dims();
  const std::size_t channels = table.channels.size();

  std::vector<std::string> meanings = table.channelMeanings;
  meanings.resize(channels);
  std::vector<std::string> axisNames;
  std::string shape;
  for (const TableAxis& a : table.axes) {
    axisNames.push_back(a.name);
    shape += (shape.empty() ? "" : " x ") + std::to_string(a.axis.size) + " " + a.name;
  }

  std::string h;
  h += "// Generated by kiln from the table " + quoted(table.name) + "; do not edit.\n";
  h += "// " + commentSafe(shape + ", channels " + joinList(table.channels, ',')) + ".\n";
  h += "// Sample it with the kiln runtime core, no OpenEXR needed:\n";
  std::string arguments;
  for (const std::string& name : axisNames) arguments += (arguments.empty() ? "" : ", ") + name;
  h += "//   const double x[" + std::to_string(dims) + "] = {" + commentSafe(arguments) + "};\n";
  h += "//   float out[kiln::baked::" + id + "::kChannels];\n";
  h += "//   kiln::baked::" + id + "::kLut.sample(x, out);  // or (x, out, kiln::Filter::Cubic)\n";
  h += "#pragma once\n\n#include <limits>\n\n#include <kiln/lut.h>\n\n";
  h += "namespace kiln {\nnamespace baked {\nnamespace " + id + " {\n\n";
  h += "inline constexpr int kFormat = " + std::to_string(kFormatVersion) + ";\n";
  h += "inline constexpr const char* kGenerator = " + quoted(table.generator) + ";\n";
  h += "inline constexpr const char* kName = " + quoted(table.name) + ";\n";
  h += "inline constexpr const char* kModel = " + quoted(table.model) + ";\n";
  h += "inline constexpr const char* kQuantity = " + quoted(table.quantity) + ";\n";
  h += "inline constexpr int kChannels = " + std::to_string(channels) + ";\n";
  h += "inline constexpr const char* kChannelNames[kChannels] = " + stringArray(table.channels) +
       ";\n";
  h +=
      "inline constexpr const char* kChannelMeanings[kChannels] = " + stringArray(meanings) + ";\n";
  h += "inline constexpr int kDims = " + std::to_string(dims) + ";\n";
  h += "inline constexpr const char* kAxisNames[kDims] = " + stringArray(axisNames) + ";\n";
  h += "inline constexpr const char* kParams = " + quoted(table.params) + ";\n";
  h += "inline constexpr const char* kMethod = " + quoted(table.method) + ";\n";
  h += "inline constexpr double kTolerance = " + doubleLiteral(table.tolerance) + ";\n";
  h += "inline constexpr double kBakeError = " + doubleLiteral(table.bakeError) + ";\n";
  h += "inline constexpr double kLookupErrorMax = " + doubleLiteral(table.lookupError.max) + ";\n";
  h += "inline constexpr double kLookupErrorRms = " + doubleLiteral(table.lookupError.rms) + ";\n";
  h +=
      "inline constexpr const char* kLookupErrorWhere = " + quoted(table.lookupError.where) + ";\n";
  h += "inline constexpr const char* kLookupErrorFilter = " + quoted(table.lookupError.filter) +
       ";\n";
  h += "inline constexpr const char* kSpecHash = " + quoted(table.specHash) + ";\n\n";

  h += "// Interleaved channels, index ((i2 * size1 + i1) * size0 + i0) * kChannels + c.\n";
  h += "inline constexpr float kData[" + std::to_string(table.data.size()) + "] = {\n";
  for (std::size_t k = 0; k < table.data.size(); ++k) {
    h += (k % kValuesPerLine == 0 ? "    " : " ") + floatLiteral(table.data[k]) + ",";
    if (k % kValuesPerLine == kValuesPerLine - 1 || k + 1 == table.data.size()) h += "\n";
  }
  h += "};\n\n";

  h += "inline constexpr kiln::LutView kLut = {kData, kChannels, kDims, {\n";
  for (int d = 0; d < 3; ++d) {
    Axis a;  // unused axes: a single node
    if (d < dims) a = table.axes[static_cast<std::size_t>(d)].axis;
    h += "    {" + doubleLiteral(a.lo) + ", " + doubleLiteral(a.hi) + ", " +
         std::to_string(a.size) + ", " + warpEnumerator(a.warp) +
         (a.hasConstantSplit() ? ", " + doubleLiteral(a.split) : std::string()) + "}," +
         (d < dims ? "  // " + commentSafe(table.axes[static_cast<std::size_t>(d)].name)
                   : "  // unused") +
         "\n";
  }
  h += "}};\n\n";
  h += "}  // namespace " + id + "\n}  // namespace baked\n}  // namespace kiln\n";
  return h;
}

void writeCppHeader(const std::string& path, const Table& table) {
  PendingFile file(path);
  writeCppHeader(file, table);
  PendingFile::CommitAll({&file});
}

void writeCppHeader(PendingFile& file, const Table& table) {
  std::string text;
  try {
    text = cppHeaderText(table);
  } catch (const std::exception& e) {
    throw std::runtime_error("kiln: cannot write '" + file.Path() + "': " + e.what());
  }
  file.WriteBytes(text);
}

}  // namespace kiln
