// Copyright contactlaws authors.
//
// A tilted lid (80 x 60 x 40 mm, 0.3 kg) dropped from 0.2 m onto a 0.1 m
// cube standing on the floor, 1 cm off centre, turned by euler 8 12 20:
// it lands on the cube's top edge, its bottom face crossing the edge, a
// face patch whose points are where the lid's edges cross the cube's side
// plane. Those points slide along the edges as the bodies move, so their
// depths change faster than the bodies approach along the normal; a force
// along the normal alone then does work the patch's elastic energy does not
// store, and the ledger's total rose by 6.9e-4 J in that impact. Along the
// depths' gradients (geometry/patch.h, ClipVertex) it does not rise.
#include <algorithm>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kTimestep = 1e-5;  // s, RK4: the impact resolved
constexpr double kDuration = 0.3;   // s: the lid's impacts at 0.119 to 0.135 s, then at rest

constexpr char kLidOnCube[] = R"(<mujoco>
  <option timestep="1e-5" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="base" pos="0 0 0.05"><freejoint/>
      <geom name="base" type="box" size="0.05 0.05 0.05" mass="1"/></body>
    <body name="lid" pos="0.01 0 0.2" euler="8 12 20"><freejoint/>
      <geom name="lid" type="box" size="0.04 0.03 0.02" mass="0.3"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:floor" data="geom1=floor geom2=base law=hunt-crossley restitution=0.5
      stiffness=1e7 min_impact_velocity=0.01 friction=coulomb mu=0.5"/>
    <text name="contactlaw:lid" data="geom1=base geom2=lid law=hunt-crossley restitution=0.5
      stiffness=1e7 friction=coulomb mu=0.4"/>
  </custom>
</mujoco>)";

class TiltedLidEnergyTest : public testing::MujocoTest {};

TEST_F(TiltedLidEnergyTest, TheLedgersTotalDoesNotRiseWhenTheLidLandsOnAnEdge) {
  SimulationOptions options;
  options.settle = true;  // the cube at rest on the floor's springs
  Simulation& sim = MakeSimulation(kLidOnCube, options);
  sim.Step(kTimestep);  // the ledger starts at the first evaluation
  const double start = sim.Energy().total();
  double rise = 0;
  while (sim.time() < kDuration) {
    sim.Step(kTimestep);
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
    rise = std::max(rise, sim.Energy().total() - start);
  }
  // measured 1.2e-6 J (the integration's: 4.7e-6, 5.7e-7 and 5.8e-8 J with
  // --timestep auto at --accuracy 1e-4, 1e-5 and 1e-6); the forces along
  // the normal alone made 6.9e-4 J at every step length
  constexpr double kRiseTolerance = 1e-5;  // J, 1e-5 of the scene's 1.08 J
  EXPECT_LT(rise, kRiseTolerance);
}

}  // namespace
}  // namespace contactlaws
