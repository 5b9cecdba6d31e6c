// Copyright contactlaws authors.
//
// libcontactlaws_plugin.so preloaded into plain_mujoco.c, a C program that
// links libmujoco alone: the paper's ball (without gravity, so that the
// closed form holds exactly) rebounds at the tagged law's exact rebound with
// the plugin and not without it; two mjData of one model each get their
// laws; a model without tags in the same program steps bit for bit as
// without the plugin; CONTACTLAWS_ACCURACY steps with the auto timestep,
// CONTACTLAWS_CONTACT_STEPS integrates the contacts inside a 2 ms step;
// refused tags and environment values are one line.

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "plugin_test_util.h"

namespace contactlaws {
namespace {

using testing::Preload;
using testing::ProgramResult;
using testing::RunProgram;

// The rebound of the Hertz-family laws against ExactRebound at 1e-5 s, 4.2
// m/s, RK4: within 2e-5 (docs/testing.md); the law tests hold it to 2e-4.
constexpr double kReboundTolerance = 2e-4;
// MuJoCo's own soft contact is no Flores contact at e = 0.9: its rebound is
// farther than this from the law's (measured: 0.135 against 0.894).
constexpr double kMujocoDifference = 0.05;
// The paper's impact speed, sqrt(2 g 0.9), m/s.
constexpr double kImpactSpeed = 4.2;
// CONTACTLAWS_ACCURACY: the relative error the auto timestep accepts in the
// rebound (docs/timestep.md: delivered within 1.0e-5 at this accuracy).
constexpr double kAccuracy = 1e-3;
// The fixed 1e-5 s takes ~630 steps from 2 cm above the floor until the ball
// is 1 mm clear of it again (4.8 ms of approach, the 1.3 ms contact); the auto
// step halves the gap in a few long steps and takes ~50 in the contact. At
// least this many times fewer says the plugin set the model's timestep.
constexpr int kAutoFewerSteps = 4;

// The paper's ball, 2 cm above the floor, without gravity; tags as given,
// stepped at timestep (s) by integrator.
std::string BallScene(const std::string& name, const std::string& tags,
                      const std::string& timestep = "1e-5",
                      const std::string& integrator = "RK4") {
  const std::string path = testing::TempPath(name + ".xml");
  std::ofstream(path) << fmt::format(R"(<mujoco>
  <option timestep="{}" gravity="0 0 0" integrator="{}"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="ball" pos="0 0 0.12">
      <freejoint/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/>
      <geom name="ball" type="sphere" size="0.1"/>
    </body>
  </worldbody>
  {}
</mujoco>)", timestep, integrator, tags);
  return path;
}

std::string Tag(const std::string& law, const std::string& restitution) {
  return fmt::format(R"(<custom><text name="contactlaw:ball-floor" data="geom1=ball geom2=floor
    law={} restitution={} stiffness=1.4e8 exponent=1.5"/></custom>)", law, restitution);
}

// One output line of plain_mujoco: its key=value fields.
using Fields = std::map<std::string, std::string>;

std::map<std::string, Fields> ParseRuns(const std::string& out) {
  std::map<std::string, Fields> runs;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name, word;
    words >> name;
    while (words >> word) {
      const size_t eq = word.find('=');
      runs[name][word.substr(0, eq)] = word.substr(eq + 1);
    }
  }
  return runs;
}

double Number(const Fields& fields, const std::string& key) {
  return std::stod(fields.at(key));
}

struct Outcome {
  ProgramResult program;
  std::map<std::string, Fields> runs;
};

Outcome RunPlain(const std::string& environment, const std::string& tagged) {
  const std::string untagged = BallScene("untagged", "");
  Outcome outcome;
  outcome.program = RunProgram(environment, fmt::format("{} {} {} {}", CONTACTLAWS_PLAIN_MUJOCO,
                                                        tagged, untagged, kImpactSpeed));
  EXPECT_EQ(outcome.program.status, 0) << outcome.program.err;
  outcome.runs = ParseRuns(outcome.program.out);
  return outcome;
}

double Exact(LawId law, double e) { return *EffectiveRestitution(law, e); }

TEST(PluginTest, PreloadedBallReboundsAtTheLawsExactRebound) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome with = RunPlain(Preload(), tagged);
  for (const char* name : {"tagged0", "tagged1"}) {
    const Fields& run = with.runs.at(name);
    EXPECT_EQ(run.at("done"), "1") << name;
    EXPECT_NEAR(Number(run, "rebound"), Exact(*ParseLawName("flores"), 0.9), kReboundTolerance) << name;
    // the tagged point shown (in gap), no MuJoCo constraint
    EXPECT_GE(Number(run, "gap_contacts"), 1) << name;
    EXPECT_EQ(Number(run, "solver_contacts"), 0) << name;
  }
  // the two mjData of one model: the same run, bit for bit
  EXPECT_EQ(with.runs.at("tagged0").at("z"), with.runs.at("tagged1").at("z"));
  EXPECT_EQ(with.runs.at("tagged0").at("vz"), with.runs.at("tagged1").at("vz"));
  // one activation line, naming the file and the pair (friction: MuJoCo's
  // default geom friction 1, condim 3)
  EXPECT_EQ(with.program.err, fmt::format("contactlaws: plugin: {}: ball-floor (ball, floor: "
                                          "flores, e = 0.9, coulomb mu 1)\n", tagged));
}

