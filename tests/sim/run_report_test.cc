// Copyright contactlaws authors.
//
// ChainedContactWarnings: a pulse through touching bodies is named, once per
// tag; bodies placed touching that settle into their contacts are not.

#include "sim/run_report.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class RunReportTest : public testing::MujocoTest {};

// A box (1 kg) on the floor with four balls (0.1 kg, r 2 cm) on it, every
// contact placed 1 nm deep (there at t = 0), at rest; gravity sinks each into
// its spring (K 1e7: the balls' static depth 2.1e-5 m) at up to ~1e-2 m/s,
// ten times the law's floor of v0 (1e-3 m/s) they "touched" at.
std::string BallsOnABox() {
  constexpr double kOverlap = 1e-9;  // m
  std::string balls;
  for (int i = 0; i < 4; ++i) {
    balls += fmt::format(R"(<body pos="{} {} {}"><freejoint/>
      <geom name="b{}" type="sphere" size="0.02" mass="0.1" group="1"/></body>)",
                         i % 2 ? 0.05 : -0.05, i / 2 ? 0.05 : -0.05, 0.1 + 0.02 - 2 * kOverlap, i);
  }
  return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body pos="0 0 {}"><freejoint/><geom name="box" type="box" size="0.1 0.1 0.05" mass="1"/></body>
    {}
  </worldbody>
  <custom>
    <text name="contactlaw:floor" data="geom1=box geom2=floor law=hunt-crossley restitution=0.5
      stiffness=1e7 friction=none"/>
    <text name="contactlaw:balls" data="geom1=group:1 geom2=box law=hunt-crossley restitution=0.5
      stiffness=1e7 friction=none"/>
  </custom>
</mujoco>)",
                     0.05 - kOverlap, balls);
}

TEST_F(RunReportTest, BodiesPlacedTouchingThatSettleAreNoChain) {
  Simulation& sim = MakeSimulation(BallsOnABox());
  while (sim.time() < 0.2) sim.Step();
  // every contact opened at t = 0 and was compressed faster than its v0
  int settled = 0;
  for (const Episode& point : sim.contacts().point_episodes()) {
    EXPECT_EQ(point.time_contact, 0.0);
    settled += point.max_approach_velocity > kChainFactor * point.touch_v0;
  }
  EXPECT_EQ(settled, 8);  // the box's four corners, the four balls
  EXPECT_EQ(ChainedContactWarnings(sim, kCommandLineSpelling), std::vector<std::string>());
}

// SimBenchmark's rolling test as issue 34 ran it (mjcf/rolling.xml with the
// laws' default floor of v0, 1e-3 m/s): a box pushed along the floor by an
// actuator, 25 balls on it, every body placed exactly touching (d = 0). Each
// sinks into its springs at ~1e-2 m/s under its weight (the box under the
// balls' too), ten times the floor it touched at: no impact, no push.
std::string RollingAtTheDefaultFloor() {
  std::ifstream file(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/rolling.xml");
  std::stringstream text;
  text << file.rdbuf();
  std::string xml = text.str();
  const std::string floor = " min_impact_velocity=1e-2";
  for (size_t at = xml.find(floor); at != std::string::npos; at = xml.find(floor)) {
    xml.erase(at, floor.size());
  }
  return xml;
}

TEST_F(RunReportTest, BodiesPlacedTouchingMakeOneLineThatPointsToSettle) {
  Simulation& sim = MakeSimulation(RollingAtTheDefaultFloor());
  while (sim.time() < 0.2) sim.Step();
  // what the chain rule alone flags: both tags (measured: 1 and 25 impacts)
  int chained = 0;
  for (const Episode& c : sim.contacts().impacts()) chained += c.chained();
  EXPECT_GT(chained, 1);
  const std::vector<std::string> w = ChainedContactWarnings(sim, kCommandLineSpelling);
  ASSERT_EQ(w.size(), 1u);
  std::printf("%s\n", w[0].c_str());
  EXPECT_NE(w[0].find(fmt::format("{} contacts touching at rest", chained)), std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("--settle"), std::string::npos) << w[0];
  EXPECT_EQ(w[0].find("pulse"), std::string::npos) << w[0];
}

// A pyramid placed exactly touching: two 10 cm balls side by side on the
// floor, a third on them. The top ball's weight wedges the two apart and,
// through friction, together: their contact compresses at 0.004 m/s with
// no weight of their own along its horizontal normal. That is the scene
// settling, as the floor's contacts do at up to 0.013 m/s: one line, which
// points to --settle (two before: the wedged pair was called pushed).
TEST_F(RunReportTest, BallsWedgedUnderABallSettleInOneLine) {
  const double r = 0.05;
  const std::string xml = fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody><geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="a" pos="0 0 {0}"><freejoint/>
      <geom type="sphere" size="{0}" mass="1" group="1"/></body>
    <body name="b" pos="{1} 0 {0}"><freejoint/>
      <geom type="sphere" size="{0}" mass="1" group="1"/></body>
    <body name="c" pos="{0} 0 {2}"><freejoint/>
      <geom type="sphere" size="{0}" mass="1" group="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:balls" data="geom1=group:1 geom2=group:1 law=hunt-crossley
      restitution=0.5 stiffness=1e8 friction=coulomb mu=0.5"/>
    <text name="contactlaw:floor" data="geom1=floor geom2=group:1 law=hunt-crossley
      restitution=0.5 stiffness=1e8 friction=coulomb mu=0.5"/>
  </custom>
</mujoco>)",
                                      r, 2 * r, r + 2 * r * std::sin(M_PI / 3));
  Simulation& sim = MakeSimulation(xml);
  while (sim.time() < 0.1) sim.Step();
  const std::vector<std::string> w = ChainedContactWarnings(sim, kCommandLineSpelling);
  ASSERT_EQ(w.size(), 1u) << w[0];
  EXPECT_NE(w[0].find("touching at rest"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("--settle"), std::string::npos) << w[0];
  EXPECT_EQ(w[0].find("pushed"), std::string::npos) << w[0];
}

