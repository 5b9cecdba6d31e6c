// Copyright contactlaws authors.
//
// contactlaws given bad input, a run that diverges, a failed run in a sweep,
// Ctrl-C, and --jobs: every bad input named in one line, no crash, no silent
// nonsense, nothing half written.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_test_util.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using testing::kBall;
using testing::Lines;
using testing::ReadFile;
using testing::Result;
using testing::RunCli;
using testing::Tag;
using testing::TagScene;
using testing::TinyScene;
using testing::WriteScene;

// The first hour's mistakes: each named in one line before anything runs.
TEST(ReliabilityTest, FirstHourMistakesAreNamedBeforeTheRun) {
  const std::string dir = ::testing::TempDir();
  // one path for the trajectory and the impact log
  Result r = RunCli("run " + kBall + " --output " + dir + "/same.csv --impacts " + dir +
                    "/./same.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "contactlaws: --impacts=" + dir +
                          "/./same.csv is the --output path too: give the two files two "
                          "paths\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/same.csv")) << "nothing was run";
  // a law's name in the wrong case, from the command line
  r = RunCli("run " + kBall + " --law Hertz");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--law=Hertz is not a law ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("): did you mean 'hertz'?\n"), std::string::npos) << r.output;
  // a file that is not there, or a directory
  EXPECT_EQ(RunCli("run " + dir + "/no-such-scene.xml").output,
            "contactlaws: " + dir + "/no-such-scene.xml: no such file\n");
  EXPECT_EQ(RunCli("check " + dir).output,
            "contactlaws: " + dir + ": is a directory, not an MJCF file\n");
  // a scene with no tag runs MuJoCo's own contact, and says so
  const std::string plain = WriteScene("untagged", TagScene(""));
  r = RunCli("run " + plain + " --duration 0.001");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("contactlaws: warning: " + plain +
                          ": no contactlaw: tags: MuJoCo's own contact acts on every pair"),
            std::string::npos)
      << r.output;
  // the version of the library and of MuJoCo
  r = RunCli("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, "contactlaws " + std::string(LibraryVersion()) + " (MuJoCo 2.2.2)\n");
}