TEST(PluginTest, WithoutThePluginMujocoContactActs) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome without = RunPlain("", tagged);
  const Fields& run = without.runs.at("tagged0");
  EXPECT_GT(std::abs(Number(run, "rebound") - Exact(*ParseLawName("flores"), 0.9)), kMujocoDifference);
  EXPECT_GE(Number(run, "solver_contacts"), 1);
  EXPECT_EQ(Number(run, "gap_contacts"), 0);
  EXPECT_EQ(without.program.err, "");
}

TEST(PluginTest, UntaggedModelStepsBitForBitAsWithoutThePlugin) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Fields with = RunPlain(Preload(), tagged).runs.at("untagged");
  const Fields without = RunPlain("", tagged).runs.at("untagged");
  EXPECT_EQ(with, without);
  EXPECT_EQ(with.at("gap_contacts"), "0");
}

TEST(PluginTest, EnvironmentOverridesTheLawAndRestitution) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome with = RunPlain(
      Preload() + " CONTACTLAWS_LAW=hunt-crossley CONTACTLAWS_RESTITUTION=0.5", tagged);
  EXPECT_NEAR(Number(with.runs.at("tagged0"), "rebound"), Exact(*ParseLawName("hunt-crossley"), 0.5),
              kReboundTolerance);
  EXPECT_NE(with.program.err.find("hunt-crossley, e = 0.5"), std::string::npos)
      << with.program.err;
}

TEST(PluginTest, AccuracyStepsWithTheAutoTimestepAtThatAccuracy) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome fixed = RunPlain(Preload(), tagged);
  const Outcome automatic =
      RunPlain(Preload() + fmt::format(" CONTACTLAWS_ACCURACY={}", kAccuracy), tagged);
  const double exact = Exact(*ParseLawName("flores"), 0.9);
  for (const char* name : {"tagged0", "tagged1"}) {
    const Fields& run = automatic.runs.at(name);
    EXPECT_EQ(run.at("done"), "1") << name;
    EXPECT_NEAR(Number(run, "rebound"), exact, kAccuracy * exact) << name;
    EXPECT_LT(kAutoFewerSteps * Number(run, "steps"), Number(fixed.runs.at(name), "steps"))
        << name << ": " << run.at("steps") << " steps against "
        << fixed.runs.at(name).at("steps");
  }
  // two mjData of one model, each setting the model's timestep before its own
  // step: the same run, bit for bit
  EXPECT_EQ(automatic.runs.at("tagged0").at("z"), automatic.runs.at("tagged1").at("z"));
  // the untagged model keeps its own timestep: its steps are those without it
  EXPECT_EQ(automatic.runs.at("untagged"), fixed.runs.at("untagged"));
}

TEST(PluginTest, BadAccuracyIsOneLineAndMujocoContactActs) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome with = RunPlain(Preload() + " CONTACTLAWS_ACCURACY=0.5", tagged);
  EXPECT_EQ(with.program.err, "contactlaws: CONTACTLAWS_ACCURACY=0.5 must be in (0, 0.1]\n");
  EXPECT_GE(Number(with.runs.at("tagged0"), "solver_contacts"), 1);
}

