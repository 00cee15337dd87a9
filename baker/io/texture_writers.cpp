// A kiln table as KTX2, DDS or 16-bit PNG: the formats engines load without an EXR reader.
#include "baker/io/texture_writers.h"

#include "baker/io/table_json.h"

#include <Imath/half.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "baker/io/atomic_write.h"
#include "baker/io/png_writer.h"
#include "baker/io/table_json.h"
#include "baker/io/half_float.h"

namespace kiln {
namespace {

void Put32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFFu);
}

void Put16(std::string& out, std::uint16_t v) {
  out += static_cast<char>(v & 0xFFu);
  out += static_cast<char>(v >> 8);
}

void PutFloat(std::string& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  Put32(out, bits);
}

void Overwrite32(std::string& out, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out[at + k] = static_cast<char>((v >> (8 * k)) & 0xFFu);
}

void Overwrite64(std::string& out, std::size_t at, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) out[at + k] = static_cast<char>((v >> (8 * k)) & 0xFFu);
}

std::string G17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The checks every texture format shares: 1 to 4 channels, half range.
void CheckEncodable(const Table& table, bool half, const char* format) {
  const std::size_t nc = table.channels.size();
  if (nc < 1 || nc > 4)
    throw std::invalid_argument(std::to_string(nc) + " channels; a " + format +
                                " texture holds 1 to 4 (R, G, B, A)");
  if (half)
    for (float v : table.data)
      if (std::fabs(v) > kHalfMax)
        throw std::invalid_argument("value " + std::to_string(v) +
                                    " does not fit in half precision");
}

/// The texels in file order (FileRowOrder), as float32 or half little-endian bytes.
std::string TexelBytes(const Table& table, bool half) {
  const std::vector<int> rows = FileRowOrder(table, FlipsY(table));
  const std::size_t rowValues =
      static_cast<std::size_t>(table.imageWidth()) * table.channels.size();
  std::string out;
  out.reserve(table.data.size() * (half ? 2 : 4));
  for (int r : rows) {
    const float* row = table.data.data() + static_cast<std::size_t>(r) * rowValues;
    for (std::size_t k = 0; k < rowValues; ++k) {
      if (half)
        Put16(out, ::half(row[k]).bits());
      else
        PutFloat(out, row[k]);
    }
  }
  return out;
}

/// The table's metadata as a JSON object (what the EXR attributes hold).
nlohmann::ordered_json MetadataJson(const Table& t) {
  nlohmann::ordered_json j;
  j["format"] = kFormatVersion;
  j["generator"] = t.generator;
  j["name"] = t.name;
  AppendTableDescription(j, t);
  j["flip_y"] = FlipsY(t);
  j["spec_hash"] = t.specHash;
  j["layout"] = kLayoutVersion;
  if (t.part.index > 0)  // one part of a table of more than 4 channels
    j["part"] = {
        {"index", t.part.index}, {"count", t.part.count}, {"table_channels", t.part.tableChannels}};
  return j;
}

}  // namespace

OutputFormat ParseOutputFormat(const std::string& text) {
  if (text == "exr") return OutputFormat::Exr;
  if (text == "ktx2") return OutputFormat::Ktx2;
  if (text == "dds") return OutputFormat::Dds;
  if (text == "png16") return OutputFormat::Png16;
  if (text == "png16-scaled") return OutputFormat::Png16Scaled;
  throw std::invalid_argument("unknown --format '" + text +
                              "' (exr, ktx2, dds, png16 or png16-scaled)");
}

const char* FormatName(OutputFormat format) {
  switch (format) {
    case OutputFormat::Exr:
      return "exr";
    case OutputFormat::Ktx2:
      return "ktx2";
    case OutputFormat::Dds:
      return "dds";
    case OutputFormat::Png16:
      return "png16";
    case OutputFormat::Png16Scaled:
      return "png16-scaled";
  }
  return "exr";
}

const char* FormatExtension(OutputFormat format) {
  switch (format) {
    case OutputFormat::Exr:
      return ".exr";
    case OutputFormat::Ktx2:
      return ".ktx2";
    case OutputFormat::Dds:
      return ".dds";
    case OutputFormat::Png16:
    case OutputFormat::Png16Scaled:
      return ".png";
  }
  return ".exr";
}

bool FlipsY(const Table& table) {
  for (const std::string& kv : splitList(table.params, ';'))
    if (kv == "flip_y=1") return true;
  return false;
}

