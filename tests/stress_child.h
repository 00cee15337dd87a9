// A kiln process the stress tests start, talk to and interrupt: stderr on a pipe, extra
// environment variables (the test pause points of baker/io/test_hooks.h), signals on demand.
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

extern char** environ;

namespace kiln::stress {

/// `kiln ARGS...` started with `env` ("NAME=value") added to the environment, stdin and stdout on
/// /dev/null, stderr on a pipe the test reads. Killed (SIGKILL) and reaped by the destructor if the
/// test did not wait for it.
class KilnChild {
 public:
  KilnChild(const std::vector<std::string>& args, const std::vector<std::string>& env) {
    // Everything execve needs is built before fork: the child only calls async-signal-safe
    // functions.
    std::vector<std::string> argStrings = {KILN_BINARY};
    argStrings.insert(argStrings.end(), args.begin(), args.end());
    std::vector<char*> argv, envp;
    for (std::string& a : argStrings) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> envStrings = env;
    for (char** e = environ; *e; ++e) envStrings.emplace_back(*e);
    for (std::string& e : envStrings) envp.push_back(e.data());
    envp.push_back(nullptr);
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      // A signal the test runner ignores (a background job ignores SIGINT) would stay ignored.
      for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGUSR1}) signal(sig, SIG_DFL);
      sigset_t none;
      sigemptyset(&none);
      sigprocmask(SIG_SETMASK, &none, nullptr);
      int null = open("/dev/null", O_RDWR);
      dup2(null, STDIN_FILENO);
      dup2(null, STDOUT_FILENO);
      dup2(fds[1], STDERR_FILENO);
      close(fds[0]);
      execve(argv[0], argv.data(), envp.data());
      _exit(127);
    }
    close(fds[1]);
    err_ = fds[0];
  }
  KilnChild(const KilnChild&) = delete;
  KilnChild& operator=(const KilnChild&) = delete;
  ~KilnChild() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      Wait();
    }
    if (err_ >= 0) close(err_);
  }
  bool Started() const { return pid_ > 0 && err_ >= 0; }
  /// Reads stderr until a line starting "kiln: test pause: " arrives and returns that line; ""
  /// when the process closed stderr (ended) first. Blocks on the pipe: no timing involved.
  std::string WaitForPause() { return WaitForLine("kiln: test pause: "); }
  /// Reads stderr until a line starting with `mark` arrives and returns it (from `mark` on); ""
  /// when the process ended first.
  std::string WaitForLine(const std::string& mark) {
    for (;;) {
      size_t at = err.find(mark);
      if (at != std::string::npos) {
        size_t end = err.find('\n', at);
        if (end != std::string::npos) return err.substr(at, end - at);
      }
      if (!ReadSome()) return "";
    }
  }
  /// Sends `sig` to the process.
  void Signal(int sig) { kill(pid_, sig); }
  /// Reads stderr to its end and reaps the process; returns its wait status.
  int Wait() {
    if (!reaped_) {
      while (ReadSome()) {
      }
      waitpid(pid_, &status_, 0);
      reaped_ = true;
    }
    return status_;
  }
  std::string err;  ///< what the process wrote on stderr so far

 private:
  bool ReadSome() {
    char buf[512];
    ssize_t n;
    do n = read(err_, buf, sizeof buf);
    while (n < 0 && errno == EINTR);
    if (n <= 0) return false;
    err.append(buf, static_cast<size_t>(n));
    return true;
  }
  pid_t pid_ = -1;
  int err_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

/// The spec_hash of table `name` in DIR/manifest.json: "" when the manifest has no such entry,
/// "<no manifest>" or "<not JSON>" when the file is missing or not valid JSON.
inline std::string ManifestSpecHash(const std::string& dir, const std::string& name) {
  std::ifstream in(dir + "/manifest.json");
  if (!in) return "<no manifest>";
  nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return "<not JSON>";
  if (doc.is_object() && doc.contains("tables") && doc["tables"].is_array())
    for (const auto& e : doc["tables"])
      if (e.is_object() && e.value("name", "") == name) return e.value("spec_hash", "");
  return "";
}

/// True when the wait status says the process ended by signal `sig`.
inline bool EndedBySignal(int status, int sig) {
  return WIFSIGNALED(status) && WTERMSIG(status) == sig;
}

}  // namespace kiln::stress
