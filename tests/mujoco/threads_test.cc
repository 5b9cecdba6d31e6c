// Copyright contactlaws authors.
//
// Threads: several models, and several mjData of one model, stepped
// concurrently give bit for bit what they give one after the other, and the
// comparison is shown to see a difference of one part in 1e9 in a speed.

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco/thread_test_util.h"

namespace contactlaws {
namespace {

using testing::Job;
using testing::RunResult;
using testing::Same;
using testing::ThreadTest;
using testing::kSteps;

TEST_F(ThreadTest, ModelsSteppedConcurrentlyGiveWhatTheyGiveOneByOne) {
  const std::vector<Job> jobs = SeveralModels();
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  for (size_t i = 0; i < jobs.size(); ++i) {
    SCOPED_TRACE(jobs[i].laws->source());
    EXPECT_TRUE(Same(alone[i], together[i]));
    // each run must have bounced, or there is nothing to compare
    ASSERT_FALSE(alone[i].impacts.empty());
    EXPECT_FALSE(alone[i].impacts[0].open);
  }
}

TEST_F(ThreadTest, DataOfOneModelSteppedConcurrentlyGiveWhatTheyGiveOneByOne) {
  // one ContactModel shared by four mjData, each at its own speed
  const ContactModel& laws = InlineLaws(
      testing::DropXml("law=lankarani-nikravesh restitution=0.6 stiffness=1.4e8", 3.0, "RK4"),
      "shared.xml");
  std::vector<Job> jobs;
  for (double speed : {1.0, 2.0, 3.0, 4.0}) jobs.push_back(Job{&laws, 0.1001, -speed});
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  for (size_t i = 0; i < jobs.size(); ++i) {
    SCOPED_TRACE(::testing::Message() << "speed " << -jobs[i].velocity);
    EXPECT_TRUE(Same(alone[i], together[i]));
    ASSERT_FALSE(alone[i].impacts.empty());
    EXPECT_FALSE(alone[i].impacts[0].open);
    // each data saw its own speed, not another's (gravity off: exact)
    EXPECT_DOUBLE_EQ(alone[i].impacts[0].impact_velocity, -jobs[i].velocity);
  }
}

TEST_F(ThreadTest, TheComparisonSeesOneThreadAtAnotherSpeed) {
  // the same concurrent run, with one thread's speed changed by 1e-9
  // relative: the comparison of the tests above must catch it, and only it
  const ContactModel& laws = InlineLaws(
      testing::DropXml("law=flores restitution=0.8 stiffness=1.4e8", 3.0, "RK4", 1e-5, true),
      "perturbed.xml");
  std::vector<Job> jobs;
  for (double speed : {1.0, 2.0, 3.0}) jobs.push_back(Job{&laws, 0.1002, -speed});
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  jobs[1].velocity *= 1 + 1e-9;
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  EXPECT_TRUE(Same(alone[0], together[0]));
  EXPECT_FALSE(Same(alone[1], together[1]));
  EXPECT_TRUE(Same(alone[2], together[2]));
}

}  // namespace
}  // namespace contactlaws