std::vector<int> FileRowOrder(const Table& table, bool flipY) {
  const int size1 = table.size(1), size2 = table.size(2);
  std::vector<int> rows;
  rows.reserve(static_cast<std::size_t>(size1) * static_cast<std::size_t>(size2));
  for (int k = 0; k < size2; ++k)
    for (int i = 0; i < size1; ++i) rows.push_back(k * size1 + (flipY ? size1 - 1 - i : i));
  return rows;
}

std::vector<Png16Channel> Png16Scales(const Table& table) {
  const std::size_t nc = table.channels.size();
  std::vector<Png16Channel> out(nc);
  for (std::size_t c = 0; c < nc && c < table.data.size(); ++c) {
    double lo = table.data[c], hi = lo;
    for (std::size_t k = c; k < table.data.size(); k += nc) {
      lo = std::min(lo, static_cast<double>(table.data[k]));
      hi = std::max(hi, static_cast<double>(table.data[k]));
    }
    out[c].offset = lo;
    out[c].scale = hi - lo;  // exact: both are floats
  }
  return out;
}

std::vector<Png16Channel> Png16Quantisation(const Table& table, bool scaled) {
  if (scaled) return Png16Scales(table);
  return std::vector<Png16Channel>(table.channels.size(), Png16Channel{1.0, 0.0});
}

bool IsPng16(OutputFormat format) {
  return format == OutputFormat::Png16 || format == OutputFormat::Png16Scaled;
}

std::string EncodeKtx2(const Table& table, bool half) {
  CheckEncodable(table, half, "KTX2");
  const std::uint32_t nc = static_cast<std::uint32_t>(table.channels.size());
  // VkFormat: R16_SFLOAT 76, R16G16 83, R16G16B16 90, R16G16B16A16 97; R32_SFLOAT 100,
  // R32G32 103, R32G32B32 106, R32G32B32A32 109.
  static const std::uint32_t kHalfFormats[4] = {76, 83, 90, 97};
  static const std::uint32_t kFloatFormats[4] = {100, 103, 106, 109};
  const std::uint32_t typeSize = half ? 2 : 4;
  const bool flip = FlipsY(table);
  const bool volume = table.dims() == 3;

  std::string f;
  static const unsigned char kIdentifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                                0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  f.append(reinterpret_cast<const char*>(kIdentifier), 12);
  Put32(f, half ? kHalfFormats[nc - 1] : kFloatFormats[nc - 1]);  // vkFormat
  Put32(f, typeSize);
  Put32(f, static_cast<std::uint32_t>(table.size(0)));  // pixelWidth
  Put32(f, static_cast<std::uint32_t>(table.size(1)));  // pixelHeight (1 for a 1D table)
  Put32(f, volume ? static_cast<std::uint32_t>(table.size(2)) : 0u);  // pixelDepth
  Put32(f, 0);                                                        // layerCount: not an array
  Put32(f, 1);                                                        // faceCount
  Put32(f, 1);                                                        // levelCount
  Put32(f, 0);                           // supercompressionScheme: none
  const std::size_t indexAt = f.size();  // 48: dfd, kvd offsets and lengths, sgd
  f.append(32, '\0');
  const std::size_t levelIndexAt = f.size();  // 80: byteOffset, byteLength, uncompressed
  f.append(24, '\0');

  // Data Format Descriptor: dfdTotalSize, then one basic descriptor block.
  const std::size_t dfdAt = f.size();
  const std::uint32_t blockSize = 24 + 16 * nc;
  Put32(f, 4 + blockSize);
  Put32(f, 0);                       // vendorId 0 (Khronos), descriptorType 0 (basic)
  Put32(f, 2u | (blockSize << 16));  // versionNumber 2, descriptorBlockSize
  Put32(f, 1u | (1u << 8) | (1u << 16) | (0u << 24));  // RGBSDA, BT709 primaries, linear, straight
  Put32(f, 0);                                         // texelBlockDimension0..3 = 1 x 1 x 1 x 1
  Put32(f, nc * typeSize);                             // bytesPlane0 = texel size; planes 1..3 = 0
  Put32(f, 0);                                         // bytesPlane4..7
  static const std::uint32_t kChannelId[4] = {0, 1, 2, 15};  // R, G, B, A
  for (std::uint32_t c = 0; c < nc; ++c) {
    const std::uint32_t qualifiers = 0x80u | 0x40u;  // FLOAT | SIGNED
    Put32(f,
          (c * typeSize * 8) | ((typeSize * 8 - 1) << 16) | ((kChannelId[c] | qualifiers) << 24));
    Put32(f, 0);            // samplePosition0..3
    Put32(f, 0xBF800000u);  // sampleLower = -1.0f
    Put32(f, 0x3F800000u);  // sampleUpper = 1.0f
  }
  const std::uint32_t dfdLength = static_cast<std::uint32_t>(f.size() - dfdAt);

  // Key/value data, sorted by key (byte order): each entry is its length, key NUL value, then
  // padding to 4 bytes.
  const std::size_t kvdAt = f.size();
  auto entry = [&](const std::string& key, const std::string& value) {
    const std::string kv = key + '\0' + value + '\0';
    Put32(f, static_cast<std::uint32_t>(kv.size()));
    f += kv;
    while (f.size() % 4) f += '\0';
  };
  entry("KTXorientation", std::string("r") + (flip ? "u" : "d") + (volume ? "i" : ""));
  entry("KTXwriter", table.generator.empty() ? "kiln" : table.generator);
  entry("kiln.json", MetadataJson(table).dump(-1, ' ', true));
  entry("kiln.spec_hash", table.specHash);
  const std::uint32_t kvdLength = static_cast<std::uint32_t>(f.size() - kvdAt);

  while (f.size() % 16) f += '\0';  // mip padding: a multiple of lcm(texel size, 4)
  const std::size_t levelAt = f.size();
  const std::string texels = TexelBytes(table, half);
  f += texels;

  Overwrite32(f, indexAt + 0, static_cast<std::uint32_t>(dfdAt));
  Overwrite32(f, indexAt + 4, dfdLength);
  Overwrite32(f, indexAt + 8, static_cast<std::uint32_t>(kvdAt));
  Overwrite32(f, indexAt + 12, kvdLength);
  Overwrite64(f, indexAt + 16, 0);  // sgdByteOffset
  Overwrite64(f, indexAt + 24, 0);  // sgdByteLength
  Overwrite64(f, levelIndexAt + 0, levelAt);
  Overwrite64(f, levelIndexAt + 8, texels.size());
  Overwrite64(f, levelIndexAt + 16, texels.size());
  return f;
}

