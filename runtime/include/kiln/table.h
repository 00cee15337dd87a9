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

/// Splits `text` at every `separator`; an empty text gives an empty list.
std::vector<std::string> splitList(const std::string& text, char separator);

/// Joins `items` with `separator` (the inverse of splitList).
std::string joinList(const std::vector<std::string>& items, char separator);

}  // namespace kiln
