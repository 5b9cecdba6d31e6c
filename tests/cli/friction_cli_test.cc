// Copyright contactlaws authors.
//
// The friction side of the command line: compare --frictions, the warning of
// a stick spring too stiff for a fixed timestep, and every bad friction
// input named in one line.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/cli_test_util.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using testing::Lines;
using testing::ReadFile;
using testing::Result;
using testing::RunCli;
using testing::Split;
using testing::WriteScene;

constexpr double kGravity = 9.81;  // m/s^2, the scenes' gravity

// A 1 kg ball of radius 0.1 m launched at 1 m/s without spin, 1 mm above a
// floor (RK4, 1e-4 s); tag: the pair's keys after geom1, geom2 and the law;
// geoms: attributes of both geoms.
std::string SlidingBall(const std::string& name, const std::string& tag,
                        const std::string& geoms = "") {
  return WriteScene(name, fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" {1}/>
    <body name="ball" pos="0 0 0.101">
      <freejoint/>
      <geom name="ball" type="sphere" size="0.1" mass="1" {1}/>
    </body>
  </worldbody>
  <keyframe><key qvel="1 0 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:ball-floor" data="geom1=ball geom2=floor law=hunt-crossley
    restitution=0.5 stiffness=1e7 min_impact_velocity=0.01 {0}"/></custom>
</mujoco>)",
                                      tag, geoms));
}

// The value of column `name` in a CSV row, given the header.
double Column(const std::string& header, const std::string& row, const std::string& name) {
  const std::vector<std::string> names = Split(header, ',');
  const auto found = std::find(names.begin(), names.end(), name);
  EXPECT_NE(found, names.end()) << name;
  return std::stod(Split(row, ',').at(found - names.begin()));
}

// compare --frictions runs every (law, e) with each friction model, with a
// friction column in the three files, the same bytes whatever --jobs.
TEST(FrictionCliTest, CompareRunsEachFrictionModel) {
  const std::string scene = SlidingBall("compare_frictions", "mu=0.3");
  const std::string dir = ::testing::TempDir() + "/frictions";
  for (const char* jobs : {"1", "3"}) {
    const Result r = RunCli("compare " + scene + " --laws hunt-crossley --frictions all " +
                            "--duration 0.3 --sample-rate 100 --quiet --jobs " + jobs +
                            " --output-dir " + dir + jobs);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("friction    collisions"), std::string::npos) << r.output;
  }
  for (const char* file : {"trajectories.csv", "impacts.csv", "summary.csv"}) {
    EXPECT_EQ(ReadFile(dir + "1/" + file), ReadFile(dir + "3/" + file)) << file;
  }
  const std::vector<std::string> summary = Lines(ReadFile(dir + "1/summary.csv"));
  ASSERT_EQ(summary.size(), 1u + FrictionModels().size());
  EXPECT_EQ(summary[0].rfind("law,restitution,friction,impacts,", 0), 0u) << summary[0];
  for (size_t i = 0; i < FrictionModels().size(); ++i) {
    const std::string run = fmt::format("hunt-crossley,0.5,{},", FrictionModels()[i].name);
    EXPECT_EQ(summary[1 + i].rfind(run, 0), 0u) << summary[1 + i];
  }
  const std::vector<std::string> impacts = Lines(ReadFile(dir + "1/impacts.csv"));
  EXPECT_EQ(impacts[0].rfind("law,restitution,friction,pair,geom1,", 0), 0u) << impacts[0];
  EXPECT_EQ(impacts[1].rfind("hunt-crossley,0.5,none,ball-floor,ball,floor,1,", 0), 0u)
      << impacts[1];

  // the last row of each run (0.3 s): without friction the ball slides on at
  // 1 m/s; with coulomb it rolls from t = 2 v0 / (7 mu g) = 0.097 s at 5/7 v0
  const std::vector<std::string> rows = Lines(ReadFile(dir + "1/trajectories.csv"));
  ASSERT_EQ(rows.size(), 1u + 31u * FrictionModels().size());
  EXPECT_EQ(rows[0].rfind("law,restitution,friction,time,ball.x,", 0), 0u) << rows[0];
  const std::string& none = rows[31];
  const std::string& coulomb = rows[62];
  EXPECT_EQ(none.rfind("hunt-crossley,0.5,none,0.3,", 0), 0u) << none;
  EXPECT_EQ(coulomb.rfind("hunt-crossley,0.5,coulomb,0.3,", 0), 0u) << coulomb;
  // the 1 mm drop's bounces are short against the 0.3 s (and take no speed
  // along x without friction): the rolling speed to 1%
  constexpr double kRollingTolerance = 1e-2;
  EXPECT_NEAR(Column(rows[0], none, "ball.vx"), 1.0, 1e-9);
  EXPECT_NEAR(Column(rows[0], coulomb, "ball.vx"), 5.0 / 7.0, kRollingTolerance);
  EXPECT_LT(2.0 / (7 * 0.3 * kGravity), 0.3) << "the ball rolls by the end";

  // the runs are named with their model, the files' column only with --frictions
  const Result plain = RunCli("compare " + scene + " --laws hunt-crossley --duration 0.01 " +
                              "--quiet --output-dir " + dir + "plain");
  ASSERT_EQ(plain.status, 0) << plain.output;
  EXPECT_EQ(Lines(ReadFile(dir + "plain/summary.csv"))[0].rfind("law,restitution,impacts,", 0),
            0u);
}

