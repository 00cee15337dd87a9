// How many threads kiln may start: -j asks, the address space (ulimit -v) decides.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "baker/cli/commands.h"

namespace kiln::cli {
namespace {

/// Address space one more thread may take: a glibc malloc arena (64 MiB reserved per arena on
/// 64-bit, and glibc makes up to 8 per core) and a worker stack (oneTBB's 4 MiB, glibc's 8 MiB
/// for other threads).
constexpr unsigned long long kThreadAddressSpace = (64ull + 8ull) << 20;

/// The address space this process maps now (/proc/self/statm, first field, in pages); 0 when
/// it cannot be read.
unsigned long long MappedBytes() {
  std::ifstream statm("/proc/self/statm");
  unsigned long long pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<unsigned long long>(sysconf(_SC_PAGESIZE));
}

}  // namespace

int ThreadLimit() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kMaxThreads;
  unsigned long long cap = limit.rlim_cur, used = MappedBytes();
  // Half of what is left goes to threads, the other half stays for the tables and their work.
  unsigned long long spare = cap > used ? (cap - used) / 2 : 0;
  return static_cast<int>(std::clamp<unsigned long long>(
      spare / kThreadAddressSpace, 1, static_cast<unsigned long long>(kMaxThreads)));
}

int ThreadsToRun(int requested, int limit) {
  if (requested <= limit) return requested;
  std::fprintf(stderr,
               "kiln: warning: -j %d: running %d thread%s (the address-space limit, ulimit -v, "
               "leaves room for no more)\n",
               requested, limit, limit == 1 ? "" : "s");
  return limit;
}

}  // namespace kiln::cli
