// kiln/exr_loader.h: reads a kiln table from an OpenEXR file.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// Loads the kiln table stored in the OpenEXR file at `path` (format in
/// runtime/FORMAT.md). FLOAT and HALF channels are read (HALF is widened to
/// float). Refuses, leaving `out` untouched: a missing or unreadable file, a
/// file that is not OpenEXR or is truncated/corrupt, an EXR without the kiln
/// attributes ("not a kiln table"), a kiln.format other than kFormatVersion,
/// a channel list that is neither the R, G, B, A names of exrChannelNames nor
/// kiln.channels itself (files written before kiln named channels R, G, B, A), axis sizes that do
/// not match the data window, dims outside 1..3, an axis with size < 1, lo >= hi or an unknown
/// warp, and NaN or infinite texels. On failure returns false and sets `error` to one line naming
/// the file and the problem. Never throws (every OpenEXR exception is caught).
bool loadTable(const std::string& path, Table& out, std::string& error) noexcept;

/// The OpenEXR channel names of a kiln table with `count` channels: the first
/// `count` of R, G, B, A, so storage channel c is R, G, B, A for c = 0..3 and
/// any RGBA reader sees the table (runtime/FORMAT.md, "The image"). Empty when
/// `count` is 0 or more than 4: kiln writes no such EXR.
std::vector<std::string> exrChannelNames(std::size_t count);

/// As above, but returns the table and throws std::runtime_error carrying the
/// same one-line message on failure.
Table loadTable(const std::string& path);

}  // namespace kiln
