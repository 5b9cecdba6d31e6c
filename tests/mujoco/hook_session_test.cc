// Copyright contactlaws authors.
//
// The hook session: the pairs the contact filter claims, in pair order, for
// the passive hook; the capture of the step's start evaluation; the notice of
// plain mj_step; the step-start velocities.

#include "mujoco/hook_session.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco/step_start.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using internal::ProposedPairs;
using internal::StepCapture;
using internal::StepStartVelocities;

class HookSessionTest : public testing::MujocoTest {};

// Four balls under one group tag over a floor (10 tagged pairs), and, when
// untagged, a box no tag claims (MuJoCo's broadphase then proposes).
std::string BallsXml(bool untagged) {
  std::string bodies;
  for (int i = 0; i < 4; ++i) {
    bodies += fmt::format(R"(<body pos="{} 0 0.5"><freejoint/>
      <geom type="sphere" size="0.1" group="3" mass="1"/></body>)",
                          i);
  }
  if (untagged) {
    bodies += R"(<body pos="0 3 0.5"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>)";
  }
  return fmt::format(R"(<mujoco>
  <worldbody><geom name="floor" type="plane" size="5 5 0.1" group="2"/>{}</worldbody>
  <custom>
    <text name="contactlaw:balls" data="geom1=group:3 geom2=group:3 law=hertz stiffness=1e7"/>
    <text name="contactlaw:floor" data="geom1=group:3 geom2=group:2 law=hertz stiffness=1e7"/>
  </custom>
</mujoco>)",
                     bodies);
}

TEST_F(HookSessionTest, ClaimedPairsAreEvaluatedInPairOrderUntilTheNextPass) {
  UniqueModel m = Load(BallsXml(true));
  ContactModel cm(m.get(), "balls");
  ASSERT_EQ(cm.pairs().size(), 10u);
  ProposedPairs proposals(cm);
  ASSERT_FALSE(proposals.own_broadphase());  // the untagged box
  // out of order, twice, and an untagged pair (-1)
  for (const int p : {7, 2, 7, -1, 5}) proposals.Claim(p);
  EXPECT_EQ(proposals.claimed(), (std::vector<int>{7, 2, 5}));
  EXPECT_EQ(proposals.Use(), (std::vector<int>{2, 5, 7}));
  // a skipped collision pass: the same pairs again
  EXPECT_EQ(proposals.Use(), (std::vector<int>{2, 5, 7}));
  // the first claim after the list was used starts the next pass's
  proposals.Claim(-1);
  proposals.Claim(9);
  EXPECT_EQ(proposals.Use(), (std::vector<int>{9}));
}

TEST_F(HookSessionTest, OwnBroadphaseEvaluatesEveryPair) {
  UniqueModel m = Load(BallsXml(false));
  ContactModel cm(m.get(), "balls");
  ProposedPairs proposals(cm);
  ASSERT_TRUE(proposals.own_broadphase());
  proposals.Claim(3);
  EXPECT_EQ(proposals.Use(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(proposals.claimed(), (std::vector<int>{3}));
}

std::vector<PointEvaluation> Points(int count, double depth) {
  std::vector<PointEvaluation> points(count);
  for (PointEvaluation& e : points) e.depth = depth;
  return points;
}

TEST_F(HookSessionTest, OnlyTheFirstEvaluationAfterArmingIsCaptured) {
  StepCapture capture(4);
  capture.Offer(Points(1, 1e-3), 0.1);  // unarmed: ignored
  EXPECT_FALSE(capture.held());
  EXPECT_TRUE(capture.points().empty());

  capture.Arm();
  EXPECT_FALSE(capture.held());
  capture.Offer(Points(2, 2e-3), 0.2);
  capture.Offer(Points(3, 3e-3), 0.3);  // RK4's later stages: ignored
  ASSERT_TRUE(capture.held());
  EXPECT_EQ(capture.points().size(), 2u);
  EXPECT_EQ(capture.time(), 0.2);
  capture.Disarm();  // AfterStep: a held capture stays for the commit
  EXPECT_TRUE(capture.held());
  capture.Release();
  EXPECT_FALSE(capture.held());
  EXPECT_EQ(capture.points().size(), 2u);  // kept until the next capture

  // a step whose hook never ran: AfterStep disarms, nothing is captured
  capture.Arm();
  capture.Disarm();
  capture.Offer(Points(4, 4e-3), 0.4);
  EXPECT_FALSE(capture.held());
  EXPECT_EQ(capture.time(), 0.2);

  capture.Arm();
  capture.Offer(Points(1, 1e-3), 0.5);
  capture.Reset();
  EXPECT_FALSE(capture.held());
  EXPECT_TRUE(capture.points().empty());
}

TEST_F(HookSessionTest, EvaluationsAdvancingUnarmedAreWarnedAboutOnce) {
  StepCapture capture(1);
  // evaluations at one time (mj_forward), and armed ones, are not counted
  for (int i = 0; i < 20; ++i) capture.NoticeEvaluation(1.0, 1.0);
  capture.Arm();
  for (int i = 0; i < 20; ++i) capture.NoticeEvaluation(i + 1.0, i);
  EXPECT_EQ(CountMujocoWarnings(""), 0u);
  capture.Disarm();
  // 8 advances unarmed are tolerated, the 9th is warned about
  for (int i = 0; i < 8; ++i) capture.NoticeEvaluation(i + 1.0, i);
  EXPECT_EQ(CountMujocoWarnings(""), 0u);
  capture.NoticeEvaluation(10.0, 9.0);
  EXPECT_EQ(ExpectMujocoWarning("stepped without ContactData::BeforeStep/AfterStep"), 1u);
  // once: neither more advances nor arming again brings it back
  capture.Arm();
  capture.Disarm();
  for (int i = 0; i < 20; ++i) capture.NoticeEvaluation(i + 11.0, i + 10.0);
  EXPECT_EQ(CountMujocoWarnings(""), 0u);
}

TEST_F(HookSessionTest, StepStartVelocitiesKeepTheCurrentAndThePreviousStep) {
  UniqueModel m = Load(BallsXml(false));
  mjData* d = MakeData(m.get());
  StepStartVelocities start(m->nv);
  EXPECT_FALSE(start.has_current());
  d->qvel[2] = -1.0;
  d->time = 0.1;
  start.Record(d);
  EXPECT_TRUE(start.has_current());
  EXPECT_FALSE(start.has_previous());
  d->qvel[2] = -2.0;
  d->time = 0.2;
  start.Record(d);
  ASSERT_TRUE(start.has_previous());
  EXPECT_EQ(start.current()[2], -2.0);
  EXPECT_EQ(start.current_time(), 0.2);
  EXPECT_EQ(start.previous()[2], -1.0);
  EXPECT_EQ(start.previous_time(), 0.1);
  start.Forget();
  EXPECT_FALSE(start.has_current());
  EXPECT_FALSE(start.has_previous());
  EXPECT_EQ(start.current_time(), 0.2);  // for the time going back
}

}  // namespace
}  // namespace contactlaws
