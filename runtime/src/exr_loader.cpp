// Reads a kiln table from an OpenEXR file, checking every kiln.* attribute.
#include "kiln/exr_loader.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "kiln/table_checks.h"

namespace kiln {

namespace {

/// A reason to refuse the file; the message is the problem, without the path.
struct Refusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Replaces line breaks so that a message stays on one line.
std::string oneLine(std::string text) {
  for (char& ch : text)
    if (ch == '\n' || ch == '\r') ch = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

/// The attribute `name` of type T, or null when absent; throws when present
/// with another type.
template <class T>
const T* findAttribute(const Imf::Header& header, const std::string& name, const char* typeName) {
  if (header.find(name) == header.end()) return nullptr;
  const T* attribute = header.findTypedAttribute<T>(name);
  if (attribute == nullptr)
    throw Refusal("attribute " + name + " is not of type " + std::string(typeName));
  return attribute;
}

template <class T>
const T& requireAttribute(const Imf::Header& header, const std::string& name,
                          const char* typeName) {
  const T* attribute = findAttribute<T>(header, name, typeName);
  if (attribute == nullptr)
    throw Refusal("missing attribute " + name + " (" + std::string(typeName) + ")");
  return *attribute;
}

std::string requireString(const Imf::Header& h, const std::string& name) {
  return requireAttribute<Imf::StringAttribute>(h, name, "string").value();
}

int requireInt(const Imf::Header& h, const std::string& name) {
  return requireAttribute<Imf::IntAttribute>(h, name, "int").value();
}

double requireDouble(const Imf::Header& h, const std::string& name) {
  return requireAttribute<Imf::DoubleAttribute>(h, name, "double").value();
}

std::string optionalString(const Imf::Header& h, const std::string& name) {
  const auto* a = findAttribute<Imf::StringAttribute>(h, name, "string");
  return a != nullptr ? a->value() : std::string();
}

double optionalDouble(const Imf::Header& h, const std::string& name, double fallback) {
  const auto* a = findAttribute<Imf::DoubleAttribute>(h, name, "double");
  return a != nullptr ? a->value() : fallback;
}

/// Refuses paths that do not name a readable, non-empty regular file.
void checkReadableFile(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  // An error other than "no such file" (a folder on the way that cannot be searched, a loop of
  // symbolic links, a name too long) is reported as it is.
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    throw Refusal("cannot access the file (" + ec.message() + ")");
  if (!std::filesystem::exists(status)) throw Refusal("no such file");
  if (!std::filesystem::is_regular_file(status)) throw Refusal("not a regular file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw Refusal("cannot open the file for reading");
  if (stream.peek() == std::ifstream::traits_type::eof()) throw Refusal("the file is empty");
}

/// Fills `table.part` from kiln.part, kiln.parts and kiln.table_channels (all three or none):
/// part `i` of `n` parts of a table whose channels are kiln.table_channels, of which this file
/// holds kiln.channels (channels 4 (i - 1) .. of the whole table).
void readPartAttributes(const Imf::Header& h, Table& table) {
  if (h.find("kiln.part") == h.end()) return;
  const int index = requireInt(h, "kiln.part");
  const int count = requireInt(h, "kiln.parts");
  const std::vector<std::string> whole = splitList(requireString(h, "kiln.table_channels"), ',');
  if (count != tablePartCount(whole.size()) || count < 2 || index < 1 || index > count)
    throw Refusal("kiln.part " + std::to_string(index) + " of kiln.parts " + std::to_string(count) +
                  " does not fit kiln.table_channels '" + joinList(whole, ',') + "' (" +
                  std::to_string(kMaxChannelsPerFile) + " channels a part)");
  const std::size_t first = static_cast<std::size_t>(index - 1) * kMaxChannelsPerFile;
  const std::size_t last = std::min(whole.size(), first + kMaxChannelsPerFile);
  if (std::vector<std::string>(whole.begin() + first, whole.begin() + last) != table.channels)
    throw Refusal("part " + std::to_string(index) + " holds channels '" +
                  joinList(table.channels, ',') + "', kiln.table_channels '" +
                  joinList(whole, ',') + "' gives it others");
  table.part = TablePart{index, count, whole};
}

/// Fills every metadata field of `table` from the kiln.* attributes.
void readAttributes(const Imf::Header& h, Table& table) {
  if (h.find("kiln.format") == h.end())
    throw Refusal("not a kiln table (no kiln.format attribute)");
  const std::string formatIssue = formatVersionProblem(requireInt(h, "kiln.format"));
  if (!formatIssue.empty()) throw Refusal(formatIssue);

  table.generator = optionalString(h, "kiln.generator");
  table.name = requireString(h, "kiln.name");
  table.model = optionalString(h, "kiln.model");
  table.quantity = optionalString(h, "kiln.quantity");
  table.channels = splitList(requireString(h, "kiln.channels"), ',');
  table.channelMeanings = splitList(optionalString(h, "kiln.channel_meanings"), ';');

  const int dims = requireInt(h, "kiln.dims");
  if (dims < 1 || dims > 3)
    throw Refusal("kiln.dims is " + std::to_string(dims) + ", must be 1, 2 or 3");
  table.axes.assign(static_cast<std::size_t>(dims), TableAxis{});
  for (int d = 0; d < dims; ++d) {
    const std::string prefix = "kiln.axis" + std::to_string(d) + ".";
    TableAxis& a = table.axes[static_cast<std::size_t>(d)];
    a.name = requireString(h, prefix + "name");
    a.axis.lo = requireDouble(h, prefix + "lo");
    a.axis.hi = requireDouble(h, prefix + "hi");
    a.axis.size = requireInt(h, prefix + "size");
    const std::string warp = requireString(h, prefix + "warp");
    if (!warpFromName(warp.c_str(), a.axis.warp))
      throw Refusal(
          prefix + "warp is '" + warp +
          "', not one of linear, sqrt, square, log, root4, root4-layer, angle, layer-eta, "
          "root4-layer-split, root4-layer-angle, root4-layer-split2, arcsine");
    // A constant split point of a root4-layer-split axis; absent: NaN, the critical cosine.
    a.axis.split = optionalDouble(h, prefix + "split", std::numeric_limits<double>::quiet_NaN());
  }

  table.params = optionalString(h, "kiln.params");
  table.method = optionalString(h, "kiln.method");
  table.tolerance = optionalDouble(h, "kiln.tolerance", 0.0);
  table.bakeError = optionalDouble(h, "kiln.bake_error", -1.0);
  table.lookupError.max = optionalDouble(h, "kiln.lookup_error.max", -1.0);
  table.lookupError.rms = optionalDouble(h, "kiln.lookup_error.rms", -1.0);
  table.lookupError.where = optionalString(h, "kiln.lookup_error.where");
  table.lookupError.filter = optionalString(h, "kiln.lookup_error.filter");
  table.lookupError.cubicMax = optionalDouble(h, "kiln.lookup_error.cubic_max", -1.0);
  table.lookupError.cubicRms = optionalDouble(h, "kiln.lookup_error.cubic_rms", -1.0);
  table.specHash = optionalString(h, "kiln.spec_hash");
  table.fitError.max = optionalDouble(h, "kiln.fit_error.max", -1.0);
  table.fitError.rms = optionalDouble(h, "kiln.fit_error.rms", -1.0);
  table.fitError.polygonMax = optionalDouble(h, "kiln.fit_error.polygon_max", -1.0);
  table.fitError.polygonRms = optionalDouble(h, "kiln.fit_error.polygon_rms", -1.0);
  table.fitError.method = optionalString(h, "kiln.fit_error.method");
  readPartAttributes(h, table);
  // The checks every table file's header goes through (KTX2, DDS and PNG readers too).
  const std::string headerIssue = tableHeaderProblem(table);
  if (!headerIssue.empty()) throw Refusal(headerIssue);
}

/// Checks the image's channels and returns the EXR channel name of each storage channel, in the
/// first of the namings that matches the image's channel list exactly: exrFileChannels (Y; R, G,
/// B with B unused; R, G, B; R, G, B, A), the first `n` of R, G, B, A (files of layout 1 named
/// so), or kiln.channels itself (older files); anything else is refused. Each channel must be
/// FLOAT or HALF and not subsampled.
std::vector<std::string> checkChannels(const Imf::ChannelList& list,
                                       const std::vector<std::string>& expected) {
  std::set<std::string> inFile;
  std::string inFileText;
  for (auto it = list.begin(); it != list.end(); ++it) {
    inFile.insert(it.name());
    inFileText += (inFileText.empty() ? "" : ",") + std::string(it.name());
  }
  const std::set<std::string> declared(expected.begin(), expected.end());
  const std::vector<std::string> fileNames = exrFileChannels(expected.size());
  const std::vector<std::string> storage = exrChannelNames(expected.size());
  const std::vector<std::string> rgba = exrLayout1ChannelNames(expected.size());
  auto isList = [&](const std::vector<std::string>& names) {
    return !names.empty() && inFile == std::set<std::string>(names.begin(), names.end());
  };
  std::vector<std::string> names;
  if (isList(fileNames))
    names = storage;
  else if (isList(rgba))
    names = rgba;
  else if (!expected.empty() && declared.size() == expected.size() && inFile == declared)
    names = expected;
  else
    throw Refusal("channel mismatch: kiln.channels is '" + joinList(expected, ',') +
                  "' but the image has channels '" + inFileText + "' (expected '" +
                  joinList(fileNames, ',') + "', '" + joinList(rgba, ',') +
                  "' or the kiln.channels names)");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Imf::Channel& channel = it.channel();
    if (channel.type != Imf::FLOAT && channel.type != Imf::HALF)
      throw Refusal("channel '" + std::string(it.name()) +
                    "' is UINT; only FLOAT and HALF are read");
    if (channel.xSampling != 1 || channel.ySampling != 1)
      throw Refusal("channel '" + std::string(it.name()) + "' is subsampled");
  }
  return names;
}

/// Little-endian int32 at `p`.
std::int32_t int32At(const unsigned char* p) {
  return static_cast<std::int32_t>(std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 |
                                   std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24);
}

/// The largest header the loader reads (kiln headers are a few KB).
constexpr std::int64_t kMaxHeaderBytes = std::int64_t{4} << 20;

/// What the header walk learns for the bounds checked before OpenEXR allocates anything.
struct HeaderFacts {
  bool haveWindow = false;
  std::int64_t minX = 0, minY = 0, maxX = 0, maxY = 0;  ///< dataWindow
  int compression = 0;                                  ///< NO_COMPRESSION when absent
  std::int64_t bytesPerPixel = 0;                       ///< sum over the channels
  std::int64_t headerEnd = 0;                           ///< offset just past the header
  std::int64_t fileSize = 0;
};

/// The exact value size of OpenEXR's fixed-size attribute types; -1 for the others.
std::int64_t fixedAttributeSize(const std::string& type) {
  static const std::pair<const char*, std::int64_t> sizes[] = {
      {"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
      {"compression", 1}, {"double", 8},   {"envmap", 1},
      {"float", 4},       {"int", 4},      {"keycode", 28},
      {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
      {"m44f", 64},       {"m44d", 128},   {"rational", 8},
      {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
      {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
      {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
  for (const auto& entry : sizes)
    if (type == entry.first) return entry.second;
  return -1;
}

/// Walks the header (OpenEXR file layout: magic, version word, then a list of name\0 type\0
/// int32-size value, ended by an empty name) and refuses, from the bytes that are there, every
/// header OpenEXR 3.1 would allocate for before failing: it allocates an attribute's declared
/// size (up to 2 GB, strings filled), reads a channel list or a fixed-size value regardless of the
/// declared size (so that the next attribute it reads is not the one this walk sees), allocates
/// each string of a string vector and a preview's pixels by their own declared sizes, and sizes
/// the line-offset table by the data window. Only single-part scanline files are kiln tables.
HeaderFacts checkHeader(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::int64_t fileSize = static_cast<std::int64_t>(in.tellg());
  in.seekg(0, std::ios::beg);
  const std::string corrupt = "cannot read the OpenEXR header (truncated or corrupt file): ";
  unsigned char start[8];
  if (!in.read(reinterpret_cast<char*>(start), 8)) throw Refusal(corrupt + "no version word");
  if ((start[5] & 0x02) != 0) throw Refusal("a tiled OpenEXR file; kiln tables are scanline files");
  if ((start[5] & 0x18) != 0)
    throw Refusal("a multi-part or deep OpenEXR file; kiln tables are single-part scanline files");
  const std::size_t maxName = (start[5] & 0x04) != 0 ? 255 : 31;  // bit 10: long names
  // The offset of the next byte, counted here: tellg() would ask the system (lseek) at every
  // byte of every name. The stream never fails between two reads of it (a failed read throws).
  std::int64_t offset = 8;
  auto position = [&] { return offset; };
  // Reads a \0-terminated string of at most maxName characters, within `limit` bytes of the
  // file; false at an empty one.
  auto readName = [&](std::string& name, const char* what, std::int64_t limit) {
    name.clear();
    for (;;) {
      if (position() >= limit) throw Refusal(corrupt + "inside an attribute " + what);
      const int ch = in.get();
      if (ch == std::ifstream::traits_type::eof())
        throw Refusal(corrupt + "inside an attribute " + what);
      ++offset;
      if (ch == 0) return !name.empty();
      if (name.size() >= maxName)
        throw Refusal(corrupt + "an attribute " + what + " longer than " + std::to_string(maxName) +
                      " characters");
      name.push_back(static_cast<char>(ch));
    }
  };
  auto readBytes = [&](unsigned char* out, std::int64_t n, const std::string& where) {
    if (!in.read(reinterpret_cast<char*>(out), n)) throw Refusal(corrupt + "inside " + where);
    offset += n;
  };

  HeaderFacts facts;
  facts.fileSize = fileSize;
  std::string name, type;
  while (readName(name, "name", fileSize)) {
    if (position() > kMaxHeaderBytes)
      throw Refusal(corrupt + "the header is larger than " + std::to_string(kMaxHeaderBytes >> 20) +
                    " MiB");
    if (!readName(type, "type name", fileSize))
      throw Refusal(corrupt + "attribute '" + name + "' has no type");
    unsigned char b[16];
    readBytes(b, 4, "attribute '" + name + "'");
    const std::int32_t size = int32At(b);
    const std::int64_t valueStart = position();
    const std::int64_t left = fileSize - valueStart;
    if (size < 0 || size > left)
      throw Refusal(corrupt + "attribute '" + name + "' declares " + std::to_string(size) +
                    " bytes, the file has " + std::to_string(left) + " left");
    const std::int64_t valueEnd = valueStart + size;
    const std::string where = "attribute '" + name + "' (" + type + ")";
    const std::int64_t fixed = fixedAttributeSize(type);
    if (fixed >= 0 && size != fixed)
      throw Refusal(corrupt + where + " declares " + std::to_string(size) + " bytes, a " + type +
                    " has " + std::to_string(fixed));
    if (type == "chlist") {
      // name\0, int32 pixel type, uchar pLinear, 3 reserved, int32 x and y sampling; an
      // empty name ends the list, which must end exactly where the declared size does.
      std::string channel;
      facts.bytesPerPixel = 0;
      while (readName(channel, "channel name", valueEnd)) {
        if (valueEnd - position() < 16)
          throw Refusal(corrupt + where + ": channel '" + channel +
                        "' runs past the declared size");
        readBytes(b, 16, where);
        const std::int32_t pixelType = int32At(b);
        if (pixelType < 0 || pixelType > 2)
          throw Refusal(corrupt + where + ": channel '" + channel + "' has pixel type " +
                        std::to_string(pixelType));
        facts.bytesPerPixel += pixelType == 1 ? 2 : 4;  // HALF : UINT, FLOAT
      }
      if (position() != valueEnd)
        throw Refusal(corrupt + where + " declares " + std::to_string(size) +
                      " bytes but its list ends after " + std::to_string(position() - valueStart));
    } else if (type == "stringvector") {
      // int32 length, then the characters, until the declared size is used up exactly.
      while (position() < valueEnd) {
        if (valueEnd - position() < 4)
          throw Refusal(corrupt + where + ": a string length runs past the declared size");
        readBytes(b, 4, where);
        const std::int32_t length = int32At(b);
        if (length < 0 || length > valueEnd - position())
          throw Refusal(corrupt + where + ": a string declares " + std::to_string(length) +
                        " bytes, the attribute has " + std::to_string(valueEnd - position()) +
                        " left");
        in.seekg(length, std::ios::cur);
        offset += length;
      }
    } else if (type == "preview") {
      if (size < 8) throw Refusal(corrupt + where + " declares " + std::to_string(size) + " bytes");
      readBytes(b, 8, where);
      const std::uint32_t width = static_cast<std::uint32_t>(int32At(b));
      const std::uint32_t height = static_cast<std::uint32_t>(int32At(b + 4));
      const std::uint64_t pixels = std::uint64_t{width} * height;  // < 2^64
      const std::uint64_t needs =
          pixels < (std::uint64_t{1} << 61) ? 8 + 4 * pixels : ~std::uint64_t{0};
      if (needs != std::uint64_t(size))
        throw Refusal(corrupt + where + " declares " + std::to_string(size) + " bytes, its " +
                      std::to_string(width) + " x " + std::to_string(height) + " pixels need " +
                      std::to_string(needs));
    } else if (type == "idmanifest") {
      throw Refusal(corrupt + where + ": ID manifests are not read by kiln");
    } else if (name == "dataWindow" && type == "box2i") {
      readBytes(b, 16, where);
      facts.haveWindow = true;
      facts.minX = int32At(b);
      facts.minY = int32At(b + 4);
      facts.maxX = int32At(b + 8);
      facts.maxY = int32At(b + 12);
    } else if (name == "compression" && type == "compression") {
      readBytes(b, 1, where);
      facts.compression = b[0];
    }
    in.clear();
    in.seekg(valueEnd, std::ios::beg);
    offset = valueEnd;
  }
  facts.headerEnd = position();
  if (facts.headerEnd > kMaxHeaderBytes)
    throw Refusal(corrupt + "the header is larger than " + std::to_string(kMaxHeaderBytes >> 20) +
                  " MiB");
  return facts;
}

/// Refuses a data window the file cannot hold, before OpenEXR sizes its line-offset table and
/// line buffers by it and the loader its texels: every block of scan lines needs 8 bytes in the
/// offset table and at least 8 in its own header, and the pixels cannot be larger than the bytes
/// after the header times the best ratio of the compression in use.
void checkDataWindow(const HeaderFacts& facts) {
  if (!facts.haveWindow) return;  // OpenEXR refuses a header without one
  const std::int64_t width = facts.maxX - facts.minX + 1;
  const std::int64_t height = facts.maxY - facts.minY + 1;
  if (width < 1 || height < 1)
    throw Refusal("the data window is " + std::to_string(width) + " x " + std::to_string(height));
  // Scan lines per block and the largest compression ratio of each OpenEXR compression: RLE
  // packs 128 equal bytes into 2, zlib (ZIPS, ZIP, PXR24) at most ~1032:1; PIZ, B44 and DWA
  // are given a wide margin.
  struct Scheme {
    std::int64_t lines, ratio;
  };
  static const Scheme schemes[] = {{1, 1},     {1, 64},    {1, 1100},  {16, 1100}, {32, 4096},
                                   {16, 1100}, {32, 4096}, {32, 4096}, {32, 4096}, {256, 4096}};
  if (facts.compression < 0 || facts.compression > 9)
    throw Refusal("unknown OpenEXR compression " + std::to_string(facts.compression));
  const Scheme scheme = schemes[facts.compression];
  const std::int64_t after = facts.fileSize - facts.headerEnd;
  const std::int64_t blocks = (height + scheme.lines - 1) / scheme.lines;
  if (blocks > after / 16)
    throw Refusal("the data window (" + std::to_string(width) + " x " + std::to_string(height) +
                  ") needs " + std::to_string(blocks) + " blocks of scan lines, the file has " +
                  std::to_string(after) + " bytes after its header");
  const double pixelBytes = double(width) * double(height) * double(facts.bytesPerPixel);
  if (pixelBytes > double(after) * double(scheme.ratio))
    throw Refusal("the data window (" + std::to_string(width) + " x " + std::to_string(height) +
                  ") holds " + std::to_string(static_cast<long long>(pixelBytes)) +
                  " bytes of pixels, more than the file's " + std::to_string(after) +
                  " bytes can hold with its compression");
}

/// Reads one file (a whole table or one part of a wider one) or throws.
Table readFile(const std::string& path) {
  checkReadableFile(path);
  if (!Imf::isOpenExrFile(path.c_str())) throw Refusal("not an OpenEXR file");
  checkDataWindow(checkHeader(path));

  std::unique_ptr<Imf::InputFile> file;
  try {
    file = std::make_unique<Imf::InputFile>(path.c_str());
  } catch (const std::exception& e) {
    throw Refusal("cannot read the OpenEXR header (truncated or corrupt file): " +
                  std::string(e.what()));
  }
  const Imf::Header& header = file->header();

  Table table;
  readAttributes(header, table);
  const std::vector<std::string> exrNames = checkChannels(header.channels(), table.channels);

  const Imath::Box2i window = header.dataWindow();
  const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
  const std::int64_t size0 = table.size(0);
  const std::int64_t rows = std::int64_t{table.size(1)} * table.size(2);
  if (width != size0 || height != rows)
    throw Refusal("axis sizes give a " + std::to_string(size0) + " x " + std::to_string(rows) +
                  " image but the data window is " + std::to_string(width) + " x " +
                  std::to_string(height));
  const std::uint64_t values = static_cast<std::uint64_t>(width) *
                               static_cast<std::uint64_t>(height) * table.channels.size();
  if (values > kMaxTableValues) throw Refusal("the table is too large");

  table.data.assign(static_cast<std::size_t>(values), 0.0f);
  const std::size_t channelCount = table.channels.size();
  const std::size_t xStride = sizeof(float) * channelCount;
  const std::size_t yStride = xStride * static_cast<std::size_t>(width);
  Imf::FrameBuffer frameBuffer;
  for (std::size_t c = 0; c < channelCount; ++c) {
    frameBuffer.insert(
        exrNames[c], Imf::Slice::Make(Imf::FLOAT, table.data.data() + c, window, xStride, yStride));
  }
  try {
    file->setFrameBuffer(frameBuffer);
    file->readPixels(window.min.y, window.max.y);
  } catch (const std::exception& e) {
    throw Refusal("cannot read the pixels (truncated or corrupt file): " + std::string(e.what()));
  }

  std::string problem;
  if (!validateTable(table, problem)) throw Refusal(problem);
  return table;
}

/// Reads the table in `path`; a part of a wider table is merged with the other parts beside it
/// (tableSiblingPartPath), which must load and match it. Throws.
Table readTable(const std::string& path) {
  Table table = readFile(path);
  if (table.part.count < 2) return table;
  const int index = table.part.index;
  std::vector<Table> parts;
  for (int other = 1; other <= table.part.count; ++other) {
    if (other == index) continue;
    std::string sibling;
    try {
      sibling = tableSiblingPartPath(path, index, other);
      parts.push_back(readFile(sibling));
    } catch (const std::exception& e) {
      throw Refusal("part " + std::to_string(other) + " of this table" +
                    (sibling.empty() ? "" : " ('" + sibling + "')") + ": " + e.what());
    }
  }
  parts.push_back(std::move(table));
  try {
    return mergeTableParts(parts);
  } catch (const std::exception& e) {
    throw Refusal(e.what());
  }
}

/// Sets `error` to the one-line message for `problem`; never throws.
void describeFailure(std::string& error, const std::string& path, const char* problem) noexcept {
  try {
    error = oneLine("kiln: cannot load table '" + path + "': " + problem);
  } catch (...) {
    // Out of memory while formatting: leave the previous message.
  }
}

}  // namespace

std::vector<std::string> exrChannelNames(std::size_t count) {
  if (count == 1) return {"Y"};
  return exrLayout1ChannelNames(count);
}

std::vector<std::string> exrFileChannels(std::size_t count) {
  if (count == 2) return {"R", "G", "B"};
  return exrChannelNames(count);
}

std::vector<std::string> exrLayout1ChannelNames(std::size_t count) {
  static const char* const kNames[] = {"R", "G", "B", "A"};
  if (count == 0 || count > 4) return {};
  return std::vector<std::string>(kNames, kNames + count);
}

bool loadTable(const std::string& path, Table& out, std::string& error) noexcept {
  try {
    Table table = readTable(path);
    out = std::move(table);
    return true;
  } catch (const std::exception& e) {
    describeFailure(error, path, e.what());
  } catch (...) {
    describeFailure(error, path, "unknown error");
  }
  return false;
}

Table loadTable(const std::string& path) {
  Table table;
  std::string error;
  if (!loadTable(path, table, error)) throw std::runtime_error(error);
  return table;
}

}  // namespace kiln
