// Copyright contactlaws authors.
//
// A mesh cube dropped 5 cm flat onto a box, and onto a mesh slab. MuJoCo
// 2.2.2's convex collider (MPR) held the face on the face at one point that
// it moved over the face from one step to the next: the cube rocked (up to
// 2.3e-2 rad/s after 3 s). contactlaws' polytope kernel (geometry/polytope.h)
// gives the patch's 4 corners with their own depths: the cube rests on 4
// points at the statics' depth, still, and the energy ledger does not rise.
// A hexagonal prism landing turned and barely tilted, a corner overhanging,
// lands on the patch too (nearly parallel faces keep the face contact).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "geometry/polytope.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class MeshLandingTest : public testing::MujocoTest {};

constexpr double kStiffness = 1e7;  // N/m^1.5, the tags'
constexpr double kMass = 1.0;       // kg, the cube's
constexpr double kGravity = 9.81;
constexpr double kDrop = 0.05;      // m, the cube's fall before touching

// Rest depths after 2 s against the statics: what is left of the settling
// oscillation, damped by Hunt-Crossley at e = 0.5. Measured: see the test.
constexpr double kRestDepthTolerance = 1e-3;  // relative
// The cube's angular velocity at rest. The one-point collider left it
// rocking at up to 2.3e-2 rad/s. On its 4 corners the flat drop is
// symmetric: what is left is round-off (measured 5.6e-14 rad/s on the box,
// 7.3e-14 on the slab); this bound is 2e7 times below the one-point rocking.
constexpr double kRockTolerance = 1e-9;  // rad/s
// At rest (from kSettled on) the ledger's total must not creep: it may rise
// by RK4's error at 1e-4 s, this fraction of the drop's energy m g h (the
// laws only dissipate). The landing itself raises the total by 2.2e-4 J
// (4.5e-4 of m g h), exactly as a box cube's landing through the box-box
// kernel does (measured with the cube's geom a box): a property of the
// landing at this step, shared with box-box, not of the patch (its cause is
// not pinned down here).
constexpr double kEnergyCreepTolerance = 1e-7;
// s: the landing at 0.1 s, its bounces until 0.44 s, then rocking onto its 4
// corners until ~0.53 s (where the total rises by 3e-5 J, as the landing's
// rise above), settled by then
constexpr double kSettled = 0.6;

// The base: a box geom free on the floor, or a mesh slab of the same size
// fixed to the world (a free one would rest on MuJoCo's plane-mesh contact:
// 3 of its corners, docs/geometry.md).
std::string Scene(bool mesh_base) {
  const std::string base =
      mesh_base ? R"(<geom name="base" type="mesh" mesh="slab" pos="0 0 0.1"/>)"
                : R"(<body name="base" pos="0 0 0.1"><freejoint/>
                       <geom name="base" type="box" size="0.2 0.2 0.1" mass="5"/></body>)";
  const std::string base_tag = mesh_base ? "" : R"(<text name="contactlaw:base"
      data="geom1=base geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7"/>)";
  return R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <asset>
    <mesh name="cube" vertex="-0.05 -0.05 -0.05  0.05 -0.05 -0.05  0.05 0.05 -0.05  -0.05 0.05 -0.05
                              -0.05 -0.05 0.05  0.05 -0.05 0.05  0.05 0.05 0.05  -0.05 0.05 0.05"/>
    <mesh name="slab" vertex="-0.2 -0.2 -0.1  0.2 -0.2 -0.1  0.2 0.2 -0.1  -0.2 0.2 -0.1
                              -0.2 -0.2 0.1  0.2 -0.2 0.1  0.2 0.2 0.1  -0.2 0.2 0.1"/>
  </asset>
  <worldbody>
    <geom name="floor" type="plane" size="3 3 0.1"/>
    )" + base + R"(
    <body name="cube" pos="0 0 0.3"><freejoint/>
      <geom name="cube" type="mesh" mesh="cube" mass="1"/></body>
  </worldbody>
  <custom>
    )" + base_tag + R"(
    <text name="contactlaw:cube" data="geom1=cube geom2=base law=hunt-crossley restitution=0.5
      stiffness=1e7"/>
  </custom>
</mujoco>)";
}

