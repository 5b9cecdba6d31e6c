// Copyright contactlaws authors.
//
// Running a shell command from a test, and reading a file whole: what the
// tests of the program (tests/cli), of the plugin (tests/plugin) and of
// scenes read from mjcf/ share.

#ifndef CONTACTLAWS_TESTS_PROCESS_UTIL_H_
#define CONTACTLAWS_TESTS_PROCESS_UTIL_H_

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace contactlaws::testing {

// How a command ended, and what it wrote to stdout.
struct ShellResult {
  int status = -1;  // exit status; -1 when killed by a signal
  int signal = 0;   // the signal that ended it, or 0
  std::string out;  // stdout (redirect stderr in the command to keep it)
};

// Runs command through the shell (/bin/sh -c), reading its stdout to the end.
inline ShellResult RunShell(const std::string& command) {
  ShellResult result;
  std::FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) result.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

// The whole of a file ("" when it cannot be read).
inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_PROCESS_UTIL_H_
