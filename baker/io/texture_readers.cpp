#include "baker/io/texture_readers.h"

#include <Imath/half.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "baker/io/bounded_json.h"
#include "baker/io/texture_writers.h"
#include "kiln/exr_loader.h"
#include "kiln/table_checks.h"

namespace kiln {
namespace {

using nlohmann::ordered_json;

/// The most texel values a texture file may declare (the writers' tables are far smaller; this
/// bounds what a hostile header can make the reader allocate: 1 GiB of floats).
constexpr std::uint64_t kMaxValues = std::uint64_t{1} << 28;

/// Where a DDS file's texels start: magic, DDS_HEADER (124 bytes), DDS_HEADER_DXT10 (20 bytes).
constexpr std::uint64_t kDdsDataAt = 148;

/// The most bytes one byte of a zlib stream inflates to (deflate's limit is about 1032).
constexpr std::uint64_t kMaxInflateRatio = 1100;

[[noreturn]] void Bad(const std::string& why) { throw std::invalid_argument(why); }

/// Little-endian reads with bounds checks.
struct Reader {
  const std::string& bytes;
  std::uint32_t U32(std::uint64_t at) const {
    if (at + 4 > bytes.size()) Bad("truncated (a header field at byte " + std::to_string(at) + ")");
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  }
  std::uint64_t U64(std::uint64_t at) const {
    return U32(at) | (static_cast<std::uint64_t>(U32(at + 4)) << 32);
  }
};

std::uint32_t BigEndian32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

ordered_json ParseJson(const std::string& text, const char* where) {
  try {
    return ParseBoundedJson(text);
  } catch (const JsonTextError& e) {
    Bad(std::string(where) + " is " + e.what());
  }
}

/// The integer j[key] (a JSON integer, not a number with a fraction) within int's range.
int GetInt(const ordered_json& j, const char* key) {
  if (!j.contains(key)) Bad(std::string("description has no \"") + key + "\"");
  const ordered_json& v = j.at(key);
  if (!v.is_number_integer())
    Bad(std::string("description's \"") + key + "\" is " + v.dump() + ", not an integer");
  const bool fits = v.is_number_unsigned()
                        ? v.get<std::uint64_t>() <= std::uint64_t{INT_MAX}
                        : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
  if (!fits) Bad(std::string("description's \"") + key + "\" is " + v.dump() + ", out of range");
  return static_cast<int>(v.get<std::int64_t>());
}

/// Refuses a description whose "format" is not the integer kFormatVersion (formatVersionProblem).
void CheckFormatVersion(const ordered_json& j, const char* where) {
  if (!j.is_object() || !j.contains("format") || !j["format"].is_number_integer())
    Bad(std::string(where) + " has no integer \"format\" (the format version)");
  const ordered_json& v = j["format"];
  const long long version =
      v.is_number_unsigned() && v.get<std::uint64_t>() > LLONG_MAX ? LLONG_MAX : v.get<long long>();
  const std::string problem = formatVersionProblem(version);
  if (!problem.empty()) Bad(std::string(where) + ": " + problem);
}

template <class T>
T Get(const ordered_json& j, const char* key) {
  if (!j.contains(key)) Bad(std::string("description has no \"") + key + "\"");
  try {
    return j.at(key).get<T>();
  } catch (const std::exception&) {
    Bad(std::string("description's \"") + key + "\" has the wrong type");
  }
}

/// Checks that the table's axes give `width` x `height` x `depth` texels of `channels` values
/// (a 1D table is N x 1, a 2D table has depth 0 or 1), and that the `need(values)` bytes of texel
/// data those take in the file are no more than the `present` bytes the file holds for them
/// (`what` says where, e.g. "in level 0"), before it sizes the table's data: a header cannot make
/// the reader allocate more than the file could fill.
template <class Need>
void CheckShape(Table& t, std::uint64_t width, std::uint64_t height, std::uint64_t depth,
                std::uint64_t channels, const Need& need, std::uint64_t present,
                const std::string& what) {
  if (channels != t.channels.size())
    Bad("the file holds " + std::to_string(channels) + " channel(s), its description " +
        std::to_string(t.channels.size()));
  const std::uint64_t want[3] = {static_cast<std::uint64_t>(t.size(0)),
                                 static_cast<std::uint64_t>(t.size(1)),
                                 static_cast<std::uint64_t>(t.size(2))};
  if (depth == 0) depth = 1;
  if (width != want[0] || height != want[1] || depth != want[2])
    Bad("the file is " + std::to_string(width) + " x " + std::to_string(height) + " x " +
        std::to_string(depth) + ", its description's axes " + std::to_string(want[0]) + " x " +
        std::to_string(want[1]) + " x " + std::to_string(want[2]));
  const std::uint64_t values = width * height * depth * channels;
  if (width > (1u << 20) || height > (1u << 20) || depth > (1u << 20) || values > kMaxValues)
    Bad("more than 2^28 values");
  const std::uint64_t needBytes = need(values);
  if (needBytes > present)
    Bad("truncated texel data (" + std::to_string(needBytes) + " bytes expected, " +
        std::to_string(present) + " " + what + ")");
  t.data.assign(static_cast<std::size_t>(values), 0.0f);
}

/// Fills t.data from the texels at `at` in file row order (texture_writers.h FileRowOrder),
/// 2-byte halves or 4-byte floats, little-endian.
void ReadTexels(Table& t, const std::string& bytes, std::uint64_t at, bool half) {
  const std::size_t typeSize = half ? 2 : 4;
  const std::size_t need = t.data.size() * typeSize;
  if (at > bytes.size() || bytes.size() - at < need)
    Bad("truncated texel data (" + std::to_string(need) + " bytes expected at byte " +
        std::to_string(at) + ", the file has " + std::to_string(bytes.size()) + ")");
  const std::size_t rowValues = static_cast<std::size_t>(t.size(0)) * t.channels.size();
  std::size_t p = static_cast<std::size_t>(at);
  for (int row : FileRowOrder(t, FlipsY(t))) {
    float* out = t.data.data() + static_cast<std::size_t>(row) * rowValues;
    for (std::size_t v = 0; v < rowValues; ++v, p += typeSize) {
      if (half) {
        ::half h;
        h.setBits(static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[p]) |
                                             (static_cast<unsigned char>(bytes[p + 1]) << 8)));
        out[v] = static_cast<float>(h);
      } else {
        std::uint32_t b = Reader{bytes}.U32(p);
        std::memcpy(&out[v], &b, 4);
      }
    }
  }
}

