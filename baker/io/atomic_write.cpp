// Temporary files, renames, the folder lock and the signal handlers that clean up
// (baker/io/atomic_write.h).
#include "baker/io/atomic_write.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <stdexcept>

#include "baker/io/test_hooks.h"

namespace kiln {

namespace {

std::string OneLine(std::string text) {
  for (char& ch : text)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return text;
}

[[noreturn]] void Fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error(OneLine("kiln: cannot write '" + path + "': " + reason));
}

const char* KindOf(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "a special file";
}

std::string FolderOf(const std::string& path) {
  size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string FileNameOf(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// --- The table of temporary files the signal handlers remove. Everything the handler touches
// is a lock-free atomic or a fixed char array: async-signal-safe.

constexpr int kSlots = 64;
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 registered
  char path[PATH_MAX] = {};   // with the atomic's {0}: constant-initialised, no start-up code
};
Slot g_slots[kSlots];

// 0: running, 1: committing (signals held back), 2: ending (a handler is removing the files).
std::atomic<int> g_phase{0};
std::atomic<int> g_pendingSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

int RegisterTemporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (g_slots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
      g_slots[i].state.store(2);
      return i;
    }
  }
  return -1;
}

void Unregister(int slot) {
  if (slot >= 0) g_slots[slot].state.store(0);
}

extern "C" void OnCleanupSignal(int sig) {
  int savedErrno = errno;
  g_pendingSignal.store(sig);
  int expected = 0;
  if (g_phase.compare_exchange_strong(expected, 2)) {
    for (Slot& s : g_slots)
      if (s.state.load() == 2) unlink(s.path);
    // Default action on return from this handler (the signal is blocked while it runs):
    // the process ends by `sig`, as if no handler had been installed.
    signal(sig, SIG_DFL);
    raise(sig);
  }
  // Committing: CommitAll raises the signal again after its last rename. Ending: another thread
  // is already ending the process.
  errno = savedErrno;
}

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

std::string RandomHex16() {
  unsigned char bytes[8];
  if (getrandom(bytes, sizeof bytes, GRND_NONBLOCK) != static_cast<ssize_t>(sizeof bytes)) {
    std::random_device rd;
    for (unsigned char& b : bytes) b = static_cast<unsigned char>(rd());
  }
  char hex[17];
  for (int i = 0; i < 8; ++i) std::snprintf(hex + 2 * i, 3, "%02x", bytes[i]);
  return hex;
}

/// True when `name` is "<something>.<pid>.<16 hex>.tmp"; sets `pid`.
bool ParseTemporaryName(const std::string& name, long& pid) {
  const size_t n = name.size();
  if (n < 4 + 17 + 2 + 1 || name.compare(n - 4, 4, ".tmp") != 0) return false;
  const size_t hexStart = n - 4 - 16;
  if (name[hexStart - 1] != '.') return false;
  for (size_t i = hexStart; i < n - 4; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return false;
  size_t pidEnd = hexStart - 1, pidStart = pidEnd;
  while (pidStart > 0 && std::isdigit(static_cast<unsigned char>(name[pidStart - 1]))) --pidStart;
  if (pidStart == pidEnd || pidEnd - pidStart > 9 || pidStart < 2 || name[pidStart - 1] != '.')
    return false;
  pid = std::stol(name.substr(pidStart, pidEnd - pidStart));
  return pid > 0;
}

}  // namespace

void CheckWritableTarget(const std::string& path) {
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0)
    return;  // missing (or unreachable: creating the file says why)
  if (S_ISREG(st.st_mode)) return;
  Fail(path, std::string("it is ") + KindOf(st.st_mode) +
                 ", not a regular file; kiln replaces only "
                 "regular files");
}

void InstallCleanupHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action {};
    action.sa_handler = OnCleanupSignal;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (int sig : kCleanupSignals) sigaddset(&action.sa_mask, sig);
    for (int sig : kCleanupSignals) {
      struct sigaction old {};
      if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // nohup
      sigaction(sig, &action, nullptr);
    }
  });
}

PendingFile::PendingFile(std::string path) : path_(std::move(path)) {
  CheckWritableTarget(path_);
  InstallCleanupHandlers();
  for (int attempt = 0; attempt < 16; ++attempt) {
    temporary_ = path_ + "." + std::to_string(getpid()) + "." + RandomHex16() + ".tmp";
    // Registered before it exists: a signal in between unlinks a name nobody else can own.
    slot_ = RegisterTemporary(temporary_);
    if (slot_ < 0) Fail(path_, "too many files written at once (or the path is too long)");
    fd_ = open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) return;
    int error = errno;
    Unregister(slot_);
    slot_ = -1;
    if (error != EEXIST)
      Fail(path_,
           "cannot create a temporary file in '" + FolderOf(path_) + "': " + std::strerror(error));
  }
  Fail(path_, "cannot create a temporary file with a fresh name in '" + FolderOf(path_) + "'");
}

