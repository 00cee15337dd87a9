#include "baker/scene/scene_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "baker/io/bounded_json.h"

namespace kiln {

std::string PointerChild(const std::string& parent, const std::string& token) {
  std::string escaped;
  for (char c : token) {
    if (c == '~')
      escaped += "~0";
    else if (c == '/')
      escaped += "~1";
    else
      escaped += c;
  }
  return parent + "/" + escaped;
}

std::string PointerChild(const std::string& parent, size_t index) {
  return parent + "/" + std::to_string(index);
}

namespace {

/// Builds the document as Json::parse does, and remembers where the parser stopped and on which
/// token when it fails: only parse_error carries its byte, not out_of_range (a number that
/// overflows a double).
class PlacedDomParser : public nlohmann::detail::json_sax_dom_parser<Json> {
 public:
  using json_sax_dom_parser::json_sax_dom_parser;
  size_t position = 0;  ///< bytes read when the parser failed, 0 when it did not
  std::string token;    ///< the last token read then

  template <class Exception>
  bool parse_error(size_t pos, const std::string& lastToken, const Exception& ex) {
    position = pos;
    token = lastToken;
    return json_sax_dom_parser::parse_error(pos, lastToken, ex);
  }
};

}  // namespace

Json ParseSceneJson(const std::string& text, const std::string& file, const std::string& prefix) {
  size_t deep = JsonTooDeepAt(text, kMaxSceneDepth);
  if (deep != std::string::npos)
    throw SceneError(file, prefix + JsonLineColumn(text, deep),
                     "nested deeper than " + std::to_string(kMaxSceneDepth) + " levels");
  Json doc;
  PlacedDomParser parser(doc);
  try {
    Json::sax_parse(text, &parser);
    return doc;
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character. nlohmann's message is
    // "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error while
    // parsing value - invalid literal; last read: 'x'": keep what follows the position.
    size_t end = e.byte == 0 ? 0 : std::min(text.size(), static_cast<size_t>(e.byte - 1));
    std::string detail = JsonErrorDetail(e.what());
    size_t colon = detail.find(": ");
    if (colon != std::string::npos) detail = detail.substr(colon + 2);
    throw SceneError(file, prefix + JsonLineColumn(text, end), "not valid JSON (" + detail + ")");
  } catch (const Json::exception& e) {
    // Valid JSON kiln cannot hold, e.g. "[json.exception.out_of_range.406] number overflow
    // parsing '1e999'": placed at the start of the token when the parser said where it stopped.
    std::string place;
    if (parser.position > 0)
      place = prefix + JsonLineColumn(
                           text, parser.position - std::min(parser.position, parser.token.size()));
    throw SceneError(file, place, "cannot be read (" + JsonErrorDetail(e.what()) + ")");
  }
}

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;  // "glTF"

uint32_t LittleU32(const char* b) {
  return static_cast<uint32_t>(static_cast<unsigned char>(b[0])) |
         static_cast<uint32_t>(static_cast<unsigned char>(b[1])) << 8 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[2])) << 16 |
         static_cast<uint32_t>(static_cast<unsigned char>(b[3])) << 24;
}

/// A glb larger than the cap (its binary chunk holds meshes and images): its 12-byte header and
/// JSON chunk, with the header's length set to what is returned, so that GlbJsonChunk reads it
/// as it would the whole file. Empty when the file is no such glb or its JSON chunk is too large.
std::string LargeGlbJson(std::ifstream& in, uint64_t fileSize) {
  char head[20];
  in.clear();
  in.seekg(0);
  if (!in.read(head, 20) || LittleU32(head) != kGlbMagic || LittleU32(head + 8) != fileSize)
    return "";
  uint32_t chunkLength = LittleU32(head + 12);
  if (chunkLength > kMaxSceneBytes || chunkLength > fileSize - 20) return "";
  std::string out(head, 20);
  out.resize(20 + size_t{chunkLength});
  if (!in.read(&out[20], chunkLength)) return "";
  uint32_t length = 20 + chunkLength;
  for (int i = 0; i < 4; ++i) out[8 + i] = static_cast<char>((length >> (8 * i)) & 0xFF);
  return out;
}

}  // namespace

