// Test pause points (baker/io/test_hooks.h).
#include "baker/io/test_hooks.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>

namespace kiln {

std::size_t TestPauseAfterTexels() {
  static const std::size_t n = [] {
    const char* text = std::getenv("KILN_TEST_PAUSE_AFTER_TEXELS");
    if (!text || !*text) return std::size_t(0);
    char* end = nullptr;
    unsigned long long v = std::strtoull(text, &end, 10);
    return *end == '\0' ? static_cast<std::size_t>(v) : std::size_t(0);
  }();
  return n;
}

bool TestPauseBeforeRename(const std::string& fileName) {
  static const std::string name = [] {
    const char* text = std::getenv("KILN_TEST_PAUSE_BEFORE_RENAME");
    return std::string(text ? text : "");
  }();
  return !name.empty() && name == fileName;
}

void TestNote(const std::string& what) {
  static const bool enabled = [] {
    const char* text = std::getenv("KILN_TEST_NOTES");
    return text && *text;
  }();
  if (!enabled) return;
  std::string line = "kiln: test note: " + what + "\n";
  ssize_t written = write(STDERR_FILENO, line.data(), line.size());
  (void)written;
}

namespace {

std::atomic<bool> g_resume{false};

extern "C" void OnResume(int) { g_resume.store(true); }

}  // namespace

void TestPause(const std::string& what) {
  struct sigaction action {};
  action.sa_handler = OnResume;
  sigemptyset(&action.sa_mask);
  sigaction(SIGUSR1, &action, nullptr);
  g_resume.store(false);
  std::string line = "kiln: test pause: " + what + "\n";
  ssize_t written = write(STDERR_FILENO, line.data(), line.size());
  (void)written;
  // SIGUSR1 may reach any thread, so the flag is polled rather than waited for with sigsuspend.
  while (!g_resume.load()) usleep(1000);
}

}  // namespace kiln
