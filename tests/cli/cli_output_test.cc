// Copyright contactlaws authors.
//
// What contactlaws writes, read as a user reads it: the impact log per
// impact, the trajectory's groups, fields at the start of a run, warnings.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/cli_test_util.h"
#include "contactlaws/auto_timestep.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using testing::kBall;
using testing::Lines;
using testing::Split;
using testing::ReadFile;
using testing::Result;
using testing::RunCli;
using testing::TinyScene;

// A flat box landing on its four corners: one row per impact of the pair,
// with its four points and their total force; --impacts-per-point gives each
// corner's own row.
TEST(CliTest, TheImpactLogHasARowPerImpactOfAPair) {
  const std::string scene = testing::WriteScene("flat_box", R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="box" pos="0 0 0.1"><freejoint/>
      <geom name="box" type="box" size="0.1 0.06 0.03" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:box-floor"
    data="geom1=box geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)");
  const std::string dir = ::testing::TempDir();
  const Result r = RunCli("run " + scene + " --duration 0.3 --impacts " + dir + "/box.csv");
  ASSERT_EQ(r.status, 0) << r.output;
  const Result p = RunCli("run " + scene + " --duration 0.3 --impacts-per-point --impacts " +
                          dir + "/box_points.csv");
  ASSERT_EQ(p.status, 0) << p.output;
  const std::vector<std::string> impacts = Lines(ReadFile(dir + "/box.csv"));
  const std::vector<std::string> points = Lines(ReadFile(dir + "/box_points.csv"));
  ASSERT_GE(impacts.size(), 3u) << "the box lands and bounces";
  // each impact on four corners, each corner a row of its own
  auto column = [&](const std::string& name) {
    const std::vector<std::string> header = Split(impacts[0], ',');
    return static_cast<int>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  auto field = [](const std::string& row, int k) { return Split(row, ',').at(k); };
  EXPECT_EQ(points.size() - 1, 4 * (impacts.size() - 1));
  for (size_t i = 1; i < impacts.size(); ++i) {
    EXPECT_EQ(field(impacts[i], column("points")), "4");
  }
  for (size_t i = 1; i < points.size(); ++i) EXPECT_EQ(field(points[i], column("points")), "1");
  // the first impact's largest force is the four corners' together: each
  // corner carries a quarter (the box lands flat), to the rounding of the sum
  const int max_force = column("max_force");
  const double pair_force = std::stod(field(impacts[1], max_force));
  for (size_t i = 1; i <= 4; ++i) {
    EXPECT_NEAR(std::stod(field(points[i], max_force)), pair_force / 4, 1e-9 * pair_force)
        << points[i];
  }
  EXPECT_NE(r.output.find("collisions"), std::string::npos) << r.output;
}

// A pair type whose depths MuJoCo gets only roughly is run, with one warning
// naming the pair and the reason, by run and check alike.
TEST(CliTest, AnUntrustedPairTypeIsWarnedAbout) {
  const std::string scene = testing::WriteScene("can_on_box", R"(<mujoco>
  <worldbody>
    <body name="base" pos="0 0 0"><geom name="base" type="box" size="0.3 0.3 0.05"/></body>
    <body name="can" pos="0 0 0.2"><freejoint/>
      <geom name="can" type="cylinder" size="0.05 0.08" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:can-base"
    data="geom1=can geom2=base law=hunt-crossley restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)");
  for (const std::string command : {"run --duration 0.01 ", "check "}) {
    const Result r = RunCli(command + scene);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("contactlaws: warning: " + scene +
                            ": contactlaw:can-base: (can, base): "),
              std::string::npos)
        << command << ": " << r.output;
  }
}