TEST(PluginTest, BadEnvironmentValueIsOneLineAndMujocoContactActs) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome with = RunPlain(Preload() + " CONTACTLAWS_RESTITUTION=0x1", tagged);
  EXPECT_EQ(with.program.err, "contactlaws: CONTACTLAWS_RESTITUTION=0x1 is not a finite number\n");
  EXPECT_GE(Number(with.runs.at("tagged0"), "solver_contacts"), 1);
  const Outcome law = RunPlain(Preload() + " CONTACTLAWS_LAW=stokes", tagged);
  EXPECT_EQ(law.program.err, fmt::format("contactlaws: CONTACTLAWS_LAW=stokes is not a law ({})\n",
                                         LawNameList()));
}

// CONTACTLAWS_CONTACT_STEPS=auto: the same ball at MuJoCo's default 2 ms
// step, Euler, rebounds at the law's exact rebound (the contacts integrated
// inside each step); without it the plugin's law at 2 ms does not.
TEST(PluginTest, ContactStepsReboundAtTheLawsExactReboundAtTwoMilliseconds) {
  // issue 35's goal for the paper's ball at 2 ms (docs/timestep.md: delivered
  // within 6e-5 relative)
  constexpr double kContactStepsTolerance = 5e-3;  // relative
  const std::string tagged = BallScene("flores_2ms", Tag("flores", "0.9"), "2e-3", "Euler");
  const double exact = Exact(*ParseLawName("flores"), 0.9);
  const Outcome inner = RunPlain(Preload() + " CONTACTLAWS_CONTACT_STEPS=auto", tagged);
  for (const char* name : {"tagged0", "tagged1"}) {
    const Fields& run = inner.runs.at(name);
    EXPECT_EQ(run.at("done"), "1") << name;
    EXPECT_NEAR(Number(run, "rebound"), exact, kContactStepsTolerance * exact) << name;
  }
  EXPECT_EQ(inner.runs.at("tagged0").at("z"), inner.runs.at("tagged1").at("z"));
  const Outcome plain = RunPlain(Preload(), tagged);
  EXPECT_GT(std::abs(Number(plain.runs.at("tagged0"), "rebound") - exact), kMujocoDifference);
  // the untagged model is MuJoCo's alone either way
  EXPECT_EQ(inner.runs.at("untagged"), plain.runs.at("untagged"));
}

TEST(PluginTest, BadContactStepsIsOneLineAndMujocoContactActs) {
  const std::string tagged = BallScene("flores_2ms", Tag("flores", "0.9"), "2e-3", "Euler");
  const Outcome zero = RunPlain(Preload() + " CONTACTLAWS_CONTACT_STEPS=0", tagged);
  EXPECT_EQ(zero.program.err, "contactlaws: CONTACTLAWS_CONTACT_STEPS=0 must be auto or a whole "
                              "number of sub-steps in [1, 1e6]\n");
  EXPECT_GE(Number(zero.runs.at("tagged0"), "solver_contacts"), 1);
  const Outcome both = RunPlain(
      Preload() + " CONTACTLAWS_CONTACT_STEPS=auto CONTACTLAWS_ACCURACY=1e-3", tagged);
  EXPECT_EQ(both.program.err, "contactlaws: CONTACTLAWS_CONTACT_STEPS=auto goes with the "
                              "program's fixed step, not with CONTACTLAWS_ACCURACY\n");
}

// CONTACTLAWS_FRICTION and CONTACTLAWS_MU: --friction and --mu, read by the
// same parsers; a bad one is one line and leaves the model to MuJoCo.
TEST(PluginTest, EnvironmentOverridesTheFriction) {
  const std::string tagged = BallScene("flores", Tag("flores", "0.9"));
  const Outcome with =
      RunPlain(Preload() + " CONTACTLAWS_FRICTION=lugre CONTACTLAWS_MU=0.3", tagged);
  EXPECT_EQ(with.program.err, fmt::format("contactlaws: plugin: {}: ball-floor (ball, floor: "
                                          "flores, e = 0.9, lugre mu 0.3)\n", tagged));
  EXPECT_EQ(Number(with.runs.at("tagged0"), "solver_contacts"), 0);
  const Outcome none = RunPlain(Preload() + " CONTACTLAWS_FRICTION=none", tagged);
  EXPECT_EQ(none.program.err, fmt::format("contactlaws: plugin: {}: ball-floor (ball, floor: "
                                          "flores, e = 0.9)\n", tagged));
  const struct {
    std::string environment;
    std::string line;
  } bad[] = {
      {"CONTACTLAWS_FRICTION=lugra",
       "contactlaws: CONTACTLAWS_FRICTION=lugra is not a friction model (" + FrictionNameList() +
           "): did you mean 'lugre'?\n"},
      {"CONTACTLAWS_MU=-0.5", "contactlaws: CONTACTLAWS_MU=-0.5 must be >= 0\n"},
      {"CONTACTLAWS_MU=high", "contactlaws: CONTACTLAWS_MU=high is not a finite number\n"},
  };
  for (const auto& b : bad) {
    const Outcome refused = RunPlain(Preload() + " " + b.environment, tagged);
    EXPECT_EQ(refused.program.err, b.line) << b.environment;
    EXPECT_GE(Number(refused.runs.at("tagged0"), "solver_contacts"), 1) << b.environment;
  }
}

