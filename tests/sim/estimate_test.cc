// Copyright contactlaws authors.
//
// The contact estimates against the simulated contact and closed forms.

#include "sim/estimate.h"

#include <cmath>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class EstimateTest : public testing::MujocoTest {};

TEST_F(EstimateTest, HertzContactDurationMatchesTheSimulatedContact) {
  // t_c = 2.9432 d_max / v for n = 3/2 (B(2/5, 1/2) / (5/2) = 1.4716).
  EXPECT_NEAR(HertzContactDuration(1.0, 1.5, 1.0, 1.0) / HertzMaxDepth(1.0, 1.5, 1.0, 1.0),
              2.9432, 1e-4);
  // Against the simulated Hertz drop (gravity off): the simulated duration is
  // extrapolated to d = 0 at both ends, O(h^2 / tau^2) ~ 1e-4 at h = 1e-5;
  // the integrator's energy error adds ~1e-4.
  constexpr double kDurationTolerance = 1e-3;  // relative
  for (double v : {0.5, 4.2}) {
    Simulation& sim = MakeSimulation(testing::DropXml(
        "law=hertz stiffness=1.4e8 exponent=1.5", v, "RK4"));
    const Episode impact = testing::FirstImpact(sim);
    const double simulated = impact.time_separation - impact.time_contact;
    EXPECT_NEAR(simulated / HertzContactDuration(1.4e8, 1.5, 1.0, v), 1.0, kDurationTolerance)
        << "v = " << v;
  }
}

TEST_F(EstimateTest, ThePaperBallFallsFromItsGap) {
  Simulation& sim = MakeSceneSimulation("bouncing_ball.xml");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  EXPECT_EQ(e.effective_mass, 1.0);
  ASSERT_TRUE(e.gap);
  EXPECT_NEAR(*e.gap, 0.9, 1e-12);
  EXPECT_NEAR(e.impact_velocity, std::sqrt(2 * 9.81 * 0.9), 1e-12);
  EXPECT_EQ(e.contact_duration, HertzContactDuration(1.4e8, 1.5, 1.0, e.impact_velocity));
  EXPECT_EQ(e.timestep(), e.contact_duration / kStepsPerContact);
  // a stated impact velocity replaces the estimate
  EXPECT_EQ(EstimateContact(sim.contacts(), 0, 1.0).impact_velocity, 1.0);
}

// Two cubes placed touching (gap 0, nothing to bring them together): no
// impact to estimate, yet the stick spring between them has a stiffness,
// Mindlin's at the depth that carries the upper cube's weight at rest. It
// read k_t 0 N/m, a period of infinity, from the depth 0 of no estimate.
TEST_F(EstimateTest, ATouchingPairsStickSpringIsTakenAtItsDepthAtRest) {
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <body name="low" pos="0 0 0.05" mocap="true">
      <geom name="low" type="box" size="0.05 0.05 0.05"/></body>
    <body name="up" pos="0 0 0.15"><freejoint/>
      <geom name="up" type="box" size="0.05 0.05 0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:t" data="geom1=low geom2=up law=hunt-crossley restitution=0.5
    stiffness=1e7 mu=0.5"/></custom>
</mujoco>)");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate normal = EstimateContact(sim.contacts(), 0);
  ASSERT_FALSE(std::isfinite(normal.max_depth));  // no impact: not estimated
  const TangentialEstimate t = EstimateTangential(sim.contact_model(), 0, normal);
  const double load = 9.81;                      // N: the upper cube's weight
  const double depth = std::pow(load / 1e7, 1 / 1.5);  // K d^1.5 = load
  const double mindlin = kMindlinRatio * 1.5 * 1e7 * std::sqrt(depth);
  EXPECT_NEAR(t.normal_force, load, 1e-12 * load);
  EXPECT_NEAR(t.stiffness, mindlin, 1e-12 * mindlin);
  EXPECT_NEAR(t.duration, M_PI * std::sqrt(1.0 / mindlin), 1e-12);  // critical: pi sqrt(m/k)
  EXPECT_NE(t.what.find("at the depth of its load at rest"), std::string::npos) << t.what;
}

TEST_F(EstimateTest, DrivenTableAddsItsTopSpeed) {
  Simulation& sim = MakeSceneSimulation("ball_table.xml");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  EXPECT_EQ(e.effective_mass, 1.0);  // the table is driven: infinitely heavy
  ASSERT_TRUE(e.gap);
  EXPECT_NEAR(*e.gap, 0.4, 1e-12);
  EXPECT_NEAR(e.impact_velocity, std::sqrt(2 * 9.81 * 0.4) + 0.1 * 7.5, 1e-12);
}

