// kiln/exr_loader.h: reads a kiln table from an OpenEXR file.
#pragma once

#include <string>

#include "kiln/table.h"

namespace kiln {

/// Loads the kiln table stored in the OpenEXR file at `path` (format in
/// runtime/FORMAT.md). FLOAT and HALF channels are read (HALF is widened to
/// float). Refuses, leaving `out` untouched: a missing or unreadable file, a
/// file that is not OpenEXR or is truncated/corrupt, an EXR without the kiln
/// attributes ("not a kiln table"), a kiln.format other than kFormatVersion,
/// a channel list that differs from kiln.channels, axis sizes that do not match
/// the data window, dims outside 1..3, an axis with size < 1, lo >= hi or an
/// unknown warp, and NaN or infinite texels. On failure returns false and sets
/// `error` to one line naming the file and the problem. Never throws (every
/// OpenEXR exception is caught).
bool loadTable(const std::string& path, Table& out, std::string& error) noexcept;

/// As above, but returns the table and throws std::runtime_error carrying the
/// same one-line message on failure.
Table loadTable(const std::string& path);

}  // namespace kiln