// A ball resting in contact when the run starts: its contact opens at t = 0
// (not before), at its rate then; no CSV field is -0, inf or nan.
TEST(CliTest, AContactOpenAtTheStartOpensThere) {
  const std::string scene = testing::WriteScene(
      "resting", testing::DropXml("law=hunt-crossley restitution=0.5 stiffness=1e8", 0.0,
                                  "RK4", 1e-5, true, 1.0, 0.1 - 1e-6));
  const std::string dir = ::testing::TempDir();
  const Result r = RunCli("run " + scene + " --duration 0.02 --output " + dir +
                          "/resting.csv --impacts " + dir + "/resting_impacts.csv");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> impacts = Lines(ReadFile(dir + "/resting_impacts.csv"));
  ASSERT_GE(impacts.size(), 2u);
  const std::vector<std::string> header = Split(impacts[0], ',');
  const std::vector<std::string> first = Split(impacts[1], ',');
  auto field = [&](const std::string& name) {
    return first.at(std::find(header.begin(), header.end(), name) - header.begin());
  };
  EXPECT_EQ(field("time_contact"), "0") << impacts[1];
  for (const char* file : {"/resting.csv", "/resting_impacts.csv"}) {
    const std::string csv = ReadFile(dir + file);
    for (const char* bad : {",-0,", ",-0\n", "inf", "nan"}) {
      EXPECT_EQ(csv.find(bad), std::string::npos) << file << " has " << bad;
    }
  }
}

// --columns picks the trajectory's groups; a bad group is named.
TEST(CliTest, ColumnsPickTheTrajectorysGroups) {
  const Result r = RunCli("run " + kBall + " --duration 0.002 --columns pairs,energy --output -");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.substr(0, r.output.find('\n')),
            "time,ball-floor.depth,ball-floor.depth_rate,ball-floor.force,energy.kinetic,"
            "energy.potential,energy.elastic,energy.dissipated,energy.total");
  EXPECT_EQ(RunCli("run " + kBall + " --columns bodies,joint").output,
            "contactlaws: --columns=bodies,joint has 'joint', which is not a group (bodies, "
            "joints, pairs, friction, energy)\n");
  EXPECT_EQ(RunCli("run " + kBall + " --columns energy,energy").output,
            "contactlaws: --columns=energy,energy names energy twice\n");
}

