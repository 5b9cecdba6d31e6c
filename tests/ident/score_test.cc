// Copyright contactlaws authors.
//
// The scores on hand-made trajectories: a known offset, a known rotation.

#include "contactlaws/replay.h"

#include <cmath>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

// Sums of a few squares: a few ulps of their size.
constexpr double kRounding = 1e-15;

TEST(ScoreTest, RotationAngleOfKnownRotations) {
  const double identity[4] = {1, 0, 0, 0};
  // 0.3 rad about z, and its double cover (-q is the same rotation)
  const double about_z[4] = {std::cos(0.15), 0, 0, std::sin(0.15)};
  const double minus[4] = {-about_z[0], 0, 0, -about_z[3]};
  EXPECT_NEAR(RotationAngle(identity, about_z), 0.3, kRounding);
  EXPECT_NEAR(RotationAngle(identity, minus), 0.3, kRounding);
  EXPECT_NEAR(RotationAngle(about_z, about_z), 0.0, kRounding);
  // a tiny angle, where 2 acos(w) would lose it to rounding
  const double tiny[4] = {std::cos(5e-9), std::sin(5e-9), 0, 0};
  EXPECT_NEAR(RotationAngle(identity, tiny), 1e-8, 1e-22);
  // the half turn is the largest
  const double half[4] = {0, 1, 0, 0};
  EXPECT_NEAR(RotationAngle(identity, half), M_PI, kRounding);
}

TEST(ScoreTest, AKnownOffsetAndRotation) {
  // two samples: the first exact, the second 3 mm off in x and turned 0.2
  // rad about y; L = 0.0524 m (the cube's half side)
  const double L = 0.0524;
  const double p[3] = {0.1, 0.2, 0.3};
  const double off[3] = {0.103, 0.2, 0.3};
  const double q[4] = {1, 0, 0, 0};
  const double turned[4] = {std::cos(0.1), 0, std::sin(0.1), 0};
  ScoreAccumulator score;
  score.AddBody(p, p, q, q, L);
  score.EndSample();
  score.AddBody(off, p, turned, q, L);
  score.EndSample();
  const Score s = score.Finish();
  EXPECT_EQ(s.samples, 2);
  EXPECT_NEAR(s.e_q, (0.003 * 0.003 / L + 0.04) / 2, kRounding);
  EXPECT_NEAR(s.position_rms, std::sqrt(0.003 * 0.003 / 2), kRounding);
  EXPECT_NEAR(s.angle_rms, std::sqrt(0.04 / 2), kRounding);
  EXPECT_EQ(s.joint_rms, 0.0);
  EXPECT_NEAR(s.weighted, s.position_rms + s.angle_rms, kRounding);
  EXPECT_EQ(s.Of(Metric::kEq), s.e_q);
  EXPECT_EQ(s.Of(Metric::kAngleRms), s.angle_rms);
}

TEST(ScoreTest, WeightsAndJoints) {
  ScoreAccumulator score({2.0, 0.0, 10.0});
  const double p[3] = {0, 0, 0}, off[3] = {0, 0.01, 0};
  score.AddBody(off, p, nullptr, nullptr, 1.0);
  score.AddJoint(0.5, 0.4);
  score.EndSample();
  const Score s = score.Finish();
  EXPECT_NEAR(s.position_rms, 0.01, kRounding);
  EXPECT_NEAR(s.joint_rms, 0.1, kRounding);
  EXPECT_EQ(s.angle_rms, 0.0);  // no orientation measured
  EXPECT_NEAR(s.weighted, 2.0 * 0.01 + 10.0 * 0.1, kRounding);
}

TEST(ScoreTest, MetricNames) {
  for (Metric m : {Metric::kEq, Metric::kPositionRms, Metric::kAngleRms, Metric::kWeighted}) {
    EXPECT_EQ(ParseMetric(MetricName(m)), m);
  }
  EXPECT_FALSE(ParseMetric("eq"));
}

}  // namespace
}  // namespace contactlaws