std::string EncodeDds(const Table& table, bool half) {
  CheckEncodable(table, half, "DDS");
  const std::uint32_t nc = static_cast<std::uint32_t>(table.channels.size());
  if (half && nc == 3)
    throw std::invalid_argument("3 channels in half precision: DXGI has no R16G16B16_FLOAT");
  static const std::uint32_t kFloatFormats[4] = {41, 16, 6, 2};  // DXGI_FORMAT_R32.._FLOAT
  static const std::uint32_t kHalfFormats[4] = {54, 34, 0, 10};  // DXGI_FORMAT_R16.._FLOAT
  const bool volume = table.dims() == 3;
  const std::uint32_t texelBytes = nc * (half ? 2 : 4);

  std::string f = "DDS ";
  // DDS_HEADER (124 bytes)
  Put32(f, 124);
  const std::uint32_t kCaps = 0x1, kHeight = 0x2, kWidth = 0x4, kPitch = 0x8, kPixelFormat = 0x1000,
                      kDepth = 0x800000;
  Put32(f, kCaps | kHeight | kWidth | kPitch | kPixelFormat | (volume ? kDepth : 0u));
  Put32(f, static_cast<std::uint32_t>(table.size(1)));                // dwHeight
  Put32(f, static_cast<std::uint32_t>(table.size(0)));                // dwWidth
  Put32(f, static_cast<std::uint32_t>(table.size(0)) * texelBytes);   // dwPitchOrLinearSize
  Put32(f, volume ? static_cast<std::uint32_t>(table.size(2)) : 0u);  // dwDepth
  Put32(f, 0);                                                        // dwMipMapCount
  f.append(11 * 4, '\0');                                             // dwReserved1
  // DDS_PIXELFORMAT (32 bytes): FOURCC "DX10", the real format in the DXT10 header.
  Put32(f, 32);
  Put32(f, 0x4);  // DDPF_FOURCC
  f += "DX10";
  f.append(5 * 4, '\0');              // RGB bit count and masks
  Put32(f, 0x1000);                   // dwCaps: DDSCAPS_TEXTURE
  Put32(f, volume ? 0x200000u : 0u);  // dwCaps2: DDSCAPS2_VOLUME
  Put32(f, 0);                        // dwCaps3
  Put32(f, 0);                        // dwCaps4
  Put32(f, 0);                        // dwReserved2
  // DDS_HEADER_DXT10 (20 bytes)
  Put32(f, half ? kHalfFormats[nc - 1] : kFloatFormats[nc - 1]);  // dxgiFormat
  Put32(f, volume ? 4u : 3u);  // resourceDimension: TEXTURE3D or TEXTURE2D
  Put32(f, 0);                 // miscFlag
  Put32(f, 1);                 // arraySize
  Put32(f, 0);                 // miscFlags2: alpha mode unknown
  f += TexelBytes(table, half);
  return f;
}