void Validate(const Table& t) {
  std::string problem;
  if (!validateTable(t, problem)) Bad("invalid table: " + problem);
}

}  // namespace

TableFileKind SniffTableFile(const std::string& b) {
  static const unsigned char kKtx2[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                          0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  static const unsigned char kExr[4] = {0x76, 0x2F, 0x31, 0x01};
  if (b.size() >= 12 && std::memcmp(b.data(), kKtx2, 12) == 0) return TableFileKind::Ktx2;
  if (b.size() >= 8 && std::memcmp(b.data(), kPng, 8) == 0) return TableFileKind::Png;
  if (b.size() >= 4 && std::memcmp(b.data(), "DDS ", 4) == 0) return TableFileKind::Dds;
  if (b.size() >= 4 && std::memcmp(b.data(), kExr, 4) == 0) return TableFileKind::Exr;
  return TableFileKind::Unknown;
}

Table TableFromDescription(const ordered_json& j) {
  if (!j.is_object()) Bad("description is not a JSON object");
  Table t;
  if (j.contains("generator") && j["generator"].is_string()) t.generator = j["generator"];
  t.name = Get<std::string>(j, "name");
  t.model = Get<std::string>(j, "model");
  t.quantity = Get<std::string>(j, "quantity");
  t.channels = Get<std::vector<std::string>>(j, "channels");
  t.channelMeanings = Get<std::vector<std::string>>(j, "channel_meanings");
  const ordered_json& axes = j.contains("axes") ? j["axes"] : ordered_json();
  if (!axes.is_array() || axes.empty() || axes.size() > 3)
    Bad("description's \"axes\" must be an array of 1 to 3 axes");
  for (const ordered_json& a : axes) {
    TableAxis ta;
    ta.name = Get<std::string>(a, "name");
    ta.axis.lo = Get<double>(a, "lo");
    ta.axis.hi = Get<double>(a, "hi");
    ta.axis.size = GetInt(a, "size");
    std::string warp = Get<std::string>(a, "warp");
    if (!warpFromName(warp.c_str(), ta.axis.warp)) Bad("unknown warp '" + warp + "'");
    if (a.contains("split")) ta.axis.split = Get<double>(a, "split");
    t.axes.push_back(ta);
  }
  t.params = Get<std::string>(j, "params");
  t.method = Get<std::string>(j, "method");
  t.tolerance = Get<double>(j, "tolerance");
  t.bakeError = Get<double>(j, "bake_error");
  if (j.contains("lookup_error")) {
    const ordered_json& e = j["lookup_error"];
    t.lookupError.max = Get<double>(e, "max");
    t.lookupError.rms = Get<double>(e, "rms");
    t.lookupError.filter = Get<std::string>(e, "filter");
    t.lookupError.where = Get<std::string>(e, "where");
  }
  if (j.contains("lookup_error_cubic")) {
    t.lookupError.cubicMax = Get<double>(j["lookup_error_cubic"], "max");
    t.lookupError.cubicRms = Get<double>(j["lookup_error_cubic"], "rms");
  }
  t.specHash = Get<std::string>(j, "spec_hash");
  if (j.contains("part")) {  // one part of a table of more than 4 channels
    const ordered_json& part = j["part"];
    t.part.index = Get<int>(part, "index");
    t.part.count = Get<int>(part, "count");
    t.part.tableChannels = Get<std::vector<std::string>>(part, "table_channels");
  }
  // The checks of the EXR loader's header (kiln/table_checks.h), before any texel is allocated.
  const std::string problem = tableHeaderProblem(t);
  if (!problem.empty()) Bad("invalid table: " + problem);
  return t;
}

Table DecodeKtx2(const std::string& bytes) {
  if (SniffTableFile(bytes) != TableFileKind::Ktx2) Bad("not a KTX2 file");
  Reader r{bytes};
  const std::uint32_t vkFormat = r.U32(12), typeSize = r.U32(16);
  const std::uint32_t width = r.U32(20), height = r.U32(24), depth = r.U32(28);
  if (r.U32(32) != 0 || r.U32(36) != 1) Bad("an array or cube texture (kiln writes neither)");
  if (r.U32(40) != 1) Bad("levelCount " + std::to_string(r.U32(40)) + " (kiln writes 1)");
  if (r.U32(44) != 0) Bad("supercompressed (kiln writes none)");
  int channels = 0;
  bool half = false;
  switch (vkFormat) {
    case 76:
    case 83:
    case 90:
    case 97:  // R16_SFLOAT .. R16G16B16A16_SFLOAT
      channels = 1 + static_cast<int>((vkFormat - 76) / 7);
      half = true;
      break;
    case 100:
    case 103:
    case 106:
    case 109:  // R32_SFLOAT .. R32G32B32A32_SFLOAT
      channels = 1 + static_cast<int>((vkFormat - 100) / 3);
      break;
    default:
      Bad("vkFormat " + std::to_string(vkFormat) + " (kiln writes 16/32-bit float R to RGBA)");
  }
  if (typeSize != (half ? 2u : 4u)) Bad("typeSize " + std::to_string(typeSize));
  // Key/value data: find kiln.json.
  const std::uint64_t kvdAt = r.U32(56), kvdLength = r.U32(60);
  if (kvdAt > bytes.size() || bytes.size() - kvdAt < kvdLength) Bad("key/value data out of file");
  std::string json;
  for (std::uint64_t p = kvdAt; p + 4 <= kvdAt + kvdLength;) {
    const std::uint64_t len = r.U32(p);
    if (len > kvdAt + kvdLength - p - 4) Bad("a key/value entry runs past its data");
    const std::string kv = bytes.substr(p + 4, len);
    const std::size_t nul = kv.find('\0');
    if (nul != std::string::npos && kv.compare(0, nul, "kiln.json") == 0) {
      json = kv.substr(nul + 1);
      if (!json.empty() && json.back() == '\0') json.pop_back();
    }
    p += 4 + ((len + 3) / 4) * 4;
  }
  if (json.empty()) Bad("no kiln.json key (not a kiln table)");
  const ordered_json meta = ParseJson(json, "kiln.json");
  CheckFormatVersion(meta, "kiln.json");
  Table t = TableFromDescription(meta);
  const std::uint64_t levelAt = r.U64(80), levelLength = r.U64(88);
  const std::uint64_t levelPresent = levelAt > bytes.size() ? 0 : bytes.size() - levelAt;
  CheckShape(
      t, width, height == 0 ? 1 : height, depth, static_cast<std::uint64_t>(channels),
      [&](std::uint64_t values) { return values * typeSize; }, std::min(levelPresent, levelLength),
      "in level 0");
  if (levelLength != t.data.size() * typeSize)
    Bad("level 0 holds " + std::to_string(levelLength) + " bytes, the texels need " +
        std::to_string(t.data.size() * typeSize));
  ReadTexels(t, bytes, levelAt, half);
  Validate(t);
  return t;
}

Table DecodeDds(const std::string& bytes, const ordered_json& description) {
  if (SniffTableFile(bytes) != TableFileKind::Dds) Bad("not a DDS file");
  Reader r{bytes};
  if (r.U32(4) != 124) Bad("DDS header size " + std::to_string(r.U32(4)) + " (must be 124)");
  const std::uint32_t height = r.U32(12), width = r.U32(16), depth = r.U32(24);
  if (bytes.size() < 128 || bytes.compare(84, 4, "DX10") != 0)
    Bad("no DX10 header (kiln writes DXGI float formats)");
  const std::uint32_t dxgi = r.U32(128), arraySize = r.U32(140);
  if (arraySize != 1) Bad("array size " + std::to_string(arraySize) + " (kiln writes 1)");
  int channels = 0;
  bool half = false;
  switch (dxgi) {
    case 41:
      channels = 1;
      break;  // R32_FLOAT
    case 16:
      channels = 2;
      break;  // R32G32_FLOAT
    case 6:
      channels = 3;
      break;  // R32G32B32_FLOAT
    case 2:
      channels = 4;
      break;  // R32G32B32A32_FLOAT
    case 54:
      channels = 1;
      half = true;
      break;  // R16_FLOAT
    case 34:
      channels = 2;
      half = true;
      break;  // R16G16_FLOAT
    case 10:
      channels = 4;
      half = true;
      break;  // R16G16B16A16_FLOAT
    default:
      Bad("DXGI format " + std::to_string(dxgi) + " (kiln writes R/RG/RGB/RGBA 16/32-bit float)");
  }
  Table t = TableFromDescription(description);
  const std::uint64_t typeSize = half ? 2 : 4;
  CheckShape(
      t, width, height, depth, static_cast<std::uint64_t>(channels),
      [&](std::uint64_t values) { return values * typeSize; },
      bytes.size() < kDdsDataAt ? 0 : bytes.size() - kDdsDataAt, "after the header");
  ReadTexels(t, bytes, kDdsDataAt, half);
  Validate(t);
  return t;
}

Table DecodePng16(const std::string& bytes) {
  if (SniffTableFile(bytes) != TableFileKind::Png) Bad("not a PNG file");
  std::uint32_t width = 0, height = 0;
  int samples = 0;
  std::string idat, json;
  bool ended = false;
  for (std::size_t p = 8; !ended;) {
    if (p + 12 > bytes.size()) Bad("truncated PNG (no IEND chunk)");
    const std::uint32_t len = BigEndian32(bytes, p);
    if (len > bytes.size() - p - 12) Bad("a PNG chunk runs past the file");
    const std::string type = bytes.substr(p + 4, 4);
    const std::string data = bytes.substr(p + 8, len);
    const uLong crc =
        crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data() + p + 4), len + 4);
    if (crc != BigEndian32(bytes, p + 8 + len)) Bad("PNG chunk " + type + " fails its CRC");
    if (type == "IHDR") {
      if (len != 13) Bad("IHDR of " + std::to_string(len) + " bytes");
      width = BigEndian32(data, 0);
      height = BigEndian32(data, 4);
      const int bitDepth = static_cast<unsigned char>(data[8]);
      const int colour = static_cast<unsigned char>(data[9]);
      if (bitDepth != 16) Bad("bit depth " + std::to_string(bitDepth) + " (kiln writes 16)");
      samples = colour == 0 ? 1 : colour == 2 ? 3 : colour == 6 ? 4 : 0;
      if (!samples) Bad("colour type " + std::to_string(colour) + " (kiln writes grey, RGB, RGBA)");
      if (data[12] != 0) Bad("interlaced (kiln writes none)");
    } else if (type == "IDAT") {
      idat += data;
    } else if (type == "tEXt") {
      const std::size_t nul = data.find('\0');
      if (nul != std::string::npos && data.compare(0, nul, "kiln.json") == 0)
        json = data.substr(nul + 1);
    } else if (type == "IEND") {
      ended = true;
    }
    p += 12 + len;
  }
  if (!samples) Bad("no IHDR chunk");
  if (json.empty()) Bad("no kiln.json text chunk (not a kiln table)");
  const ordered_json meta = ParseJson(json, "kiln.json");
  CheckFormatVersion(meta, "kiln.json");
  Table t = TableFromDescription(meta);
  const std::size_t nc = t.channels.size();
  const std::size_t expectSamples = nc == 1 ? 1 : nc == 4 ? 4 : 3;
  if (static_cast<std::size_t>(samples) != expectSamples)
    Bad(std::to_string(samples) + " samples per pixel for " + std::to_string(nc) + " channel(s)");
  if (static_cast<std::uint64_t>(height) !=
      static_cast<std::uint64_t>(t.size(1)) * static_cast<std::uint64_t>(t.size(2)))
    Bad("the image has " + std::to_string(height) + " rows, the axes need " +
        std::to_string(t.size(1) * t.size(2)));
  // Each row is a filter byte and width x samples 16-bit values; no deflate stream inflates by
  // more than kMaxInflateRatio.
  CheckShape(
      t, width, static_cast<std::uint64_t>(t.size(1)), static_cast<std::uint64_t>(t.size(2)), nc,
      [&](std::uint64_t) { return (std::uint64_t{width} * samples * 2 + 1) * height; },
      static_cast<std::uint64_t>(idat.size()) * kMaxInflateRatio,
      "at most from the compressed image data");
  std::vector<double> scale, offset;
  try {
    scale = meta.at("png16").at("scale").get<std::vector<double>>();
    offset = meta.at("png16").at("offset").get<std::vector<double>>();
  } catch (const std::exception&) {
    Bad("kiln.json has no png16 scale and offset");
  }
  if (scale.size() != nc || offset.size() != nc) Bad("png16 scale/offset count != channels");

  // Inflate, then undo the row filters (PNG specification, section 9).
  const std::size_t stride = static_cast<std::size_t>(width) * samples * 2;
  std::vector<std::uint8_t> raw((stride + 1) * height);
  uLongf rawSize = static_cast<uLongf>(raw.size());
  if (uncompress(raw.data(), &rawSize, reinterpret_cast<const Bytef*>(idat.data()),
                 static_cast<uLong>(idat.size())) != Z_OK ||
      rawSize != raw.size())
    Bad("the image data does not inflate to " + std::to_string(raw.size()) + " bytes");
  const std::size_t bpp = static_cast<std::size_t>(samples) * 2;
  std::vector<std::uint8_t> prev(stride, 0), cur(stride);
  const std::vector<int> rows = FileRowOrder(t, FlipsY(t));
  for (std::uint32_t y = 0; y < height; ++y) {
    const std::uint8_t* in = raw.data() + y * (stride + 1);
    const int filter = in[0];
    for (std::size_t x = 0; x < stride; ++x) {
      const int a = x >= bpp ? cur[x - bpp] : 0, b = prev[x], c = x >= bpp ? prev[x - bpp] : 0;
      int pred = 0;
      switch (filter) {
        case 0:
          pred = 0;
          break;
        case 1:
          pred = a;
          break;
        case 2:
          pred = b;
          break;
        case 3:
          pred = (a + b) / 2;
          break;
        case 4: {
          const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
          pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default:
          Bad("row filter " + std::to_string(filter));
      }
      cur[x] = static_cast<std::uint8_t>(in[1 + x] + pred);
    }
    float* out = t.data.data() + static_cast<std::size_t>(rows[y]) * width * nc;
    for (std::uint32_t x = 0; x < width; ++x)
      for (std::size_t ch = 0; ch < nc; ++ch) {
        const std::size_t at = (static_cast<std::size_t>(x) * samples + ch) * 2;
        const double stored = (cur[at] << 8) | cur[at + 1];
        out[x * nc + ch] = static_cast<float>(stored / 65535.0 * scale[ch] + offset[ch]);
      }
    prev.swap(cur);
  }
  Validate(t);
  return t;
}

