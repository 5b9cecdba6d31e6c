// Copyright contactlaws authors.
//
// The friction scenes of mjcf/, each loaded and run against its closed form:
// the ball going from sliding to rolling, and the block on the incline, with
// the friction columns of the trajectory and MuJoCo's own contact on the
// same incline. (The belt: friction_test.cc.)

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

class FrictionScenesTest : public testing::MujocoTest {};

using testing::kG;
using testing::RunUntil;
using testing::Vx;
using testing::Wy;
using testing::X;

// The value of column name in a row sampled from sim.
double Column(const Simulation& sim, const std::vector<double>& row, const std::string& name) {
  const std::vector<std::string> columns = sim.Columns();
  const auto found = std::find(columns.begin(), columns.end(), name);
  EXPECT_NE(found, columns.end()) << name;
  return found == columns.end() ? NAN : row[found - columns.begin()];
}

// mjcf/friction_slide_roll.xml: v0 = 2 m/s, no spin, mu = 0.3, R = 0.1 m.
TEST_F(FrictionScenesTest, BallSlidesToRollingAtFiveSeventhsFromTheClosedFormTime) {
  constexpr double kV0 = 2.0, kMu = 0.3, kR = 0.1;
  Simulation& sim = MakeSceneSimulation("friction_slide_roll.xml");
  const double t_roll = 2 * kV0 / (7 * kMu * kG);
  // the lever R - d/2 (d = 0.1 mm) is 0.05% short of R: the closed forms,
  // written with R, hold to that share of v0 (1e-3 m/s) and of t_roll
  constexpr double kLeverShare = 5e-4;
  // sliding: v = v0 - mu g t, w R = 5/2 mu g t
  RunUntil(sim, 0.5 * t_roll);
  const double t = sim.time();
  EXPECT_NEAR(Vx(sim), kV0 - kMu * kG * t, kLeverShare * kV0);
  EXPECT_NEAR(Wy(sim) * kR, 2.5 * kMu * kG * t, kLeverShare * kV0);
  RunUntil(sim, (1 - 4 * kLeverShare) * t_roll);
  EXPECT_GT(Vx(sim) - Wy(sim) * kR, 0) << "rolls before t_roll";
  // rolling soon after t_roll: the stick spring catches the slip,
  // overshoots (3.5e-3 m/s) and relaxes with an e-fold of 5 ms (measured
  // within 1e-3 m/s of the final speeds 7 ms after t_roll)
  constexpr double kCatchTime = 1e-2;  // s
  RunUntil(sim, (1 + 4 * kLeverShare) * t_roll + kCatchTime);
  EXPECT_NEAR(Vx(sim), 5.0 / 7.0 * kV0, kLeverShare * kV0);
  EXPECT_NEAR(Wy(sim) * kR, 5.0 / 7.0 * kV0, 2 * kLeverShare * kV0);
  // 2/7 of the kinetic energy went to friction: the ledger's dissipated
  // (the normal law's damping adds nothing at rest: measured 1e-9 J)
  RunUntil(sim, 0.5);
  mj_forward(sim.model(), sim.data());
  const EnergyLedger e = sim.Energy();
  const double start = 0.5 * kV0 * kV0;
  EXPECT_NEAR(e.kinetic, 5.0 / 7.0 * start, 2 * kLeverShare * start);
  EXPECT_NEAR(e.dissipated, 2.0 / 7.0 * start, 2 * kLeverShare * start);
}

// mjcf/friction_incline.xml: tan(theta) = 0.3 < mu_static = 0.5, coulomb.
// The friction columns carry what holds the block: m g sin(theta) up the
// slope, on the tag's geom1 (the block).
TEST_F(FrictionScenesTest, InclineHoldsTheBlockWithTheWeightsShareAlongTheSlope) {
  Simulation& sim = MakeSceneSimulation("friction_incline.xml");
  const double gx = sim.model()->opt.gravity[0];
  ASSERT_NEAR(gx, kG * 0.3 / std::sqrt(1.09), 1e-4);
  RunUntil(sim, 1.0);
  std::vector<double> row;
  sim.Sample(&row);
  // the four corners' friction springs hold it, up to what is left of the
  // block's settling: friction tips it, its corners' loads shift, the
  // overdamped normal springs follow with an e-fold of 0.1 s (measured 1e-7 N
  // at 1 s)
  constexpr double kForceTolerance = 1e-6;  // N
  EXPECT_NEAR(Column(sim, row, "block-floor.friction_x"), -gx, kForceTolerance);
  EXPECT_NEAR(Column(sim, row, "block-floor.friction_y"), 0, kForceTolerance);
  EXPECT_NEAR(Column(sim, row, "block-floor.friction_z"), 0, kForceTolerance);
  // no creep after settling: the 1e-9 m in 10 s, here in 0.5 s
  // (measured 9e-12 m from 1.5 s to 2 s, the settling's tail)
  RunUntil(sim, 1.5);
  const double settled = X(sim);
  RunUntil(sim, 2.0);
  constexpr double kCreepBound = 1e-9;  // m
  EXPECT_NEAR(X(sim), settled, kCreepBound);
}

// mjcf/friction_incline_mujoco.xml: the same incline with MuJoCo's own
// contact (no tag). MuJoCo's soft constraint creeps (google-deepmind/mujoco
// #3328): measured 1.24e-3 m/s down the slope, steady.
TEST_F(FrictionScenesTest, MujocosOwnContactCreepsOnTheSameIncline) {
  Simulation& sim = MakeSceneSimulation("friction_incline_mujoco.xml");
  EXPECT_TRUE(sim.contact_model().tags().empty());
  RunUntil(sim, 0.5);
  const double x1 = X(sim);
  RunUntil(sim, 1.0);
  const double creep = (X(sim) - x1) / 0.5;
  // a creep, far above coulomb's none (the order of MuJoCo's issue: 5e-5 to
  // 2.3e-3 m/s)
  constexpr double kCreepAtLeast = 1e-4;  // m/s
  EXPECT_GT(creep, kCreepAtLeast);
  EXPECT_GT(Vx(sim), kCreepAtLeast);
  std::printf("MuJoCo's own contact creeps at %.4g m/s\n", creep);
}

}  // namespace
}  // namespace contactlaws
