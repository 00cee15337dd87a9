// kiln/exr_loader.h: reads a kiln table from an OpenEXR file.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kiln/table.h"

namespace kiln {

/// Loads the kiln table stored in the OpenEXR file at `path` (format in
/// runtime/FORMAT.md). FLOAT and HALF channels are read (HALF is widened to
/// float). A file that is one part of a table of more than 4 channels (`kiln.part`) is read
/// with the other parts beside it (tableSiblingPartPath: `NAME-1.exr`, `NAME-2.exr`) and the
/// whole table is returned, from either file. Refuses, leaving `out` untouched: a missing or
/// unreadable file (or part), a
/// file that is not OpenEXR or is truncated/corrupt, an EXR without the kiln
/// attributes ("not a kiln table"), a kiln.format other than kFormatVersion,
/// a channel list that is none of exrFileChannels, exrLayout1ChannelNames and kiln.channels
/// itself (the three layouts kiln has written), parts that do not match, axis sizes that do
/// not match the data window, dims outside 1..3, an axis with size < 1, lo >= hi or an unknown
/// warp, and NaN or infinite texels. On failure returns false and sets `error` to one line naming
/// the file and the problem. Never throws (every OpenEXR exception is caught).
bool loadTable(const std::string& path, Table& out, std::string& error) noexcept;

/// The OpenEXR channel that holds each storage channel of a table (or part) of `count`
/// channels in the layout kiln writes (kLayoutVersion): `Y` for 1 channel (the luminance
/// channel every RGBA reader accepts), else the first `count` of R, G, B, A in storage order.
/// Empty when `count` is 0 or more than 4.
std::vector<std::string> exrChannelNames(std::size_t count);

/// The OpenEXR channels of a file of `count` channels in the layout kiln writes: those of
/// exrChannelNames plus, for 2 channels, an unused `B` of zeros (`kiln.unused_channels`), so
/// that every RGB(A) reader opens it: Y; R, G, B; R, G, B; R, G, B, A.
std::vector<std::string> exrFileChannels(std::size_t count);

/// The channel names of layout-1 files that used R, G, B, A: the first `count` (a 1-channel
/// table as `R`, a 2-channel one as R, G). Read, never written.
std::vector<std::string> exrLayout1ChannelNames(std::size_t count);

/// As above, but returns the table and throws std::runtime_error carrying the
/// same one-line message on failure.
Table loadTable(const std::string& path);

}  // namespace kiln
