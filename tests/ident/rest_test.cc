// Copyright contactlaws authors.
//
// Resting poses: the support distance of known shapes, a board's height
// recovered from tosses that rest on it, the end gaps of a replay with the
// board moved by a known distance.

#include "contactlaws/fit.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ident_scenes.h"

namespace contactlaws::testing {
namespace {

// Rotations of unit quaternions: a few ulps.
constexpr double kRounding = 1e-12;
constexpr double kHalfSide = 0.0524;
constexpr char kTag[] = "law=flores restitution=0.3 stiffness=3e5 friction=coulomb mu=0.35";

TEST(RestTest, SupportDistanceOfACubeAndASphere) {
  const Scene scene = CubeScene(kTag);
  const int cube = mj_name2id(scene.model(), mjOBJ_BODY, "cube");
  const double flat[4] = {1, 0, 0, 0};
  EXPECT_NEAR(SupportDistance(scene.model(), cube, flat), kHalfSide, kRounding);
  // on an edge: 45 degrees about x, the half diagonal of a face
  const double edge[4] = {std::cos(M_PI / 8), std::sin(M_PI / 8), 0, 0};
  EXPECT_NEAR(SupportDistance(scene.model(), cube, edge), kHalfSide * std::sqrt(2.0), kRounding);
  // resting: on the face nearest to down, whatever a tracker's tilt
  const double tilted[4] = {std::cos(0.05), std::sin(0.05), 0, 0};  // 0.1 rad about x
  EXPECT_NEAR(SupportDistance(scene.model(), cube, tilted),
              kHalfSide * (std::cos(0.1) + std::sin(0.1)), kRounding);
  EXPECT_NEAR(SupportDistance(scene.model(), cube, tilted, true), kHalfSide, kRounding);
  // a quarter turn puts another face down at the same distance
  const double quarter[4] = {std::cos(M_PI / 4), 0, std::sin(M_PI / 4), 0};
  EXPECT_NEAR(SupportDistance(scene.model(), cube, quarter), kHalfSide, kRounding);
  const Scene ball("ball.xml", LoadModelString(R"(<mujoco><worldbody><body name="b">
    <freejoint/><geom type="sphere" size="0.03" pos="0 0 0.01"/></body></worldbody></mujoco>)",
                                                "ball.xml"));
  EXPECT_NEAR(SupportDistance(ball.model(), 1, flat), 0.02, kRounding);
}

ReplayOptions Options(double board_offset, int board) {
  ReplayOptions options;
  options.simulation.timestep = 6.756756756756757e-4;
  if (board_offset != 0) options.edits.push_back({ModelEdit::Kind::kOffset, board, board_offset});
  return options;
}

// Tosses simulated onto a board 2 mm below the nominal plane: the board's
// height from where they rest, 2 mm down less the corners' sink.
TEST(RestTest, ABoardsHeightFromTossesThatRestOnIt) {
  const Scene scene = CubeScene(kTag);
  const int board = mj_name2id(scene.model(), mjOBJ_GEOM, "board");
  const MeasuredData tosses = Simulated(scene, TossStarts(12, 7), Options(-0.002, board));
  const PlaneEstimate e = EstimatePlaneHeight(scene.model(), tosses, RestRule{}, 1);
  EXPECT_EQ(e.trajectories, 12);
  EXPECT_GE(e.at_rest, 8);
  // a face on 4 corners sinks (m g / 4 / K)^(1 / 1.5) (flores: K d^1.5)
  const double sink = std::pow(0.37 * 9.81 / 4 / 3e5, 1 / 1.5);
  // the simulated rest wobbles under 0.02 m/s: tens of micrometres
  constexpr double kRestWobble = 5e-5;
  EXPECT_NEAR(e.height.value.median, -0.002 - sink, kRestWobble);
  EXPECT_TRUE(e.height.median.Contains(e.height.value.median));
  EXPECT_NEAR(e.support.median, kHalfSide, kRounding);

  // the same tosses cut before they land: none rests, refused in one line
  MeasuredData falling = tosses;
  for (MeasuredTrajectory& t : falling.trajectories) {
    t.time.resize(10);
    t.values.resize(10 * falling.columns.size());
  }
  try {
    EstimatePlaneHeight(scene.model(), falling, RestRule{}, 1);
    ADD_FAILURE() << "accepted";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              "tosses: 0 of 12 trajectories come to rest (slower than 0.02 m/s over their last 5 "
              "samples): an offset from their resting height needs at least 5");
  }
}

