// Copyright contactlaws authors.
//
// contactlaws run as a user runs it: each command's exit status, output and
// the CSV it writes.

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
using testing::Split;
using testing::ReadFile;
using testing::Result;
using testing::RunCli;
using testing::TinyScene;

TEST(CliTest, RefusalsExitTwoWithOneLine) {
  const struct {
    std::string arguments;
    std::string message;
  } cases[] = {
      {"run " + kBall + " --law hooke", "contactlaws: --law=hooke is not a law"},
      {"run " + kBall + " --restitution 1.5", "contactlaws: --restitution=1.5 must be in [0, 1]"},
      {"run " + kBall + " --restitution 0",
       "contactlaws: " + kBall +
           ": contactlaw:ball-floor: restitution=0 must be in (0, 1] for flores"},
      {"run " + kBall + " --duration 0", "contactlaws: --duration=0 must be a number > 0 (s)"},
      {"run " + kBall + " --timestep -1e-5", "contactlaws: --timestep=-1e-05 must be a number > 0"},
      {"run " + kBall + " --duration abc", "contactlaws: "},
      {"run " + kBall + " --timestep fast", "contactlaws: --timestep=fast must be a number > 0 (s) or auto"},
      {"run " + kBall + " --max-timestep 1e-3",
       "contactlaws: --max-timestep=0.001 goes with --timestep auto"},
      {"compare " + kBall + " --timestep auto --max-timestep 0",
       "contactlaws: --max-timestep=0 must be a number > 0 (s)"},
      {"run " + kBall + " --accuracy abc",
       "contactlaws: --accuracy=abc must be a number in (0, 0.1] (relative error)"},
      {"restitution " + kBall + " --timestep auto --accuracy 0.2",
       "contactlaws: --accuracy=0.2 must be a number in (0, 0.1] (relative error)"},
      {"compare " + kBall + " --accuracy 0",
       "contactlaws: --accuracy=0 must be a number in (0, 0.1] (relative error)"},
      {"run " + kBall + " --timestep 1e-5 --accuracy 1e-4",
       "contactlaws: --accuracy=0.0001 goes with --timestep auto, not with the fixed "
       "--timestep=1e-5"},
      {"check " + kBall + " --timestep 1e-5 --accuracy 1e-4",
       "contactlaws: --accuracy=0.0001 goes with --timestep auto, not with the fixed "
       "--timestep=1e-5"},
      {"check " + kBall + " --accuracy 0.5",
       "contactlaws: --accuracy=0.5 must be a number in (0, 0.1] (relative error)"},
      {"render " + kBall + " --output x.gif --timestep 1e-4 --accuracy 1e-3",
       "contactlaws: --accuracy=0.001 goes with --timestep auto, not with the fixed "
       "--timestep=1e-4"},
      {"compare " + kBall + " --jobs 0", "contactlaws: --jobs=0 must be a whole number >= 1"},
      {"run " + kBall + " --integrator rk5", "contactlaws: --integrator=rk5 must be euler, rk4 or implicit"},
      {"run " + kBall + " --frobnicate", "contactlaws: "},
      {"run /nonexistent.xml", "contactlaws: /nonexistent.xml: "},
      {"run " + kBall + " --duration 0.01 --output /nonexistent/dir/out.csv",
       "contactlaws: /nonexistent/dir/out.csv: cannot write"},
      {"compare " + kBall + " --laws flores,hooke",
       "contactlaws: --laws=flores,hooke has 'hooke', which is not a law"},
      {"compare " + kBall + " --laws flores --restitution 0,0.5",
       "contactlaws: " + kBall +
           ": contactlaw:ball-floor: restitution=0 must be in (0, 1] for flores"},
      {"compare " + kBall + " --dissipation 0.1 --duration 0.01 --output-dir /etc/passwd/out",
       "contactlaws: /etc/passwd/out: cannot create the output directory"},
      {"compare " + kBall + " --sample-rate 0", "contactlaws: --sample-rate=0 must be a number > 0"},
      {"restitution " + kBall + " --restitution 0:1:0",
       "contactlaws: --restitution=0:1:0 must have a step > 0 (start:stop:step)"},
      {"restitution " + kBall + " --restitution 0.5,1.5",
       "contactlaws: --restitution=0.5,1.5 has 1.5, outside [0, 1]"},
      {"restitution " + kBall + " --dissipation 0.1 --output /nonexistent/dir/e.csv",
       "contactlaws: /nonexistent/dir/e.csv: cannot write"},
      {"check " + kBall + " --impact-velocity -1",
       "contactlaws: --impact-velocity=-1 must be a number > 0 (m/s)"},
      {"check " + kBall + " --law hooke", "contactlaws: --law=hooke is not a law"},
      // the laws added after the paper: ranges and the dissipation
      {"run " + kBall + " --law gonthier --restitution 0",
       "contactlaws: " + kBall +
           ": contactlaw:ball-floor: restitution=0 must be in (0, 1] for gonthier"},
      {"run " + kBall + " --dissipation -1", "contactlaws: --dissipation=-1 must be >= 0 (s/m)"},
      {"restitution " + kBall + " --laws hunt-crossley-constant",
       "contactlaws: " + kBall +
           ": contactlaw:ball-floor: missing key dissipation (law=hunt-crossley-constant takes: "
           "stiffness K (N/m^n) > 0, exponent n in [1, 3], dissipation c (s/m) >= 0); the tag's "
           "law=flores does not read it: give the dissipation override (--dissipation)"},
      {"check " + kBall + " --law hunt-crossley-constant",
       "contactlaws: " + kBall + ": contactlaw:ball-floor: missing key dissipation"},
      {"check /nonexistent.xml", "contactlaws: /nonexistent.xml: "},
  };
  for (const auto& c : cases) {
    const Result r = RunCli(c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << "\n" << r.output;
    EXPECT_EQ(r.output.rfind(c.message, 0), 0u) << c.arguments << "\n" << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
  }
}

TEST(CliTest, RunWritesTheTrajectoryAndImpactLog) {
  const std::string dir = ::testing::TempDir();
  const std::string trajectory = dir + "/cli_ball.csv";
  const std::string impacts = dir + "/cli_impacts.csv";
  const Result r = RunCli("run " + kBall + " --law hunt-crossley --restitution 0.8 --duration 0.5 " +
                       "--sample-rate 100 --output " + trajectory + " --impacts " + impacts);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ball-floor"), std::string::npos) << r.output;

  const std::string csv = ReadFile(trajectory);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "time,ball.x,ball.y,ball.z,ball.vx,ball.vy,ball.vz,ball.qw,ball.qx,ball.qy,"
            "ball.qz,ball.wx,ball.wy,ball.wz,ball-floor.depth,ball-floor.depth_rate,"
            "ball-floor.force,ball-floor.friction_x,ball-floor.friction_y,"
            "ball-floor.friction_z,energy.kinetic,energy.potential,energy.elastic,"
            "energy.dissipated,energy.total");
  // 0 to 0.5 s at 100 rows per second: 51 rows and the header
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 52);
  EXPECT_NE(csv.find("\n0.5,"), std::string::npos);
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const std::string log = ReadFile(impacts);
  EXPECT_EQ(log.substr(0, log.find('\n')),
            "law,restitution,pair,geom1,geom2,index,points,time_contact,time_separation,"
            "impact_velocity,separation_velocity,max_approach_velocity,restitution_post,chained,"
            "max_depth,max_force,tangential_impact_velocity,tangential_separation_velocity,"
            "tangential_restitution,spin_before,spin_after");
  EXPECT_EQ(log.find("\nhunt-crossley,0.8,ball-floor,ball,floor,1,1,0.42"), log.find('\n'));
}

