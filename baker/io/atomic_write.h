// baker/io/atomic_write.h: every output file is written to a temporary file of its own and
// renamed into place; a folder lock for read-modify-write files such as manifest.json; removal
// of the temporary files on SIGINT, SIGTERM, SIGHUP and SIGXFSZ.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace kiln {

/// Throws std::runtime_error ("kiln: cannot write '<path>': <reason>") when `path` exists and is
/// not a regular file: a symbolic link (even to a regular file), a folder, a FIFO, a socket or a
/// device. A missing `path` or a regular file passes. Writers call it before writing and again
/// just before the rename.
void CheckWritableTarget(const std::string& path);

/// A file being written: a fresh temporary file "<path>.<pid>.<random>.tmp" in the folder of
/// `path` (created with O_CREAT | O_EXCL | O_NOFOLLOW, mode 0666 minus the umask, so it is never
/// a file or link that was there before), and renamed onto `path` by Commit. While it exists its
/// name is registered for removal by the signal handlers (InstallCleanupHandlers).
class PendingFile {
 public:
  /// Checks `path` (CheckWritableTarget) and creates the temporary file; throws
  /// std::runtime_error naming `path` when either fails.
  explicit PendingFile(std::string path);
  /// Removes the temporary file unless Commit renamed it.
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  /// Calls `write(p)` where `p` opens the temporary file itself (/proc/self/fd/N when /proc is
  /// mounted, so a link planted under the temporary name after its creation is never followed;
  /// otherwise the temporary path). `write` may open `p` any number of times, truncating it.
  /// Throws std::runtime_error "kiln: cannot write '<path>': <reason>" (one line) when `write`
  /// throws or the temporary name no longer holds the file it created.
  void Write(const std::function<void(const std::string& writePath)>& write);
  /// Write() with a callback that writes `bytes`.
  void WriteBytes(const std::string& bytes);

  const std::string& Path() const { return path_; }
  const std::string& TemporaryPath() const { return temporary_; }

  /// Renames `files` onto their paths in order (after checking each target again), with SIGINT,
  /// SIGTERM, SIGHUP and SIGXFSZ held back until the last rename is done: only SIGKILL (or a
  /// crash) can leave some renamed and others not. Throws std::runtime_error naming the file
  /// whose rename failed; the files before it stay renamed, the ones after stay temporary (and
  /// are removed by their destructors).
  static void CommitAll(const std::vector<PendingFile*>& files);

 private:
  std::string path_, temporary_;
  int fd_ = -1;
  int slot_ = -1;  // index in the signal handlers' table of temporary paths
  bool committed_ = false;
};

/// An exclusive advisory lock (flock) on a folder, held while the object lives. A second process
/// asking for the same folder's lock waits until the first releases it (at the latest when it
/// ends: the kernel releases the lock of a killed process). Throws std::runtime_error naming
/// `dir` when it cannot be opened or locked.
class FolderLock {
 public:
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

/// Removes from `dir` the temporary files ("<name>.<pid>.<16 hex digits>.tmp") whose process no
/// longer exists (kill(pid, 0) fails with ESRCH); hold the folder's FolderLock while calling it.
/// Returns how many it removed. Files of living processes and every other name are left alone.
int RemoveStaleTemporaries(const std::string& dir);

/// Installs (once per process) handlers for SIGINT, SIGTERM, SIGHUP and SIGXFSZ that remove every
/// registered temporary file and then end the process by the same signal (default action), so
/// the exit status still says which signal ended it. A signal ignored at start-up (nohup) stays
/// ignored. PendingFile calls it; calling it again does nothing.
void InstallCleanupHandlers();

/// Writes `bytes` to `path` through a PendingFile and renames it into place: readers see the
/// old file or the new one, never a partial one. Throws std::runtime_error
/// "kiln: cannot write '<path>': <reason>" (one line); the old file is then left untouched and
/// no temporary file is left behind.
void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& temporaryPath)>& write);

/// Writes `bytes` to the file `path` (truncating it) with write(2). Throws std::runtime_error
/// "cannot create '<path>': <strerror>" when it cannot be opened, and the bare strerror text
/// ("No space left on device") when a write or the close fails: PendingFile::Write, its caller,
/// names the destination. Used inside writeAtomically's callback.
void writeBytes(const std::string& path, const std::string& bytes);

}  // namespace kiln