std::string EncodePng16(const Table& table, bool scaled) {
  CheckEncodable(table, false, "16-bit PNG");
  const std::size_t nc = table.channels.size();
  if (!scaled) {
    // Plain [0, 1] values: a channel beyond them is refused, naming its range.
    const std::vector<Png16Channel> ranges = Png16Scales(table);
    for (std::size_t c = 0; c < nc; ++c) {
      const double lo = ranges[c].offset, hi = ranges[c].offset + ranges[c].scale;
      if (lo < 0.0 || hi > 1.0)
        throw std::invalid_argument("channel '" + table.channels[c] + "' spans [" + G17(lo) + ", " +
                                    G17(hi) +
                                    "], outside [0, 1]: png16 stores plain values in [0, 1]; "
                                    "--format png16-scaled stores a scale and offset per channel");
    }
  }
  const std::vector<Png16Channel> scales = Png16Quantisation(table, scaled);
  const int samples = nc == 1 ? 1 : nc == 4 ? 4 : 3;
  const int colourType = nc == 1 ? 0 : nc == 4 ? 6 : 2;
  const std::vector<int> rows = FileRowOrder(table, FlipsY(table));
  const std::size_t width = static_cast<std::size_t>(table.imageWidth());
  std::vector<std::uint8_t> pixels;
  pixels.reserve(rows.size() * width * static_cast<std::size_t>(samples) * 2);
  for (int r : rows) {
    for (std::size_t x = 0; x < width; ++x) {
      const float* texel = table.data.data() + (static_cast<std::size_t>(r) * width + x) * nc;
      for (int s = 0; s < samples; ++s) {
        std::uint16_t stored = 0;
        if (static_cast<std::size_t>(s) < nc && scales[s].scale > 0) {
          const double q = (texel[s] - scales[s].offset) / scales[s].scale * 65535.0;
          stored = static_cast<std::uint16_t>(std::lround(std::min(65535.0, std::max(0.0, q))));
        }
        pixels.push_back(static_cast<std::uint8_t>(stored >> 8));  // big-endian
        pixels.push_back(static_cast<std::uint8_t>(stored & 0xFFu));
      }
    }
  }
  std::string scaleText, offsetText;
  nlohmann::ordered_json meta = MetadataJson(table);
  nlohmann::ordered_json js = nlohmann::ordered_json::array(), jo = nlohmann::ordered_json::array();
  for (const Png16Channel& c : scales) {
    scaleText += (scaleText.empty() ? "" : " ") + G17(c.scale);
    offsetText += (offsetText.empty() ? "" : " ") + G17(c.offset);
    js.push_back(c.scale);
    jo.push_back(c.offset);
  }
  meta["png16"] = {{"scale", js}, {"offset", jo}, {"encoding", scaled ? "scaled" : "unit"}};
  // The samples are linear (cICP, gAMA 1.0): no viewer or loader applies an sRGB curve.
  const std::string decode = scaled ? "value = stored / 65535 * scale + offset, per channel"
                                    : "value = stored / 65535 (linear, every channel)";
  return encodePngImage(static_cast<int>(width), static_cast<int>(rows.size()), 16, colourType,
                        pixels,
                        {{"kiln.scale", scaleText},
                         {"kiln.offset", offsetText},
                         {"kiln.decode", decode},
                         {"kiln.json", meta.dump(-1, ' ', true)}},
                        true);
}

void WriteTextureTable(PendingFile& file, const Table& table, OutputFormat format, bool half) {
  const std::string& path = file.Path();
  std::string problem;
  if (!validateTable(table, problem))
    throw std::runtime_error("kiln: cannot write '" + path + "': invalid table: " + problem);
  std::string bytes;
  try {
    switch (format) {
      case OutputFormat::Ktx2:
        bytes = EncodeKtx2(table, half);
        break;
      case OutputFormat::Dds:
        bytes = EncodeDds(table, half);
        break;
      case OutputFormat::Png16:
      case OutputFormat::Png16Scaled:
        if (half) throw std::invalid_argument("--half does not apply to png16");
        bytes = EncodePng16(table, format == OutputFormat::Png16Scaled);
        break;
      case OutputFormat::Exr:
        throw std::invalid_argument("EXR is written by writeTable");
    }
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("kiln: cannot write '" + path + "': " + e.what());
  }
  file.WriteBytes(bytes);
}

}  // namespace kiln
