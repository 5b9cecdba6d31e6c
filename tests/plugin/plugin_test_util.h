// Copyright contactlaws authors.
//
// Running a program with libcontactlaws_plugin.so preloaded (or not), from
// the tests of tests/plugin/: stdout and stderr apart, and the exit status.

#ifndef CONTACTLAWS_TESTS_PLUGIN_PLUGIN_TEST_UTIL_H_
#define CONTACTLAWS_TESTS_PLUGIN_PLUGIN_TEST_UTIL_H_

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "process_util.h"
#include "test_programs.h"

namespace contactlaws::testing {

struct ProgramResult {
  int status = -1;     // exit status; -1 when killed by a signal
  int signal = 0;      // the signal that ended it
  std::string out;     // stdout
  std::string err;     // stderr
};

// A file name of this test process's own in the test temporary directory
// (ctest runs the tests of one executable as processes side by side).
inline std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "/plugin_" + std::to_string(getpid()) + "_" + name;
}

// Runs `environment command` through the shell.
inline ProgramResult RunProgram(const std::string& environment, const std::string& command) {
  const std::string err_path = TempPath("stderr.txt");
  const ShellResult r = RunShell(environment + " " + command + " 2>" + err_path);
  ProgramResult result;
  result.status = r.status;
  result.signal = r.signal;
  result.out = r.out;
  result.err = ReadFile(err_path);
  return result;
}

inline std::string Preload() { return std::string("LD_PRELOAD=") + CONTACTLAWS_PLUGIN; }

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_PLUGIN_PLUGIN_TEST_UTIL_H_
