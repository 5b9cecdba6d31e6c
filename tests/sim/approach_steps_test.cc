// Copyright contactlaws authors.
//
// The steps the pairs apart allow the auto timestep (sim/approach_steps.h):
// the time to close a gap against its closed forms, and the first step of
// a ball flying at a wall, spinning or not; the step after a landing on a
// touch.

#include "sim/approach_steps.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class ApproachStepsTest : public testing::MujocoTest {};

// Closed forms are met to the last bits but a few roundings.
constexpr double kRoundoff = 1e-14;

TEST_F(ApproachStepsTest, TimeToCloseMeetsItsClosedForms) {
  // speed alone: g / v; acceleration alone: sqrt(2 g / a); both: the root
  // of a h^2 / 2 + v h = g
  EXPECT_NEAR(TimeToClose(0.1, 2.0, 0.0), 0.05, kRoundoff * 0.05);
  EXPECT_NEAR(TimeToClose(0.1, 0.0, 9.81), std::sqrt(0.2 / 9.81), kRoundoff);
  const double h = TimeToClose(0.1, 2.0, 9.81);
  EXPECT_NEAR(9.81 * h * h / 2 + 2.0 * h, 0.1, kRoundoff);
  // moving apart while accelerated together: first away, then back
  const double back = TimeToClose(0.1, -1.0, 9.81);
  EXPECT_NEAR(9.81 * back * back / 2 - back, 0.1, kRoundoff);
  // apart and not accelerated together: never
  EXPECT_EQ(TimeToClose(0.1, -1.0, 0.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(TimeToClose(0.1, 0.0, 0.0), std::numeric_limits<double>::infinity());
}

TEST_F(ApproachStepsTest, ATinyAccelerationDoesNotCancelTheSpeed) {
  // gravity's rounding along a vertical wall's normal (2e-15 m/s^2) against
  // a ball closing at 1.4 m/s: -v + sqrt(v^2 + 2 a g) is 0 in doubles
  const double v = 1.415, g = 0.106, a = 2.17826e-15;
  EXPECT_NEAR(TimeToClose(g, v, a), g / v, kRoundoff * g / v);
}

// The first auto step of a ball (radius 0.05 m) flying at 1.415 m/s at a
// wall (a plane whose normal is horizontal) from 0.1 m, spinning at spin
// rad/s about the vertical: no other pair, no contact.
double FirstStepAtAWall(double spin) {
  constexpr double kSpeed = 1.415;  // m/s, towards the wall
  constexpr double kGap = 0.1;      // m, between the ball's surface and the wall
  constexpr double kRadius = 0.05;  // m
  const std::string xml = fmt::format(R"(<mujoco>
  <option integrator="RK4" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="wall" type="plane" pos="0.2 0 0" zaxis="-1 0 0" size="1 1 0.1"/>
    <body pos="{} 0 1"><freejoint/><geom name="ball" type="sphere" size="{}" mass="0.125"/></body>
  </worldbody>
  <keyframe><key qvel="{} 0 0 0 0 {}"/></keyframe>
  <custom>
    <text name="contactlaw:wall" data="geom1=ball geom2=wall law=hertz stiffness=1e8"/>
  </custom>
</mujoco>)",
                                      0.2 - kGap - kRadius, kRadius, kSpeed, spin);
  const Scene scene("wall.xml", LoadModelString(xml, "wall.xml"));
  std::unique_ptr<Simulation> sim = scene.Make({});
  mj_forward(sim->model(), sim->data());
  AutoTimestep stepper(sim->contacts());
  return stepper.Next(sim->data(), 1.0);
}

TEST_F(ApproachStepsTest, ABallFlyingAtAWallStepsHalfItsGap) {
  // gravity is along the wall: only the speed closes the gap
  const double half_gap_time = 0.5 * 0.1 / 1.415;
  EXPECT_NEAR(FirstStepAtAWall(0), half_gap_time, 1e-9 * half_gap_time);
}

TEST_F(ApproachStepsTest, SpinDoesNotCloseASpheresGap) {
  // a sphere's surface turns within itself: spinning at 30 rad/s (1.5 m/s
  // at its surface) it closes its gap as it does without spin
  EXPECT_EQ(FirstStepAtAWall(30), FirstStepAtAWall(0));
}

// The paper's ball dropped from 1 m: the steps that land on its touch (just
// before, just past) are slivers of the fine step, and the contact after
// them takes its fine step at once, not a growth from the sliver (2x a
// step: ~10 steps of 1e-3 ... 1 fine step).
TEST_F(ApproachStepsTest, AContactLandedOnTakesItsFineStepAtOnce) {
  const Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  std::unique_ptr<Simulation> sim = scene.Make({});
  AutoTimestep stepper(sim->contacts());
  mjData* d = sim->data();
  const double fine = HertzContactDuration(1.4e8, 1.5, 1.0, std::sqrt(2 * 9.81 * 0.9)) /
                      StepsPerContact(kDefaultAccuracy);
  // the first two steps in contact
  std::vector<double> in_contact;
  while (in_contact.size() < 2) {
    const double h = stepper.Next(d, 1.0);
    if (!sim->contacts().latest().empty()) in_contact.push_back(h);
    sim->Step(h);
    ASSERT_LT(d->time, 1.0);
  }
  // the fine step at the impact speed read just before the touch (5%: as
  // AutoTimestepTest.TheStepShrinksOnApproachAndIsFineInContact)
  for (const double h : in_contact) EXPECT_NEAR(h, fine, 0.05 * fine);
}

}  // namespace
}  // namespace contactlaws
