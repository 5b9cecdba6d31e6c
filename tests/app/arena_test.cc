// Copyright contactlaws authors.
//
// The program's arena sizing (app/arena.h): a scene whose every collidable
// pair is tagged gets the constraint rows it can make and the stack they and
// the passive hook need; a scene with an untagged contact, or with sizes of
// its own, keeps MuJoCo's; CONTACTLAWS_ARENA=mujoco keeps MuJoCo's always.

#include "app/arena.h"

#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws::app {
namespace {

// MuJoCo 2.2.2's defaults when a scene gives no <size>
constexpr int kDefaultNjmax = 500;

class ArenaTest : public ::testing::Test {
 protected:
  void TearDown() override { unsetenv("CONTACTLAWS_ARENA"); }
  const std::string ball_ = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";
};

TEST_F(ArenaTest, ASceneWithEveryPairTaggedGetsTheRowsItCanMake) {
  // the paper's ball: one free body, its one pair tagged, no limits: no rows
  UniqueModel mujoco = LoadModelFile(ball_);
  ASSERT_EQ(mujoco->njmax, kDefaultNjmax);
  UniqueModel sized = LoadSizedModel(ball_, {});
  EXPECT_EQ(sized->njmax, 0);
  EXPECT_LT(sized->nstack, mujoco->nstack);
  // with the ball's stack, a run's steps and samples fit (MuJoCo would stop
  // the process with its own error otherwise)
  Simulation sim(std::move(sized), "bouncing_ball.xml");
  for (int i = 0; i < 100; ++i) sim.Step();
  std::vector<double> row;
  sim.Sample(&row);
  EXPECT_GT(sim.time(), 0.0);
}

TEST_F(ArenaTest, MujocosSizesStayWithAnUntaggedContactOrTheOption) {
  // the incline without its tag: MuJoCo's own contact makes rows
  const std::string untagged = std::string(CONTACTLAWS_SOURCE_DIR) +
                               "/mjcf/friction_incline_mujoco.xml";
  EXPECT_EQ(LoadSizedModel(untagged, {})->njmax, LoadModelFile(untagged)->njmax);
  setenv("CONTACTLAWS_ARENA", "mujoco", 1);
  EXPECT_EQ(LoadSizedModel(ball_, {})->njmax, kDefaultNjmax);
}

TEST_F(ArenaTest, TagsTheOverridesRefuseLeaveTheSceneAsMujocoMadeIt) {
  // flores refuses e = 0: the run that reads the tags says so
  Overrides overrides;
  overrides.restitution = 0.0;
  EXPECT_EQ(LoadSizedModel(ball_, overrides)->njmax, kDefaultNjmax);
}

}  // namespace
}  // namespace contactlaws::app