std::string ReadSceneFile(const std::string& path) {
  std::error_code ec;
  std::filesystem::file_status status = std::filesystem::status(path, ec);
  // A folder on the way that cannot be searched, a loop of links: said as it is, not "missing".
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    throw SceneError(path, "", "cannot access the file (" + ec.message() + ")");
  if (std::filesystem::is_directory(status))
    throw SceneError(path, "", "is a folder, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", "cannot open the file");
  const std::string tooLarge = "larger than " + std::to_string(kMaxSceneBytes >> 20) +
                               " MiB, the most kiln reads of a scene";
  if (std::filesystem::is_regular_file(status)) {
    uint64_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxSceneBytes) {
      std::string glb = LargeGlbJson(in, size);
      if (glb.empty()) throw SceneError(path, "", tooLarge);
      return glb;
    }
  }
  // A bounded read, also for what stat cannot size (a device such as /dev/zero, a pipe): at most
  // the cap, then one byte more says the file is larger.
  std::string bytes;
  char buffer[65536];
  while (in && bytes.size() < kMaxSceneBytes) {
    in.read(buffer,
            static_cast<std::streamsize>(std::min(sizeof buffer, kMaxSceneBytes - bytes.size())));
    bytes.append(buffer, static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) throw SceneError(path, "", "cannot read the file");
  if (in && in.peek() != std::ifstream::traits_type::eof()) throw SceneError(path, "", tooLarge);
  return bytes;
}

std::string JsonKind(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

std::string ShortNumber(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string ExactNumber(double x) {
  char buf[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

void JsonReader::Fail(const std::string& at, const std::string& problem) const {
  throw SceneError(file, at.empty() ? "/" : at, problem);
}

const Json& JsonReader::Object(const Json& v, const std::string& at) const {
  if (!v.is_object()) Fail(at, "expected an object, got " + JsonKind(v));
  return v;
}

const Json& JsonReader::Array(const Json& v, const std::string& at) const {
  if (!v.is_array()) Fail(at, "expected an array, got " + JsonKind(v));
  return v;
}

double JsonReader::Number(const Json& v, const std::string& at) const {
  if (!v.is_number()) Fail(at, "expected a number, got " + JsonKind(v));
  double x = v.get<double>();
  if (!std::isfinite(x)) Fail(at, "expected a finite number");
  return x;
}

std::string JsonReader::String(const Json& v, const std::string& at) const {
  if (!v.is_string()) Fail(at, "expected a string, got " + JsonKind(v));
  return v.get<std::string>();
}

size_t JsonReader::Index(const Json& v, const std::string& at, size_t count,
                         const std::string& what) const {
  if (!v.is_number_integer() && !v.is_number_unsigned())
    Fail(at, "expected an index (an integer), got " + JsonKind(v));
  long long i = v.is_number_unsigned() ? static_cast<long long>(v.get<unsigned long long>())
                                       : v.get<long long>();
  if (i < 0) Fail(at, "index " + std::to_string(i) + " is negative");
  if (static_cast<unsigned long long>(i) >= count)
    Fail(at, what + " " + std::to_string(i) + " does not exist (the file has " +
                 std::to_string(count) + " " + what + (count == 1 ? "" : "s") + ")");
  return static_cast<size_t>(i);
}

const Json* JsonReader::Find(const Json& obj, const std::string& key) {
  if (!obj.is_object()) return nullptr;
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

double JsonReader::NumberIn(const Json& obj, const std::string& at, const std::string& key,
                            double def, double lo, double hi) const {
  const Json* v = Find(obj, key);
  if (!v) return def;
  std::string p = PointerChild(at, key);
  double x = Number(*v, p);
  if (x < lo || x > hi)
    Fail(p, ExactNumber(x) + " is outside [" + ExactNumber(lo) + ", " + ExactNumber(hi) + "]");
  return x;
}

const Json& JsonReader::ArrayOrEmpty(const Json& obj, const std::string& at,
                                     const std::string& key) const {
  static const Json empty = Json::array();
  const Json* v = Find(obj, key);
  return v ? Array(*v, PointerChild(at, key)) : empty;
}

}  // namespace kiln
