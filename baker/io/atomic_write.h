// baker/io/atomic_write.h: write-to-temporary-and-rename for every output file.
#pragma once

#include <functional>
#include <string>

namespace kiln {

/// The temporary sibling written before the rename: "<path>.tmp", in the same
/// folder as `path` so that the rename stays on one file system.
std::string temporaryPathFor(const std::string& path);

/// Calls `write(temporaryPathFor(path))`, then renames the temporary file onto
/// `path` (atomic on POSIX: readers see the old file or the new one, never a
/// partial one). If `write` throws or the rename fails, the temporary file is
/// removed, the old file at `path` is left untouched, and std::runtime_error is
/// thrown with the one-line message "kiln: cannot write '<path>': <reason>".
void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& temporaryPath)>& write);

/// Writes `bytes` to the file `path` (truncating it); throws std::runtime_error
/// naming the file when it cannot be opened or written completely.
void writeBytes(const std::string& path, const std::string& bytes);

}  // namespace kiln