TEST(FrictionCliTest, CompareWarnsWhenNoPairHasFriction) {
  const std::string scene = SlidingBall("compare_condim1", "", R"(condim="1")");
  const Result r = RunCli("compare " + scene + " --laws hunt-crossley --frictions none,coulomb " +
                          "--quiet --duration 0.01 --output-dir " + ::testing::TempDir() +
                          "/condim1");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("contactlaws: warning: " + scene + ": --frictions: every tagged pair "
                           "is frictionless (condim 1, as in MuJoCo): the friction models do "
                           "not act\n", 0),
            0u)
      << r.output;
}

// laws lists every friction model and the torque caps' keys with their unit
TEST(FrictionCliTest, LawsListsTheFrictionModelsAndTheTorqueCaps) {
  const Result r = RunCli("laws");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const FrictionInfo& model : FrictionModels()) {
    EXPECT_NE(r.output.find("\n" + std::string(model.name) + "\n  "), std::string::npos)
        << model.name;
  }
  for (const char* expected : {"torsional_friction x F_n (condim >= 4)",
                               "rolling_friction x F_n (condim 6): tag keys, m >= 0"}) {
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  }
}

TEST(FrictionCliTest, CompareRefusesABadFrictionList) {
  const std::string scene = SlidingBall("compare_bad_frictions", "mu=0.3");
  const struct {
    std::string arguments;
    std::string message;
  } cases[] = {
      {"--frictions coulomb,lugra",
       "contactlaws: --frictions=coulomb,lugra has 'lugra', which is not a friction model (all, " +
           FrictionNameList() + "): did you mean 'lugre'?\n"},
      {"--frictions coulomb,coulomb",
       "contactlaws: --frictions=coulomb,coulomb names coulomb twice\n"},
      {"--frictions coulomb,none --friction lugre",
       "contactlaws: --frictions=coulomb,none goes without --friction=lugre (each run takes one "
       "of the list)\n"},
      {"--friction regularised",
       "contactlaws: --friction=regularised is not a friction model (" + FrictionNameList() +
           "): did you mean 'regularized'?\n"},
  };
  for (const auto& c : cases) {
    const Result r = RunCli("compare " + scene + " --quiet --duration 0.01 --output-dir " +
                            ::testing::TempDir() + "/bad_frictions " + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments;
    EXPECT_EQ(r.output, c.message) << c.arguments;
  }
}

// A stick spring too stiff for the scene's fixed timestep is named before
// the run, with the pair and the timestep that would do, by every command
// that runs a fixed step; not with --timestep auto (it resolves the spring),
// nor for a spring the step resolves (Mindlin's default).
TEST(FrictionCliTest, AStickSpringTooStiffForTheTimestepIsWarnedBeforeTheRun) {
  // k_t = 1e9 N/m on 1 kg: period 2 pi sqrt(1e-9) = 1.987e-4 s, 20 steps of
  // 9.93e-6 s; the scene steps 1e-4 s
  const std::string scene = SlidingBall("stiff_stick", "mu=0.3 tangential_stiffness=1e9");
  const std::string warning =
      "contactlaws: warning: " + scene +
      ": contactlaw:ball-floor (ball, floor): timestep 0.0001 s puts 1.99 steps in the period "
      "0.0001987 s of its stick spring (coulomb, k_t 1e+09 N/m, mass 1 kg) (>= 20 needed): use "
      "--timestep 9.93e-06 or smaller (see contactlaws check)\n";
  const std::string out = ::testing::TempDir() + "/stiff_stick";
  for (const std::string& command :
       {"run " + scene + " --duration 0.001",
        "compare " + scene + " --laws hunt-crossley --quiet --duration 0.001 --output-dir " + out,
        "restitution " + scene + " --laws hunt-crossley --restitution 0.5 --quiet --duration "
                                 "0.001 --output " + out + ".csv"}) {
    const Result r = RunCli(command);
    EXPECT_NE(r.output.find(warning), std::string::npos) << command << "\n" << r.output;
    const Result automatic = RunCli(command + " --timestep auto");
    EXPECT_EQ(automatic.output.find("stick spring"), std::string::npos) << automatic.output;
  }
  // the same line as check's verdict on it
  const Result check = RunCli("check " + scene);
  EXPECT_NE(check.output.find("tangential: stick spring (coulomb, k_t 1e+09 N/m, mass 1 kg): "
                              "period 0.0001987 s: TOO COARSE (needs timestep <= 9.93e-06 s)"),
            std::string::npos)
      << check.output;
  const Result mindlin = RunCli("run " + SlidingBall("mindlin_stick", "mu=0.3") +
                                " --duration 0.001");
  EXPECT_EQ(mindlin.output.find("stick spring"), std::string::npos) << mindlin.output;
  // LuGre's bristles: sigma0 F_n = 1e7 N/m per newton on 1 kg, at the load of
  // the estimated depth (68.2 N: the ball falls onto the floor from its 1 mm
  // gap), not its weight alone
  const std::string lugre =
      SlidingBall("stiff_bristles", "friction=lugre mu=0.3 bristle_stiffness=1e7");
  const Result bristles = RunCli("run " + lugre + " --duration 0.001");
  EXPECT_NE(bristles.output.find("of its bristles (lugre, sigma0 F_n 6.82e+08 N/m, F_n 68.2 N, "
                                 "mass 1 kg)"),
            std::string::npos)
      << bristles.output;
}

// The issue's bad friction input, each one line naming the file, the tag,
// the key, the value and the range: refused (exit 2) or warned.
TEST(FrictionCliTest, BadFrictionInputIsNamedInOneLine) {
  const struct {
    std::string name;
    std::string keys;   // the tag's friction keys
    std::string geoms;  // the geoms' attributes
    std::string message;
  } refused[] = {
      {"unknown_model", "friction=lugra", "",
       "contactlaw:ball-floor: friction=lugra is not a friction model (" + FrictionNameList() +
           "): did you mean 'lugre'?"},
      {"negative_mu", "mu=-0.2", "", "contactlaw:ball-floor: mu=-0.2 must be >= 0"},
      {"kinetic_above_static", "mu_static=0.3 mu_kinetic=0.5", "",
       "contactlaw:ball-floor: mu_kinetic=0.5 must be in [0, mu_static=0.3]"},
      // MuJoCo's default geom friction: 1
      {"kinetic_above_geoms", "mu_kinetic=1.5", "",
       "contactlaw:ball-floor: (ball, floor): mu_kinetic=1.5 must be in [0, mu_static=1] "
       "(mu_static from the geoms' friction)"},
      {"zero_stiffness", "tangential_stiffness=0", "",
       "contactlaw:ball-floor: tangential_stiffness=0 must be > 0 (N/m)"},
      {"negative_bristles", "friction=lugre bristle_stiffness=-1e5", "",
       "contactlaw:ball-floor: bristle_stiffness=-1e5 must be > 0 (1/m, per newton of normal "
       "force)"},
      {"negative_torsion", "torsional_friction=-0.01", "",
       "contactlaw:ball-floor: torsional_friction=-0.01 must be >= 0 (m, the torque cap over the "
       "normal force)"},
  };
  for (const auto& c : refused) {
    const std::string scene = SlidingBall("bad_" + c.name, c.keys, c.geoms);
    const Result r = RunCli("run " + scene + " --duration 0.001");
    EXPECT_EQ(r.status, 2) << c.name;
    EXPECT_EQ(r.output, "contactlaws: " + scene + ": " + c.message + "\n") << c.name;
  }
  // a friction key on a frictionless pair (condim 1): warned, and the run goes on
  const std::string frictionless = SlidingBall("condim1", "mu=0.5", R"(condim="1")");
  Result r = RunCli("run " + frictionless + " --duration 0.001");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("contactlaws: warning: " + frictionless +
                          ": contactlaw:ball-floor: (ball, floor): mu is not read: the pair is "
                          "frictionless (condim 1, as in MuJoCo)\n"),
            std::string::npos)
      << r.output;
  // a belt (linear drive) without a finite speed
  const std::string belt = WriteScene("belt_no_speed", R"(<mujoco>
  <worldbody>
    <body name="belt" mocap="true"><geom name="belt" type="box" size="1 1 0.01"/></body>
    <body name="box" pos="0 0 0.2"><freejoint/><geom name="box" type="sphere" size="0.1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:box-belt" data="geom1=box geom2=belt law=hertz stiffness=1e6"/>
    <text name="contactdrive:belt" data="body=belt motion=linear axis=x speed=nan"/>
  </custom>
</mujoco>)");
  r = RunCli("run " + belt + " --duration 0.001");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output,
            "contactlaws: " + belt + ": contactdrive:belt: speed=nan is not a finite number\n");
  // and the options
  r = RunCli("run " + frictionless + " --mu -0.1");
  EXPECT_EQ(r.output, "contactlaws: --mu=-0.1 must be >= 0\n");
}

}  // namespace
}  // namespace contactlaws