TEST(CliTest, LawsListsEveryLaw) {
  const Result r = RunCli("laws");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* expected :
       {"\nhertz\n  F = K d^n\n", "\nkelvin-voigt\n  F = k d + c d'\n",
        "\nhunt-crossley\n  F = K d^n (1 + 3(1-e)/2 * d'/v0)\n",
        "\nlankarani-nikravesh\n  F = K d^n (1 + 3(1-e^2)/4 * d'/v0)\n",
        "\nflores\n  F = K d^n (1 + 8(1-e)/(5e) * d'/v0)\n", "Hunt, F. R. E. Crossley",
        "restitution e in (0, 1]", "default 0.001 m/s",
        // the effective restitution at the five points (docs/laws.md's table)
        "\n  effective e: 0.9: 0.9009, 0.7: 0.7227, 0.5: 0.5936, 0.3: 0.5200, 0.1: 0.4907\n",
        "\n  effective e: 0.9: 0.9000, 0.7: 0.7000, 0.5: 0.5000, 0.3: 0.3000, 0.1: 0.1000\n",
        "\nhunt-crossley-constant\n  F = K d^n (1 + c d')\n",
        "effective e: reads no e: ExactRebound(c v0), set by the impact speed"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
  for (const LawInfo& law : Laws()) {
    EXPECT_NE(r.output.find("\n" + std::string(law.name) + "\n  F = "), std::string::npos)
        << law.name;
  }
}

// laws --format csv: a row per law and e, with a(e) and the closed-form
// rebound, which the figure scripts plot instead of copies of the formulas.
TEST(CliTest, LawsAsCsvGiveEachLawsCoefficientAndRebound) {
  const Result r = RunCli("laws --format csv --restitution 0.5,1");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> rows = Lines(r.output);
  ASSERT_EQ(rows.size(), 1 + 2 * AllLaws().size());
  EXPECT_EQ(rows[0], "law,family,restitution,hysteresis_coefficient,effective_restitution");
  // flores at e = 0.5: a = 1.6, and the rebound ExactRebound gives for it
  const std::string flores = fmt::format("flores,hysteresis,0.5,{},{}", 1.6, ExactRebound(1.6));
  EXPECT_NE(std::find(rows.begin(), rows.end(), flores), rows.end()) << r.output;
  EXPECT_NE(std::find(rows.begin(), rows.end(), "hertz,hysteresis,1,0,1"), rows.end());
  // no closed form for kelvin-voigt: empty fields
  EXPECT_NE(std::find(rows.begin(), rows.end(), "kelvin-voigt,linear,0.5,,"), rows.end());
  // nor for hunt-crossley-constant: its rebound depends on the impact speed
  EXPECT_NE(std::find(rows.begin(), rows.end(),
                      "hunt-crossley-constant,constant-dissipation,0.5,,"),
            rows.end());
  // e = 0 outside gonthier's range: empty fields
  EXPECT_NE(RunCli("laws --format csv --restitution 0").output.find("\ngonthier,hysteresis,0,,\n"),
            std::string::npos);

  EXPECT_EQ(RunCli("laws --format yaml").output,
            "contactlaws: --format=yaml must be text or csv\n");
  EXPECT_EQ(RunCli("laws --restitution 0.5").output,
            "contactlaws: --restitution=0.5 goes with --format csv\n");
  EXPECT_EQ(RunCli("laws --format csv --restitution 0x1").output,
            "contactlaws: --restitution=0x1 has '0x1', which is not a finite number\n");
}

// --laws all runs every law the scene and options can run: one that needs a
// dissipation nobody gave is left out with one warning; named, it is refused.
TEST(CliTest, AllLawsLeaveOutALawMissingItsDissipation) {
  const Result all = RunCli("restitution " + kBall + " --restitution 0.5 --timestep auto --quiet");
  ASSERT_EQ(all.status, 0) << all.output;
  EXPECT_NE(all.output.find("warning: " + kBall + ": --laws all leaves out "
                            "hunt-crossley-constant: it needs a dissipation (give "
                            "--dissipation, s/m)"),
            std::string::npos)
      << all.output;
  // the warning, the header, a row for every law but the one left out
  EXPECT_EQ(Lines(all.output).size(), 1 + 1 + AllLaws().size() - 1) << all.output;
  const Result named = RunCli("restitution " + kBall + " --laws hunt-crossley-constant");
  EXPECT_EQ(named.status, 2) << named.output;
  const Result given = RunCli("restitution " + kBall + " --restitution 0.5 --timestep auto "
                              "--quiet --dissipation 0.1 --output -");
  ASSERT_EQ(given.status, 0) << given.output;
  EXPECT_NE(given.output.find("\nhunt-crossley-constant,0.5,"), std::string::npos)
      << given.output;
}

TEST(CliTest, CompareWritesTheThreeLongFormatFiles) {
  const std::string dir = ::testing::TempDir() + "/cli_compare";
  const Result r = RunCli("compare " + TinyScene() +
                          " --laws hertz,flores --restitution 0.5,0.9 --duration 0.1 "
                          "--sample-rate 100 --quiet --output-dir " + dir);
  ASSERT_EQ(r.status, 0) << r.output;

  // Hertz once (restitution 1), Flores at each e: 3 runs of 11 rows (0 to 0.1 s)
  const std::vector<std::string> trajectories = Lines(ReadFile(dir + "/trajectories.csv"));
  ASSERT_EQ(trajectories.size(), 1u + 3 * 11);
  EXPECT_EQ(trajectories[0],
            "law,restitution,time,ball.x,ball.y,ball.z,ball.vx,ball.vy,ball.vz,ball.qw,"
            "ball.qx,ball.qy,ball.qz,ball.wx,ball.wy,ball.wz,ball-floor.depth,"
            "ball-floor.depth_rate,ball-floor.force,ball-floor.friction_x,"
            "ball-floor.friction_y,ball-floor.friction_z,energy.kinetic,energy.potential,"
            "energy.elastic,energy.dissipated,energy.total");
  EXPECT_EQ(trajectories[1].rfind("hertz,1,0,", 0), 0u) << trajectories[1];
  EXPECT_EQ(trajectories[12].rfind("flores,0.5,0,", 0), 0u) << trajectories[12];
  EXPECT_EQ(trajectories[33].rfind("flores,0.9,0.1,", 0), 0u) << trajectories[33];

  const std::vector<std::string> impacts = Lines(ReadFile(dir + "/impacts.csv"));
  ASSERT_GE(impacts.size(), 4u);
  EXPECT_EQ(impacts[0],
            "law,restitution,pair,geom1,geom2,index,points,time_contact,time_separation,"
            "impact_velocity,separation_velocity,max_approach_velocity,restitution_post,chained,"
            "max_depth,max_force,tangential_impact_velocity,tangential_separation_velocity,"
            "tangential_restitution,spin_before,spin_after");
  EXPECT_EQ(impacts[1].rfind("hertz,1,ball-floor,ball,floor,1,1,0.04", 0), 0u) << impacts[1];

  const std::vector<std::string> summary = Lines(ReadFile(dir + "/summary.csv"));
  ASSERT_EQ(summary.size(), 4u);
  EXPECT_EQ(summary[0],
            "law,restitution,impacts,restitution_post,max_depth,max_force,contact_duration,"
            "time_to_rest,dissipated_energy,status,reason");
  EXPECT_EQ(summary[1].rfind("hertz,1,", 0), 0u);
  for (size_t i = 1; i < summary.size(); ++i) {
    EXPECT_EQ(summary[i].substr(summary[i].size() - 4), ",ok,") << summary[i];
  }
  EXPECT_EQ(summary[2].rfind("flores,0.5,", 0), 0u);
  EXPECT_EQ(summary[3].rfind("flores,0.9,", 0), 0u);
  // the aligned table on stdout, and no progress when stderr is not a terminal
  EXPECT_NE(r.output.find("first e_post"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("[1/3]"), std::string::npos) << r.output;
}

// Every law of the table at ten restitutions: a row each (hunt-crossley-constant
// reads no e and runs with the dissipation at each, as hertz runs at each).
TEST(CliTest, RestitutionSweepCoversEveryLaw) {
  const std::string out = ::testing::TempDir() + "/cli_sweep.csv";
  const Result r = RunCli("restitution " + TinyScene() +
                          " --laws all --dissipation 0.1 --restitution 0.1:1.0:0.1 --output " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> rows = Lines(ReadFile(out));
  ASSERT_EQ(rows.size(), 1 + 10 * Laws().size());
  EXPECT_EQ(rows[0], "law,restitution,restitution_post,impact_velocity,max_depth,max_force,"
                     "contact_duration");
  EXPECT_EQ(rows[1].rfind("hertz,0.1,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[50].rfind("flores,1,", 0), 0u) << rows[50];
  EXPECT_EQ(rows.back().rfind("hunt-crossley-constant,1,", 0), 0u) << rows.back();
  for (const std::string& row : rows) {
    EXPECT_EQ(row.find(",,"), std::string::npos) << "every first contact ended: " << row;
  }
}

TEST(CliTest, RestitutionSaysWhenTheFirstContactDoesNotEnd) {
  const Result r = RunCli("restitution " + TinyScene() +
                          " --laws flores --restitution 0.5 --duration 0.01 --output -");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("contactlaws: warning: " + TinyScene() +
                          ": flores e=0.5: no contact within --duration=0.01 s"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("\nflores,0.5,,,,,\n"), std::string::npos) << r.output;
}

TEST(CliTest, CheckPrintsTheEstimateAndTheTimestepItNeeds) {
  Result r = RunCli("check " + TinyScene());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* expected :
       {"contactlaw:ball-floor: ball - floor, 1 geom pair(s), law flores",
        "stiffness K 1.4e+08 N/m^1.5", "effective mass 1 kg, gap 0.01 m",
        "impact velocity 0.442945 m/s", "steps per contact at 1e-05 s: ok",
        "rule: a contact is resolved by >= 20 steps"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
  r = RunCli("check " + TinyScene() + " --timestep 1e-3 --impact-velocity 4.2");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("impact velocity 4.2 m/s (--impact-velocity)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("TOO COARSE (needs timestep <= 6.66e-05 s)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("warning: 1 tag(s) need a smaller timestep"), std::string::npos)
      << r.output;
}

TEST(CliTest, AutoTimestepKeepsTheSampleGrid) {
  const std::string csv = ::testing::TempDir() + "/auto.csv";
  const Result r = RunCli("run " + kBall + " --timestep auto --duration 0.6 --sample-rate 250 " +
                          "--output " + csv);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ball-floor"), std::string::npos) << r.output;
  const std::vector<std::string> rows = Lines(ReadFile(csv));
  ASSERT_EQ(rows.size(), 1u + 151u);  // 0 to 0.6 s at 250 rows/s
  for (size_t i = 1; i < rows.size(); ++i) {
    const double t = std::stod(rows[i].substr(0, rows[i].find(',')));
    EXPECT_DOUBLE_EQ(t, (i - 1) / 250.0) << rows[i];
  }
}

TEST(CliTest, TrajectoryToStandardOutput) {
  const Result r = RunCli("run " + kBall + " --duration 0.002 --output -");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("time,ball.x", 0), 0u) << r.output;
}

}  // namespace
}  // namespace contactlaws
