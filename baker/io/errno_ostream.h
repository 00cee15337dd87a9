// baker/io/errno_ostream.h: an OpenEXR output stream on a file descriptor that reports why a
// write failed (errno: "No space left on device", "Disk quota exceeded", ...). OpenEXR's own
// file stream loses the reason, and writes the line-offset table in a destructor that swallows
// every error; this stream remembers the first failure so that Close() reports it afterwards.
#pragma once
#include <OpenEXR/ImfIO.h>

#include <cstdint>
#include <string>

namespace kiln {

/// An Imf::OStream writing with pwrite(2) to a file it opens; a failed write throws
/// std::runtime_error with strerror(errno) and is remembered for Close().
class ErrnoOStream : public Imf::OStream {
 public:
  /// Opens `path` for writing (truncating it, created with mode 0666 minus the umask); throws
  /// std::runtime_error "cannot create '<path>': <strerror>" when it cannot.
  explicit ErrnoOStream(const std::string& path);
  ~ErrnoOStream() override;
  ErrnoOStream(const ErrnoOStream&) = delete;
  ErrnoOStream& operator=(const ErrnoOStream&) = delete;

  /// Writes `n` bytes at the current position; throws std::runtime_error with strerror(errno)
  /// (and remembers it) when the system refuses.
  void write(const char c[], int n) override;
  std::uint64_t tellp() override;
  void seekp(std::uint64_t pos) override;

  /// Closes the file; throws std::runtime_error with the text of the first write error (even one
  /// a destructor swallowed) or of close(2) itself. Call it after the Imf::OutputFile is gone.
  void Close();

 private:
  int fd_ = -1;
  std::uint64_t position_ = 0;
  int firstError_ = 0;  ///< errno of the first failed write, 0 while none failed
};

}  // namespace kiln
