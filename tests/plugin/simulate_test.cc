// Copyright contactlaws authors.
//
// contactlaws simulate: MuJoCo's own viewer, mujoco-simulate (Debian's
// libmujoco-samples), started with the plugin under a virtual X server
// (Xvfb), runs the paper's ball for a few seconds with the laws active, until
// it is stopped; and a missing viewer is one line naming its package.

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/friction.h"
#include "plugin_test_util.h"

namespace contactlaws {
namespace {

using testing::ProgramResult;
using testing::RunProgram;

// Seconds the viewer runs before timeout stops it (SIGINT); timeout's exit
// status 124 says it was still running then, so it had not crashed.
constexpr int kViewerSeconds = 4;
constexpr int kStillRunningStatus = 124;

bool OnPath(const std::string& program) {
  return std::system(fmt::format("command -v {} > /dev/null", program).c_str()) == 0;
}

const std::string kBall = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";

TEST(SimulateTest, MujocoSimulateRunsTheBallWithThePlugin) {
  if (!OnPath("mujoco-simulate") || !OnPath("xvfb-run")) {
    GTEST_SKIP() << "mujoco-simulate (libmujoco-samples) or xvfb-run (xvfb) is not installed "
                    "(scripts/install-deps.sh installs both)";
  }
  const ProgramResult r = RunProgram(
      "", fmt::format("xvfb-run -a -s '-screen 0 1024x768x24' timeout -s INT {} {} simulate {} "
                      "--restitution 0.7 --friction stribeck --mu 0.4", kViewerSeconds,
                      CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(r.status, kStillRunningStatus) << "signal " << r.signal << "\n" << r.err;
  EXPECT_NE(r.err.find(fmt::format("contactlaws: plugin: {}: ball-floor (ball, floor: flores, "
                                   "e = 0.7, stribeck mu 0.4)\n", kBall)),
            std::string::npos)
      << r.err;
}

TEST(SimulateTest, MissingViewerIsOneLineNamingItsPackage) {
  const ProgramResult r =
      RunProgram("PATH=/nonexistent", fmt::format("{} simulate {}", CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "contactlaws: simulate needs mujoco-simulate, which is not on PATH (Debian "
                   "package libmujoco-samples)\n");
}

TEST(SimulateTest, RefusedOverrideIsRunsLineBeforeAnyWindow) {
  const ProgramResult r = RunProgram(
      "PATH=/nonexistent", fmt::format("{} simulate {} --restitution 1.5", CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "contactlaws: --restitution=1.5 must be in [0, 1]\n");
  const ProgramResult friction = RunProgram(
      "PATH=/nonexistent", fmt::format("{} simulate {} --friction lugra", CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(friction.status, 2);
  EXPECT_EQ(friction.err, "contactlaws: --friction=lugra is not a friction model (" +
                              FrictionNameList() + "): did you mean 'lugre'?\n");
  const ProgramResult mu = RunProgram(
      "PATH=/nonexistent", fmt::format("{} simulate {} --mu -1", CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(mu.status, 2);
  EXPECT_EQ(mu.err, "contactlaws: --mu=-1 must be >= 0\n");
}

TEST(SimulateTest, RefusedAccuracyIsRunsLineBeforeAnyWindow) {
  const ProgramResult r = RunProgram(
      "PATH=/nonexistent", fmt::format("{} simulate {} --accuracy 0.5", CONTACTLAWS_CLI, kBall));
  const ProgramResult run = RunProgram(
      "", fmt::format("{} run {} --accuracy 0.5 --duration 1e-3", CONTACTLAWS_CLI, kBall));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "contactlaws: --accuracy=0.5 must be a number in (0, 0.1] (relative error)\n");
  EXPECT_EQ(r.err, run.err);
}

TEST(SimulateTest, RefusedContactStepsIsRunsLineBeforeAnyWindow) {
  for (const char* options : {"--contact-steps 0", "--contact-steps auto --accuracy 1e-3"}) {
    const ProgramResult r = RunProgram(
        "PATH=/nonexistent", fmt::format("{} simulate {} {}", CONTACTLAWS_CLI, kBall, options));
    const std::string run_options =
        std::string(options).find("--accuracy") != std::string::npos
            ? "--contact-steps auto --timestep auto" : options;
    const ProgramResult run = RunProgram(
        "", fmt::format("{} run {} {} --duration 1e-3", CONTACTLAWS_CLI, kBall, run_options));
    EXPECT_EQ(r.status, 2) << options;
    EXPECT_EQ(r.err, run.err) << options;
    EXPECT_NE(r.err.find("contactlaws: --contact-steps="), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace contactlaws
