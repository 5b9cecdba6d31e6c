// Copyright contactlaws authors.
//
// The many-ball scene of the benchmarks (issue 5): n = k^3 free balls in a
// walled box, launched from a grid, under two group tags. The one source of
// every size: mjcf/ball_box_64.xml is BallBoxXml(64), written by
// `ball_box_scene write 64 mjcf/ball_box_64.xml` and checked by ctest
// (ball_box_64_up_to_date); the benchmark makes 8, 64 and 512 from it.

#ifndef CONTACTLAWS_TESTS_BENCH_BALL_BOX_H_
#define CONTACTLAWS_TESTS_BENCH_BALL_BOX_H_

#include <string>
#include <vector>

namespace contactlaws::bench {

// The scene's geometry, the same for every size but the box's width.
struct BallBox {
  int per_side = 4;         // k balls along each axis: k^3 balls
  double radius = 0.05;     // m, half the paper's ball
  double mass = 0.125;      // kg: the paper's ball's density (1 kg at 0.1 m)
  double spacing = 0.104;   // m between grid centres: 4 mm gaps, impacts within 2 ms
  double launch_speed = 1.5;  // m/s, the bound of each initial velocity component

  int balls() const { return per_side * per_side * per_side; }
  // the walls' distance from the centre, m: s/2 - r = 2 mm from the outer balls
  double half_width() const { return 0.5 * per_side * spacing; }
};

// The geometry of n balls; throws std::invalid_argument unless n = k^3, k >= 1.
BallBox BallBoxOf(int balls);

// MuJoCo 2.2.2 reads at most 1000 numbers from one attribute ("too much
// data"): the launch fits a keyframe's qvel up to 166 balls.
inline constexpr int kMaxKeyframeNumbers = 1000;

// The launch velocities of n balls, qvel order (vx vy vz 0 0 0 per ball),
// each a multiple of 1 mm/s: exactly what MuJoCo reads from the keyframe
// (BallBoxXml writes them with 3 decimals).
std::vector<double> BallBoxLaunch(int balls);

// The MJCF text of the scene of n balls (deterministic, byte for byte). Its
// keyframe 0 is the launch when 6 n <= kMaxKeyframeNumbers; larger scenes
// have none: set qvel from BallBoxLaunch.
std::string BallBoxXml(int balls);

}  // namespace contactlaws::bench

#endif  // CONTACTLAWS_TESTS_BENCH_BALL_BOX_H_
