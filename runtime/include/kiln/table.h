// kiln/table.h: an owning kiln table, the in-memory twin of a kiln EXR file.
//
// Every field mirrors one `kiln.*` attribute of the file format (see
// runtime/FORMAT.md); `data` holds the texels in the LutView layout
// (interleaved channels, axis 0 fastest, 3D slices stacked).
#pragma once

#include <string>
#include <vector>

#include "kiln/lut.h"

namespace kiln {

/// The file format version this runtime reads and writes (`kiln.format`).
constexpr int kFormatVersion = 1;

/// The file layout this runtime writes (`kiln.layout`; absent in older files: layout 1). Layout 2
/// names a 1-channel table's EXR channel `Y`, gives a 2-channel table an unused `B` channel of
/// zeros (R, G, B) and stores a table of more than 4 channels as parts of at most 4 (runtime/
/// FORMAT.md "The image"). The loader reads every layout; a bake rewrites files of another one.
constexpr int kLayoutVersion = 2;

/// The most channels one file (an RGBA texture) holds; a wider table is stored as parts.
constexpr int kMaxChannelsPerFile = 4;

/// Which part of a wider table a Table holds (`kiln.part`, `kiln.parts`, `kiln.table_channels`):
/// part `index` (1-based) of `count` holds the table's channels 4 (index - 1) .. 4 index - 1.
/// index 0: a whole table (every table of at most 4 channels, and a merged one).
struct TablePart {
  int index = 0;                           ///< 1..count; 0 for a whole table
  int count = 0;                           ///< number of parts; 0 for a whole table
  std::vector<std::string> tableChannels;  ///< the whole table's channels, in storage order
};

/// One axis of a table with its name (`kiln.axis<i>.*`).
struct TableAxis {
  std::string name;  ///< e.g. "mu", "roughness", "eta"
  Axis axis;         ///< lo, hi, size, warp
};

/// The measured interpolation error of a table (`kiln.lookup_error.*`);
/// -1 (and empty strings) when not measured.
struct LookupError {
  double max = -1.0;       ///< max abs error of a lookup vs the exact integral
  double rms = -1.0;       ///< rms of the same
  std::string where;       ///< where the max was found, free text
  std::string filter;      ///< filter it was measured with: "linear" or "cubic"
  double cubicMax = -1.0;  ///< the same max with the cubic filter (informative, not a bound)
  double cubicRms = -1.0;  ///< rms with the cubic filter
};

/// The measured error of a fitted table (`kiln.fit_error.*`, LTC tables: kind `ltc`); -1 (and
/// an empty text) when the table is not a fit. Written only when `max >= 0`.
struct FitError {
  double max = -1.0;  ///< max over texels of the fit's declared norm (LTC: L1 over the sphere)
  double rms = -1.0;  ///< rms over texels of the same
  double polygonMax = -1.0;  ///< max abs error of the polygon-light integral over the test polygons
  double polygonRms = -1.0;  ///< rms of the same
  std::string method;        ///< how both were measured, free text
};

/// A kiln table: metadata and texels. A plain value; validateTable says
/// whether it is consistent.
struct Table {
  std::string generator;                     ///< kiln.generator, e.g. "kiln 0.1.0"
  std::string name;                          ///< kiln.name, e.g. "ggx-dfg"
  std::string model;                         ///< kiln.model, e.g. "ggx" or "none"
  std::string quantity;                      ///< kiln.quantity, e.g. "dfg"
  std::vector<std::string> channels;         ///< kiln.channels, in storage order
  std::vector<std::string> channelMeanings;  ///< kiln.channel_meanings, one per channel
  std::vector<TableAxis> axes;               ///< kiln.dims = axes.size(), 1..3
  std::string params;                        ///< kiln.params, "key=value;key=value"
  std::string method;                        ///< kiln.method
  double tolerance = 0.0;                    ///< kiln.tolerance
  double bakeError = -1.0;                   ///< kiln.bake_error
  LookupError lookupError;                   ///< kiln.lookup_error.*
  FitError fitError;                         ///< kiln.fit_error.* (fitted tables only)
  std::string specHash;                      ///< kiln.spec_hash (hex)
  TablePart part;                            ///< kiln.part*: which part of a wider table
  std::vector<float> data;                   ///< the texels, see LutView

  /// Number of axes (kiln.dims).
  int dims() const noexcept { return static_cast<int>(axes.size()); }

  /// Nodes along axis d; 1 for d >= dims().
  int size(int d) const noexcept {
    return d >= 0 && d < dims() ? axes[static_cast<std::size_t>(d)].axis.size : 1;
  }

  /// Image width of the table in its file: size(0).
  int imageWidth() const noexcept { return size(0); }

  /// Image height of the table in its file: size(1) * size(2) (slices stacked).
  int imageHeight() const noexcept { return size(1) * size(2); }

  /// A non-owning view for sampling; valid while this table's data vector
  /// is neither resized nor destroyed. At most 3 axes are viewed.
  LutView view() const noexcept {
    LutView v;
    v.data = data.data();
    v.channels = static_cast<int>(channels.size());
    v.dims = dims();
    for (int d = 0; d < 3 && d < dims(); ++d) v.axis[d] = axes[static_cast<std::size_t>(d)].axis;
    return v;
  }
};

/// Checks that a table is consistent and writable: its header passes
/// tableHeaderProblem (kiln/table_checks.h: 1..3 named axes, each valid with lo
/// and hi within +-1e6, at most 2^30 values, at least one channel, channel names
/// non-empty, unique and free of ',', channel meanings either empty or one per
/// channel and free of ';'), data size equal to size0 * size1 * size2 *
/// channels, every texel finite. Returns true when it is; otherwise false with a
/// one-line description of the first problem in `problem`.
bool validateTable(const Table& table, std::string& problem);

/// Why `axis` is not Axis::valid() ("size is 0, must be >= 1", "lo 2 >= hi 1",
/// "lo 0 <= 0 with the log warp", ...), or an empty string when it is valid.
std::string axisProblem(const Axis& axis);

/// The number of files a table of `channels` channels is stored in: 1 up to kMaxChannelsPerFile,
/// else ceil(channels / 4) (an ltc table's 6: 2, channels 0-3 and 4-5).
int tablePartCount(std::size_t channels);

/// Part `index` (1-based, <= tablePartCount) of `table`: the same metadata with only that part's
/// channels, meanings and texels (none when `table.data` is empty), and `part` filled in.
/// Throws std::invalid_argument for an index out of range.
Table tablePart(const Table& table, int index);

/// The whole table from all its parts, in any order: each must be part i of the same count, with
/// the same name, axes and spec hash, and their channels in part order must be the declared
/// `tableChannels`. Throws std::invalid_argument with a one-line reason otherwise.
Table mergeTableParts(const std::vector<Table>& parts);

/// The file of part `index` of `count` for a table written to `path`: `path` itself when `count`
/// <= 1, else `-<index>` inserted before the extension (`luts/ltc-ggx.exr` part 2:
/// `luts/ltc-ggx-2.exr`).
std::string tablePartPath(const std::string& path, int index, int count);

/// The file of part `other` beside `path`, the file of part `index` (its name ends in
/// `-<index>` before the extension, as tablePartPath writes). Throws std::invalid_argument when
/// the name does not end so.
std::string tableSiblingPartPath(const std::string& path, int index, int other);

/// Splits `text` at every `separator`; an empty text gives an empty list.
std::vector<std::string> splitList(const std::string& text, char separator);

/// Joins `items` with `separator` (the inverse of splitList).
std::string joinList(const std::vector<std::string>& items, char separator);

}  // namespace kiln