// A pendulum released from rest swings into a wall: nothing closes the pair
// by the current speeds and gravity along the normal (horizontal), so the
// estimate steps ahead to the touch. Energy gives the swing rate there:
// (1/2) I w^2 = g (sum m_i l_i) (cos a_touch - cos a_0), and the bob's speed
// towards the wall w L cos a_touch; the effective mass is I / (L cos)^2.
TEST_F(EstimateTest, APendulumIsSteppedAheadToItsTouch) {
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="wall" type="plane" size="1 1 0.1" pos="0.3 0 0.5" zaxis="-1 0 0"/>
    <body name="arm" pos="0 0 1">
      <joint name="swing" type="hinge" axis="0 -1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.005" mass="0.01"/>
      <body name="bob" pos="0 0 -0.5"><geom name="bob" type="sphere" size="0.1" mass="1"/></body>
    </body>
  </worldbody>
  <keyframe><key qpos="-0.5"/></keyframe>
  <custom><text name="contactlaw:bob-wall"
    data="geom1=bob geom2=wall law=hunt-crossley restitution=0.5 stiffness=1e8"/></custom>
</mujoco>)");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  ASSERT_TRUE(e.looked_ahead);
  const double touch = std::asin(0.4);  // the bob's surface at the wall
  const double inertia = 0.25 + 0.004 + 0.01 * 0.16 / 3;  // about the hinge, kg m^2
  const double moment = 1.0 * 0.5 + 0.01 * 0.2;           // sum m_i l_i, kg m
  const double swing =
      std::sqrt(2 * 9.81 * moment * (std::cos(touch) - std::cos(0.5)) / inertia);
  // the look stops at the last step before the touch: one step of swing
  // (w' L h = g L h ~ 5e-4 m/s) and the capsule's inertia taken as a rod's
  constexpr double kLookAheadTolerance = 1e-3;  // m/s
  EXPECT_NEAR(e.impact_velocity, swing * 0.5 * std::cos(touch), kLookAheadTolerance);
  EXPECT_NEAR(e.effective_mass, inertia / std::pow(0.5 * std::cos(touch), 2), 1e-2);
  EXPECT_TRUE(std::isfinite(e.contact_duration));
}

// A plank (1 m, 0.5 kg) on a pivot at one end, level, 0.3 m above the floor:
// gravity alone would close the gap at g (2.39 m/s over 0.29 m, with all its
// 0.5 kg); on its pivot its far corner lands at w L cos(theta) with I / (L
// cos(theta))^2 of it, which the estimate steps ahead to find although
// gravity over the gap already gives a speed.
TEST_F(EstimateTest, APlankOnAPivotIsSteppedAheadToItsLanding) {
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="1e-4"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="plank" pos="0 0 0.3"><joint type="hinge" axis="0 1 0"/>
      <geom name="plank" type="box" pos="0.5 0 0" size="0.5 0.05 0.01" mass="0.5"/></body>
  </worldbody>
  <custom><text name="contactlaw:plank-floor" data="geom1=plank geom2=floor law=hunt-crossley
    restitution=0.3 stiffness=1e7 friction=none"/></custom>
</mujoco>)");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  ASSERT_TRUE(e.looked_ahead);
  // the lower far corner (1 m out, 1 cm below the axis) touches the floor
  const double arm = std::hypot(1.0, 0.01);
  const double theta = std::asin(0.3 / arm) - std::atan2(0.01, 1.0);  // the plank's tilt
  const double inertia = 0.5 * (1.0 / 3 + 0.02 * 0.02 / 12);  // about the pivot, kg m^2
  const double w = std::sqrt(2 * 0.5 * 9.81 * 0.5 * std::sin(theta) / inertia);  // rad/s
  const double lever = std::cos(theta) - 0.01 * std::sin(theta);  // the corner's, horizontal, m
  // the look stops at the last step before the touch: one step of fall
  // (w' lever h ~ 2e-3 m/s at 1e-4 s)
  constexpr double kLookAheadTolerance = 3e-3;  // m/s
  EXPECT_NEAR(e.impact_velocity, w * lever, kLookAheadTolerance);
  // read a step before the touch, at the nearest points MuJoCo's collider
  // gives: measured 4.6e-4 kg (2.5e-3) from the closed form; twice that
  constexpr double kEffectiveMassTolerance = 1e-3;  // kg, of 0.18 kg
  EXPECT_NEAR(e.effective_mass, inertia / (lever * lever), kEffectiveMassTolerance);
}

}  // namespace
}  // namespace contactlaws