TEST(ReliabilityTest, EveryBadSceneIsRefusedByRunAndCheckWithTheSameLine) {
  const std::string ok = "geom1=ball geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e8";
  const struct {
    std::string name;
    std::string xml;
    std::string message;  // after "contactlaws: PATH: "
  } cases[] = {
      {"unknown_law", TagScene(Tag("geom1=ball geom2=floor law=hooke stiffness=1e8")),
       "contactlaw:t: law=hooke is not a law"},
      {"unknown_key", TagScene(Tag(ok + " restitusion=0.5")),
       "contactlaw:t: unknown key 'restitusion' (did you mean 'restitution'?)"},
      {"missing_geom1", TagScene(Tag("geom2=floor law=hertz stiffness=1e8")),
       "contactlaw:t: missing key geom1"},
      {"missing_geom2", TagScene(Tag("geom1=ball law=hertz stiffness=1e8")),
       "contactlaw:t: missing key geom2"},
      {"missing_law", TagScene(Tag("geom1=ball geom2=floor stiffness=1e8")),
       "contactlaw:t: missing key law"},
      {"no_such_geom", TagScene(Tag("geom1=bal geom2=floor law=hertz stiffness=1e8")),
       "contactlaw:t: geom1=bal: no geom is named 'bal'"},
      {"no_such_group", TagScene(Tag("geom1=group:5 geom2=floor law=hertz stiffness=1e8")),
       "contactlaw:t: geom1=group:5: no geom is in group 5"},
      {"not_a_number", TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=1e8x")),
       "contactlaw:t: stiffness=1e8x is not a finite number"},
      {"nan", TagScene(Tag("geom1=ball geom2=floor law=flores restitution=nan stiffness=1e8")),
       "contactlaw:t: restitution=nan is not a finite number"},
      {"infinite", TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=inf")),
       "contactlaw:t: stiffness=inf is not a finite number"},
      {"overflow", TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=1e999")),
       "contactlaw:t: stiffness=1e999 is not a finite number"},
      {"repeated_key", TagScene(Tag(ok + " restitution=0.7")),
       "contactlaw:t: key 'restitution' is given twice"},
      {"restitution_above_one",
       TagScene(Tag("geom1=ball geom2=floor law=flores restitution=1.5 stiffness=1e8")),
       "contactlaw:t: restitution=1.5 must be in [0, 1]"},
      {"negative_stiffness", TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=-1")),
       "contactlaw:t: stiffness=-1 must be > 0 (N/m^n)"},
      {"exponent_range",
       TagScene(Tag("geom1=ball geom2=floor law=hertz stiffness=1e8 exponent=5")),
       "contactlaw:t: exponent=5 must be in [1, 3]"},
      {"youngs_range",
       TagScene(Tag("geom1=ball geom2=floor law=hertz youngs1=-2 poisson1=0.3 youngs2=2e11 "
                    "poisson2=0.3")),
       "contactlaw:t: youngs1=-2 must be > 0 (Pa)"},
      {"poisson_range",
       TagScene(Tag("geom1=ball geom2=floor law=hertz youngs1=2e11 poisson1=0.5 youngs2=2e11 "
                    "poisson2=0.3")),
       "contactlaw:t: poisson1=0.5 must be in (-1, 0.5)"},
      {"flores_e0", TagScene(Tag("geom1=ball geom2=floor law=flores restitution=0 stiffness=1e8")),
       "contactlaw:t: restitution=0 must be in (0, 1] for flores"},
      {"kelvin_voigt_stiffness",
       TagScene(Tag("geom1=ball geom2=floor law=kelvin-voigt restitution=0.5 stiffness=1e8 "
                    "exponent=1.5")),
       "contactlaw:t: law=kelvin-voigt needs linear_stiffness (N/m)"},
      {"tagged_twice", TagScene(Tag(ok) + Tag("geom1=floor geom2=ball law=hertz stiffness=1e8", "u")),
       "contactlaw:u: (floor, ball) is already tagged by contactlaw:t"},
      {"explicit_pair",
       TagScene(Tag(ok), R"(<contact><pair geom1="ball" geom2="floor"/></contact>)"),
       "contactlaw:t: (ball, floor) is also a <contact><pair>, which bypasses the contact "
       "filter"},
      {"prefix_case", TagScene(R"(<text name="ContactLaw:t" data="geom1=ball geom2=floor"/>)"),
       "ContactLaw:t: the tag prefix must be 'contactlaw:' (not 'ContactLaw:'), or the tag is "
       "not read"},
      {"prefix_typo", TagScene(R"(<text name="contactlaws:t" data="geom1=ball geom2=floor"/>)"),
       "contactlaws:t: the tag prefix must be 'contactlaw:' (not 'contactlaws:')"},
      {"drive_prefix_typo",
       TagScene(Tag(ok) + R"(<text name="contactdrve:d" data="body=ball amplitude=1 omega=1"/>)"),
       "contactdrve:d: the tag prefix must be 'contactdrive:' (not 'contactdrve:')"},
      {"law_case", TagScene(Tag("geom1=ball geom2=floor law=Flores restitution=0.5 stiffness=1e8")),
       "contactlaw:t: law=Flores is not a law ("},
      {"passive_disabled", TagScene(Tag(ok), R"(<option><flag passive="disable"/></option>)"),
       "<flag passive=\"disable\"/> turns off mjcb_passive"},
      {"contact_disabled", TagScene(Tag(ok), R"(<option><flag contact="disable"/></option>)"),
       "<flag contact=\"disable\"/> turns off collision detection"},
      {"collision_predefined", TagScene(Tag(ok), R"(<option collision="predefined"/>)"),
       "<option collision=\"predefined\"/> checks only <contact><pair>"},
      {"plane_plane", TagScene(Tag("geom1=floor geom2=floor2 law=hertz stiffness=1e8")),
       "contactlaw:t: (floor, floor2): MuJoCo has no collision function for these geom types"},
      {"same_body", TagScene(Tag("geom1=ball geom2=cap law=hertz stiffness=1e8")),
       "contactlaw:t: (ball, cap): the two geoms belong to the same body"},
      {"malformed_xml", "<mujoco>\n  <worldbody>\n    <geom type=\"sphere\" size=\"0.1\">\n</mujoco>",
       "XML parse error 14: Error=XML_ERROR_MISMATCHED_ELEMENT ErrorID=14 (0xe) Line number=3"},
  };
  for (const auto& c : cases) {
    const std::string path = WriteScene("refused_" + c.name, c.xml);
    const Result run = RunCli("run " + path + " --duration 0.001");
    const Result check = RunCli("check " + path);
    EXPECT_EQ(run.status, 2) << c.name << "\n" << run.output;
    EXPECT_EQ(check.status, 2) << c.name << "\n" << check.output;
    const std::string start = "contactlaws: " + path + ": ";
    EXPECT_EQ(run.output.rfind(start, 0), 0u) << c.name << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.name << "\n" << run.output;
    EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << c.name << " one line:\n"
                                                            << run.output;
    EXPECT_EQ(run.output, check.output) << c.name << ": run and check say the same";
  }
}

