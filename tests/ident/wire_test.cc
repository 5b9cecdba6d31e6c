// Copyright contactlaws authors.
//
// The serialiser of what the ranks of a job exchange (ident/wire.h): every
// field of each type sent arrives bit for bit, and bytes cut short are
// refused rather than read past.

#include "ident/wire.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <cereal/details/helpers.hpp>
#include <gtest/gtest.h>

namespace contactlaws {
namespace {

// Distinct values, none of them a default: a field left out of a serialize
// function arrives as its default and differs.
TEST(WireTest, AReplayedTrajectoryArrivesBitForBit) {
  ReplayedTrajectory sent;
  sent.status = ReplayedTrajectory::Status::kDiverged;
  sent.start = 7;
  sent.score = {11, 0.25, 1e-3, 0.125, 3.5, 0.0625};
  sent.diverged_at = 0.1;
  sent.settled_bodies = 2;
  sent.settled_distance = 1.0 / 3.0;
  sent.last = {1.5, -0.0, std::numeric_limits<double>::denorm_min()};
  sent.simulated = {std::nan(""), 2.0, 1e300};
  const ReplayedTrajectory got = internal::Read<ReplayedTrajectory>(internal::Written(sent));
  EXPECT_EQ(got.status, sent.status);
  EXPECT_EQ(got.start, sent.start);
  EXPECT_EQ(got.score.samples, sent.score.samples);
  EXPECT_EQ(got.score.e_q, sent.score.e_q);
  EXPECT_EQ(got.score.position_rms, sent.score.position_rms);
  EXPECT_EQ(got.score.angle_rms, sent.score.angle_rms);
  EXPECT_EQ(got.score.joint_rms, sent.score.joint_rms);
  EXPECT_EQ(got.score.weighted, sent.score.weighted);
  EXPECT_EQ(got.diverged_at, sent.diverged_at);
  EXPECT_EQ(got.settled_bodies, sent.settled_bodies);
  EXPECT_EQ(got.settled_distance, sent.settled_distance);
  ASSERT_EQ(got.last.size(), sent.last.size());
  ASSERT_EQ(got.simulated.size(), sent.simulated.size());
  // bit for bit: -0 keeps its sign, a NaN stays a NaN
  EXPECT_TRUE(std::signbit(got.last[1]));
  EXPECT_EQ(got.last[2], sent.last[2]);
  EXPECT_TRUE(std::isnan(got.simulated[0]));
  EXPECT_EQ(got.simulated[2], sent.simulated[2]);
}

TEST(WireTest, AnEpisodeArrivesWithEveryField) {
  Episode sent;
  double next = 0.5;
  const auto value = [&next] { return next += 1.0; };
  sent.tag = 3;
  sent.pair = 4;
  sent.index = 5;
  sent.points = 6;
  sent.time_contact = value();
  sent.impact_velocity = value();
  sent.open = false;
  sent.time_separation = value();
  sent.separation_velocity = value();
  sent.max_depth = value();
  sent.max_force = value();
  sent.max_approach_velocity = value();
  sent.touch_v0 = value();
  sent.points_chained = true;
  sent.resolved = true;
  sent.settling_velocity = value();
  sent.tangential_impact_velocity = value();
  sent.tangential_separation_velocity = value();
  sent.spin_before = value();
  sent.spin_after = value();
  for (double& t : sent.tangent) t = value();
  for (double& n : sent.normal) n = value();
  const Episode got = internal::Read<Episode>(internal::Written(sent));
  EXPECT_EQ(got.tag, 3);
  EXPECT_EQ(got.pair, 4);
  EXPECT_EQ(got.index, 5);
  EXPECT_EQ(got.points, 6);
  EXPECT_FALSE(got.open);
  EXPECT_TRUE(got.points_chained);
  EXPECT_TRUE(got.resolved);
  const std::vector<double> doubles_sent = {
      sent.time_contact, sent.impact_velocity, sent.time_separation, sent.separation_velocity,
      sent.max_depth, sent.max_force, sent.max_approach_velocity, sent.touch_v0,
      sent.settling_velocity, sent.tangential_impact_velocity,
      sent.tangential_separation_velocity, sent.spin_before, sent.spin_after, sent.tangent[0],
      sent.tangent[1], sent.tangent[2], sent.normal[0], sent.normal[1], sent.normal[2]};
  const std::vector<double> doubles_got = {
      got.time_contact, got.impact_velocity, got.time_separation, got.separation_velocity,
      got.max_depth, got.max_force, got.max_approach_velocity, got.touch_v0,
      got.settling_velocity, got.tangential_impact_velocity,
      got.tangential_separation_velocity, got.spin_before, got.spin_after, got.tangent[0],
      got.tangent[1], got.tangent[2], got.normal[0], got.normal[1], got.normal[2]};
  EXPECT_EQ(doubles_got, doubles_sent);
}

TEST(WireTest, ASummaryKeepsWhatItDoesNotKnow) {
  RunSummary sent;
  sent.impacts = 9;
  sent.restitution_post = 0.75;
  sent.contact_duration = 2e-3;  // impact_velocity and time_to_rest not known
  sent.max_depth = 1e-4;
  sent.max_force = 250;
  const RunSummary got = internal::Read<RunSummary>(internal::Written(sent));
  EXPECT_EQ(got.impacts, 9);
  EXPECT_EQ(got.restitution_post, sent.restitution_post);
  EXPECT_FALSE(got.impact_velocity.has_value());
  EXPECT_EQ(got.contact_duration, sent.contact_duration);
  EXPECT_EQ(got.max_depth, sent.max_depth);
  EXPECT_EQ(got.max_force, sent.max_force);
  EXPECT_FALSE(got.time_to_rest.has_value());
}

TEST(WireTest, BytesCutShortAreRefused) {
  ReplayedTrajectory sent;
  sent.simulated.assign(100, 1.0);
  const std::string bytes = internal::Written(sent);
  EXPECT_THROW(internal::Read<ReplayedTrajectory>(bytes.substr(0, bytes.size() - 8)),
               cereal::Exception);
}

}  // namespace
}  // namespace contactlaws
