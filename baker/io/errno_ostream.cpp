// An OpenEXR output stream that keeps errno (baker/io/errno_ostream.h).
#include "baker/io/errno_ostream.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace kiln {

ErrnoOStream::ErrnoOStream(const std::string& path) : Imf::OStream(path.c_str()) {
  fd_ = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throw std::runtime_error("cannot create '" + path + "': " + std::strerror(errno));
}

ErrnoOStream::~ErrnoOStream() {
  if (fd_ >= 0) close(fd_);
}

void ErrnoOStream::write(const char c[], int n) {
  if (firstError_ != 0) throw std::runtime_error(std::strerror(firstError_));
  std::size_t done = 0;
  while (done < static_cast<std::size_t>(n)) {
    const ssize_t w = pwrite(fd_, c + done, static_cast<std::size_t>(n) - done,
                             static_cast<off_t>(position_ + done));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      firstError_ = w < 0 ? errno : ENOSPC;  // a write of 0 bytes: the device is full
      throw std::runtime_error(std::strerror(firstError_));
    }
    done += static_cast<std::size_t>(w);
  }
  position_ += done;
}

std::uint64_t ErrnoOStream::tellp() { return position_; }

void ErrnoOStream::seekp(std::uint64_t pos) { position_ = pos; }

void ErrnoOStream::Close() {
  const int fd = fd_;
  fd_ = -1;
  const int closed = fd >= 0 ? close(fd) : 0;
  if (firstError_ != 0) throw std::runtime_error(std::strerror(firstError_));
  if (closed != 0) throw std::runtime_error(std::strerror(errno));
}

}  // namespace kiln
