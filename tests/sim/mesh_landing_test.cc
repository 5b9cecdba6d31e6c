// Copyright contactlaws authors.
//
// A mesh cube dropped flat onto a box: MuJoCo 2.2.2's convex collider (MPR)
// returns one point for the face on the face, anywhere on it from one step
// to the next. The pair keeps one contact episode wherever the point goes
// (EpisodeLog): as a new point, found deep and approaching far above the
// floor of v0, it turned the law's damping into a wall, and the run diverged
// 3 ms after the landing (forces of 7e7 N, e_post 2e4).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class MeshLandingTest : public testing::MujocoTest {};

constexpr char kMeshOnBox[] = R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <asset>
    <mesh name="cube" vertex="-0.05 -0.05 -0.05  0.05 -0.05 -0.05  0.05 0.05 -0.05  -0.05 0.05 -0.05
                              -0.05 -0.05 0.05  0.05 -0.05 0.05  0.05 0.05 0.05  -0.05 0.05 0.05"/>
  </asset>
  <worldbody>
    <geom name="floor" type="plane" size="3 3 0.1"/>
    <body name="base" pos="0 0 0.1"><freejoint/>
      <geom name="base" type="box" size="0.2 0.2 0.1" mass="5"/></body>
    <body name="cube" pos="0 0 0.3"><freejoint/>
      <geom name="cube" type="mesh" mesh="cube" mass="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:base" data="geom1=base geom2=floor law=hunt-crossley restitution=0.5
      stiffness=1e7"/>
    <text name="contactlaw:cube" data="geom1=cube geom2=base law=hunt-crossley restitution=0.5
      stiffness=1e7"/>
  </custom>
</mujoco>)";

TEST_F(MeshLandingTest, AMeshCubeLandsFlatOnABoxAndRestsThere) {
  Simulation& sim = MakeSimulation(kMeshOnBox);
  const int cube_pair = 1;
  ASSERT_EQ(sim.contact_model().pairs()[cube_pair].slots, 1);  // MPR, no multiCCD
  while (sim.time() < 1.0) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
  }
  // dropped 5 cm: 0.99 m/s. The elastic peak of its whole mass (1 kg; the
  // point's effective mass is less), K d^1.5 at d = (5 m v^2 / 4K)^(2/5):
  // 713 N. Hunt-Crossley's damping adds to it while compressing; no landing
  // of this cube can reach twice it. Measured: 598 N.
  const double v = std::sqrt(2 * 9.81 * 0.05);
  const double depth = std::pow(5 * 1.0 * v * v / (4 * 1e7), 0.4);
  const double peak_bound = 2 * 1e7 * std::pow(depth, 1.5);
  int landings = 0;
  for (const Impact& c : sim.contacts().impacts()) {
    if (c.pair != cube_pair) continue;
    ++landings;
    EXPECT_LT(c.max_force, peak_bound) << "collision " << c.index;
    if (!c.open) {
      EXPECT_LT(c.restitution_post(), 1.0) << "collision " << c.index;
    }
  }
  EXPECT_GE(landings, 1);
  // on the box's top (z = 0.25 less the static depths), flat, still: held
  // at its one point, which the collider moves over the face, it rocks a
  // little (measured up to 2.3e-2 rad/s in 3 s, corners at 1e-3 m/s)
  const mjData* d = sim.data();
  const double* cube_q = d->qpos + 7;
  constexpr double kRestTolerance = 1e-3;  // m, m/s: depths are ~1e-4 m
  constexpr double kRockTolerance = 5e-2;  // rad/s
  EXPECT_NEAR(cube_q[2], 0.25, kRestTolerance);
  for (int i = 6; i < 9; ++i) EXPECT_NEAR(d->qvel[i], 0, kRestTolerance) << "dof " << i;
  for (int i = 9; i < 12; ++i) EXPECT_NEAR(d->qvel[i], 0, kRockTolerance) << "dof " << i;
  EXPECT_GT(std::abs(cube_q[3]), 0.999);  // upright: tilts below 2.6 degrees
}

}  // namespace
}  // namespace contactlaws
