// libFuzzer target for the kiln runtime's EXR loader (runtime/src/exr_loader.cpp).
//
// Every input is written to an anonymous memory file (memfd, nothing on disk) and loaded with
// kiln::loadTable through its /proc/self/fd path. The contract checked (a violation aborts, which
// libFuzzer reports as a crash):
// - loadTable never throws and never crashes (ASan/UBSan watch the memory and arithmetic);
// - on failure the error is one non-empty line starting "kiln: cannot load table '";
// - on success the table passes validateTable, and sampling it anywhere (corners, NaN and
//   out-of-range coordinates) gives finite channels, with the linear and the cubic filter
//   (a cubic that overshoots the largest float saturates:
//   tests/fuzz_corpus/known-cubic-overflow.exr);
// - an input whose header declares an attribute larger than the input is refused: OpenEXR 3.1
//   would allocate the declared size (up to 2 GB) before reading it, so the loader checks the
//   sizes first (the regression files are tests/fuzz_corpus/oom-*.exr).
// See docs/stress.md for how to build and run it; the corpus to start from is
// tests/fuzz_corpus/ (small valid kiln tables and the crashers found so far).
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "kiln/exr_loader.h"

namespace {

[[noreturn]] void Violation(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_loader: contract violated: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// The file the inputs are written to: an anonymous memory file (memfd), reached by path through
/// /proc/self/fd, so that nothing is left in /tmp however a -fork job ends (a file per job was
/// left behind when it was a named temporary file). Empty when memfd_create is not available.
int InputFd() {
  static const int fd = memfd_create("kiln_fuzz_loader", 0);
  return fd;
}

const std::string& InputPath() {
  static const std::string path = "/proc/self/fd/" + std::to_string(InputFd());
  return path;
}

/// Replaces the memory file's contents with the input; false when it cannot.
bool WriteInput(const uint8_t* data, size_t size) {
  const int fd = InputFd();
  if (fd < 0 || ftruncate(fd, 0) != 0) return false;
  size_t done = 0;
  while (done < size) {
    ssize_t n = pwrite(fd, data + done, size - done, static_cast<off_t>(done));
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

void CheckSampling(const kiln::Table& table) {
  const kiln::LutView view = table.view();
  if (!view.valid()) Violation("loaded table gives an invalid view", table.name);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  float out[64];
  if (table.channels.size() > 64) return;  // sampling needs an output per channel
  for (double probe : {-1e300, 0.0, 0.25, 0.5, 1.0, 1e300, nan}) {
    double x[3];
    for (int d = 0; d < 3; ++d) {
      const kiln::Axis& a = view.axis[d];
      x[d] = probe >= 0 && probe <= 1 ? a.lo + (a.hi - a.lo) * probe : probe;
    }
    for (kiln::Filter filter : {kiln::Filter::Linear, kiln::Filter::Cubic}) {
      view.sample(x, out, filter);
      for (size_t c = 0; c < table.channels.size(); ++c)
        if (!std::isfinite(out[c])) Violation("non-finite sample", table.name);
    }
  }
}

/// True when the OpenEXR header declares an attribute larger than the whole input (see above);
/// a simpler walk than the loader's (one part, short names), enough to say "must be refused".
bool DeclaresOversizedAttribute(const uint8_t* data, size_t size) {
  size_t p = 8;  // magic and version
  auto cstring = [&](size_t& at) {
    while (at < size && data[at] != 0) ++at;
    return at < size ? at++ : size;  // index of the NUL, or size when missing
  };
  for (int guard = 0; guard < 10000 && p < size; ++guard) {
    size_t nameStart = p, nameEnd = cstring(p);
    if (nameEnd == size || nameEnd == nameStart) return false;  // truncated, or end of header
    if (cstring(p) == size || p + 4 > size) return false;       // type
    uint32_t declared = uint32_t(data[p]) | uint32_t(data[p + 1]) << 8 |
                        uint32_t(data[p + 2]) << 16 | uint32_t(data[p + 3]) << 24;
    p += 4;
    if (declared > size) return true;
    p += declared;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool oversized = DeclaresOversizedAttribute(data, size);
  if (!WriteInput(data, size)) {
    std::fprintf(stderr, "fuzz_loader: cannot write the input to a memory file\n");
    std::abort();
  }
  const std::string& path = InputPath();

  kiln::Table table;
  std::string error;
  bool ok = kiln::loadTable(path, table, error);
  if (ok) {
    if (oversized) Violation("a table declaring an oversized attribute was loaded", table.name);
    std::string problem;
    if (!kiln::validateTable(table, problem)) Violation("loaded table is not valid", problem);
    CheckSampling(table);
  } else {
    if (error.empty()) Violation("failure without a message", "");
    if (error.find('\n') != std::string::npos) Violation("message on several lines", error);
    if (error.rfind("kiln: cannot load table '", 0) != 0)
      Violation("message without the prefix", error);
  }
  return 0;
}