void ExpectLandsAndRestsOnFourCorners(Simulation& sim, const char* name) {
  const int cube_pair = static_cast<int>(sim.contact_model().pairs().size()) - 1;  // the last tag
  ASSERT_EQ(sim.contact_model().pairs()[cube_pair].slots, kMaxPolytopePoints);
  double total0 = 0, creep = 0;
  while (sim.time() < 2.0) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
    if (total0 == 0 && sim.time() >= kSettled) total0 = sim.Energy().total();
    if (total0 != 0) creep = std::max(creep, sim.Energy().total() - total0);
  }
  // dropped 5 cm: 0.99 m/s. The elastic peak of its whole mass on one point,
  // K d^1.5 at d = (5 m v^2 / 4K)^(2/5): 713 N; Hunt-Crossley's damping adds
  // to it while compressing; no corner of this cube can reach twice it.
  const double v = std::sqrt(2 * kGravity * kDrop);
  const double peak_bound = 2 * kStiffness * std::pow(5 * kMass * v * v / (4 * kStiffness), 0.6);
  int landings = 0;
  for (const Episode& c : sim.contacts().impacts()) {
    if (c.pair != cube_pair) continue;
    ++landings;
    EXPECT_LT(c.max_force, peak_bound) << "impact " << c.index;
  }
  EXPECT_GE(landings, 1);
  // on 4 corners, each at the statics' depth: K d^1.5 = m g / 4
  const double rest = std::pow(kMass * kGravity / (4 * kStiffness), 2.0 / 3);
  int corners = 0;
  double worst_depth = 0;
  for (const PointEvaluation& e : sim.contacts().latest()) {
    if (e.pair != cube_pair) continue;
    ++corners;
    worst_depth = std::max(worst_depth, std::fabs(e.depth / rest - 1));
  }
  EXPECT_EQ(corners, 4);
  EXPECT_LT(worst_depth, kRestDepthTolerance);
  const mjModel* m = sim.model();
  const mjData* d = sim.data();
  const int body = mj_name2id(m, mjOBJ_BODY, "cube");
  const mjtNum* w = d->qvel + m->jnt_dofadr[m->body_jntadr[body]] + 3;
  const double rock = std::max({std::fabs(w[0]), std::fabs(w[1]), std::fabs(w[2])});
  EXPECT_LT(rock, kRockTolerance);
  EXPECT_LT(creep, kEnergyCreepTolerance * kMass * kGravity * kDrop);
  // on the base's top face, the corners' depth into it
  const double* base = d->geom_xpos + 3 * mj_name2id(m, mjOBJ_GEOM, "base");
  const double* cube = d->geom_xpos + 3 * mj_name2id(m, mjOBJ_GEOM, "cube");
  EXPECT_NEAR(cube[2] - base[2], 0.15 - rest, kRestDepthTolerance * rest) << "height";
  std::printf("%s: %d corners, depth error %.3g, |w| %.3g rad/s, ledger creep %.3g J\n", name,
              corners, worst_depth, rock, creep);
}

TEST_F(MeshLandingTest, AMeshCubeLandsFlatOnABoxAndRestsOnFourCorners) {
  ExpectLandsAndRestsOnFourCorners(MakeSimulation(Scene(false)), "mesh on box");
}

TEST_F(MeshLandingTest, AMeshCubeLandsFlatOnAMeshSlabAndRestsOnFourCorners) {
  ExpectLandsAndRestsOnFourCorners(MakeSimulation(Scene(true)), "mesh on mesh");
}

// A hexagonal prism (circumradius 5 cm, 10 cm tall, 1 kg; a mesh of 12
// vertices) turned 37 degrees, tilted 0.2 degrees (3.5e-3 rad), off centre
// by 1.4 cm, dropped 2 cm onto a fixed 10 cm box: its lowest corner lands
// overhanging the box. The least overlap alone chose an edge-pair axis and
// carried the prism on one point of that edge crossing: it rebounded at
// e = 0.82 for the tag's 0.5, peaked at 2498 N, the ledger rose by 0.44 J
// (2.2 times m g h), and after 1 s it still rocked at 1.8e-3 rad/s. Nearly
// parallel faces keep the face contact (geometry/patch.h, kParallelFaceSine):
// the patch, each corner at its own depth.
TEST_F(MeshLandingTest, APrismLandingTurnedAndBarelyTiltedOnABoxGainsNoEnergy) {
  std::string prism;
  for (const double z : {-0.05, 0.05}) {
    for (int k = 0; k < 6; ++k) {
      const double t = k * mjPI / 3;
      prism += fmt::format(" {} {} {}", 0.05 * std::cos(t), 0.05 * std::sin(t), z);
    }
  }
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <asset><mesh name="prism" vertex=")" + prism + R"("/></asset>
  <worldbody>
    <geom name="base" type="box" size="0.05 0.05 0.05" pos="0 0 0.05"/>
    <body name="prism" pos="0.012 -0.008 0.17" euler="0.15 0.13 37"><freejoint/>
      <geom name="prism" type="mesh" mesh="prism" mass="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:prism" data="geom1=base geom2=prism law=hunt-crossley
      restitution=0.5 stiffness=1e7 min_impact_velocity=0.01 friction=coulomb mu=0.5"/>
  </custom>
</mujoco>)");
  constexpr double kPrismDrop = 0.02;  // m
  sim.Step();  // the ledger's positions are MuJoCo's after a step
  const double total0 = sim.Energy().total();
  double rise = 0;
  while (sim.time() < 1.0) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
    rise = std::max(rise, sim.Energy().total() - total0);
  }
  // the landing's rise at this step, as the cube's above: measured 7.5e-5 J
  // (3.8e-4 of m g h); the one-point landing's is 45 times this bound
  EXPECT_LT(rise, 0.05 * kMass * kGravity * kPrismDrop);
  // the elastic peak of the whole mass on one point (above), damping
  // included: measured 636 N on the patch
  const double v = std::sqrt(2 * kGravity * kPrismDrop);
  const double peak_bound = 2 * kStiffness * std::pow(5 * kMass * v * v / (4 * kStiffness), 0.6);
  double peak = 0;
  for (const Episode& c : sim.contacts().impacts()) {
    EXPECT_LT(c.max_force, peak_bound) << "impact " << c.index;
    peak = std::max(peak, c.max_force);
  }
  // at rest on a patch by 1 s
  int points = 0;
  for (const PointEvaluation& e : sim.contacts().latest()) points += e.depth > 0;
  EXPECT_GE(points, 3);
  const mjModel* m = sim.model();
  const mjtNum* w = sim.data()->qvel + m->jnt_dofadr[0] + 3;
  const double rock = std::max({std::fabs(w[0]), std::fabs(w[1]), std::fabs(w[2])});
  EXPECT_LT(rock, kRockTolerance);
  std::printf("prism on box: %d points, |w| %.3g rad/s, ledger rise %.3g J, peak %.4g N\n",
              points, rock, rise, peak);
}

}  // namespace
}  // namespace contactlaws