// The same tosses replayed with the board 3 mm lower: every resting cube
// 3 mm lower, on the same face, where it was measured.
TEST(RestTest, EndGapsOfAReplayWithTheBoardMoved) {
  const Scene scene = CubeScene(kTag);
  const int board = mj_name2id(scene.model(), mjOBJ_GEOM, "board");
  const MeasuredData tosses = Simulated(scene, TossStarts(12, 7), Options(0, board));
  const Replay replay(scene, tosses);
  const std::vector<std::vector<EndGap>> same = EndGaps(tosses, replay.Run(Options(0, board)), {});
  const std::vector<std::vector<EndGap>> lower =
      EndGaps(tosses, replay.Run(Options(-0.003, board)), {});
  ASSERT_EQ(lower.size(), 12u);
  int resting = 0;
  for (size_t i = 0; i < lower.size(); ++i) {
    ASSERT_EQ(lower[i].size(), 1u);
    // a replay of a simulation from its own samples: the rounding of a
    // restart from a sample (replay_test: 1e-9 of e_q)
    EXPECT_NEAR(same[i][0].simulated_z, same[i][0].measured_z, 1e-9);
    EXPECT_NEAR(same[i][0].angle, 0, 1e-9);
    if (!lower[i][0].at_rest) continue;
    ++resting;
    // the board's move changes each landing a little: a few mm sideways, a
    // few degrees of turn, never another face
    EXPECT_NEAR(lower[i][0].simulated_z - lower[i][0].measured_z, -0.003, 5e-5) << i;
    EXPECT_LT(lower[i][0].tilt, kAnotherFaceTilt) << i;
  }
  EXPECT_GE(resting, 8);
}

// A cube at rest, measured, and three replays' last states: the same; turned
// 60 degrees about the vertical (the same face up); turned 90 degrees about
// x (another face up).
TEST(RestTest, ReadableScoresCountAnotherFaceByTheTiltAlone) {
  MeasuredData data;
  data.source = "rest";
  data.columns = CubeColumns();
  const std::vector<double> resting = {0.1, 0.2, kHalfSide, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  std::vector<ReplayedTrajectory> replayed(3);
  const double turns[3][4] = {{1, 0, 0, 0},
                              {std::cos(M_PI / 6), 0, 0, std::sin(M_PI / 6)},
                              {std::cos(M_PI / 4), std::sin(M_PI / 4), 0, 0}};
  for (int i = 0; i < 3; ++i) {
    MeasuredTrajectory t;
    t.name = fmt::format("{}", i);
    for (int k = 0; k < 8; ++k) {
      t.time.push_back(k / 148.0);
      t.values.insert(t.values.end(), resting.begin(), resting.end());
    }
    data.trajectories.push_back(t);
    replayed[i].last = resting;
    replayed[i].last[2] += 0.001 * i;  // 1 mm higher each
    for (int c = 0; c < 4; ++c) replayed[i].last[3 + c] = turns[i][c];
    replayed[i].score.e_q = 0.5 * i;
    replayed[i].score.position_rms = 0.001 * i;
    replayed[i].score.angle_rms = 0.1 * i;
  }
  const std::vector<ScoreArray> scores = ReadableScores(data, replayed, Metric::kEq);
  ASSERT_EQ(scores.size(), 5u);  // the metric, mm, degrees, final degrees, another face
  EXPECT_EQ(scores[0].values, (std::vector<double>{0, 0.5, 1.0}));
  EXPECT_NEAR(scores[1].values[2], 2.0, kRounding);          // mm
  EXPECT_NEAR(scores[2].values[1], 0.1 * 180 / M_PI, 1e-9);  // degrees
  EXPECT_NEAR(scores[3].values[1], 60, 1e-9);
  EXPECT_NEAR(scores[3].values[2], 90, 1e-9);
  EXPECT_EQ(scores[4].name, "another_face");
  EXPECT_EQ(scores[4].values, (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(ReadableScores(data, replayed, Metric::kPositionRms)[1].name, "e_q");

  const std::vector<RestingGaps> gaps = SummarizeRestingGaps(data, replayed, RestRule{}, 1);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(gaps[0].body, "cube");
  EXPECT_EQ(gaps[0].at_rest, 3);
  EXPECT_NEAR(gaps[0].gap_z.value.median, 0.001, kRounding);
  EXPECT_NEAR(gaps[0].gap_z_p25, 0.0005, kRounding);
}

}  // namespace
}  // namespace contactlaws::testing
