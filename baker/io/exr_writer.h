// baker/io/exr_writer.h: writes a kiln table as an OpenEXR file.
#pragma once

#include <OpenEXR/ImfForward.h>

#include <string>

#include "kiln/table.h"

namespace kiln {

class PendingFile;

/// Sets every kiln.* attribute of `table` on `header` (the contract in
/// runtime/FORMAT.md): kiln.format = kFormatVersion, strings as
/// StringAttribute, ints as IntAttribute, doubles as DoubleAttribute. Does not
/// touch the channel list or the windows.
void setKilnAttributes(Imf::Header& header, const Table& table);

/// Writes `table` to the OpenEXR file `path`: one scanline image of width
/// size0 and height size1 * size2 (data window origin (0, 0)), its channels named as
/// exrFileChannels (`Y` for 1 channel; R, G, B, A in storage order for 2 to 4, a 2-channel
/// table with an unused `B` of zeros named in kiln.unused_channels; the kiln names stay in
/// kiln.channels), ZIP compression, FLOAT pixels or HALF when `half` is true, and all kiln.*
/// attributes (kiln.layout = kLayoutVersion). A table of more than 4 channels is written as
/// tablePartCount files, part i to tablePartPath(path, i, count), each a table of at most 4
/// channels with kiln.part, kiln.parts and kiln.table_channels, committed together. The same
/// table always gives the same bytes. The file is written to a temporary file of its own
/// (PendingFile, baker/io/atomic_write.h) and renamed into place; on any error
/// the temporary file is removed, an existing file at `path` is left intact,
/// and std::runtime_error is thrown with a one-line message; `path` must be
/// missing or a regular file (CheckWritableTarget). Refuses a table that fails validateTable, and
/// in half mode a texel whose magnitude exceeds the largest half (65504). Before the rename the
/// temporary file is reopened and must be complete (header and every line
/// offset readable): OpenEXR writes the offsets in a destructor that swallows
/// errors such as a full disk. `threads` > 1 compresses the line blocks on
/// OpenEXR's global thread pool (grown to that size); the bytes do not depend
/// on it.
void writeTable(const std::string& path, const Table& table, bool half, int threads = 1);

/// writeTable's checks and write into `file`'s temporary file, without the
/// rename: the caller commits it (PendingFile::CommitAll), e.g. together with
/// the manifest. `table` has at most 4 channels (a whole table or a tablePart). Throws like
/// writeTable.
void writeTable(PendingFile& file, const Table& table, bool half, int threads = 1);

}  // namespace kiln