TEST(PluginTest, RefusedTagsPrintRunsLineAndLeaveTheModelToMujoco) {
  const std::string refused = BallScene("refused", Tag("flores", "0"));
  const Outcome with = RunPlain(Preload(), refused);
  const ProgramResult run =
      RunProgram("", fmt::format("{} run {} --duration 0.001", CONTACTLAWS_CLI, refused));
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(with.program.err, run.err);  // the same one line
  EXPECT_NE(run.err.find("restitution=0 must be in (0, 1] for flores"), std::string::npos);
  EXPECT_GE(Number(with.runs.at("tagged0"), "solver_contacts"), 1);
}

// CONTACTLAWS_SETTLE=1 (simulate --settle): a cube placed exactly on the
// floor starts in the static equilibrium of its four corners, as
// mujoco-simulate makes and resets its data; without it the cube drops into
// its springs. A value other than 1 is one line.
TEST(PluginTest, SettleStartsAndResetsTheDataInTheStaticEquilibrium) {
  constexpr double kHalf = 0.05, kStiffness = 1e7;  // m; N/m^1.5
  const std::string scene = testing::TempPath("cube.xml");
  std::ofstream(scene) << fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="cube" pos="0 0 {0}"><freejoint/>
      <geom name="cube" type="box" size="{0} {0} {0}" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:cube-floor" data="geom1=cube geom2=floor law=hunt-crossley
    restitution=0.5 stiffness={1} min_impact_velocity=1e-2"/></custom>
</mujoco>)", kHalf, kStiffness);
  auto run = [&](const std::string& environment) {
    const ProgramResult r = RunProgram(Preload() + environment,
                                       fmt::format("{} {} 1000", CONTACTLAWS_RESTING_MUJOCO, scene));
    EXPECT_EQ(r.status, 0) << r.err;
    std::istringstream words(r.out);
    std::map<std::string, double> fields;
    for (std::string word; words >> word;) {
      fields[word.substr(0, word.find('='))] = std::stod(word.substr(word.find('=') + 1));
    }
    return std::make_pair(r.err, fields);
  };
  // statics: each corner carries W / 4 at d = (W / 4 / K)^(2/3)
  const double depth = std::pow(9.81 / 4 / kStiffness, 2.0 / 3.0);
  const auto [settled_err, settled] = run(" CONTACTLAWS_SETTLE=1");
  EXPECT_NE(settled_err.find(fmt::format("contactlaws: plugin: {}: settled 1 body in contact at "
                                         "t = 0 (", scene)), std::string::npos)
      << settled_err;
  // what is left of the relaxation: below 1e-6 of the depth (settle_test)
  EXPECT_NEAR(settled.at("start"), kHalf - depth, 1e-6 * depth);
  EXPECT_EQ(settled.at("reset"), settled.at("start"));
  // 0.1 s at rest: the relaxation's residual, 1e-6 g, moves it < 5e-8 m
  EXPECT_LT(settled.at("moved"), 1e-8);
  const auto [placed_err, placed] = run("");
  EXPECT_EQ(placed.at("start"), kHalf);
  EXPECT_GT(placed.at("moved"), 0.1 * depth);  // dropped into its springs
  EXPECT_EQ(run(" CONTACTLAWS_SETTLE=yes").first,
            "contactlaws: CONTACTLAWS_SETTLE=yes must be 1 (or unset)\n");
}

}  // namespace
}  // namespace contactlaws
