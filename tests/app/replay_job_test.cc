// Copyright contactlaws authors.
//
// The replay job (app/replay_job.h): its columns are Replay's scores, in the
// data's order, and its simulated table the data's columns; a stop token
// set before the run stops it, reported as interrupted, with no columns.

#include "app/replay_job.h"

#include <atomic>
#include <cmath>

#include <gtest/gtest.h>

#include "ident/ident_scenes.h"

namespace contactlaws::app {
namespace {

using contactlaws::testing::CubeScene;
using contactlaws::testing::Simulated;
using contactlaws::testing::TossStarts;

constexpr char kTag[] = "law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.3";

class ReplayJobTest : public ::testing::Test {
 protected:
  ReplayJobTest() : scene_(CubeScene(kTag)) {
    ReplayOptions made;
    made.auto_timestep.emplace();
    data_ = Simulated(scene_, TossStarts(4, 2), made);
    // scored under another restitution: the errors are not zero
    request_.options.auto_timestep.emplace();
    request_.options.simulation.overrides.keys = {{"restitution", "0.5"}};
  }
  const Scene scene_;
  MeasuredData data_;
  ReplayRequest request_;
};

TEST_F(ReplayJobTest, ItsColumnsAreReplaysScoresInTheDatasOrder) {
  const std::vector<ReplayedTrajectory> direct = Replay(scene_, data_).Run(request_.options);
  const ReplayResult result = ReplayJob(scene_, data_, request_).Run();
  ASSERT_FALSE(result.interrupted);
  const ReplayScores& s = result.scores;
  ASSERT_EQ(s.trajectory.size(), data_.trajectories.size());
  size_t rows = 0;
  for (size_t i = 0; i < direct.size(); ++i) {
    EXPECT_EQ(s.trajectory[i], data_.trajectories[i].name);
    EXPECT_GT(s.e_q[i], 0.0);
    EXPECT_EQ(s.e_q[i], direct[i].score.e_q) << i;
    EXPECT_EQ(s.position_rms[i], direct[i].score.position_rms) << i;
    EXPECT_EQ(s.angle_rms[i], direct[i].score.angle_rms) << i;
    EXPECT_EQ(s.samples[i], direct[i].score.samples) << i;
    EXPECT_EQ(s.start[i], direct[i].start) << i;
    EXPECT_EQ(s.status[i], ReplayedTrajectory::Status::kComplete);
    rows += static_cast<size_t>(direct[i].score.samples);
  }
  // the simulated table: a row per sample compared, the data's columns
  const SimulatedSamples& t = result.simulated;
  EXPECT_EQ(t.columns, data_.columns);
  ASSERT_EQ(t.time.size(), rows);
  ASSERT_EQ(t.values.size(), rows * t.columns.size());
  EXPECT_EQ(t.trajectory.front(), 0);
  EXPECT_EQ(t.trajectory.back(), static_cast<int>(data_.trajectories.size()) - 1);
  EXPECT_EQ(t.time.front(), data_.trajectories[0].time[s.start[0]]);
  // the report names the source and summarises the metric first
  EXPECT_NE(result.report.find("4 trajectories of " + data_.source), std::string::npos);
  EXPECT_NE(result.report.find("\n  e_q mean "), std::string::npos);
  EXPECT_TRUE(result.diverged.empty());
}

TEST_F(ReplayJobTest, AStopTokenSetStopsIt) {
  std::atomic<bool> stop{true};
  request_.stop = StopToken(&stop);
  const ReplayResult result = ReplayJob(scene_, data_, request_).Run();
  EXPECT_TRUE(result.interrupted);
  EXPECT_TRUE(result.scores.trajectory.empty());
  EXPECT_TRUE(result.report.empty());
  // and the same job with the flag down runs every trajectory
  stop = false;
  EXPECT_FALSE(ReplayJob(scene_, data_, request_).Run().interrupted);
}

TEST_F(ReplayJobTest, ARestPlaneThatIsNoPlaneIsRefusedBeforeAnyRun) {
  request_.rest_plane = "no-such-geom";
  try {
    ReplayJob job(scene_, data_, request_);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no geom 'no-such-geom'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace contactlaws::app