// check takes --timestep auto as run does, and says what steps it would take.
TEST(CliTest, CheckTakesTheAutoTimestep) {
  const Result r = RunCli("check " + kBall + " --timestep auto");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("  --timestep auto: steps of 2.66e-05 s near and in this contact (50 "
                          "per contact, accuracy 0.001)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("TOO COARSE"), std::string::npos) << r.output;
}

TEST(CliOutputTest, AContactThatWouldHangAtRestIsWarnedBeforeTheRunAndInCheck) {
  // flores e = 0.2 (a = 6.4) at the v0 floor 1e-3 m/s under 9.81 N: lag
  // 1e-3 / (6.4 g) = 1.59e-5 s; 1e-4 s is 6 lags (it hangs: auto_timestep_test)
  const auto box = [](const std::string& keys) {
    return testing::CubeOnFloorXml(1e-4, 0.04996, "law=flores restitution=0.2 " + keys);
  };
  const std::string scene = testing::WriteScene("hangs_at_rest", box(""));
  const Result run = RunCli("run " + scene + " --duration 0.001");
  EXPECT_NE(run.output.find("contactlaw:box (box, floor): timestep 0.0001 s is longer than 2 lags "
                            "of its law's damping at rest (lag 1.59e-05 s: flores under the "
                            "weight 9.81 N at the v0 floor min_impact_velocity 0.001 m/s)"),
            std::string::npos)
      << run.output;
  const Result check = RunCli("check " + scene);
  EXPECT_NE(check.output.find("at rest: damping lag 1.59e-05 s under the weight 9.81 N at the v0 "
                              "floor 0.001 m/s: TOO COARSE (needs timestep <= 3.19e-05 s, or a "
                              "larger min_impact_velocity)"),
            std::string::npos)
      << check.output;
  // a floor of 1e-2 m/s: ten times the lag, no warning
  const std::string raised =
      testing::WriteScene("rests", box("min_impact_velocity=1e-2"));
  EXPECT_EQ(RunCli("run " + raised + " --duration 0.001").output.find("at rest"), std::string::npos);
  const Result fine = RunCli("check " + raised);
  EXPECT_NE(fine.output.find("at rest: damping lag 0.000159 s"), std::string::npos) << fine.output;
}

// Occurrences of what in text.
int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The lead's slide.xml block, 0.1 mm into its floor: 40 N against its 1.962 N
// weight (zhiying-qishao, 4 corners). Its runs warn once and point to
// --settle; check takes the damper's lag at that depth (20.4x shorter than at
// rest) and flags 5e-5 s. At its static depth neither happens.
TEST(CliOutputTest, ABlockStartingDeepIsWarnedOnceAndCheckTakesTheStartsDepth) {
  const std::string deep = testing::WriteScene("starts_deep", testing::SlidingBlockXml(1e-4));
  const std::string warning =
      "contactlaw:block-floor (block, floor): starts 0.0001 m deep in contact: its law pushes "
      "with 40 N against the 1.962 N that presses it (20.4 times, beyond the 2.5 times of a "
      "body placed touching; at rest under that load its 4 points would be 1.34e-05 m deep)";
  const Result run = RunCli("run " + deep + " --duration 0.001");
  EXPECT_EQ(Count(run.output, warning), 1) << run.output;
  EXPECT_NE(run.output.find("--settle moves the bodies in contact into the static equilibrium"),
            std::string::npos)
      << run.output;
  const Result compare = RunCli("compare " + deep + " --laws zhiying-qishao --restitution "
                                "0.3,0.6 --duration 0.001 --quiet --output-dir " +
                                ::testing::TempDir() + "/starts_deep");
  EXPECT_EQ(Count(compare.output, warning), 1) << compare.output;
  const Result settled = RunCli("run " + deep + " --duration 0.001 --settle");
  EXPECT_EQ(settled.output.find("deep in contact"), std::string::npos) << settled.output;

  const Result check = RunCli("check " + deep);
  EXPECT_NE(check.output.find("  at rest: damping lag 3.68e-05 s under the weight 1.962 N at the "
                              "v0 floor 0.001 m/s: ok"),
            std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("  at the start: damping lag 1.81e-06 s at the depth 0.0001 m of "
                              "contactlaw:block-floor (block, floor), its law's force 40 N "
                              "against the load 1.962 N: TOO COARSE (needs timestep <= "
                              "3.61e-06 s, or --settle)"),
            std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("warning: 1 tag(s) need a smaller timestep"), std::string::npos)
      << check.output;

  // 4 K d^1.5 = 1.962 N
  const std::string rest = testing::WriteScene(
      "starts_at_rest", testing::SlidingBlockXml(std::pow(1.962 / 4e7, 1 / 1.5)));
  const Result quiet = RunCli("run " + rest + " --duration 0.001");
  EXPECT_EQ(quiet.output.find("deep in contact"), std::string::npos) << quiet.output;
  const Result fine = RunCli("check " + rest);
  // its lag at the start is the one at rest: check's table is unchanged
  EXPECT_NE(fine.output.find("  at rest: damping lag 3.68e-05 s"), std::string::npos)
      << fine.output;
  EXPECT_EQ(fine.output.find("at the start"), std::string::npos) << fine.output;
  EXPECT_EQ(fine.output.find("warning:"), std::string::npos) << fine.output;
}

// The text in text between the first before and the after that follows it
// ("" when either is missing).
std::string Between(const std::string& text, const std::string& before, const std::string& after) {
  const size_t from = text.find(before);
  if (from == std::string::npos) return "";
  const size_t to = text.find(after, from + before.size());
  if (to == std::string::npos) return "";
  return text.substr(from + before.size(), to - from - before.size());
}

// A fixed-step run takes the damper's lag where a pair starts as check does:
// the block 0.1 mm deep at 5e-5 s is warned with check's step and its
// divergence names it; mjcf/friction_slide_roll.xml's ball starts 0.1 mm
// deep with 10 N against its 9.81 N weight, its lag there 1.33e-4 s against
// 1.36e-4 s at rest: a step between the two lags' 2 is warned, one within
// both is not. The block at its static depth is warned as before.
TEST(CliOutputTest, AFixedStepRunTakesTheLagWhereAPairStartsAsCheckDoes) {
  const std::string deep = testing::WriteScene("starts_deep_run", testing::SlidingBlockXml(1e-4));
  const std::string needs =
      Between(RunCli("check " + deep).output, "  at the start: damping lag 1.81e-06 s",
              " s, or --settle)");
  ASSERT_NE(needs.find("(needs timestep <= 3.61e-06"), std::string::npos) << needs;
  const std::string step = needs.substr(needs.find("<= ") + 3);
  const Result run = RunCli("run " + deep + " --timestep 5e-5 --duration 0.002");
  EXPECT_NE(run.output.find("contactlaw:block-floor (block, floor): timestep 5e-05 s is longer "
                            "than 2 lags of its law's damping where it starts (lag 1.81e-06 s at "
                            "the depth 0.0001 m, its law's force 40 N against the load 1.962 N): "
                            "use --timestep " + step + " or smaller, or --settle\n"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("diverged at t = 0.00115 s"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("likely cause: the timestep 5e-05 s is longer than 2 lags of the "
                            "law's damping where contactlaw:block-floor (block, floor) starts, "
                            "1.81e-06 s at the depth 0.0001 m (--timestep " + step +
                            ", or --settle)"),
            std::string::npos)
      << run.output;

  const std::string ball = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/friction_slide_roll.xml";
  const std::string where = "longer than 2 lags of its law's damping where it starts";
  const std::string between = RunCli("check " + ball + " --timestep 2.7e-4").output;
  EXPECT_NE(between.find("TOO COARSE (needs timestep <= 0.000267 s, or --settle)"),
            std::string::npos)
      << between;
  const Result coarse = RunCli("run " + ball + " --timestep 2.7e-4 --duration 0.01");
  EXPECT_NE(coarse.output.find("(ball, floor): timestep 0.00027 s is " + where +
                               " (lag 0.000133 s at the depth 0.0001 m, its law's force 10 N "
                               "against the load 9.81 N): use --timestep 0.000267 or smaller"),
            std::string::npos)
      << coarse.output;
  const Result fine = RunCli("run " + ball + " --timestep 2.6e-4 --duration 0.01");
  EXPECT_EQ(fine.output.find(where), std::string::npos) << fine.output;

  // 4 K d^1.5 = 1.962 N: its lag at the start is the one at rest
  const std::string rest = testing::WriteScene(
      "starts_at_rest_run", testing::SlidingBlockXml(std::pow(1.962 / 4e7, 1 / 1.5)));
  const Result resting = RunCli("run " + rest + " --timestep 1e-4 --duration 0.001");
  EXPECT_EQ(resting.output.find(where), std::string::npos) << resting.output;
  EXPECT_NE(resting.output.find("(block, floor): timestep 0.0001 s is longer than 2 lags of its "
                                "law's damping at rest"),
            std::string::npos)
      << resting.output;
}

// The step of check's "  --timestep auto: steps of X s" line (the normal
// contact's; the tangential line says it after "tangential: ...").
double StepsOf(const std::string& output) {
  const std::string key = "\n  --timestep auto: steps of ";
  const size_t at = output.find(key);
  return at == std::string::npos ? 0.0 : std::stod(output.substr(at + key.size()));
}

// check prints the step to 3 significant digits: each is within 5e-3 of
// itself, a ratio of two within 1e-2.
constexpr double kPrintedDigits = 1e-2;

// check --accuracy TOL (auto implied) shows the steps of that accuracy: the
// rule's steps per contact, and the elastic contact's duration over them.
TEST(CliTest, CheckTakesTheAccuracy) {
  constexpr double kTol = 1e-5;
  const Result r = RunCli(fmt::format("check {} --accuracy {}", kBall, kTol));
  ASSERT_EQ(r.status, 0) << r.output;
  const Result coarse = RunCli("check " + kBall + " --timestep auto");
  const double per_contact = StepsPerContact(kTol);
  EXPECT_NE(r.output.find(fmt::format("({:.0f} per contact, accuracy {})", per_contact, kTol)),
            std::string::npos)
      << r.output;
  // the same contact as at the default accuracy, in more steps
  const double ratio = StepsOf(coarse.output) / StepsOf(r.output);
  EXPECT_NEAR(ratio, per_contact / StepsPerContact(kDefaultAccuracy), kPrintedDigits * ratio);
}

// The program run with environment variables set (NAME=VALUE ...).
Result RunCliWith(const std::string& environment, const std::string& arguments) {
  const testing::ShellResult r =
      testing::RunShell(environment + " " + CONTACTLAWS_CLI + " " + arguments + " 2>&1");
  return {r.status, r.out};
}

// A warning of MuJoCo's compiler reaches the program's sink and is reported
// once at the end, with its count.
TEST(CliTest, AWarningOfMujocosCompilerIsReported) {
  const std::string nan = testing::WriteScene(
      "cli_nan", testing::TagScene(testing::Tag("geom1=ball geom2=floor law=hertz"),
                                   R"(<custom><numeric name="n" data="nan"/></custom>)"));
  const Result r = RunCliWith("", fmt::format("run {} --duration 1e-3", nan));
  EXPECT_NE(r.output.find("warning: MuJoCo: XML contains a 'NaN'"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace contactlaws
