// Runs the kiln binary the way a user does and captures what it prints.
#pragma once
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace kiln::test {

struct CommandResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Removes `path` and everything under it, as `rm -rf` does: a missing path or one that cannot be
/// removed is no error (the test's own checks say what matters), and no shell is started.
inline void RemoveTree(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
}

/// A fresh, empty folder /tmp/kiln_test_TAG_PID for one test (removed first if it exists).
inline std::string TempDir(const char* tag) {
  std::string dir = "/tmp/kiln_test_" + std::string(tag) + "_" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Splits `line` into the words /bin/sh would pass on, when it holds nothing but words: blanks
/// between them, '...' and "..." quotes and a backslash before one character. Returns false (and
/// the caller runs the line through the shell) at anything else the shell would act on:
/// redirections, pipes, lists, expansions ($, `), globs, ~, # and braces.
inline bool SplitShellWords(const std::string& line, std::vector<std::string>& words) {
  words.clear();
  std::string word;
  bool inWord = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ' ' || c == '\t') {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else if (c == '\'') {
      const size_t end = line.find('\'', i + 1);
      if (end == std::string::npos) return false;
      word.append(line, i + 1, end - i - 1);
      inWord = true;
      i = end;
    } else if (c == '"') {
      const size_t end = line.find('"', i + 1);
      if (end == std::string::npos) return false;
      const std::string inside = line.substr(i + 1, end - i - 1);
      if (inside.find_first_of("$`\\") != std::string::npos) return false;
      word += inside;
      inWord = true;
      i = end;
    } else if (c == '\\') {
      if (i + 1 == line.size() || line[i + 1] == '\n') return false;
      word += line[++i];
      inWord = true;
    } else if (c == '\0' || std::string("|&;<>()$`*?[]{}~#\n\r").find(c) != std::string::npos) {
      return false;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (inWord) words.push_back(word);
  return true;
}

/// Waits for `pid` at most `seconds` (0: no limit). Returns its wait status, or -1 when the
/// time ran out (the child still running).
inline int WaitWithin(pid_t pid, int seconds) {
  int status = 0;
  if (seconds <= 0) return waitpid(pid, &status, 0) == pid ? status : 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  const int fd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) break;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      if (fd >= 0) close(fd);
      return -1;
    }
    if (fd >= 0) {  // readable once the child has ended
      pollfd p{fd, POLLIN, 0};
      poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  if (fd >= 0) close(fd);
  return status;
}

/// Runs `argv` directly (no shell) with stdin from /dev/null and stdout and stderr into
/// `base`.out and .err. With `seconds` > 0 the child leads a process group of its own, killed
/// (SIGKILL) after that long as `timeout -s KILL` does: exit 137. A child ended by signal n
/// reports `signalExit` + n (`signalExit` < 0: -1). False when the spawn itself failed.
inline bool SpawnToFiles(const std::vector<std::string>& argv, const std::string& base, int seconds,
                         int signalExit, int& exitCode) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
  const std::string out = base + ".out", err = base + ".err";
  posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  if (seconds > 0) {
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &files, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  if (spawned != 0) return false;
  const int status = WaitWithin(pid, seconds);
  if (status == -1) {
    kill(-pid, SIGKILL);
    int ignored = 0;
    waitpid(pid, &ignored, 0);
    exitCode = 128 + SIGKILL;
  } else if (WIFEXITED(status)) {
    exitCode = WEXITSTATUS(status);
  } else {
    exitCode = signalExit < 0 || !WIFSIGNALED(status) ? -1 : signalExit + WTERMSIG(status);
  }
  return true;
}

/// Reads and removes `base`.out and .err into `r`.
inline void TakeOutput(const std::string& base, CommandResult& r) {
  r.out = ReadFile(base + ".out");
  r.err = ReadFile(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
}

/// Runs `kiln ARGS` (ARGS is shell-quoted by the caller) with stdin closed: as /bin/sh would run
/// the line `kiln ARGS`, and directly (posix_spawn, no shell) when ARGS holds only words and
/// quotes (SplitShellWords). A kiln ended by a signal reports exit -1.
inline CommandResult RunKiln(const std::string& args) {
  static int counter = 0;
  std::string base =
      "/tmp/kiln_cli_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  CommandResult r;
  std::vector<std::string> argv;
  if (!SplitShellWords(args, argv) ||
      (argv.insert(argv.begin(), KILN_BINARY), !SpawnToFiles(argv, base, 0, -1, r.exitCode))) {
    std::string cmd =
        std::string(KILN_BINARY) + " " + args + " </dev/null >" + base + ".out 2>" + base + ".err";
    int status = std::system(cmd.c_str());
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  TakeOutput(base, r);
  return r;
}

inline int CountLines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace kiln::test