// Settled, then struck: box_stack.xml's top cube lands on the two settled
// ones, and the bottom one, bounced, comes to rest on the floor again at
// 0.149 s: a contact touching at rest that sinks under its load, said in one
// line, which cannot point to --settle: the run was settled.
TEST_F(RunReportTest, ASettledRunIsNotToldToSettle) {
  SimulationOptions options;
  options.settle = true;
  options.timestep = 2e-3;
  options.integrator = mjINT_EULER;
  options.contact_steps.substeps = kContactStepsAuto;
  Simulation& sim = MakeSceneSimulation("box_stack.xml", options);
  while (sim.time() < 0.5) sim.Step();
  const std::vector<std::string> w = ChainedContactWarnings(sim, kCommandLineSpelling);
  bool resting = false;
  for (const std::string& line : w) {
    resting = resting || line.find("touching at rest") != std::string::npos;
    EXPECT_EQ(line.find("--settle"), std::string::npos) << line;
  }
  EXPECT_TRUE(resting);
}

// A seesaw: a block resting on one end of a hinged plank (there at t = 0),
// a ball dropped onto the other end. The plank flings the block: a push
// through a contact that was there at the start, named with the speed it
// touched at: none (printed 0, not -0).
TEST_F(RunReportTest, APushThroughAContactThereAtTheStartTouchedAtZero) {
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="1e-4"/>
  <worldbody>
    <body name="plank" pos="0 0 0.3"><joint type="hinge" axis="0 1 0"/>
      <geom name="plank" type="box" size="0.5 0.05 0.01" mass="0.5"/></body>
    <body name="ball" pos="0.4 0 0.8"><freejoint/>
      <geom name="ball" type="sphere" size="0.03" mass="0.3"/></body>
    <body name="block" pos="-0.4 0 0.33"><freejoint/>
      <geom name="block" type="box" size="0.02 0.02 0.02" mass="0.05"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:ball" data="geom1=ball geom2=plank law=hunt-crossley restitution=0.7
      stiffness=1e6 friction=none"/>
    <text name="contactlaw:block" data="geom1=block geom2=plank law=gonthier restitution=0.5
      stiffness=1e6 friction=none"/>
  </custom>
</mujoco>)");
  while (sim.time() < 0.35) sim.Step();
  std::string push;
  for (const std::string& w : ChainedContactWarnings(sim, kCommandLineSpelling)) {
    if (w.find("contactlaw:block") != std::string::npos) push = w;
  }
  ASSERT_FALSE(push.empty());
  EXPECT_NE(push.find("touched at 0 m/s"), std::string::npos) << push;
  EXPECT_EQ(push.find("-0 m/s"), std::string::npos) << push;
}

}  // namespace
}  // namespace contactlaws