namespace {

/// The manifest entry `e` (of a whole table) narrowed to its part in `file` when `e` lists the
/// table's parts ("files"): that part's channels, meanings and "part"; `e` itself otherwise.
ordered_json PartDescription(const ordered_json& e, const std::string& file) {
  if (!e.contains("files") || !e["files"].is_array() || e["files"].size() < 2) return e;
  const ordered_json& files = e["files"];
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (files[i] != file) continue;
    const Table whole = TableFromDescription(e);
    const Table part = tablePart(whole, static_cast<int>(i) + 1);
    ordered_json out = e;
    out["channels"] = part.channels;
    out["channel_meanings"] = part.channelMeanings;
    out["part"] = {{"index", part.part.index},
                   {"count", part.part.count},
                   {"table_channels", part.part.tableChannels}};
    return out;
  }
  return e;
}

/// Whether the manifest entry `e` describes `file` (its "file", or one of its "files").
bool EntryNames(const ordered_json& e, const std::string& file) {
  if (!e.is_object()) return false;
  if (e.contains("file") && e["file"] == file) return true;
  if (!e.contains("files") || !e["files"].is_array()) return false;
  for (const ordered_json& f : e["files"])
    if (f == file) return true;
  return false;
}

/// LoadAnyTable of one file: a part of a wider table comes back as that part (EXR: whole).
Table LoadOneFile(const std::string& path) {
  auto fail = [&](const std::string& why) {
    return std::runtime_error("cannot read '" + path + "': " + why);
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) return loadTable(path);  // its message names the problem (missing, unreadable)
  char head[12] = {};
  in.read(head, sizeof head);
  const TableFileKind kind = SniffTableFile(std::string(head, static_cast<size_t>(in.gcount())));
  if (kind == TableFileKind::Exr || kind == TableFileKind::Unknown) return loadTable(path);
  in.clear();  // a file shorter than the 12 bytes read ended the stream
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw fail("cannot tell its size");
  if (static_cast<std::uint64_t>(size) > kMaxValues * 4 + (64u << 20))
    throw fail("larger than any table kiln writes");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(bytes.data(), size);
  if (in.gcount() != size) throw fail("short read");
  try {
    if (kind == TableFileKind::Ktx2) return DecodeKtx2(bytes);
    if (kind == TableFileKind::Png) return DecodePng16(bytes);
    // DDS: the description is manifest.json's entry for this file, in the same folder.
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
    const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::string manifestPath = dir + "/manifest.json";
    if (access(manifestPath.c_str(), F_OK) != 0 && errno == ENOENT)
      throw fail("a DDS file carries no description; manifest.json must be beside it");
    std::shared_ptr<const ordered_json> parsed;
    try {
      parsed = ReadJsonFileCached(manifestPath);  // parsed once for all the DDS files of a run
    } catch (const JsonTextError& e) {
      throw fail(manifestPath + " is " + e.what());
    } catch (const std::runtime_error& e) {
      throw fail(e.what());
    }
    const ordered_json& manifest = *parsed;
    CheckFormatVersion(manifest, "manifest.json");
    if (manifest.contains("tables") && manifest["tables"].is_array())
      for (const ordered_json& e : manifest["tables"])
        if (EntryNames(e, file)) {
          ordered_json entry = PartDescription(e, file);
          if (!entry.contains("generator") && manifest.contains("generator"))
            entry["generator"] = manifest["generator"];
          return DecodeDds(bytes, entry);
        }
    throw fail("manifest.json beside it has no entry for '" + file + "'");
  } catch (const std::invalid_argument& e) {
    throw fail(e.what());
  }
}

}  // namespace

Table LoadAnyTable(const std::string& path) {
  Table table = LoadOneFile(path);
  if (table.part.count < 2) return table;
  std::vector<Table> parts;
  try {
    for (int other = 1; other <= table.part.count; ++other)
      if (other != table.part.index)
        parts.push_back(LoadOneFile(tableSiblingPartPath(path, table.part.index, other)));
    parts.push_back(std::move(table));
    return mergeTableParts(parts);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("cannot read '" + path + "': " + e.what());
  }
}

}  // namespace kiln
