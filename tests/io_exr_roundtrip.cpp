// Specification of the EXR writer and loader: round trip, determinism,
// write-to-temporary-and-rename, and refusal of hostile files.
#include <catch2/catch.hpp>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "baker/io/atomic_write.h"
#include "baker/io/exr_writer.h"
#include "kiln/exr_loader.h"

namespace fs = std::filesystem;

namespace {

/// A fresh, empty folder under the system temp folder, removed at the end.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() / ("kiln-test-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path))
      names.push_back(e.path().filename().string());
    return names;
  }
};

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeBytesTo(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

/// A table of `dims` axes with three channels in non-alphabetical storage
/// order, every metadata field set, and values of mixed sign and magnitude.
kiln::Table makeTable(int dims) {
  kiln::Table t;
  t.generator = "kiln 0.1.0";
  t.name = "test-table";
  t.model = "ggx";
  t.quantity = "dfg";
  t.channels = {"scale", "bias", "albedo"};
  t.channelMeanings = {"F0 scale", "F0 bias, the second term", "directional albedo"};
  const kiln::TableAxis all[3] = {{"mu", {0.0, 1.0, 5, kiln::Warp::Sqrt}},
                                  {"roughness", {0.0, 1.0, 4, kiln::Warp::Linear}},
                                  {"eta", {1.05, 3.0, 3, kiln::Warp::Log}}};
  t.axes.assign(all, all + dims);
  t.params = "f0=0.04;multiscatter=1";
  t.method = "gauss-legendre adaptive";
  t.tolerance = 1e-7;
  t.bakeError = 3.25e-8;
  t.lookupError = {1.5e-3, 2.5e-4, "mu=0.03 roughness=0.11", "linear"};
  t.specHash = "0123456789abcdef";
  std::uint32_t state = 17;
  t.data.resize(std::size_t(t.size(0)) * t.size(1) * t.size(2) * t.channels.size());
  for (float& v : t.data) {
    state = state * 1664525u + 1013904223u;
    v = (float(state >> 8) / float(1u << 24) - 0.3f) * (state % 3 == 0 ? 100.0f : 1.0f);
  }
  return t;
}

void requireSameMetadata(const kiln::Table& a, const kiln::Table& b) {
  CHECK(a.generator == b.generator);
  CHECK(a.name == b.name);
  CHECK(a.model == b.model);
  CHECK(a.quantity == b.quantity);
  CHECK(a.channels == b.channels);
  CHECK(a.channelMeanings == b.channelMeanings);
  REQUIRE(a.dims() == b.dims());
  for (int d = 0; d < a.dims(); ++d) {
    const auto& x = a.axes[std::size_t(d)];
    const auto& y = b.axes[std::size_t(d)];
    CHECK(x.name == y.name);
    CHECK(x.axis.lo == y.axis.lo);
    CHECK(x.axis.hi == y.axis.hi);
    CHECK(x.axis.size == y.axis.size);
    CHECK(x.axis.warp == y.axis.warp);
  }
  CHECK(a.params == b.params);
  CHECK(a.method == b.method);
  CHECK(a.tolerance == b.tolerance);
  CHECK(a.bakeError == b.bakeError);
  CHECK(a.lookupError.max == b.lookupError.max);
  CHECK(a.lookupError.rms == b.lookupError.rms);
  CHECK(a.lookupError.where == b.lookupError.where);
  CHECK(a.lookupError.filter == b.lookupError.filter);
  CHECK(a.specHash == b.specHash);
}

/// Writes an EXR with plain OpenEXR: `header` as given plus the channels
/// (name, file type); `data` interleaved in the order of `channels`, converted
/// to each channel's type.
void writeRawExr(const std::string& path, Imf::Header header,
                 const std::vector<std::pair<std::string, Imf::PixelType>>& channels,
                 const std::vector<float>& data) {
  const Imath::Box2i window = header.dataWindow();
  const std::size_t width = std::size_t(window.max.x - window.min.x + 1);
  const std::size_t count = channels.size();
  const std::size_t pixels = data.size() / count;
  std::vector<std::vector<float>> floats(count);
  std::vector<std::vector<half>> halves(count);
  std::vector<std::vector<unsigned>> uints(count);
  Imf::FrameBuffer fb;
  for (std::size_t c = 0; c < count; ++c) {
    const Imf::PixelType type = channels[c].second;
    header.channels().insert(channels[c].first, Imf::Channel(type));
    const char* base = nullptr;
    for (std::size_t k = 0; k < pixels; ++k) {
      const float v = data[k * count + c];
      if (type == Imf::FLOAT) floats[c].push_back(v);
      if (type == Imf::HALF) halves[c].push_back(half(v));
      if (type == Imf::UINT) uints[c].push_back(unsigned(v));
    }
    std::size_t size = sizeof(float);
    if (type == Imf::FLOAT) base = reinterpret_cast<const char*>(floats[c].data());
    if (type == Imf::HALF)
      base = reinterpret_cast<const char*>(halves[c].data()), size = sizeof(half);
    if (type == Imf::UINT)
      base = reinterpret_cast<const char*>(uints[c].data()), size = sizeof(unsigned);
    fb.insert(channels[c].first, Imf::Slice::Make(type, base, window, size, size * width));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(window.max.y - window.min.y + 1);
}

/// A kiln header for `t` (image sized by its axes), to be edited by a test.
Imf::Header kilnHeader(const kiln::Table& t) {
  Imf::Header h(t.imageWidth(), t.imageHeight());
  kiln::setKilnAttributes(h, t);
  return h;
}

/// A copy of `source` without the attribute `name`. (Header::erase leaks the
/// erased attribute in OpenEXR 3.1, which would fail sanitizer builds.)
Imf::Header withoutAttribute(const Imf::Header& source, const std::string& name) {
  Imf::Header copy(source.displayWindow(), source.dataWindow());
  for (auto it = source.begin(); it != source.end(); ++it)
    if (name != it.name()) copy.insert(it.name(), it.attribute());
  return copy;
}

std::vector<std::pair<std::string, Imf::PixelType>> floatChannels(const kiln::Table& t) {
  std::vector<std::pair<std::string, Imf::PixelType>> c;
  for (const auto& name : t.channels) c.emplace_back(name, Imf::FLOAT);
  return c;
}

}  // namespace

TEST_CASE("a table written to EXR loads back identical: data and every attribute", "[io][exr]") {
  ScratchDir dir("exr-roundtrip");
  for (int dims = 1; dims <= 3; ++dims) {
    INFO("dims " << dims);
    const kiln::Table original = makeTable(dims);
    const std::string path = dir.file("table" + std::to_string(dims) + ".exr");
    kiln::writeTable(path, original, false);
    const kiln::Table loaded = kiln::loadTable(path);
    requireSameMetadata(original, loaded);
    REQUIRE(loaded.data.size() == original.data.size());
    CHECK(std::memcmp(loaded.data.data(), original.data.data(),
                      original.data.size() * sizeof(float)) == 0);

    // The file itself: FLOAT channels, ZIP, width size0, height size1*size2 at (0, 0).
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    CHECK(window.min.x == 0);
    CHECK(window.min.y == 0);
    CHECK(window.max.x + 1 == original.size(0));
    CHECK(window.max.y + 1 == original.size(1) * original.size(2));
    CHECK(file.header().compression() == Imf::ZIP_COMPRESSION);
    // EXR channels R, G, B in storage order (the kiln names are in kiln.channels).
    for (const auto& name : kiln::exrChannelNames(original.channels.size())) {
      const Imf::Channel* channel = file.header().channels().findChannel(name);
      REQUIRE(channel != nullptr);
      CHECK(channel->type == Imf::FLOAT);
    }
    CHECK(file.header().typedAttribute<Imf::IntAttribute>("kiln.format").value() == 1);
    CHECK(file.header().typedAttribute<Imf::StringAttribute>("kiln.channels").value() ==
          "scale,bias,albedo");
  }
}

TEST_CASE("a texel sits at column i0 and row i2 * size1 + i1 of the EXR image", "[io][exr]") {
  ScratchDir dir("exr-layout");
  const kiln::Table t = makeTable(3);
  const std::string path = dir.file("layout.exr");
  kiln::writeTable(path, t, false);
  // Read the "bias" channel (storage channel 1, so EXR channel G) alone with plain OpenEXR.
  Imf::InputFile file(path.c_str());
  const int width = t.size(0), height = t.size(1) * t.size(2);
  std::vector<float> bias(std::size_t(width) * height);
  Imf::FrameBuffer fb;
  fb.insert("G", Imf::Slice::Make(Imf::FLOAT, bias.data(), file.header().dataWindow()));
  file.setFrameBuffer(fb);
  file.readPixels(0, height - 1);
  const kiln::LutView view = t.view();
  for (int i2 = 0; i2 < t.size(2); ++i2)
    for (int i1 = 0; i1 < t.size(1); ++i1)
      for (int i0 = 0; i0 < t.size(0); ++i0)
        CHECK(bias[std::size_t(i2 * t.size(1) + i1) * width + i0] == view.at(i0, i1, i2, 1));
}

TEST_CASE("half mode stores every texel to half precision", "[io][exr]") {
  ScratchDir dir("exr-half");
  kiln::Table original = makeTable(2);
  const std::string path = dir.file("half.exr");
  kiln::writeTable(path, original, true);
  const kiln::Table loaded = kiln::loadTable(path);
  requireSameMetadata(original, loaded);
  REQUIRE(loaded.data.size() == original.data.size());
  for (std::size_t k = 0; k < original.data.size(); ++k) {
    const float v = original.data[k];
    CHECK(loaded.data[k] == float(half(v)));  // rounded to nearest half
    CHECK(std::fabs(loaded.data[k] - v) <= std::ldexp(std::fabs(v), -11) + 6e-8);
  }
  Imf::InputFile file(path.c_str());
  CHECK(file.header().channels().findChannel("R")->type == Imf::HALF);

  original.data[3] = 70000.0f;  // beyond the largest half
  CHECK_THROWS_WITH(kiln::writeTable(dir.file("big.exr"), original, true),
                    Catch::Contains("does not fit in half"));
}

TEST_CASE("the same table always gives the same bytes", "[io][exr]") {
  ScratchDir dir("exr-deterministic");
  for (bool half : {false, true}) {
    const kiln::Table t = makeTable(3);
    kiln::writeTable(dir.file("a.exr"), t, half);
    kiln::writeTable(dir.file("b.exr"), t, half);
    const std::string a = readBytes(dir.file("a.exr"));
    CHECK(a.size() > 100);
    CHECK(a == readBytes(dir.file("b.exr")));
    kiln::writeTable(dir.file("a.exr"), t, half);  // overwrite in place
    CHECK(a == readBytes(dir.file("a.exr")));
    // ... and a different table gives different bytes.
    kiln::Table other = t;
    other.data[0] += 1.0f;
    kiln::writeTable(dir.file("c.exr"), other, half);
    CHECK(a != readBytes(dir.file("c.exr")));
  }
}

TEST_CASE("writing leaves no temporary file and never a broken one", "[io][exr]") {
  ScratchDir dir("exr-temporary");
  const kiln::Table t = makeTable(2);
  const std::string path = dir.file("lut.exr");

  kiln::writeTable(path, t, false);
  CHECK(dir.entries() == std::vector<std::string>{"lut.exr"});
  const std::string before = readBytes(path);

  SECTION("a refused table leaves the old file intact") {
    kiln::Table bad = t;
    bad.data[5] = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_WITH(kiln::writeTable(path, bad, false),
                      Catch::Contains(path) && Catch::Contains("NaN texel"));
    CHECK(readBytes(path) == before);
    CHECK(dir.entries() == std::vector<std::string>{"lut.exr"});
  }
  SECTION("a folder at the destination is refused, no temporary file is left") {
    // The destination is a non-empty folder: refused before anything is written.
    const std::string folder = dir.file("folder.exr");
    fs::create_directories(fs::path(folder) / "keep");
    CHECK_THROWS_WITH(kiln::writeTable(folder, t, false),
                      Catch::Contains("cannot write '" + folder + "'"));
    CHECK(dir.entries() == std::vector<std::string>{"folder.exr", "lut.exr"});
    CHECK(fs::is_directory(fs::path(folder) / "keep"));
  }
  SECTION("a failure while writing removes the temporary file, the old file stays") {
    CHECK_THROWS_WITH(kiln::writeAtomically(path,
                                            [](const std::string& temporary) {
                                              kiln::writeBytes(temporary, "half a fi");
                                              throw std::runtime_error("disk full\nreally");
                                            }),
                      "kiln: cannot write '" + path + "': disk full really");
    CHECK(readBytes(path) == before);
    CHECK(dir.entries() == std::vector<std::string>{"lut.exr"});
  }
  SECTION("a missing folder is reported") {
    const std::string missing = dir.file("no/such/folder/lut.exr");
    CHECK_THROWS_WITH(kiln::writeTable(missing, t, false), Catch::Contains(missing));
  }
}

TEST_CASE("hostile files are refused with a clear one-line message", "[io][exr]") {
  ScratchDir dir("exr-hostile");
  const kiln::Table good = makeTable(2);
  const std::string goodPath = dir.file("good.exr");
  kiln::writeTable(goodPath, good, false);
  const std::string goodBytes = readBytes(goodPath);

  struct Case {
    const char* name;
    std::function<void(const std::string&)> make;
    std::string expected;
  };
  auto withHeader = [&](std::function<void(Imf::Header&)> edit) {
    return [&good, edit](const std::string& path) {
      Imf::Header h = kilnHeader(good);
      edit(h);
      writeRawExr(path, h, floatChannels(good), good.data);
    };
  };
  const std::vector<Case> cases = {
      {"missing file", [](const std::string&) {}, "no such file"},
      {"a folder", [](const std::string& p) { fs::create_directory(p); }, "not a regular file"},
      {"empty file", [](const std::string& p) { writeBytesTo(p, ""); }, "the file is empty"},
      {"random bytes",
       [](const std::string& p) {
         std::string bytes(4096, '\0');
         std::uint32_t s = 99;
         for (char& ch : bytes) ch = char((s = s * 1103515245u + 12345u) >> 16);
         writeBytesTo(p, bytes);
       },
       "not an OpenEXR file"},
      {"truncated in the pixels",
       [&](const std::string& p) { writeBytesTo(p, goodBytes.substr(0, goodBytes.size() - 16)); },
       "cannot read the pixels (truncated or corrupt file)"},
      {"truncated in the header",
       [&](const std::string& p) { writeBytesTo(p, goodBytes.substr(0, 60)); },
       "cannot read the OpenEXR header (truncated or corrupt file)"},
      {"plain EXR without kiln attributes",
       [&](const std::string& p) {
         writeRawExr(p, Imf::Header(good.imageWidth(), good.imageHeight()), floatChannels(good),
                     good.data);
       },
       "not a kiln table"},
      {"wrong format version",
       withHeader([](Imf::Header& h) { h.insert("kiln.format", Imf::IntAttribute(2)); }),
       "format version 2, this runtime reads 1"},
      {"wrong channel count",
       [&](const std::string& p) {
         auto channels = floatChannels(good);
         channels.emplace_back("extra", Imf::FLOAT);
         std::vector<float> data;
         for (std::size_t k = 0; k < good.data.size(); k += 3) {
           data.insert(data.end(), good.data.begin() + long(k), good.data.begin() + long(k) + 3);
           data.push_back(0.0f);
         }
         writeRawExr(p, kilnHeader(good), channels, data);
       },
       "channel mismatch"},
      {"channel names differ", withHeader([](Imf::Header& h) {
         h.insert("kiln.channels", Imf::StringAttribute("scale,bias,alpha"));
       }),
       "channel mismatch"},
      {"UINT channel",
       [&](const std::string& p) {
         auto channels = floatChannels(good);
         channels[1].second = Imf::UINT;
         std::vector<float> data(good.data.size(), 1.0f);
         writeRawExr(p, kilnHeader(good), channels, data);
       },
       "only FLOAT and HALF"},
      {"HALF channel holding infinity",
       [&](const std::string& p) {
         auto channels = floatChannels(good);
         channels[2].second = Imf::HALF;
         std::vector<float> data = good.data;
         data[2] = 1e6f;  // overflows half
         writeRawExr(p, kilnHeader(good), channels, data);
       },
       "infinite texel at node (0, 0, 0) of channel 'albedo'"},
      {"NaN texel",
       [&](const std::string& p) {
         std::vector<float> data = good.data;
         data[7] = std::numeric_limits<float>::quiet_NaN();
         writeRawExr(p, kilnHeader(good), floatChannels(good), data);
       },
       "NaN texel at node (2, 0, 0) of channel 'bias'"},
      {"infinite texel",
       [&](const std::string& p) {
         std::vector<float> data = good.data;
         data[0] = -std::numeric_limits<float>::infinity();
         writeRawExr(p, kilnHeader(good), floatChannels(good), data);
       },
       "infinite texel"},
      {"axis size not matching the image",
       withHeader([](Imf::Header& h) { h.insert("kiln.axis1.size", Imf::IntAttribute(3)); }),
       "data window is 5 x 4"},
      {"dims 4", withHeader([](Imf::Header& h) { h.insert("kiln.dims", Imf::IntAttribute(4)); }),
       "kiln.dims is 4, must be 1, 2 or 3"},
      {"dims 0", withHeader([](Imf::Header& h) { h.insert("kiln.dims", Imf::IntAttribute(0)); }),
       "kiln.dims is 0"},
      {"axis size 0",
       withHeader([](Imf::Header& h) { h.insert("kiln.axis0.size", Imf::IntAttribute(0)); }),
       "axis 0 ('mu'): size is 0, must be >= 1"},
      {"lo >= hi",
       withHeader([](Imf::Header& h) { h.insert("kiln.axis1.lo", Imf::DoubleAttribute(1.0)); }),
       "axis 1 ('roughness'): lo 1 >= hi 1"},
      {"log warp with lo <= 0",
       withHeader([](Imf::Header& h) { h.insert("kiln.axis1.warp", Imf::StringAttribute("log")); }),
       "axis 1 ('roughness'): lo 0 <= 0 with the log warp"},
      {"unknown warp", withHeader([](Imf::Header& h) {
         h.insert("kiln.axis0.warp", Imf::StringAttribute("cubic"));
       }),
       "kiln.axis0.warp is 'cubic'"},
      {"attribute of the wrong type", withHeader([](Imf::Header& h) {
         h = withoutAttribute(h, "kiln.dims");
         h.insert("kiln.dims", Imf::StringAttribute("2"));
       }),
       "attribute kiln.dims is not of type int"},
      {"missing axis attribute",
       withHeader([](Imf::Header& h) { h = withoutAttribute(h, "kiln.axis1.warp"); }),
       "missing attribute kiln.axis1.warp"},
  };

  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    INFO("case: " << c.name);
    const std::string path = dir.file("hostile" + std::to_string(k) + ".exr");
    c.make(path);
    kiln::Table out;
    out.name = "untouched";
    std::string error;
    CHECK_FALSE(kiln::loadTable(path, out, error));
    CHECK_THAT(error, Catch::StartsWith("kiln: cannot load table '" + path + "': "));
    CHECK_THAT(error, Catch::Contains(c.expected));
    CHECK(error.find('\n') == std::string::npos);
    CHECK(out.name == "untouched");
    CHECK_THROWS_WITH(kiln::loadTable(path), error);
  }
  // The unedited file loads: the failures above come from the edits.
  std::string error;
  kiln::Table out;
  CHECK(kiln::loadTable(goodPath, out, error));
  CHECK(error.empty());
  Imf::Header plain = kilnHeader(good);
  writeRawExr(dir.file("raw-good.exr"), plain, floatChannels(good), good.data);
  CHECK(kiln::loadTable(dir.file("raw-good.exr"), out, error));
}
