// Writes a kiln table as an OpenEXR file (a temporary file of its own + rename).
#include "baker/io/exr_writer.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <Imath/half.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "baker/io/atomic_write.h"
#include "baker/io/errno_ostream.h"
#include "baker/io/half_float.h"
#include "kiln/exr_loader.h"

namespace kiln {

namespace {

void setString(Imf::Header& h, const std::string& name, const std::string& value) {
  h.insert(name, Imf::StringAttribute(value));
}

void setInt(Imf::Header& h, const std::string& name, int value) {
  h.insert(name, Imf::IntAttribute(value));
}

void setDouble(Imf::Header& h, const std::string& name, double value) {
  h.insert(name, Imf::DoubleAttribute(value));
}

/// Writes the image (no temporary-file handling) to `filePath`.
void writeExrFile(const std::string& filePath, const Table& table, bool asHalf, int threads) {
  Imf::Header header(table.imageWidth(), table.imageHeight());
  header.compression() = Imf::ZIP_COMPRESSION;
  setKilnAttributes(header, table);
  const Imf::PixelType fileType = asHalf ? Imf::HALF : Imf::FLOAT;
  // Y for 1 channel, R, G, B(, A) for 2 to 4 (a 2-channel table's B unused, zeros): every
  // RGBA reader opens the file (exrFileChannels). A wider table is written as parts.
  if (table.channels.size() > static_cast<std::size_t>(kMaxChannelsPerFile))
    throw std::runtime_error(std::to_string(table.channels.size()) +
                             " channels in one EXR: write each tablePart");
  const std::vector<std::string> names = exrChannelNames(table.channels.size());
  const std::vector<std::string> fileNames = exrFileChannels(table.channels.size());
  for (const std::string& channel : fileNames)
    header.channels().insert(channel, Imf::Channel(fileType));

  const std::size_t channelCount = table.channels.size();
  const Imath::Box2i window = header.dataWindow();
  Imf::FrameBuffer frameBuffer;
  std::vector<::half> halves;  // OpenEXR does not convert FLOAT to HALF on output
  // The unused channels: one row of zeros, repeated (yStride 0) on every row.
  const std::vector<float> zeroRow(static_cast<std::size_t>(table.imageWidth()), 0.0f);
  const std::vector<::half> zeroHalfRow(zeroRow.size(), ::half(0.0f));
  for (std::size_t c = names.size(); c < fileNames.size(); ++c) {
    char* base = asHalf ? (char*)zeroHalfRow.data() : (char*)zeroRow.data();
    frameBuffer.insert(fileNames[c], Imf::Slice(asHalf ? Imf::HALF : Imf::FLOAT, base,
                                                asHalf ? sizeof(::half) : sizeof(float), 0));
  }
  if (asHalf) {
    halves.reserve(table.data.size());
    for (float v : table.data) halves.push_back(::half(v));  // round to nearest even
    const std::size_t xStride = sizeof(::half) * channelCount;
    const std::size_t yStride = xStride * static_cast<std::size_t>(table.imageWidth());
    for (std::size_t c = 0; c < channelCount; ++c)
      frameBuffer.insert(names[c],
                         Imf::Slice::Make(Imf::HALF, halves.data() + c, window, xStride, yStride));
  } else {
    const std::size_t xStride = sizeof(float) * channelCount;
    const std::size_t yStride = xStride * static_cast<std::size_t>(table.imageWidth());
    for (std::size_t c = 0; c < channelCount; ++c)
      frameBuffer.insert(
          names[c], Imf::Slice::Make(Imf::FLOAT, table.data.data() + c, window, xStride, yStride));
  }
  ErrnoOStream stream(filePath);  // keeps errno: "No space left on device"
  {
    Imf::OutputFile file(stream, header, threads > 1 ? threads : 0);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(table.imageHeight());
  }  // the line offsets are written here, errors swallowed: Close() reports them
  stream.Close();
}

}  // namespace

void setKilnAttributes(Imf::Header& h, const Table& t) {
  setInt(h, "kiln.format", kFormatVersion);
  setString(h, "kiln.generator", t.generator);
  setString(h, "kiln.name", t.name);
  setString(h, "kiln.model", t.model);
  setString(h, "kiln.quantity", t.quantity);
  setString(h, "kiln.channels", joinList(t.channels, ','));
  setString(h, "kiln.channel_meanings", joinList(t.channelMeanings, ';'));
  setInt(h, "kiln.dims", t.dims());
  for (int d = 0; d < t.dims(); ++d) {
    const TableAxis& a = t.axes[static_cast<std::size_t>(d)];
    const std::string prefix = "kiln.axis" + std::to_string(d) + ".";
    setString(h, prefix + "name", a.name);
    setDouble(h, prefix + "lo", a.axis.lo);
    setDouble(h, prefix + "hi", a.axis.hi);
    setInt(h, prefix + "size", a.axis.size);
    setString(h, prefix + "warp", warpName(a.axis.warp));
    // Only a constant split is written: files without it keep the critical cosine.
    if (a.axis.hasConstantSplit()) setDouble(h, prefix + "split", a.axis.split);
  }
  setString(h, "kiln.params", t.params);
  setString(h, "kiln.method", t.method);
  setDouble(h, "kiln.tolerance", t.tolerance);
  setDouble(h, "kiln.bake_error", t.bakeError);
  setDouble(h, "kiln.lookup_error.max", t.lookupError.max);
  setDouble(h, "kiln.lookup_error.rms", t.lookupError.rms);
  setString(h, "kiln.lookup_error.where", t.lookupError.where);
  setString(h, "kiln.lookup_error.filter", t.lookupError.filter);
  if (t.lookupError.cubicMax >= 0) {
    setDouble(h, "kiln.lookup_error.cubic_max", t.lookupError.cubicMax);
    setDouble(h, "kiln.lookup_error.cubic_rms", t.lookupError.cubicRms);
  }
  setString(h, "kiln.spec_hash", t.specHash);
  setInt(h, "kiln.layout", kLayoutVersion);
  const std::vector<std::string> used = exrChannelNames(t.channels.size());
  const std::vector<std::string> file = exrFileChannels(t.channels.size());
  if (file.size() > used.size())
    setString(h, "kiln.unused_channels",
              joinList(std::vector<std::string>(file.begin() + used.size(), file.end()), ','));
  if (t.part.index > 0) {
    setInt(h, "kiln.part", t.part.index);
    setInt(h, "kiln.parts", t.part.count);
    setString(h, "kiln.table_channels", joinList(t.part.tableChannels, ','));
  }
  if (t.fitError.max >= 0) {
    setDouble(h, "kiln.fit_error.max", t.fitError.max);
    setDouble(h, "kiln.fit_error.rms", t.fitError.rms);
    setDouble(h, "kiln.fit_error.polygon_max", t.fitError.polygonMax);
    setDouble(h, "kiln.fit_error.polygon_rms", t.fitError.polygonRms);
    setString(h, "kiln.fit_error.method", t.fitError.method);
  }
}

void writeTable(const std::string& path, const Table& table, bool half, int threads) {
  const int count = tablePartCount(table.channels.size());
  if (count == 1) {
    PendingFile file(path);
    writeTable(file, table, half, threads);
    PendingFile::CommitAll({&file});
    return;
  }
  std::vector<std::unique_ptr<PendingFile>> files;
  std::vector<PendingFile*> commit;
  for (int part = 1; part <= count; ++part) {
    files.push_back(std::make_unique<PendingFile>(tablePartPath(path, part, count)));
    writeTable(*files.back(), tablePart(table, part), half, threads);
    commit.push_back(files.back().get());
  }
  PendingFile::CommitAll(commit);
}

void writeTable(PendingFile& file, const Table& table, bool half, int threads) {
  const std::string& path = file.Path();
  std::string problem;
  if (!validateTable(table, problem))
    throw std::runtime_error("kiln: cannot write '" + path + "': invalid table: " + problem);
  if (table.channels.size() > static_cast<std::size_t>(kMaxChannelsPerFile))
    throw std::runtime_error("kiln: cannot write '" + path +
                             "': " + std::to_string(table.channels.size()) +
                             " channels in one file; write each tablePart");
  if (half) {
    for (float v : table.data) {
      if (std::fabs(v) > kHalfMax)
        throw std::runtime_error("kiln: cannot write '" + path + "': value " + std::to_string(v) +
                                 " does not fit in half precision");
    }
  }
  if (threads > 1 && Imf::globalThreadCount() < threads) Imf::setGlobalThreadCount(threads);
  file.Write([&](const std::string& temporaryPath) {
    writeExrFile(temporaryPath, table, half, threads);
    // OpenEXR writes the line offset table in a destructor that swallows
    // errors (e.g. a full disk), so reopen the file before the rename.
    bool complete = false;
    std::string error = "line offsets missing";
    try {
      complete = Imf::InputFile(temporaryPath.c_str(), 0).isComplete();
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!complete) throw std::runtime_error("the written file is incomplete: " + error);
  });
}

}  // namespace kiln
