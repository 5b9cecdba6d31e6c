// Copyright contactlaws authors.
//
// The contactlaws program run as a user runs it, from the tests of tests/cli/.

#ifndef CONTACTLAWS_TESTS_CLI_CLI_TEST_UTIL_H_
#define CONTACTLAWS_TESTS_CLI_CLI_TEST_UTIL_H_

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"
#include "process_util.h"
#include "test_programs.h"

namespace contactlaws::testing {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

inline Result RunCli(const std::string& arguments) {
  const ShellResult r = RunShell(std::string(CONTACTLAWS_CLI) + " " + arguments + " 2>&1");
  return {r.status, r.out};
}

// Starts the program with arguments in a child process, its stdout and
// stderr written to log (a previous log removed); its pid (-1 on failure).
inline pid_t SpawnCli(const std::vector<std::string>& arguments, const std::string& log) {
  std::remove(log.c_str());
  const pid_t pid = fork();
  if (pid != 0) return pid;
  std::FILE* out = std::fopen(log.c_str(), "w");
  dup2(fileno(out), STDOUT_FILENO);
  dup2(fileno(out), STDERR_FILENO);
  std::vector<char*> argv = {const_cast<char*>(CONTACTLAWS_CLI)};
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(CONTACTLAWS_CLI, argv.data());
  _exit(127);
}

inline const std::string kBall = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";

inline std::string WriteScene(const std::string& name, const std::string& xml) {
  const std::string path = ::testing::TempDir() + "/" + name + ".xml";
  std::ofstream(path) << xml;
  return path;
}

// A ball over two planes, and a capsule on the ball's body (group 1).
inline std::string TagScene(const std::string& tags, const std::string& extra = "") {
  return fmt::format(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <geom name="floor2" type="plane" size="1 1 0.1" pos="0 0 -1"/>
    <body name="ball" pos="0 0 0.2">
      <freejoint/>
      <geom name="ball" type="sphere" size="0.1" mass="1"/>
      <geom name="cap" type="capsule" size="0.05 0.1" pos="0.3 0 0" group="1"/>
    </body>
  </worldbody>
  {}
  <custom>{}</custom>
</mujoco>)",
                     extra, tags);
}

inline std::string Tag(const std::string& data, const std::string& label = "t") {
  return fmt::format(R"(<text name="contactlaw:{}" data="{}"/>)", label, data);
}

// A ball 1 cm above a floor, falling from rest under gravity (RK4, 1e-5 s):
// first touch at 0.045 s, 0.44 m/s; written to the test's temporary directory.
inline std::string TinyScene() {
  const std::string path = ::testing::TempDir() + "/cli_tiny.xml";
  std::ofstream(path) << contactlaws::testing::DropXml(
      "law=flores restitution=0.9 stiffness=1.4e8 linear_stiffness=5e6", 0.0, "RK4", 1e-5,
      /*gravity=*/true, /*mass=*/1.0, /*height=*/0.11);
  return path;
}

inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The fields of one CSV line (no quoting).
inline std::vector<std::string> Split(const std::string& line, char separator) {
  std::vector<std::string> fields(1);
  for (const char c : line) {
    if (c == separator) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_CLI_CLI_TEST_UTIL_H_