// The drop of DropXml's ball (radius 0.1) at speed onto the floor, Hertz K.
std::string DropScene(const std::string& name, double stiffness, double speed,
                      const char* integrator, double timestep) {
  return WriteScene(name, contactlaws::testing::DropXml(
                              fmt::format("law=hertz stiffness={}", stiffness), speed,
                              integrator, timestep, /*gravity=*/true, /*mass=*/1.0,
                              /*height=*/0.2));
}

// Every line of a CSV has the header's number of fields, and all are finite.
void ExpectValidCsv(const std::string& path) {
  const std::vector<std::string> lines = Lines(ReadFile(path));
  ASSERT_FALSE(lines.empty()) << path;
  const auto fields = [](const std::string& line) {
    return std::count(line.begin(), line.end(), ',') + 1;
  };
  for (const std::string& line : lines) {
    EXPECT_EQ(fields(line), fields(lines[0])) << path << ": " << line;
    EXPECT_EQ(line.find("nan"), std::string::npos) << path << ": " << line;
    EXPECT_EQ(line.find("inf"), std::string::npos) << path << ": " << line;
  }
}

TEST(ReliabilityTest, AContactTooSoftStopsTheRunAtDivergence) {
  // K = 1e4 N/m^1.5 at 5 m/s: the elastic depth would be 0.1 m, the whole
  // radius; the run stops when the depth passes half of it
  const std::string scene = DropScene("soft", 1e4, 5.0, "RK4", 1e-5);
  const std::string csv = ::testing::TempDir() + "/soft.csv";
  const Result r = RunCli("run " + scene + " --duration 0.1 --output " + csv);
  EXPECT_EQ(r.status, 3) << r.output;
  for (const char* expected :
       {"run stopped: diverged at t = 0.0", "contactlaw:ball-floor (ball, floor): depth 0.05",
        "beyond 0.05 m (0.5 of the smaller geom's size)",
        "likely cause: a contact too soft for the impact"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
  ExpectValidCsv(csv);
  // the rows up to the divergence are there
  EXPECT_GT(Lines(ReadFile(csv)).size(), 20u);
}

// Without the timestep's warnings (the auto timestep, contact steps), the
// advice a divergence's message reads is taken when the run diverges, from
// the start: the same likely cause as above.
TEST(ReliabilityTest, ADivergenceWithoutTimestepWarningsNamesTheSameLikelyCause) {
  const std::string scene = DropScene("soft_inner", 1e4, 5.0, "Euler", 2e-3);
  for (const char* step : {"--timestep auto", "--contact-steps auto"}) {
    const Result r = RunCli("run " + scene + " --duration 0.1 " + step);
    EXPECT_EQ(r.status, 3) << step << "\n" << r.output;
    EXPECT_NE(r.output.find("likely cause: a contact too soft for the impact"), std::string::npos)
        << step << "\n" << r.output;
  }
}

TEST(ReliabilityTest, MujocosResetOnAHugeAccelerationStopsTheRun) {
  // K = 1e15: the first step in contact gives qacc > 1e10, and MuJoCo resets
  // the state (to t = 0) instead of integrating it
  const std::string scene = DropScene("reset", 1e15, 5.0, "Euler", 1e-3);
  const std::string csv = ::testing::TempDir() + "/reset.csv";
  const Result r = RunCli("run " + scene + " --duration 0.5 --output " + csv);
  EXPECT_EQ(r.status, 3) << r.output;
  for (const char* expected :
       {"timestep 0.001 s puts 0.00", "steps in the estimated contact duration",
        "MuJoCo found NaN, infinity or a value beyond 1e+10 in qacc (dof 2) and reset the state",
        "(>= 20 needed: --timestep 1.", "MuJoCo: Nan, Inf or huge value in QACC at DOF 2. The "
        "simulation is unstable. (1 time)"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
  // surfaced once: not again from MuJoCo's own message with its time
  EXPECT_EQ(r.output.find("Time = "), std::string::npos) << r.output;
  ExpectValidCsv(csv);
}

TEST(ReliabilityTest, ACoarseTimestepIsNamedBeforeTheRunAndTheEnergyGrowthAfter) {
  const std::string scene = DropScene("coarse", 1.4e8, 5.0, "Euler", 1e-3);
  const Result r = RunCli("run " + scene + " --duration 0.2");
  EXPECT_EQ(r.status, 0) << r.output;
  const size_t coarse = r.output.find(
      "contactlaw:ball-floor (ball, floor): timestep 0.001 s puts 1.28 steps in the estimated "
      "contact duration 0.001277 s (>= 20 needed): use --timestep 6.38e-05 or smaller");
  EXPECT_NE(coarse, std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the total energy of this undriven scene grew by"), std::string::npos)
      << r.output;
  // resolved: neither warning
  const Result fine = RunCli("run " + DropScene("fine", 1.4e8, 5.0, "RK4", 2e-5) +
                             " --duration 0.2");
  EXPECT_EQ(fine.status, 0) << fine.output;
  EXPECT_EQ(fine.output.find("warning"), std::string::npos) << fine.output;
}

TEST(ReliabilityTest, MujocoWarningsAreSurfacedOnceWithTheirCount) {
  // two untagged balls at rest on the floor, room for one contact: MuJoCo
  // warns at every step that its contact buffer is full
  const std::string scene = WriteScene("full", R"(<mujoco>
  <size nconmax="1"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body pos="0 0 0.1"><freejoint/><geom name="a" type="sphere" size="0.1"/></body>
    <body pos="0.5 0 0.1"><freejoint/><geom name="b" type="sphere" size="0.1"/></body>
    <body name="ball" pos="0 0 1"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
  </worldbody>
  <custom><text name="contactlaw:t" data="geom1=ball geom2=floor law=hertz stiffness=1e8"/></custom>
</mujoco>)");
  const Result r = RunCli("run " + scene + " --duration 0.01 --timestep 1e-3");
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string line = "MuJoCo: Pre-allocated contact buffer is full. Increase nconmax above 1. (";
  const size_t at = r.output.find(line);
  EXPECT_NE(at, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("contact buffer is full", at + line.size()), std::string::npos)
      << "once:\n" << r.output;
}

TEST(ReliabilityTest, CompareKeepsGoingWhenOneRunFails) {
  // K = 4.4e4: the elastic (hertz) drop goes deeper than half the radius,
  // the damped laws stop short of it
  const std::string scene = DropScene("one_fails", 4.4e4, 5.0, "RK4", 1e-4);
  const std::string dir = ::testing::TempDir() + "/one_fails";
  const Result r = RunCli("compare " + scene +
                          " --laws hertz,flores,hunt-crossley --restitution 0.3 --duration 0.3 "
                          "--output-dir " + dir);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("hertz e=1: run failed: diverged at t = 0.03"), std::string::npos)
      << r.output;
  const std::vector<std::string> summary = Lines(ReadFile(dir + "/summary.csv"));
  ASSERT_EQ(summary.size(), 4u);
  EXPECT_EQ(summary[1].rfind("hertz,1,,,,,,,,failed,\"diverged at t = 0.03", 0), 0u)
      << summary[1];
  EXPECT_EQ(summary[2].rfind("flores,0.3,1,", 0), 0u) << summary[2];
  EXPECT_EQ(summary[2].substr(summary[2].size() - 4), ",ok,") << summary[2];
  EXPECT_EQ(summary[3].substr(summary[3].size() - 4), ",ok,") << summary[3];
  ExpectValidCsv(dir + "/trajectories.csv");
}

TEST(ReliabilityTest, CtrlCDuringCompareLeavesTheFinishedRunsIntact) {
  // each run is 2 s of RK4 at 1e-5 s (about a second of wall time): Ctrl-C
  // comes once the first run's rows are on disk
  const std::string dir = ::testing::TempDir() + "/interrupted";
  std::filesystem::remove_all(dir);
  const std::string log = ::testing::TempDir() + "/interrupted.log";
  const pid_t pid = testing::SpawnCli({"compare", kBall, "--laws", "hertz,flores", "--restitution",
                              "0.3,0.6,0.9", "--duration", "2", "--jobs", "1", "--output-dir", dir},
                             log);
  ASSERT_GE(pid, 0);
  const std::string temp = dir + "/trajectories.csv.tmp";
  bool first_run_written = false;
  for (int i = 0; i < 600 && !first_run_written; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    first_run_written = ReadFile(temp).find("\nhertz,") != std::string::npos;
  }
  ASSERT_TRUE(first_run_written);
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << ReadFile(log);
  EXPECT_EQ(WEXITSTATUS(status), 130) << ReadFile(log);
  EXPECT_NE(ReadFile(log).find("interrupted: the finished runs are written"), std::string::npos)
      << ReadFile(log);

  // summary: the finished runs ok, the others interrupted or not run
  const std::vector<std::string> summary = Lines(ReadFile(dir + "/summary.csv"));
  ASSERT_EQ(summary.size(), 5u);
  int finished = 0;
  for (size_t i = 1; i < summary.size(); ++i) {
    const bool ok = summary[i].find(",ok,") != std::string::npos;
    finished += ok;
    if (!ok) {
      EXPECT_TRUE(summary[i].find(",interrupted,") != std::string::npos ||
                  summary[i].find(",not run,") != std::string::npos)
          << summary[i];
    }
  }
  EXPECT_GE(finished, 1);
  EXPECT_LT(finished, 4);
  // trajectories: exactly the finished runs' 2001 rows each, all valid
  ExpectValidCsv(dir + "/trajectories.csv");
  EXPECT_EQ(Lines(ReadFile(dir + "/trajectories.csv")).size(), 1u + 2001u * finished);
  EXPECT_FALSE(std::filesystem::exists(temp));
}

TEST(ReliabilityTest, JobsDoNotChangeABite) {
  const std::string dir = ::testing::TempDir() + "/jobs";
  for (const char* jobs : {"1", "3"}) {
    const Result r = RunCli("compare " + TinyScene() + " --laws all --dissipation 0.1 --restitution 0.4,0.8 " +
                            "--duration 0.1 --output-dir " + dir + jobs + " --jobs " + jobs);
    ASSERT_EQ(r.status, 0) << r.output;
    const Result e = RunCli("restitution " + TinyScene() + " --laws all --dissipation 0.1 --restitution " +
                            "0.2:1:0.2 --output " + dir + jobs + "/e.csv --jobs " + jobs);
    ASSERT_EQ(e.status, 0) << e.output;
  }
  for (const char* file : {"trajectories.csv", "impacts.csv", "summary.csv", "e.csv"}) {
    const std::string one = ReadFile(dir + "1/" + file);
    EXPECT_GT(one.size(), 100u) << file;
    EXPECT_EQ(one, ReadFile(dir + "3/" + file)) << file;
  }
}

}  // namespace
}  // namespace contactlaws