PendingFile::~PendingFile() {
  if (!committed_ && !temporary_.empty() && fd_ >= 0) unlink(temporary_.c_str());
  Unregister(slot_);
  if (fd_ >= 0) close(fd_);
}

void PendingFile::Write(const std::function<void(const std::string& writePath)>& write) {
  struct stat own {};
  if (fstat(fd_, &own) != 0) Fail(path_, std::string("fstat: ") + std::strerror(errno));
  // /proc/self/fd/N reopens this very file whatever the folder holds under its name now.
  std::string writePath = "/proc/self/fd/" + std::to_string(fd_);
  struct stat viaProc {};
  if (stat(writePath.c_str(), &viaProc) != 0 || viaProc.st_ino != own.st_ino ||
      viaProc.st_dev != own.st_dev)
    writePath = temporary_;
  std::string reason;
  try {
    write(writePath);
  } catch (const std::exception& e) {
    reason = e.what();
  } catch (...) {
    reason = "unknown error";
  }
  if (!reason.empty()) {
    for (size_t at; writePath != temporary_ && (at = reason.find(writePath)) != std::string::npos;)
      reason.replace(at, writePath.size(), temporary_);
    Fail(path_, reason);
  }
  struct stat now {};
  if (lstat(temporary_.c_str(), &now) != 0 || !S_ISREG(now.st_mode) || now.st_ino != own.st_ino ||
      now.st_dev != own.st_dev)
    Fail(path_, "the temporary file '" + temporary_ + "' was replaced while it was written");
  if (fsync(fd_) != 0) Fail(path_, "cannot flush '" + temporary_ + "': " + std::strerror(errno));
  if (TestPauseBeforeRename(FileNameOf(path_))) TestPause("before renaming '" + temporary_ + "'");
}

void PendingFile::WriteBytes(const std::string& bytes) {
  Write([&](const std::string& writePath) { writeBytes(writePath, bytes); });
}

void PendingFile::CommitAll(const std::vector<PendingFile*>& files) {
  for (PendingFile* f : files) CheckWritableTarget(f->path_);
  // Hold SIGINT, SIGTERM, SIGHUP and SIGXFSZ back while renaming: the files land together.
  for (int expected = 0; !g_phase.compare_exchange_weak(expected, 1); expected = 0) {
    if (expected == 2)
      for (;;) pause();  // a handler is ending the process
    sched_yield();       // another thread is committing
  }
  std::string failure;
  for (PendingFile* f : files) {
    if (std::rename(f->temporary_.c_str(), f->path_.c_str()) != 0) {
      failure =
          f->path_ + "': cannot rename '" + f->temporary_ + "' into place: " + std::strerror(errno);
      break;
    }
    f->committed_ = true;
    Unregister(f->slot_);
    f->slot_ = -1;
  }
  g_phase.store(0);
  if (int sig = g_pendingSignal.exchange(0)) raise(sig);  // held back: handle it now
  if (!failure.empty()) throw std::runtime_error(OneLine("kiln: cannot write '" + failure));
}

FolderLock::FolderLock(const std::string& dir) {
  fd_ = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot open folder '" + dir +
                             "' to lock it: " + std::strerror(errno));
  int r = flock(fd_, LOCK_EX | LOCK_NB);
  if (r != 0 && errno == EWOULDBLOCK) {
    TestNote("waiting for the lock on '" + dir + "'");
    do r = flock(fd_, LOCK_EX);
    while (r != 0 && errno == EINTR);
  }
  if (r != 0) {
    int error = errno;
    close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot lock folder '" + dir + "': " + std::strerror(error));
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

int RemoveStaleTemporaries(const std::string& dir) {
  DIR* d = opendir(dir.c_str());
  if (!d) return 0;
  int removed = 0;
  const long self = static_cast<long>(getpid());
  while (dirent* e = readdir(d)) {
    long pid = 0;
    if (!ParseTemporaryName(e->d_name, pid) || pid == self) continue;
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue;  // alive (or not ours to judge)
    if (unlinkat(dirfd(d), e->d_name, 0) == 0) ++removed;
  }
  closedir(d);
  return removed;
}

void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& temporaryPath)>& write) {
  PendingFile file(path);
  file.Write(write);
  PendingFile::CommitAll({&file});
}

void writeBytes(const std::string& path, const std::string& bytes) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error("cannot create '" + path + "': " + std::strerror(errno));
  int error = 0;
  for (std::size_t done = 0; done < bytes.size() && error == 0;) {
    const ssize_t w = write(fd, bytes.data() + done, bytes.size() - done);
    if (w > 0)
      done += static_cast<std::size_t>(w);
    else if (w == 0)
      error = ENOSPC;  // nothing written and no error: the device is full
    else if (errno != EINTR)
      error = errno;
  }
  if (close(fd) != 0 && error == 0) error = errno;
  // The system's reason alone: the caller (PendingFile::Write) names the destination file.
  if (error != 0) throw std::runtime_error(std::strerror(error));
}

}  // namespace kiln
