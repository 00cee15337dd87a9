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

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <system_error>
#include <utility>

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
const T& requireAttribute(const Imf::Header& header, const std::string& name, const char* typeName) {
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
    if (!std::filesystem::exists(status)) throw Refusal("no such file");
    if (!std::filesystem::is_regular_file(status)) throw Refusal("not a regular file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw Refusal("cannot open the file for reading");
    if (stream.peek() == std::ifstream::traits_type::eof()) throw Refusal("the file is empty");
}

/// Fills every metadata field of `table` from the kiln.* attributes.
void readAttributes(const Imf::Header& h, Table& table) {
    if (h.find("kiln.format") == h.end())
        throw Refusal("not a kiln table (no kiln.format attribute)");
    const int format = requireInt(h, "kiln.format");
    if (format != kFormatVersion)
        throw Refusal("format version " + std::to_string(format) + ", this runtime reads " +
                      std::to_string(kFormatVersion));

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
            throw Refusal(prefix + "warp is '" + warp +
                          "', not one of linear, sqrt, square, log, root4, root4-layer, angle");
        const std::string axisIssue = axisProblem(a.axis);
        if (!axisIssue.empty())
            throw Refusal("axis " + std::to_string(d) + " ('" + a.name + "'): " + axisIssue);
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
}

/// Checks that the image's channels are exactly kiln.channels, each FLOAT or
/// HALF and not subsampled.
void checkChannels(const Imf::ChannelList& list, const std::vector<std::string>& expected) {
    std::set<std::string> inFile;
    std::string inFileText;
    for (auto it = list.begin(); it != list.end(); ++it) {
        inFile.insert(it.name());
        inFileText += (inFileText.empty() ? "" : ",") + std::string(it.name());
    }
    const std::set<std::string> declared(expected.begin(), expected.end());
    if (expected.empty() || declared.size() != expected.size() || inFile != declared)
        throw Refusal("channel mismatch: kiln.channels is '" + joinList(expected, ',') +
                      "' but the image has channels '" + inFileText + "'");
    for (auto it = list.begin(); it != list.end(); ++it) {
        const Imf::Channel& channel = it.channel();
        if (channel.type != Imf::FLOAT && channel.type != Imf::HALF)
            throw Refusal("channel '" + std::string(it.name()) +
                          "' is UINT; only FLOAT and HALF are read");
        if (channel.xSampling != 1 || channel.ySampling != 1)
            throw Refusal("channel '" + std::string(it.name()) + "' is subsampled");
    }
}

/// Walks the attribute list of every header (OpenEXR file layout: magic, version word, then per
/// part a list of name\0 type\0 int32-size value, ended by an empty name; a multi-part file
/// ends its list of headers with one more empty name) and refuses an attribute whose declared
/// size does not fit in the rest of the file. OpenEXR 3.1 allocates (and for strings fills) the
/// declared size before it reads the value, so a 1 KB file declaring a 2 GB attribute would cost
/// 2 GB before it fails: this check answers from the bytes that are there.
void checkAttributeSizes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const std::int64_t fileSize = static_cast<std::int64_t>(in.tellg());
    in.seekg(0, std::ios::beg);
    unsigned char start[8];
    if (!in.read(reinterpret_cast<char*>(start), 8)) throw Refusal("truncated OpenEXR header");
    const bool multiPart = (start[5] & 0x10) != 0;  // bit 12 of the version word
    const std::size_t maxName = (start[5] & 0x04) != 0 ? 255 : 31;  // bit 10: long names
    // Reads a \0-terminated string of at most maxName characters; false at an empty one.
    auto readName = [&](std::string& name, const char* what) {
        name.clear();
        for (;;) {
            const int ch = in.get();
            if (ch == std::ifstream::traits_type::eof())
                throw Refusal(std::string("truncated OpenEXR header (inside an attribute ") + what + ")");
            if (ch == 0) return !name.empty();
            if (name.size() >= maxName)
                throw Refusal(std::string("corrupt OpenEXR header (an attribute ") + what +
                              " longer than " + std::to_string(maxName) + " characters)");
            name.push_back(static_cast<char>(ch));
        }
    };
    std::string name, type;
    for (int part = 0;; ++part) {
        int attributes = 0;
        while (readName(name, "name")) {
            if (!readName(type, "type name"))
                throw Refusal("corrupt OpenEXR header (attribute '" + name + "' has no type)");
            unsigned char b[4];
            if (!in.read(reinterpret_cast<char*>(b), 4)) throw Refusal("truncated OpenEXR header");
            const std::int32_t size = static_cast<std::int32_t>(
                std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 |
                std::uint32_t{b[3]} << 24);
            const std::int64_t left = fileSize - static_cast<std::int64_t>(in.tellg());
            if (size < 0 || size > left)
                throw Refusal("cannot read the OpenEXR header (truncated or corrupt file): attribute '" +
                              name + "' declares " +
                              std::to_string(size) + " bytes, the file has " + std::to_string(left) +
                              " left");
            in.seekg(size, std::ios::cur);
            ++attributes;
        }
        if (!multiPart || attributes == 0) return;  // single part: one list; multi-part: empty header ends
        if (part > 1024) throw Refusal("corrupt OpenEXR header (too many parts)");
    }
}

/// Reads the whole table or throws.
Table readTable(const std::string& path) {
    checkReadableFile(path);
    if (!Imf::isOpenExrFile(path.c_str())) throw Refusal("not an OpenEXR file");
    checkAttributeSizes(path);

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
    checkChannels(header.channels(), table.channels);

    const Imath::Box2i window = header.dataWindow();
    const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
    const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
    const std::int64_t size0 = table.size(0);
    const std::int64_t rows = std::int64_t{table.size(1)} * table.size(2);
    if (width != size0 || height != rows)
        throw Refusal("axis sizes give a " + std::to_string(size0) + " x " + std::to_string(rows) +
                      " image but the data window is " + std::to_string(width) + " x " +
                      std::to_string(height));
    const std::uint64_t values =
        static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * table.channels.size();
    if (values > (std::uint64_t{1} << 30)) throw Refusal("the table is too large");

    table.data.assign(static_cast<std::size_t>(values), 0.0f);
    const std::size_t channelCount = table.channels.size();
    const std::size_t xStride = sizeof(float) * channelCount;
    const std::size_t yStride = xStride * static_cast<std::size_t>(width);
    Imf::FrameBuffer frameBuffer;
    for (std::size_t c = 0; c < channelCount; ++c) {
        frameBuffer.insert(table.channels[c],
                           Imf::Slice::Make(Imf::FLOAT, table.data.data() + c, window, xStride, yStride));
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

/// Sets `error` to the one-line message for `problem`; never throws.
void describeFailure(std::string& error, const std::string& path, const char* problem) noexcept {
    try {
        error = oneLine("kiln: cannot load table '" + path + "': " + problem);
    } catch (...) {
        // Out of memory while formatting: leave the previous message.
    }
}

}  // namespace

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
