// Copyright contactlaws authors.
//
// SimBenchmark's rolling test (mjcf/rolling.xml): a 10 kg box pushed along
// the ground by a 150 N actuator force, 25 balls rolling on it. Settled, it
// follows the analytic velocities to within 1e-9 (m/s)^2 over its 4 s;
// placed touching, every body first drops into its springs.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

// The scene's constants (mjcf/rolling.xml).
constexpr double kG = 9.81;        // m/s^2
constexpr double kBall = 1.0;      // m, a ball's mass, kg
constexpr double kBox = 10.0;      // M, kg
constexpr double kForce = 150.0;   // F, N, horizontal, at 60 degrees to x
constexpr double kGroundMu = 0.4;  // mu1, box-ground
constexpr int kBalls = 25;
constexpr double kDuration = 4.0;  // s, SimBenchmark's T
constexpr double kSample = 1e-3;   // s, SimBenchmark's dt: one error sample each

// The box slides, each ball rolls on it without slipping (I = 2/5 m r^2: the
// contact point's acceleration is 7/2 of the centre's), so with f2 the box's
// friction on a ball: m a2 = f2, a1 = 7/2 a2, M a1 = F - mu1 (M + n m) g - n f2.
struct Analytic {
  double ball = 0;  // a2, m/s^2
  double box = 0;   // a1, m/s^2
};
Analytic Accelerations() {
  const double f1 = kGroundMu * (kBox + kBalls * kBall) * kG;
  const double f2 = (kForce - f1) / (3.5 * kBox / kBall + kBalls);
  return {f2 / kBall, 3.5 * f2 / kBall};
}

// The squared velocity error at sim's state against a velocity a t along
// the force, (m/s)^2: the box's plus the balls' mean. Body 1 is the box, 2..26
// the balls; a free body's linear velocity is its qvel[0..2].
double SquaredError(const Simulation& sim, const Analytic& a) {
  const double t = sim.time();
  const double direction[3] = {0.5, std::sqrt(3.0) / 2, 0};
  auto error = [&](int body, double accel) {
    const double* v = sim.data()->qvel + 6 * (body - 1);
    double e = 0;
    for (int i = 0; i < 3; ++i) e += std::pow(v[i] - accel * t * direction[i], 2);
    return e;
  };
  double balls = 0;
  for (int b = 2; b < 2 + kBalls; ++b) balls += error(b, a.ball);
  return error(1, a.box) + balls / kBalls;
}

// Mean of SquaredError over the samples of [0, until] (s), divided by the
// count of the whole run's samples: for until < kDuration, a lower bound of
// the whole run's mean.
double MeanSquaredError(Simulation& sim, double until) {
  const Analytic a = Accelerations();
  const int samples = static_cast<int>(std::lround(kDuration / kSample)) + 1;
  double sum = 0;
  for (int k = 0; k * kSample <= until + 1e-12; ++k) {
    while (sim.time() < k * kSample - 0.5 * sim.model()->opt.timestep) sim.Step();
    sum += SquaredError(sim, a);
  }
  return sum / samples;
}

class RollingTest : public testing::MujocoTest {};

TEST_F(RollingTest, AnalyticAccelerations) {
  // f1 = 137.34 N, f2 = 12.66 / 60 N
  const Analytic a = Accelerations();
  EXPECT_NEAR(a.ball, 0.211, 1e-12);
  EXPECT_NEAR(a.box, 0.7385, 1e-12);
}

TEST_F(RollingTest, SettledItFollowsTheAnalyticVelocitiesOverItsFourSeconds) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSceneSimulation("rolling.xml", options);
  ASSERT_TRUE(sim.settled());
  EXPECT_EQ(sim.settled()->bodies, 26);
  // the scene's positions along the ground and the box's face, and its turns
  EXPECT_EQ(sim.settled()->angle, 0.0);
  const mjtNum* q0 = sim.model()->qpos0;
  for (int b = 0; b < 1 + kBalls; ++b) {
    EXPECT_EQ(sim.data()->qpos[7 * b], q0[7 * b]) << b;
    EXPECT_EQ(sim.data()->qpos[7 * b + 1], q0[7 * b + 1]) << b;
  }
  const double error = MeanSquaredError(sim, kDuration);
  std::printf("rolling, settled: mean squared velocity error over %g s: %.3g (m/s)^2\n",
              kDuration, error);
  // the goal (issue 34); measured 1.42e-11: the contacts' compliance (the
  // balls roll on a lever shortened by their depth), after 0.1 s as before
  constexpr double kGoal = 1e-9;  // (m/s)^2
  EXPECT_LT(error, kGoal);
}

TEST_F(RollingTest, PlacedTouchingEveryBodyFirstDropsIntoItsSprings) {
  Simulation& sim = MakeSceneSimulation("rolling.xml");
  // the first 0.2 s alone already cost more than the settled run's 4 s
  // (measured: 2.7e-7 (m/s)^2 over 4 s, all of it in the first 0.1 s)
  const double bound = MeanSquaredError(sim, 0.2);
  std::printf("rolling, placed touching: the first 0.2 s give %.3g (m/s)^2 to the 4 s mean\n",
              bound);
  EXPECT_GT(bound, 1e-8);
}

}  // namespace
}  // namespace contactlaws
