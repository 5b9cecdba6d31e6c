// Copyright contactlaws authors.
//
// The contact estimates against the simulated contact and closed forms.

#include "contactlaws/estimate.h"

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
    const Impact impact = testing::FirstImpact(sim);
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

TEST_F(EstimateTest, DrivenTableAddsItsTopSpeed) {
  Simulation& sim = MakeSceneSimulation("ball_table.xml");
  mj_forward(sim.model(), sim.data());
  const ContactEstimate e = EstimateContact(sim.contacts(), 0);
  EXPECT_EQ(e.effective_mass, 1.0);  // the table is driven: infinitely heavy
  ASSERT_TRUE(e.gap);
  EXPECT_NEAR(*e.gap, 0.4, 1e-12);
  EXPECT_NEAR(e.impact_velocity, std::sqrt(2 * 9.81 * 0.4) + 0.1 * 7.5, 1e-12);
}

}  // namespace
}  // namespace contactlaws
