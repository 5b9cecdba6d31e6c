// Copyright contactlaws authors.
//
// Articulated and rotating bodies: the trajectory's columns (every moving
// body, joints, orientation and spin, by group) and a pendulum whose bob
// strikes a wall through its joint chain, against the law's exact rebound.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/law.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

// A pendulum (hinge at 1 m, a light rod body and a joint-less bob body below
// it) swinging at `spin` rad/s with gravity off, its bob 0.05 mm from a wall
// (a plane facing -x at x = 0.3), and a free ball spinning far away.
std::string PendulumXml(const std::string& tag, double spin) {
  return fmt::format(R"(<mujoco>
  <option timestep="1e-5" integrator="RK4" gravity="0 0 0"/>
  <worldbody>
    <geom name="wall" type="plane" size="1 1 0.1" pos="0.3 0 0.5" zaxis="-1 0 0"/>
    <body name="arm" pos="0 0 1">
      <joint name="swing" type="hinge" axis="0 -1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.005" mass="0.01"/>
      <body name="bob" pos="0 0 -0.5">
        <geom name="bob" type="sphere" size="0.1" mass="1"/>
      </body>
    </body>
    <body name="spinner" pos="5 5 1"><freejoint/>
      <geom type="sphere" size="0.1" mass="1"/></body>
  </worldbody>
  <keyframe><key qpos="0.38 5 5 1 1 0 0 0" qvel="{} 0 0 0 0 0 3"/></keyframe>
  <custom><text name="contactlaw:bob-wall" data="geom1=bob geom2=wall friction=none {}"/></custom>
</mujoco>)",
                     spin, tag);
}

class ArticulatedTest : public testing::MujocoTest {};

TEST_F(ArticulatedTest, TheTrajectoryHasEveryMovingBodyJointAndSpin) {
  Simulation& sim =
      MakeSimulation(PendulumXml("law=hertz stiffness=1e8", 2.0));
  const std::vector<std::string> columns = sim.Columns();
  auto has = [&](const std::string& name) {
    return std::find(columns.begin(), columns.end(), name) != columns.end();
  };
  // the arm (jointed), the bob (joint-less child), the spinner (free)
  for (const char* c : {"arm.x", "bob.x", "bob.vz", "spinner.qw", "spinner.wz", "swing.q",
                        "swing.v", "bob-wall.force", "energy.total"}) {
    EXPECT_TRUE(has(c)) << c;
  }
  EXPECT_FALSE(has("arm.qw")) << "a hinged body has its joint's angle, not a quaternion";

  std::vector<double> row;
  sim.Sample(&row);
  ASSERT_EQ(row.size(), columns.size());
  auto value = [&](const std::string& name) {
    return row[std::find(columns.begin(), columns.end(), name) - columns.begin()];
  };
  // the bob is 0.5 m below the hinge, turned 0.38 rad about -y: x = 0.5 sin
  EXPECT_NEAR(value("bob.x"), 0.5 * std::sin(0.38), 1e-12);
  EXPECT_NEAR(value("bob.vx"), 0.5 * 2.0 * std::cos(0.38), 1e-12);
  EXPECT_EQ(value("swing.q"), 0.38);
  EXPECT_EQ(value("swing.v"), 2.0);
  EXPECT_EQ(value("spinner.wz"), 3.0);  // world frame: the spinner is not turned
  EXPECT_EQ(value("spinner.qw"), 1.0);

  // groups leave their columns out
  SimulationOptions only_joints;
  only_joints.columns = {false, true, false, false, false};
  Simulation& joints = MakeSimulation(PendulumXml("law=hertz stiffness=1e8", 2.0), only_joints);
  EXPECT_EQ(joints.Columns(), (std::vector<std::string>{"time", "swing.q", "swing.v"}));
}

// The bob strikes the wall through the hinge: the rebound is the law's exact
// one whatever the effective mass (hysteresis family), and Kelvin-Voigt's
// damping from e needs the effective mass along the joint chain (I / L^2
// here) to rebound at e. Gravity is off, as in the closed forms.
TEST_F(ArticulatedTest, APendulumReboundsAtTheLawsRestitutionThroughItsChain) {
  // RK4 at 1e-5 s against a contact of ~100 steps, measured within 3e-5 of
  // the closed form; the paper's drop tests hold the laws to 2e-4
  constexpr double kReboundTolerance = 2e-4;
  for (const char* law : {"hunt-crossley", "flores"}) {
    Simulation& sim = MakeSimulation(
        PendulumXml(fmt::format("law={} restitution=0.6 stiffness=1e8", law), 2.0));
    const Episode impact = testing::FirstImpact(sim, 0.5);
    EXPECT_NEAR(impact.restitution_post(),
                ExactRebound(HysteresisCoefficient(*ParseLawName(law), 0.6)), kReboundTolerance)
        << law;
    // the bob touches at sin(angle) = (0.3 - 0.1) / 0.5; its speed towards
    // the wall is then the swing rate times the arm's vertical extent
    // (exact but for the 1e-5 s step before the touch, at 2 rad/s)
    const double touch = std::asin(0.4);
    EXPECT_NEAR(impact.impact_velocity, 2.0 * 0.5 * std::cos(touch), 1e-5) << law;
  }
  // Kelvin-Voigt with tension kept rebounds at e itself, if its damping
  // c = 2 zeta sqrt(k m_eff) has the right m_eff: here I / (L cos)^2 = 1.21 kg
  // (the bob's 1 kg would rebound at 0.63). Its force jumps to c v0 at the
  // touch, which a fixed step sees late: up to zeta omega h = 1.5e-3 in e.
  const double inertia = 1.0 * 0.25 + 0.004 + 0.01 * 0.16 / 3;  // about the hinge, kg m^2
  const double lever = 0.5 * std::cos(std::asin(0.4));          // m
  const double m_eff = inertia / (lever * lever);
  const double kelvin_voigt_tolerance =
      KelvinVoigtDampingRatio(0.6) * std::sqrt(1e6 / m_eff) * 1e-5;
  Simulation& kv = MakeSimulation(PendulumXml(
      "law=kelvin-voigt restitution=0.6 linear_stiffness=1e6 allow_tension=true", 2.0));
  EXPECT_NEAR(testing::FirstImpact(kv, 0.5).restitution_post(), 0.6, kelvin_voigt_tolerance);
}

}  // namespace
}  // namespace contactlaws
