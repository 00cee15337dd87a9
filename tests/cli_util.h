// Runs the kiln binary the way a user does and captures what it prints.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

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

/// A fresh, empty folder /tmp/kiln_test_TAG_PID for one test (removed first if it exists).
inline std::string TempDir(const char* tag) {
  std::string dir = "/tmp/kiln_test_" + std::string(tag) + "_" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs `kiln ARGS` (ARGS is shell-quoted by the caller) with stdin closed.
inline CommandResult RunKiln(const std::string& args) {
  static int counter = 0;
  std::string base =
      "/tmp/kiln_cli_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  std::string cmd =
      std::string(KILN_BINARY) + " " + args + " </dev/null >" + base + ".out 2>" + base + ".err";
  int status = std::system(cmd.c_str());
  CommandResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadFile(base + ".out");
  r.err = ReadFile(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

inline int CountLines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace kiln::test
